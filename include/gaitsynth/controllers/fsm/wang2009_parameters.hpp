#pragma once
/// \file controllers/fsm/wang2009_parameters.hpp
/// The 184 parameters of Wang, Fleet & Hertzmann 2009's controller and start state (Sec. 3,
/// "Start state", and the fixed DOFs listed there), their names and where each lives.
///
/// Roles: the controller's two optimized states (0 and 1) are written for the left leg swinging;
/// states 2 and 3 use them mirrored (model.mirror_dof / mirror_sign). Role r is joint DOF r of the
/// model as seen in state 0: a left DOF is the swing side's ("swing_knee"), a right one the stance
/// side's ("stance_knee"), a central one keeps its name. The stance hip's gains serve the torso
/// servo (the stance hip's torque keeps the pelvis on its world target, as in SIMBICON), so those
/// roles are called torso_x, torso_y, torso_z.
///
/// Layout (n = 30 joint DOFs):
///   per state s in {0, 1}: kp of every role (n), kd of every role (n), then the free targets:
///     swing_hip_y (world sagittal angle of the swing thigh), torso_y (the pelvis' world sagittal
///     angle), swing_knee, stance_knee, swing_ankle_y, stance_ankle_y (world sagittal angles of the
///     feet), back_y, back_z, neck_y, swing_elbow_y, stance_elbow_y, and in state 1 stance_toe;
///     every other target is fixed at 0 (rotations about local x and z, except back_z; the toes
///     except the stance toe in states 1 and 3), and the shoulders' y targets follow the hips
///     (eq. 2);
///   balance feedback cd_sagittal, cv_sagittal, cd_coronal, cv_coronal; alpha_arm; c_trans;
///   start state: root height, pitch, forward, vertical and pitch velocity, then the 15 DOFs about
///   local y and back_z, angles and rates (root x, y, roll, yaw, their rates and v_y fixed at 0).
/// 2 (60 + 11) + 1 + 4 + 2 + 5 + 30 = 184.
#include <array>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

/// Index arithmetic of the parameter vector for a model with nj joint DOFs.
struct wang2009_parameter_layout {
  static constexpr int num_targets_state0 = 11;
  static constexpr int num_targets_state1 = 12;
  static constexpr int num_balance = 4;  ///< cd_sag, cv_sag, cd_cor, cv_cor
  static constexpr int num_root_start = 5;
  /// Target roles, in parameter order (state 1 has the last one too).
  static constexpr std::array<const char*, 12> target_roles{
      "swing_hip_y", "torso_y", "swing_knee", "stance_knee",   "swing_ankle_y",  "stance_ankle_y",
      "back_y",      "back_z",  "neck_y",     "swing_elbow_y", "stance_elbow_y", "stance_toe"};
  /// Joint DOFs of the start state (model names; the free ones of Sec. 3).
  static constexpr std::array<const char*, 15> start_dofs{
      "lhip_y", "lknee",  "lankle_y", "ltoe",        "rhip_y",   "rknee",       "rankle_y", "rtoe",
      "back_y", "back_z", "neck_y",   "lshoulder_y", "lelbow_y", "rshoulder_y", "relbow_y"};

  int nj = 30;

  int state_size(int s) const {
    return 2 * nj + (s == 0 ? num_targets_state0 : num_targets_state1);
  }
  int state_offset(int s) const { return s == 0 ? 0 : state_size(0); }
  int kp(int s, int role) const { return state_offset(s) + role; }
  int kd(int s, int role) const { return state_offset(s) + nj + role; }
  int target(int s, int k) const { return state_offset(s) + 2 * nj + k; }
  int balance(int k) const { return state_size(0) + state_size(1) + k; }
  int alpha_arm() const { return balance(num_balance); }
  int c_trans() const { return alpha_arm() + 1; }
  int root_start(int k) const { return c_trans() + 1 + k; }  ///< z, pitch, vx, vz, wy
  int start_angle(int k) const { return root_start(num_root_start) + k; }
  int start_rate(int k) const { return start_angle(static_cast<int>(start_dofs.size())) + k; }
  int size() const { return start_rate(static_cast<int>(start_dofs.size())); }
};

/// The role name of joint DOF r (see the file comment).
template <root_joint Root>
std::string wang2009_role_name(const model<Root>& m, int r) {
  const std::string& n = m.dofs[r].name;
  if (m.mirror_dof[r] == r) return n;
  const std::string base = n.substr(1);
  if (n[0] == 'r' && base.rfind("hip_", 0) == 0) return "torso_" + base.substr(4);
  return (n[0] == 'l' ? "swing_" : "stance_") + base;
}

/// Every parameter's name, in order ("s0.kp.swing_knee", "s1.target.stance_toe", "cd_sagittal",
/// "start.q.lknee", ...).
template <root_joint Root>
std::vector<std::string> wang2009_parameter_names(const model<Root>& m) {
  const wang2009_parameter_layout L{m.num_joint_dofs()};
  std::vector<std::string> out(static_cast<std::size_t>(L.size()));
  for (int s = 0; s < 2; ++s) {
    const std::string p = s == 0 ? "s0." : "s1.";
    for (int r = 0; r < L.nj; ++r) {
      out[L.kp(s, r)] = p + "kp." + wang2009_role_name(m, r);
      out[L.kd(s, r)] = p + "kd." + wang2009_role_name(m, r);
    }
    const int nt = s == 0 ? L.num_targets_state0 : L.num_targets_state1;
    for (int k = 0; k < nt; ++k)
      out[L.target(s, k)] = p + "target." + wang2009_parameter_layout::target_roles[k];
  }
  const std::array<const char*, 4> bal{"cd_sagittal", "cv_sagittal", "cd_coronal", "cv_coronal"};
  for (int k = 0; k < 4; ++k) out[L.balance(k)] = bal[k];
  out[L.alpha_arm()] = "alpha_arm";
  out[L.c_trans()] = "c_trans";
  const std::array<const char*, 5> root{"start.root_z", "start.root_pitch", "start.root_vx",
                                        "start.root_vz", "start.root_wy"};
  for (int k = 0; k < 5; ++k) out[L.root_start(k)] = root[k];
  for (int k = 0; k < static_cast<int>(L.start_dofs.size()); ++k) {
    out[L.start_angle(k)] = std::string("start.q.") + L.start_dofs[k];
    out[L.start_rate(k)] = std::string("start.v.") + L.start_dofs[k];
  }
  return out;
}

}  // namespace gaitsynth
