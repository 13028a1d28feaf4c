#pragma once
/// \file controllers/end_effector/standing_balance.hpp
/// A standing controller built on the lower level of Wu & Popovic 2010 (lower_level.hpp): it holds
/// FIXED end-effector targets, the feet where they stand and the upper body upright over the
/// middle of the feet, and turns them into joint torques through eq. 5's QP every tick. The
/// simplest user of the lower level; the planner of Sec. 4 will replace the fixed targets with
/// paths. (The paper's standing controller "s" is a planned one with r = 0, Sec. 8.3.)
///
/// Targets, set at the first command from the sensed state: each foot's current pose; the upper
/// body's LA frame (its COM) above the midpoint of the two feet's centres, `upper_body_drop` below
/// its start height, the upper body upright with its start heading. The drop makes appendix B's
/// knee control bend knees that start straight (the model's neutral pose), away from the
/// singularity. All targets are still, so every touching foot frame near its target is pinned
/// (Sec. 6.3).
///
/// Parameters (bind): end_effector_gains in to_array()'s order (12 values, each finite and >= 0).
/// Output: joint torques (torque_actuator).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/controllers/sensors.hpp"

namespace gaitsynth {

struct standing_balance_options {
  /// s between commands; 0: every physics step. The paper runs at 64 Hz (Appendix C), but with the
  /// command held over 1/64 s our explicit simulation of these gains diverges within 0.1 s (also
  /// at 240 Hz): the upper body's yaw inertia is 0.1 kg m^2 (Table 3) and a foot weighs 1 kg, so
  /// eq. 2's bo = 60 alone gives 2 bo dt / I = 19 > 2 at 64 Hz. Every physics step (2400 Hz) holds.
  double period = 0.0;
  double upper_body_drop = 0.05;  ///< m below the start height (bends the knees, appendix B)
  lower_level_options lower{};
};

template <root_joint Root = floating_root>
class standing_balance {
 public:
  struct state_type {
    lower_level_workspace<Root> lower;
    std::vector<link_target> targets;  ///< [upper body, left foot, right foot]
    bool has_targets = false;
    std::int64_t commands = 0;
    std::int64_t qp_failures = 0;  ///< ticks whose eq. 5 QP did not return optimal (torques 0)
  };
  using options = standing_balance_options;

  explicit standing_balance(const model<Root>& m, options o = {}, end_effector_gains g = {})
      : opt_(std::move(o)),
        gains_(g),
        layout_(biped_end_effector_layout(m)),
        num_joint_dofs_(m.num_joint_dofs()) {
    check_argument(std::isfinite(opt_.period) && opt_.period >= 0.0,
                   "standing_balance: period must be finite and >= 0 s, got ", opt_.period);
    check_argument(std::isfinite(opt_.upper_body_drop),
                   "standing_balance: upper_body_drop must be finite, got ", opt_.upper_body_drop);
    const lower_level_options& l = opt_.lower;
    check_argument(
        std::isfinite(l.eps_p) && l.eps_p >= 0.0 && std::isfinite(l.eps_pdot) && l.eps_pdot >= 0.0,
        "standing_balance: eps_p and eps_pdot must be finite and >= 0, got ", l.eps_p, " and ",
        l.eps_pdot);
    check_argument(std::isfinite(l.qp.f_max) && l.qp.f_max > 0.0,
                   "standing_balance: f_max must be finite and > 0, got ", l.qp.f_max);
    check_argument(std::isfinite(l.qp.regularization) && l.qp.regularization > 0.0,
                   "standing_balance: regularization must be finite and > 0, got ",
                   l.qp.regularization);
    gains_.validate();
  }

  std::size_t num_parameters() const { return end_effector_gains::size; }
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "standing_balance parameters (end_effector_gains)");
    gains_ = end_effector_gains::from(p);
  }
  const end_effector_gains& gains() const { return gains_; }
  const end_effector_layout& layout() const { return layout_; }
  double period() const { return opt_.period; }
  static constexpr command_kind output_kind() { return command_kind::joint_torque; }
  int command_size(const model<Root>& m) const { return m.num_joint_dofs(); }

  state_type make_state(const model<Root>& m) const {
    check_size(m.num_joint_dofs(), num_joint_dofs_, "standing_balance: model joint DOFs");
    state_type st{make_lower_level_workspace(m, layout_),
                  std::vector<link_target>(layout_.link_body.size()), false, 0, 0};
    return st;
  }
  void reset_state(const model<Root>&, state_type& st) const {
    st.has_targets = false;
    st.commands = 0;
    st.qp_failures = 0;
  }

  /// The targets the controller holds, from a sensed state (what the first command does).
  void set_targets_from(const sensors<Root>& s, std::vector<link_target>& targets) const {
    const auto& ws = s.workspace();
    const model<Root>& m = s.model();
    vec3 mid = vec3::Zero();
    for (int i = 1; i < layout_.num_links(); ++i) {
      const int b = layout_.link_body[i];
      targets[i] = {ws.body_position[b], ws.body_rotation[b], vec3::Zero(), vec3::Zero()};
      mid += ws.body_position[b] + ws.body_rotation[b] * m.bodies[b].com;
    }
    mid /= static_cast<double>(layout_.num_links() - 1);
    const int ub = layout_.link_body[0];
    const mat3& R = ws.body_rotation[ub];
    const double yaw = std::atan2(R(1, 0), R(0, 0));
    const mat3 Rd = Eigen::AngleAxisd(yaw, vec3::UnitZ()).toRotationMatrix();
    const vec3 la = ws.body_position[ub] + R * layout_.reaction_point;
    const vec3 la_target(mid.x(), mid.y(), la.z() - opt_.upper_body_drop);
    targets[0] = {la_target - Rd * layout_.reaction_point, Rd, vec3::Zero(), vec3::Zero()};
  }

  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    ++st.commands;
    if (!st.has_targets) {
      set_targets_from(s, st.targets);
      st.has_targets = true;
    }
    const Eigen::VectorXd& tau = lower_level_torques(s.model(), layout_, gains_, opt_.lower, s.q(),
                                                     s.v(), st.targets, s.contact_active, st.lower);
    if (st.lower.qp.status != qp_status::optimal) ++st.qp_failures;
    cmd.head(num_joint_dofs_) = tau;
  }

 private:
  options opt_;
  end_effector_gains gains_;
  end_effector_layout layout_;
  int num_joint_dofs_ = 0;
};

}  // namespace gaitsynth
