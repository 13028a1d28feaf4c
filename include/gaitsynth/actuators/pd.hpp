#pragma once
/// \file actuators/pd.hpp
/// Proportional-derivative servos at every joint DOF (Wang et al. 2009, Eq. 1):
///   tau_j = kp_j (theta_d_j - q_j) - kd_j qdot_j  [+ tau_ff_j],  clamped to +-torque_limit_j.
/// The command is the target angles theta_d (num_joint_dofs, rad); with `feedforward`, it is
/// followed by a feed-forward torque per DOF (2 num_joint_dofs), which SIMBICON-style controllers
/// use for torques computed in the world frame. Gains are fixed per actuator; a controller whose
/// gains are optimized computes its torques itself and uses torque_actuator.
#include <Eigen/Core>
#include <cmath>
#include <utility>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct pd_actuator {
  using state_type = no_actuator_state;

  Eigen::VectorXd kp;  ///< N m / rad, per joint DOF
  Eigen::VectorXd kd;  ///< N m s / rad, per joint DOF
  bool feedforward = false;

  pd_actuator() = default;
  pd_actuator(Eigen::VectorXd kp_, Eigen::VectorXd kd_, bool feedforward_ = false)
      : kp(std::move(kp_)), kd(std::move(kd_)), feedforward(feedforward_) {}

  /// The same gains at every joint DOF of m.
  template <root_joint Root>
  static pd_actuator uniform(const model<Root>& m, double kp, double kd, bool feedforward = false) {
    const int nj = m.num_joint_dofs();
    return pd_actuator(Eigen::VectorXd::Constant(nj, kp), Eigen::VectorXd::Constant(nj, kd),
                       feedforward);
  }

  /// Validates the gains against the model (sizes, finite, >= 0); throws std::invalid_argument
  /// naming the DOF and value.
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    const int nj = m.num_joint_dofs();
    check_size(kp.size(), nj, "pd_actuator kp (one gain per joint DOF)");
    check_size(kd.size(), nj, "pd_actuator kd (one gain per joint DOF)");
    for (int j = 0; j < nj; ++j) {
      check_argument(std::isfinite(kp[j]) && kp[j] >= 0, "pd_actuator: kp of DOF ", j, " ('",
                     m.dofs[j].name, "') must be finite and >= 0, got ", kp[j]);
      check_argument(std::isfinite(kd[j]) && kd[j] >= 0, "pd_actuator: kd of DOF ", j, " ('",
                     m.dofs[j].name, "') must be finite and >= 0, got ", kd[j]);
    }
    return {};
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return (feedforward ? 2 : 1) * m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_target; }

  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               state_type&, Eigen::Ref<Eigen::VectorXd> tau) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      double t = kp[j] * (cmd[j] - s.q[Root::nq + j]) - kd[j] * s.v[Root::nv + j];
      if (feedforward) t += cmd[nj + j];
      const double lim = m.dofs[j].torque_limit;
      tau[j] = t > lim ? lim : (t < -lim ? -lim : t);
    }
  }
};

}  // namespace gaitsynth
