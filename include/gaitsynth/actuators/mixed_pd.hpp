#pragma once
/// \file actuators/mixed_pd.hpp
/// PD servos whose gains come with the command (command_kind::mixed): some DOFs servo to targets
/// with gains the controller may change at every command (SIMBICON's per-state gains, Yin et al.
/// 2007; Wang et al. 2009 Table 2), others take torques the controller computed itself (the
/// stance hip's world-frame torso torque, Wang et al. 2009 Sec. 3).
///
/// Command layout, 4 blocks of num_joint_dofs (nj) entries, no allocation and no mode flag:
///
///   [ target_0 .. target_nj-1 | kp_0 .. kp_nj-1 | kd_0 .. kd_nj-1 | tau_0 .. tau_nj-1 ]
///
///   torque_j = clamp_torque(pd_torque(kp_j, kd_j, target_j, q_j, qdot_j) + tau_j, limit_j)
///
/// A target DOF has its gains (N m / rad, N m s / rad) and tau_j = 0, or a feed-forward torque
/// (gravity compensation). A torque DOF has kp_j = kd_j = 0 and its torque in tau_j: the law
/// then adds +-0 and the torque passes through exactly, clamped (for any finite target_j; write
/// 0). A target with zero gains is a limp joint, not a torque: the mode is given by the gains,
/// never by the target's value. Every entry must be finite; the actuator does not validate gains
/// in the step loop (negative gains destabilize, NaN ones make the rollout report a non-finite
/// state). mixed_command writes the blocks by DOF.
#include <Eigen/Core>
#include <limits>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/pd_law.hpp"

namespace gaitsynth {

/// A view of a mixed command (its 4 nj entries) that writes it by DOF. Holds a reference to the
/// caller's vector; no allocation.
class mixed_command {
 public:
  /// cmd: the command vector (size 4 num_joint_dofs, as mixed_pd_actuator::command_size).
  explicit mixed_command(Eigen::Ref<Eigen::VectorXd> cmd)
      : cmd_(cmd), nj_(static_cast<int>(cmd.size() / 4)) {}

  int num_joint_dofs() const { return nj_; }
  auto target() { return cmd_.segment(0, nj_); }
  auto kp() { return cmd_.segment(nj_, nj_); }
  auto kd() { return cmd_.segment(2 * nj_, nj_); }
  auto torque() { return cmd_.segment(3 * nj_, nj_); }

  /// DOF j servos to `target` with gains kp, kd, plus a feed-forward torque.
  void set_target(int j, double target, double kp, double kd, double feedforward = 0.0) {
    cmd_[j] = target;
    cmd_[nj_ + j] = kp;
    cmd_[2 * nj_ + j] = kd;
    cmd_[3 * nj_ + j] = feedforward;
  }
  /// DOF j takes torque tau (N m): zero gains, target 0.
  void set_torque(int j, double tau) {
    cmd_[j] = 0.0;
    cmd_[nj_ + j] = 0.0;
    cmd_[2 * nj_ + j] = 0.0;
    cmd_[3 * nj_ + j] = tau;
  }

 private:
  Eigen::Ref<Eigen::VectorXd> cmd_;
  int nj_;
};

struct mixed_pd_actuator {
  using state_type = no_actuator_state;

  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return 4 * m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::mixed; }

  /// torque_j = clamp_torque(pd_torque(kp_j, kd_j, target_j, q_j, qdot_j) + tau_j, limit_j), the
  /// blocks of cmd as in the file comment.
  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type&, Eigen::Ref<Eigen::VectorXd> tau) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      const double t =
          pd_torque(cmd[nj + j], cmd[2 * nj + j], cmd[j], s.q[Root::nq + j], s.v[Root::nv + j]) +
          cmd[3 * nj + j];
      tau[j] = clamp_torque(t, m.dofs[j].torque_limit);
    }
  }

  /// The joint-rate coefficient of each DOF's law (actuators/concept.hpp, joint_damping): kd_j
  /// (0 where kd_j <= 0 or not finite), also where the torque is clamped: taken implicitly, the
  /// damper acts on the step's change of velocity beyond the limit (rollout_options::
  /// implicit_joint_damping).
  template <root_joint Root>
  void joint_damping(const model<Root>& m, const sim_state&, Eigen::Ref<const Eigen::VectorXd> cmd,
                     const state_type&, Eigen::Ref<Eigen::VectorXd> c) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      const double kd = cmd[2 * nj + j];
      c[j] = (kd > 0.0 && kd < std::numeric_limits<double>::infinity()) ? kd : 0.0;
    }
  }
};

}  // namespace gaitsynth
