#pragma once
/// \file controllers/pose_hold.hpp
/// The simplest controller: hold one target pose. Its parameters are the target joint angles
/// (num_joint_dofs, rad). With pd_actuator it outputs the targets (mode joint_target); with
/// torque_actuator it runs its own PD law tau = kp (target - q) - kd qdot (mode joint_torque).
/// Used by tests, benchmarks (a standing humanoid) and the simulation demo.
#include <Eigen/Core>
#include <cstdint>
#include <span>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct pose_hold_options {
  command_kind output = command_kind::joint_target;  ///< joint_target or joint_torque
  double period = 0.0;                               ///< s between commands (0: every physics step)
  double kp = 0.0;                                   ///< N m / rad, joint_torque mode only
  double kd = 0.0;                                   ///< N m s / rad, joint_torque mode only
};

class pose_hold {
 public:
  /// Number of commands issued; the rollout's controller-period test reads it.
  struct state_type {
    std::int64_t commands = 0;
  };

  using options = pose_hold_options;

  /// A pose holder for a model with `num_joint_dofs` joint DOFs.
  explicit pose_hold(int num_joint_dofs, options o = {}) : opt_(o), target_(num_joint_dofs) {
    check_argument(num_joint_dofs >= 0, "pose_hold: num_joint_dofs must be >= 0, got ",
                   num_joint_dofs);
    check_argument(o.output == command_kind::joint_target || o.output == command_kind::joint_torque,
                   "pose_hold: output must be joint_target or joint_torque");
    check_argument(std::isfinite(o.period) && o.period >= 0,
                   "pose_hold: period must be finite and >= 0 s, got ", o.period);
    check_argument(std::isfinite(o.kp) && o.kp >= 0 && std::isfinite(o.kd) && o.kd >= 0,
                   "pose_hold: gains must be finite and >= 0, got kp = ", o.kp, ", kd = ", o.kd);
    target_.setZero();
  }
  template <root_joint Root>
  explicit pose_hold(const model<Root>& m, options o = {}) : pose_hold(m.num_joint_dofs(), o) {}

  std::size_t num_parameters() const { return static_cast<std::size_t>(target_.size()); }

  /// Target joint angles (rad). Throws std::invalid_argument on wrong size or a non-finite value.
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "pose_hold parameters (target joint angles)");
    for (std::size_t i = 0; i < p.size(); ++i) target_[static_cast<Eigen::Index>(i)] = p[i];
  }
  const Eigen::VectorXd& target() const { return target_; }

  double period() const { return opt_.period; }
  command_kind output_kind() const { return opt_.output; }

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
    } else {
      cmd = opt_.kp * (target_ - s.joint_angles()) - opt_.kd * s.joint_velocities();
    }
  }

 private:
  options opt_;
  Eigen::VectorXd target_;
};

}  // namespace gaitsynth
