#pragma once
/// \file controllers/reflex/upper_body_parameters.hpp
/// The PD parameters of Wang et al. 2012 Sec. 4.4 for the DOFs the muscles do not drive: the
/// coronal and transverse hips and ankles, the back, the neck and the arm swing. 31 values, named.
///
/// The paper optimizes "spring-damper constants, target angle, balance feedback" of these DOFs and
/// only a target elbow angle and a swing scale for the arms, in two states (left or right foot
/// strike). The states are mirror images, so one set serves both, written by role (the stance
/// leg is the one that struck last). Which values exist is ours, read from the text and from
/// Wang et al. 2009 (whose controller the text follows):
///   stance hip_x   kp, kd, and the pelvis' world coronal target (the stance hip holds the pelvis)
///   swing hip_x    kp, kd, and the swing thigh's world coronal target + cd_cor d_y + cv_cor v_y
///                  (SIMBICON balance feedback, "the same feedback law as theta_h")
///   hip_z          kp, kd per role, local target 0
///   ankle_x        kp, kd, the foot's world coronal target, per role
///   back_x         kp, kd, the torso's world coronal target ("global orientation of the torso")
///   back_y, back_z kp, kd, local target
///   neck           kp, kd on all three axes, targets 0
///   arms           alpha_arm and the target elbow angle (the shoulders follow, Sec. 4.4)
/// The paper's count is 124 - 56 - 33 = 35 with its two balance gains of the sagittal hip, which
/// reflex_parameters.hpp holds (c_d, c_v): 33 against our 31 + 2.
///
/// Initial values (ours): Wang et al. 2009 Table 2's gains for the 70 kg body (kd = 0.1 kp), the
/// targets 0, SIMBICON's coronal feedback 0.2, alpha_arm 1 and the elbow flexed 0.2 rad.
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"

namespace gaitsynth::reflex {

enum upper_body_parameter : int {
  kp_hip_x_stance,
  kd_hip_x_stance,
  pelvis_coronal,  // rad, world coronal angle of the pelvis (+ left side up)
  kp_hip_x_swing,
  kd_hip_x_swing,
  swing_hip_coronal,  // rad, world coronal angle of the swing thigh (before the feedback)
  cd_coronal,         // rad per m of COM offset from the stance ankle, sideways
  cv_coronal,         // rad per m/s of COM velocity, sideways
  kp_hip_z_stance,
  kd_hip_z_stance,
  kp_hip_z_swing,
  kd_hip_z_swing,
  kp_ankle_x_stance,
  kd_ankle_x_stance,
  stance_foot_coronal,  // rad, world coronal angle of the stance foot
  kp_ankle_x_swing,
  kd_ankle_x_swing,
  swing_foot_coronal,  // rad
  kp_back_x,
  kd_back_x,
  torso_coronal,  // rad, world coronal angle of the torso
  kp_back_y,
  kd_back_y,
  back_y_target,  // rad, local (+ forward flexion)
  kp_back_z,
  kd_back_z,
  back_z_target,  // rad, local
  kp_neck,
  kd_neck,
  alpha_arm,     // shoulder swing per rad of hip difference
  elbow_target,  // rad (elbow_y, - flexion)
  upper_body_parameter_count
};

static_assert(upper_body_parameter_count == 31);

inline constexpr std::array<std::string_view, upper_body_parameter_count>
    upper_body_parameter_names{
        "kp_hip_x_stance",   "kd_hip_x_stance",    "pelvis_coronal",      "kp_hip_x_swing",
        "kd_hip_x_swing",    "swing_hip_coronal",  "cd_coronal",          "cv_coronal",
        "kp_hip_z_stance",   "kd_hip_z_stance",    "kp_hip_z_swing",      "kd_hip_z_swing",
        "kp_ankle_x_stance", "kd_ankle_x_stance",  "stance_foot_coronal", "kp_ankle_x_swing",
        "kd_ankle_x_swing",  "swing_foot_coronal", "kp_back_x",           "kd_back_x",
        "torso_coronal",     "kp_back_y",          "kd_back_y",           "back_y_target",
        "kp_back_z",         "kd_back_z",          "back_z_target",       "kp_neck",
        "kd_neck",           "alpha_arm",          "elbow_target"};

using upper_body_parameter_vector = std::array<double, upper_body_parameter_count>;

/// The initial values of the file comment (ours).
inline upper_body_parameter_vector upper_body_initial_parameters() {
  upper_body_parameter_vector p{};
  auto gains = [&](int kp, double value) {
    p[kp] = value;
    p[kp + 1] = 0.1 * value;
  };
  gains(kp_hip_x_stance, 1000.0);
  gains(kp_hip_x_swing, 1000.0);
  p[cd_coronal] = 0.2, p[cv_coronal] = 0.2;
  gains(kp_hip_z_stance, 1000.0);
  gains(kp_hip_z_swing, 1000.0);
  gains(kp_ankle_x_stance, 100.0);
  gains(kp_ankle_x_swing, 30.0);
  gains(kp_back_x, 300.0);
  gains(kp_back_y, 300.0);
  gains(kp_back_z, 300.0);
  gains(kp_neck, 100.0);
  p[alpha_arm] = 1.0;
  p[elbow_target] = -0.2;
  return p;
}

/// Copies a bound parameter vector, refusing a wrong size or a value that is not finite.
inline upper_body_parameter_vector upper_body_parameters_from(std::span<const double> p) {
  check_argument(p.size() == upper_body_parameter_count, "upper-body parameters: expected ",
                 static_cast<int>(upper_body_parameter_count), " values, got ", p.size());
  upper_body_parameter_vector out{};
  for (std::size_t i = 0; i < out.size(); ++i) {
    check_argument(std::isfinite(p[i]), "upper-body parameter ", upper_body_parameter_names[i],
                   " is not finite (", p[i], ")");
    out[i] = p[i];
  }
  return out;
}

}  // namespace gaitsynth::reflex
