#pragma once
/// \file controllers/pose_hold.hpp
/// The simplest controller: hold one target pose. Its parameters are the target joint angles
/// (num_joint_dofs, rad). With pd_actuator it outputs the targets (mode joint_target); with
/// torque_actuator it runs its own PD law tau_j = kp_j (target_j - q_j) - kd_j qdot_j (mode
/// joint_torque, pd_torque of actuators/pd_law.hpp; all gains 0 makes a passive character); with
/// mixed_pd_actuator it sends the targets with its gains (mode mixed: [target | kp | kd | 0]);
/// with musculotendon_actuator every MTU gets one constant excitation before the mixed block
/// (mode excitation: [u .. u | target | kp | kd | 0], num_excitations of u). Used by tests,
/// benchmarks (a standing humanoid) and the simulation demo.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <utility>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct pose_hold_options {
  command_kind output = command_kind::joint_target;  ///< joint_target, joint_torque, mixed or
                                                     ///< excitation
  double period = 0.0;                               ///< s between commands (0: every physics step)
  /// joint_torque and mixed modes: per joint DOF gains (N m / rad, N m s / rad); empty means 0
  /// (a passive character). pd_actuator::capped gives gains that are stable at a timestep.
  Eigen::VectorXd kp, kd;
  int num_excitations = 0;  ///< excitation mode: MTUs (musculotendon_actuator::num_units)
  double excitation = 0.0;  ///< excitation mode: every MTU's excitation, in [0, 1]
};

class pose_hold {
 public:
  /// Number of commands issued; the rollout's controller-period test reads it.
  struct state_type {
    std::int64_t commands = 0;
  };

  using options = pose_hold_options;

  /// A pose holder for a model with `num_joint_dofs` joint DOFs.
  explicit pose_hold(int num_joint_dofs, options o = {})
      : opt_(std::move(o)), target_(num_joint_dofs > 0 ? num_joint_dofs : 0) {
    check_argument(num_joint_dofs >= 0, "pose_hold: num_joint_dofs must be >= 0, got ",
                   num_joint_dofs);
    check_argument(
        opt_.output == command_kind::joint_target || opt_.output == command_kind::joint_torque ||
            opt_.output == command_kind::mixed || opt_.output == command_kind::excitation,
        "pose_hold: output must be joint_target, joint_torque, mixed or excitation, got ",
        to_string(opt_.output));
    check_argument(opt_.num_excitations >= 0, "pose_hold: num_excitations must be >= 0, got ",
                   opt_.num_excitations);
    check_argument(opt_.excitation >= 0.0 && opt_.excitation <= 1.0,
                   "pose_hold: excitation must be in [0, 1], got ", opt_.excitation);
    check_argument(std::isfinite(opt_.period) && opt_.period >= 0,
                   "pose_hold: period must be finite and >= 0 s, got ", opt_.period);
    for (Eigen::VectorXd* g : {&opt_.kp, &opt_.kd}) {
      if (g->size() == 0) g->setZero(num_joint_dofs);
      check_size(g->size(), num_joint_dofs, "pose_hold: gains (one per joint DOF)");
      for (Eigen::Index j = 0; j < g->size(); ++j)
        check_argument(std::isfinite((*g)[j]) && (*g)[j] >= 0, "pose_hold: gain of DOF ", j,
                       " must be finite and >= 0, got ", (*g)[j]);
    }
    target_.setZero();
  }
  template <root_joint Root>
  explicit pose_hold(const model<Root>& m, options o = {})
      : pose_hold(m.num_joint_dofs(), std::move(o)) {}

  std::size_t num_parameters() const { return static_cast<std::size_t>(target_.size()); }

  /// Target joint angles (rad). Throws std::invalid_argument on wrong size or a non-finite value.
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "pose_hold parameters (target joint angles)");
    for (std::size_t i = 0; i < p.size(); ++i) target_[static_cast<Eigen::Index>(i)] = p[i];
  }
  const Eigen::VectorXd& target() const { return target_; }

  double period() const { return opt_.period; }
  command_kind output_kind() const { return opt_.output; }
  /// Entries written: nj (joint_torque), 4 nj (mixed), num_excitations + 4 nj (excitation); -1
  /// for joint_target, which zero-fills any feed-forward tail.
  template <root_joint Root>
  int command_size(const model<Root>&) const {
    const int nj = static_cast<int>(target_.size());
    switch (opt_.output) {
      case command_kind::joint_torque:
        return nj;
      case command_kind::mixed:
        return 4 * nj;
      case command_kind::excitation:
        return opt_.num_excitations + 4 * nj;
      default:
        return -1;
    }
  }

  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    check_size(m.num_joint_dofs(), target_.size(), "pose_hold: model joint DOFs");
    return {};
  }

  template <root_joint Root>
  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    ++st.commands;
    const Eigen::Index nj = target_.size();
    if (opt_.output == command_kind::joint_target) {
      cmd.head(nj) = target_;
      if (cmd.size() > nj) cmd.tail(cmd.size() - nj).setZero();  // no feed-forward torque
    } else if (opt_.output == command_kind::mixed || opt_.output == command_kind::excitation) {
      const Eigen::Index ne = opt_.output == command_kind::excitation ? opt_.num_excitations : 0;
      cmd.head(ne).setConstant(opt_.excitation);
      cmd.segment(ne, nj) = target_;  // mixed_pd_actuator's layout: every DOF servos to its target
      cmd.segment(ne + nj, nj) = opt_.kp;
      cmd.segment(ne + 2 * nj, nj) = opt_.kd;
      cmd.segment(ne + 3 * nj, nj).setZero();  // no torque
    } else {
      // The vector form of the law (kept a vector expression: the same rounding as before).
      cmd = pd_torque(opt_.kp, opt_.kd, target_, s.joint_angles(), s.joint_velocities());
    }
  }

 private:
  options opt_;
  Eigen::VectorXd target_;
};

}  // namespace gaitsynth
