#pragma once
/// \file gaitsynth.hpp
/// The core of gaitsynth: model, dynamics, contact, actuators, controllers, objectives, rollout,
/// optimizers, QP, models, I/O and visualization, with the Sharon 2005 synthesis and the Wang 2009
/// controller and objective. Each later paper's system has its own umbrella header (wang2009.hpp,
/// wu2010.hpp, wang2012.hpp; analysis.hpp for gait measures), so a program pays only for the
/// systems it uses; one that cares about compile time includes only the headers it uses (each
/// header includes what it needs).
/// The headers that use nlohmann::json (motion/keyframes_json.hpp,
/// controllers/nearest_neighbor_json.hpp, viz/html_player.hpp, which writes the player's data,
/// and io/viewer_outputs.hpp, which writes the player) are included only when
/// <nlohmann/json.hpp> is available.
/// Architecture: docs/architecture.md.

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/error.hpp"

#include "gaitsynth/spatial/spatial.hpp"
#include "gaitsynth/spatial/types.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

#include "gaitsynth/model/fingerprint.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/model/root.hpp"
#include "gaitsynth/model/state.hpp"

#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/energy.hpp"
#include "gaitsynth/dynamics/jacobian.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/momentum.hpp"
#include "gaitsynth/dynamics/rnea.hpp"
#include "gaitsynth/dynamics/workspace.hpp"

#include "gaitsynth/integrators/concept.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/actuators/torque.hpp"

#include "gaitsynth/motion/keyframes.hpp"

#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_parameters.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/controllers/nearest_neighbor.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/controllers/sensor_history.hpp"
#include "gaitsynth/controllers/sensors.hpp"

#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"

#include "gaitsynth/rollout/observer.hpp"
#include "gaitsynth/rollout/options.hpp"
#include "gaitsynth/rollout/policy_states.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/problem_with_constraint.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/rollout/recorder.hpp"
#include "gaitsynth/rollout/result.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/termination.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/rollout/walk_check.hpp"

#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/continuation.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/optimizers/optimizers.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"
#include "gaitsynth/optimizers/random.hpp"
#include "gaitsynth/optimizers/restarts.hpp"
#include "gaitsynth/optimizers/sds.hpp"
#include "gaitsynth/optimizers/test_functions.hpp"

#include "gaitsynth/qp/dense_qp.hpp"
#include "gaitsynth/qp/goldfarb_idnani.hpp"
#include "gaitsynth/qp/kkt.hpp"

#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"

#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/models.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/models/wu2010.hpp"

#include "gaitsynth/io/bvh.hpp"
#include "gaitsynth/io/csv.hpp"
#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/io/mjcf_replay.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"

#include "gaitsynth/viz/convergence_plot_svg.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"
#include "gaitsynth/viz/gait_plot_svg.hpp"
#include "gaitsynth/viz/scene.hpp"
#include "gaitsynth/viz/svg.hpp"

#if __has_include(<nlohmann/json.hpp>)
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/io/viewer_outputs.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/viz/html_player.hpp"
#endif
