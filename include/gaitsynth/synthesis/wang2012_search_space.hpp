#pragma once
/// \file synthesis/wang2012_search_space.hpp
/// The search space of Wang et al. 2012 Sec. 5: the 122 parameters of wang2012_reflex_controller
/// with bounds, so that CMA-ES with sigma = 0.005 steps on parameters scaled to [0, 1]
/// (parameter_space). The paper gives neither bounds nor scaling; ours, wide enough to hold every
/// initial value with room to move:
///   excitations p_, q_, s_                              [0, 1]
///   force and length gains G_, k_lean, k_knee           [0, 5]
///   length offsets H_ (l_CE / l_opt)                    [0.3, 1.5]
///   muscle PD stiffness K_ (per rad), damping D_ (s)    [0, 10], [0, 1]
///   angles (lean_, targets, offsets)                    [-0.5, 1.5] rad
///   d_SI, d_SP (leg lengths)                            [-1, 1.5]
///   balance gains c_d, c_v, cd_coronal, cv_coronal      [-1, 1]
///   PD gains kp_, kd_ of Sec. 4.4                       [0, 3000] N m/rad, [0, 300] N m s/rad
///   coronal and transverse targets                      [-0.5, 0.5] rad
///   alpha_arm, elbow_target                             [0, 3], [-2.5, 0] rad
///   start: height +-0.1 m about the initial, pitch and roll [-0.3, 0.3] rad, forward speed
///   [0, max(3, 2 x0)] m/s (x0 its initial value: 3 for walking starts), sideways and vertical [-1,
///   1] m/s, pitch rate [-3, 3] rad/s, joint angles
///   [-2.5, 2.5] rad, joint rates [-10, 10] rad/s.
#include <algorithm>
#include <string>
#include <vector>

#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"

namespace gaitsynth {

/// The bounds of the file comment for the parameter called `name`, whose initial value is x0.
inline std::pair<double, double> wang2012_parameter_bounds(const std::string& name, double x0) {
  auto starts = [&](const char* p) { return name.rfind(p, 0) == 0; };
  if (starts("start.")) {
    if (name == "start.root_z") return {x0 - 0.1, x0 + 0.1};
    if (name == "start.root_pitch" || name == "start.root_roll") return {-0.3, 0.3};
    // Walking starts (1.3 m/s) keep [0, 3]; the running start (3.05 m/s) gets room above it.
    if (name == "start.root_vx") return {0.0, std::max(3.0, 2.0 * x0)};
    if (name == "start.root_vy" || name == "start.root_vz") return {-1.0, 1.0};
    if (name == "start.root_wy") return {-3.0, 3.0};
    if (starts("start.q.")) return {-2.5, 2.5};
    return {-10.0, 10.0};  // start.v.
  }
  if (starts("kp_")) return {0.0, 3000.0};
  if (starts("kd_")) return {0.0, 300.0};
  if (name == "cd_coronal" || name == "cv_coronal" || name == "c_d" || name == "c_v")
    return {-1.0, 1.0};
  if (name == "alpha_arm") return {0.0, 3.0};
  if (name == "elbow_target") return {-2.5, 0.0};
  if (name == "pelvis_coronal" || name == "swing_hip_coronal" || name == "stance_foot_coronal" ||
      name == "swing_foot_coronal" || name == "torso_coronal" || name == "back_z_target" ||
      name == "back_y_target")
    return {-0.5, 0.5};
  if (name == "d_SI" || name == "d_SP") return {-1.0, 1.5};
  if (starts("p_") || starts("q_") || starts("s_")) return {0.0, 1.0};
  if (starts("G_") || name == "k_lean" || name == "k_knee") return {0.0, 5.0};
  if (starts("H_")) return {0.3, 1.5};
  if (starts("K_")) return {0.0, 10.0};
  if (starts("D_")) return {0.0, 1.0};
  return {-0.5, 1.5};  // lean_*, knee_offset, knee_target, hip_target (rad)
}

/// The parameter space of wang2012_reflex_controller with `initial` as the initial values.
/// \throws std::invalid_argument naming a parameter whose initial value lies outside its bounds.
inline parameter_space wang2012_search_space(const std::vector<double>& initial) {
  const std::vector<std::string> names = wang2012_reflex_controller::parameter_names();
  check_size(static_cast<std::ptrdiff_t>(initial.size()), static_cast<std::ptrdiff_t>(names.size()),
             "wang2012_search_space: initial parameters");
  parameter_space space;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto [lo, hi] = wang2012_parameter_bounds(names[i], initial[i]);
    space.add({.name = names[i], .lower = lo, .upper = hi, .initial = initial[i]});
  }
  return space;
}

}  // namespace gaitsynth
