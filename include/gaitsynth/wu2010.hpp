#pragma once
/// \file wu2010.hpp
/// Umbrella header of Wu & Popovic 2010 (docs/reproductions/wu2010.md): the Table 3 biped, the
/// end-effector planner (Sec. 4, appendix A), the lower level's frames, ideal forces and eq. 5's QP
/// (Sec. 5-6, appendix B) on the library's dense QP solver, the standing and cyclical controllers,
/// the offline-optimization cost (Sec. 8.1-8.2), Table 1's search space and the per-iteration
/// terrain reference. gaitsynth.hpp holds the core they build on.
#include "gaitsynth/contact/terrain_choice.hpp"
#include "gaitsynth/contact/terrain_ref.hpp"
#include "gaitsynth/controllers/end_effector/foot_clearance.hpp"
#include "gaitsynth/controllers/end_effector/force_qp.hpp"
#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/generalized_forces.hpp"
#include "gaitsynth/controllers/end_effector/half_cycle_plan.hpp"
#include "gaitsynth/controllers/end_effector/height_hull.hpp"
#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/controllers/end_effector/null_space_damper.hpp"
#include "gaitsynth/controllers/end_effector/null_space_knee.hpp"
#include "gaitsynth/controllers/end_effector/path_curves.hpp"
#include "gaitsynth/controllers/end_effector/pd_forces.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_report.hpp"
#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planner_targets.hpp"
#include "gaitsynth/controllers/end_effector/planner_timing.hpp"
#include "gaitsynth/controllers/end_effector/standing_balance.hpp"
#include "gaitsynth/controllers/end_effector/swing_foot_path.hpp"
#include "gaitsynth/controllers/end_effector/upper_body_path.hpp"
#include "gaitsynth/controllers/end_effector/walk_script.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"
#include "gaitsynth/qp/dense_qp.hpp"
#include "gaitsynth/qp/goldfarb_idnani.hpp"
#include "gaitsynth/synthesis/wu2010_search_space.hpp"
