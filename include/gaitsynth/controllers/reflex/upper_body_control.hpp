#pragma once
/// \file controllers/reflex/upper_body_control.hpp
/// The joint-space PD control of Wang et al. 2012 Sec. 4.4 for every DOF the muscles do not drive,
/// written into the mixed block (targets, kp, kd, feed-forward) of the musculotendon actuator's
/// command. Two mirrored states: `support` is the leg that struck the ground last (the paper's
/// "triggered by left/right foot-strike"); upper_body_parameters.hpp's values are written for the
/// right leg standing, so a coronal or transverse target changes sign when the left stands.
///
///   stance hip_x   holds the pelvis' world coronal angle: -(pelvis servo torque + swing hip's
///                  coronal torque), as SIMBICON's stance hip holds the torso;
///   swing hip_x    servos the swing thigh's world coronal angle to target + cd_cor d_y + cv_cor
///   v_y
///                  (d_y, v_y: the COM's sideways offset from the stance ankle and velocity; the
///                  same feedback law as the sagittal hip target theta_h);
///   ankle_x        servos each foot's world coronal angle;
///   back_x         servos the torso's world coronal angle ("global orientation of the torso");
///   hip_z, back_y, back_z, neck: local PD;
///   toes           the 30 N m/rad spring, target 0, no damping;
///   arms           30 N m/rad, 3 N m s/rad springs; elbow_y to theta_e, shoulders
///                  theta_s = alpha_arm (q_hip_y,other - q_hip_y,own) + beta theta_e (sagittal) and
///                  phi_s = gamma theta_e (transverse; Sec. 4.4).
/// World servos act with their stiffness on the world angle and damp the joint's own rate, as in
/// wang2009_controller (world damping rings at 2400 Hz). The sagittal hip, knee and ankle DOFs are
/// left limp: their torques are the muscles'.
///
/// beta and gamma are "chosen based on human motion data (see supplemental material)", which we do
/// not have: ours, shoulder_beta = -0.5 (the shoulder extends as the elbow flexes) and
/// shoulder_gamma = 0.5 (and turns inwards).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <tuple>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/controllers/reflex/upper_body_parameters.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/models/wang2012.hpp"

namespace gaitsynth::reflex {

inline constexpr double shoulder_beta = -0.5;  ///< ours (file comment)
inline constexpr double shoulder_gamma = 0.5;  ///< ours

/// Per-DOF gain caps for explicit PD at the physics timestep (pd_actuator::capped).
struct gain_caps {
  Eigen::VectorXd kp, kd;
};

/// Writes Sec. 4.4's control into out. support: 0 left stands, 1 right; heading: the walking
/// direction (rad about z); d, v: the COM's offset from the stance ankle and its velocity (world).
template <root_joint Root>
void upper_body_control(const sensors<Root>& s, const biped_layout& B,
                        const upper_body_parameter_vector& P, const gain_caps& caps, int support,
                        double heading, const vec3& d, const vec3& v, mixed_command& out) {
  const biped_leg& stl = B.leg[support];
  const biped_leg& sw = B.leg[1 - support];
  const double sign = support == 1 ? 1.0 : -1.0;  // parameters written for the right leg standing
  auto kp = [&](int j, int i) { return std::clamp(P[i], 0.0, caps.kp[j]); };
  auto kd = [&](int j, int i) { return std::clamp(P[i], 0.0, caps.kd[j]); };
  auto local = [&](int j, double target, int kp_index) {
    out.set_target(j, target, kp(j, kp_index), kd(j, kp_index + 1));
  };
  // A world-coronal servo of body b through DOF j: the torque's share along j's axis.
  auto coronal = [&](int b, int j, double target, int kp_index) {
    world_servo_gains g;
    g.kp[0] = kp(j, kp_index);
    g.target[0] = target;
    return world_servo_torque(s, b, g, heading);
  };
  const vec3 dh = to_heading_frame(d, heading), vh = to_heading_frame(v, heading);
  // Hips.
  const vec3 tau_swing =
      coronal(sw.thigh, sw.hip_x,
              sign * P[swing_hip_coronal] + P[cd_coronal] * dh.y() + P[cv_coronal] * vh.y(),
              kp_hip_x_swing);
  const vec3 tau_pelvis = coronal(B.pelvis, stl.hip_x, sign * P[pelvis_coronal], kp_hip_x_stance);
  out.set_target(sw.hip_x, 0.0, 0.0, kd(sw.hip_x, kd_hip_x_swing),
                 dof_world_axis(s, sw.hip_x).dot(tau_swing));
  out.set_target(stl.hip_x, 0.0, 0.0, kd(stl.hip_x, kd_hip_x_stance),
                 -dof_world_axis(s, stl.hip_x).dot(tau_pelvis + tau_swing));
  local(stl.hip_z, 0.0, kp_hip_z_stance);
  local(sw.hip_z, 0.0, kp_hip_z_swing);
  // Ankles: the feet's world coronal angles.
  for (const auto& [leg, kp_i, target] :
       {std::tuple{&stl, int(kp_ankle_x_stance), P[stance_foot_coronal]},
        std::tuple{&sw, int(kp_ankle_x_swing), P[swing_foot_coronal]}}) {
    const vec3 tau = coronal(leg->foot, leg->ankle_x, sign * target, kp_i);
    out.set_target(leg->ankle_x, 0.0, 0.0, kd(leg->ankle_x, kp_i + 1),
                   dof_world_axis(s, leg->ankle_x).dot(tau));
  }
  // Back and neck.
  const vec3 tau_torso = coronal(B.torso, B.back_x, sign * P[torso_coronal], kp_back_x);
  out.set_target(B.back_x, 0.0, 0.0, kd(B.back_x, kd_back_x),
                 dof_world_axis(s, B.back_x).dot(tau_torso));
  local(B.back_y, P[back_y_target], kp_back_y);
  local(B.back_z, sign * P[back_z_target], kp_back_z);
  for (int j : {B.neck_x, B.neck_y, B.neck_z}) local(j, 0.0, kp_neck);
  // Toes: passive springs. Muscle DOFs: limp.
  for (const biped_leg& g : B.leg) {
    out.set_target(g.toe, 0.0, wang2012_passive::toe_stiffness, 0.0);
    for (int j : {g.hip_y, g.knee, g.ankle_y}) out.set_target(j, 0.0, 0.0, 0.0);
  }
  // Arms.
  const double elbow = P[elbow_target];
  for (int side = 0; side < 2; ++side) {
    const biped_arm& a = B.arm[side];
    const double own = s.joint_angle(B.leg[side].hip_y),
                 other = s.joint_angle(B.leg[1 - side].hip_y);
    const double mirror = side == 0 ? 1.0 : -1.0;  // shoulder_z mirrors; shoulder_y does not
    auto spring = [&](int j, double target) {
      out.set_target(j, target, wang2012_passive::arm_stiffness, wang2012_passive::arm_damping);
    };
    spring(a.shoulder_x, 0.0);
    spring(a.shoulder_y, P[alpha_arm] * (other - own) + shoulder_beta * elbow);
    spring(a.shoulder_z, mirror * shoulder_gamma * elbow);
    spring(a.elbow_y, elbow);
    spring(a.elbow_z, 0.0);
  }
}

}  // namespace gaitsynth::reflex
