#pragma once
/// \file synthesis/wang2009_simulation.hpp
/// The simulation settings of Wang, Fleet & Hertzmann 2009 (Sec. 4.2) in one place, so the
/// optimization (examples/wang2009_walk.cpp) and the claim tests that re-simulate its walkers
/// (tests/wang2009/) run the same rollout: 2400 Hz, penalty contact kp = 75000 N/m, kd = 2000
/// N s/m, mu = 10, a rollout stopped once the COM is below E_fail's height, and the joint
/// dampers taken implicitly.
#include <string>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/rollout/options.hpp"

namespace gaitsynth {

/// Rollout settings for a wang2009_controller on m (10 s; its start state is the controller's).
/// fail_height: E_fail's COM height (0.7 m; 0.4 m for "long arm").
inline rollout_options wang2009_rollout_options(const floating_model& m, double fail_height = 0.7) {
  rollout_options o;    // 2400 Hz, 10 s, kp 75000 N/m, kd 2000 N s/m
  o.contact.mu = 10.0;  // Sec. 4.2
  o.fall_height = fail_height;
  // Joint dampers by backward Euler: explicit ones diverge at the hips' gimbal lock (hip_y near
  // -pi/2, a leg kicked up in a fall), which made ~45 % of the rollouts around Table 2 blow up
  // (docs/reproductions/wang2009.md, "Damping").
  o.implicit_joint_damping = true;
  o.initial_state = make_state(m);  // sized, so the controller writes its start in place
  return o;
}

/// E_fail's height for a shape: 0.4 m for "long arm", else 0.7 m (Sec. 4.1).
inline double wang2009_fail_height(const std::string& shape) {
  return shape == "long_arm" || shape == "long arm" ? 0.4 : 0.7;
}

}  // namespace gaitsynth
