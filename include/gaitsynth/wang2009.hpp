#pragma once
/// \file wang2009.hpp
/// Umbrella header of Wang, Fleet & Hertzmann 2009 (docs/reproductions/wang2009.md): the 30-DOF
/// humanoid with toes, the finite-state world-frame PD controller and the SIMBICON baseline, every
/// term of the biomechanical objective, the 184-dimensional search space, Table 1's push protocol
/// and the robust stages' perturbed variants. gaitsynth.hpp holds the core they build on.
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_parameters.hpp"
#include "gaitsynth/controllers/fsm/wang2009_shape_transfer.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"
#include "gaitsynth/synthesis/wang2009_search_space.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#if __has_include(<nlohmann/json.hpp>)
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#endif
