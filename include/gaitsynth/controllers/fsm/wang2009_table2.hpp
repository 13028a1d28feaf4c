#pragma once
/// \file controllers/fsm/wang2009_table2.hpp
/// The initial controller and start state of Wang, Fleet & Hertzmann 2009, Table 2 and Sec. 4.3,
/// as a parameter vector of wang2009_controller. The paper tuned it to "take a few steps" on the
/// "stocky" character: "It is not stable and does not walk in a straight line, but is sufficient
/// for initialization"; kp and kd are scaled by the body's weight relative to stocky's 70 kg.
///
/// How Table 2 is read (docs/reproductions/wang2009.md):
///   - kd = 0.1 kp everywhere (the caption);
///   - the row "rhip_y" and "rhip_xz" are the swing hip (the stance hip is torque-controlled
///     through "torso_xyz", which Table 2 lists separately, and lknee, lankle are the swing leg's
///     in state 0): swing_hip_y kp 1000, target -1 (state 0) and -0.65 (state 1), world frame;
///   - knee targets use SIMBICON's sign (flexion negative), ours is flexion positive: the swing
///     knee's -1.3 and -0.55 become 1.3 and 0.55, the stance knee's 0.4 and -0.5 become -0.4 (held
///     straight against the knee's limit) and 0.5. The start state's knee angles (1.35, 0.6) are
///     already flexion-positive, like ours (docs/models.md);
///   - the swing ankle's state-0 target "3" is read as 0.3 rad (3 rad turns the foot over);
///   - ankle and toe signs are ours (plantarflexion, toe flexion positive), as the stance ankle's
///     push-off target 0.75 in state 1 and the swing ankle's -0.35 before landing require;
///   - the start state's root height puts the lowest sole or toe point on the ground z = 0, pitch
///     0; unspecified DOFs and rates are 0 (the caption).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"

namespace gaitsynth {

/// Table 2's parameters for wang2009_controller c on model m (gains scaled by m's mass / 70 kg).
inline std::vector<double> wang2009_table2_parameters(const floating_model& m,
                                                      const wang2009_controller& c) {
  const wang2009_parameter_layout& L = c.layout();
  const biped_layout& B = c.body_layout();
  std::vector<double> p(static_cast<std::size_t>(L.size()), 0.0);
  const double w = m.total_mass() / 70.0;
  auto gain = [&](int s, int role, double kp) {
    p[L.kp(s, role)] = w * kp;
    p[L.kd(s, role)] = w * 0.1 * kp;
  };
  const biped_leg& sw = B.leg[0];
  const biped_leg& st = B.leg[1];
  for (int s = 0; s < 2; ++s) {
    for (const int r : {B.back_x, B.back_y, B.back_z}) gain(s, r, 300);
    for (const int r : {sw.hip_x, sw.hip_y, sw.hip_z}) gain(s, r, 1000);  // "rhip_y", "rhip_xz"
    for (const int r : {st.hip_x, st.hip_y, st.hip_z}) gain(s, r, 1000);  // "torso_xyz"
    gain(s, sw.knee, s == 0 ? 300 : 50);
    gain(s, sw.ankle_x, s == 0 ? 30 : 50);
    gain(s, sw.ankle_y, 300);
    gain(s, st.knee, s == 0 ? 150 : 500);
    gain(s, st.ankle_y, 300);
    gain(s, st.ankle_x, 100);
    gain(s, sw.toe, 20);
    gain(s, st.toe, 20);
    for (const int r : {B.neck_x, B.neck_y, B.neck_z}) gain(s, r, 100);
    for (int side = 0; side < 2; ++side) {
      const biped_arm& a = B.arm[side];
      for (const int r : {a.shoulder_x, a.shoulder_y, a.shoulder_z, a.elbow_y, a.elbow_z})
        gain(s, r, 30);
    }
  }
  // Free targets, in wang2009_parameter_layout::target_roles order: swing_hip_y, torso_y,
  // swing_knee, stance_knee, swing_ankle_y, stance_ankle_y, back_y, back_z, neck_y,
  // swing_elbow_y, stance_elbow_y (, stance_toe).
  const std::array<double, 11> t0{-1.0, 0.0, 1.3, -0.4, 0.3, -0.2, 0.0, 0.0, 0.0, 0.0, 0.0};
  const std::array<double, 12> t1{-0.65, 0.0, 0.55, 0.5, -0.35, 0.75, 0.0, 0.0, 0.0, 0.0, 0.0, 0.6};
  for (int k = 0; k < 11; ++k) p[L.target(0, k)] = t0[k];
  for (int k = 0; k < 12; ++k) p[L.target(1, k)] = t1[k];
  p[L.balance(0)] = 0.0;  // cd_sagittal
  p[L.balance(1)] = 0.0;  // cv_sagittal
  p[L.balance(2)] = 0.2;  // cd_coronal
  p[L.balance(3)] = 0.2;  // cv_coronal
  p[L.alpha_arm()] = 1.0;
  p[L.c_trans()] = 0.01;
  // Start state (Table 2, left): angles and rates of the free DOFs.
  auto start = [&](const char* dof, double q, double v) {
    for (int k = 0; k < static_cast<int>(L.start_dofs.size()); ++k)
      if (std::string(L.start_dofs[k]) == dof) {
        p[L.start_angle(k)] = q;
        p[L.start_rate(k)] = v;
      }
  };
  start("lhip_y", -0.4, 0.3);
  start("lknee", 1.35, 0.1);
  start("lankle_y", 0.35, -15.0);
  start("rhip_y", -0.4, 1.0);
  start("rknee", 0.6, 2.0);
  start("rankle_y", -0.2, -9.0);
  p[L.root_start(2)] = 1.3;  // globpos_x velocity, m/s
  // Root height: the lowest sole or toe point on z = 0.
  Eigen::VectorXd q = neutral_configuration(m);
  for (int k = 0; k < static_cast<int>(L.start_dofs.size()); ++k)
    q[floating_root::nq + m.dof_index(L.start_dofs[k])] = p[L.start_angle(k)];
  p[L.root_start(0)] = -lowest_foot_point(m, q);
  return p;
}

}  // namespace gaitsynth
