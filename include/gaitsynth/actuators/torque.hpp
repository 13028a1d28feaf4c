#pragma once
/// \file actuators/torque.hpp
/// Direct torque actuation: the command is the joint torque, clamped to each DOF's torque limit.
/// For controllers that compute torques themselves (SIMBICON's world-frame torso and stance-hip
/// torques, Wang et al. 2009 Sec. 3; QP controllers, Wu & Popovic 2010 Sec. 5).
#include <Eigen/Core>
#include <algorithm>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct torque_actuator {
  using state_type = no_actuator_state;

  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_torque; }

  /// tau_j = clamp(cmd_j, -limit_j, limit_j). A NaN command stays NaN (the rollout then reports a
  /// non-finite state instead of silently clamping garbage to a limit).
  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state&, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type&, Eigen::Ref<Eigen::VectorXd> tau) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) tau[j] = clamp_torque(cmd[j], m.dofs[j].torque_limit);
  }
};

}  // namespace gaitsynth
