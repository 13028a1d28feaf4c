#pragma once
/// \file controllers/end_effector/walk_script.hpp
/// planned_walk controllers picked per half-cycle by a script: Wu & Popovic 2010's cyclical and
/// transitioning controllers (Table 2) chained at run time. Sec. 9: "the system chooses
/// appropriate cyclical or transitioning controllers to achieve the goals"; Sec. 8.3 optimizes a
/// transition on "the first three half-cycles using the first cyclical controller, followed by
/// the transitioning controller, and then the second cyclical controller".
///
/// Half-cycle k runs controllers[c] of the last script entry with from_half_cycle <= k (the first
/// entry starts at 0). The controllers share one state (planned_walk's: the current and previous
/// plan), so the first half-cycle of a controller plans from the last plan of the one before,
/// as a single planned_walk plans from its own. Each keeps its own Omega, Pi, goal (and
/// goal_schedule, in the script's half-cycles) and helper force; they must agree on what the
/// shared schedule and state assume: t_h, the command period, the first stance foot and the
/// body. Half-cycle k uses Omega_{k mod 2} and Pi_{k mod 2} of its controller, so Omega_0 is
/// always the half-cycle on options.first_stance.
///
/// Parameters: those of controllers[free_controller] (its bind, names and bounds), or none
/// (free_controller = -1: every controller keeps what it was bound to). The transition's
/// optimization frees the transition; the scripted demo frees nothing.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/controllers/end_effector/planned_walk.hpp"

namespace gaitsynth {

/// From half-cycle `from_half_cycle` on, run controllers[controller].
struct walk_script_entry {
  std::int64_t from_half_cycle = 0;
  int controller = 0;
};

template <terrain T = flat_terrain, root_joint Root = floating_root>
class walk_script {
 public:
  using walk = planned_walk<T, Root>;
  using state_type = typename walk::state_type;

  /// \throws std::invalid_argument naming the entry or controller that is out of range, out of
  /// order, or disagrees with controllers[0] on t_h, period, first stance or body.
  walk_script(std::vector<walk> controllers, std::vector<walk_script_entry> script,
              int free_controller = -1)
      : controllers_(std::move(controllers)), script_(std::move(script)), free_(free_controller) {
    check_argument(!controllers_.empty(), "walk_script: no controllers");
    check_argument(
        !script_.empty() && script_[0].from_half_cycle == 0,
        "walk_script: the script must start at half-cycle 0, got ",
        script_.empty() ? std::string("no entries") : std::to_string(script_[0].from_half_cycle));
    const int n = static_cast<int>(controllers_.size());
    for (std::size_t i = 0; i < script_.size(); ++i) {
      const walk_script_entry& e = script_[i];
      check_argument(i == 0 || e.from_half_cycle > script_[i - 1].from_half_cycle,
                     "walk_script: entry ", i, "'s from_half_cycle must be above entry ", i - 1,
                     "'s, got ", e.from_half_cycle);
      check_argument(e.controller >= 0 && e.controller < n, "walk_script: entry ", i,
                     " names controller ", e.controller, " of ", n);
    }
    check_argument(free_ >= -1 && free_ < n, "walk_script: free_controller must be -1 or below ", n,
                   ", got ", free_);
    const walk& a = controllers_[0];
    // The script switches controllers on the clock (half_cycle_at), as the paper's demo does.
    for (int c = 0; c < n; ++c)
      check_argument(
          controllers_[static_cast<std::size_t>(c)].opts().timing == half_cycle_end::fixed,
          "walk_script: controller ", c,
          " ends its half-cycles on touchdown; a script needs fixed timing");
    for (int c = 1; c < n; ++c) {
      const walk& b = controllers_[static_cast<std::size_t>(c)];
      check_argument(b.half_cycle_duration() == a.half_cycle_duration(), "walk_script: controller ",
                     c, "'s t_h (", b.half_cycle_duration(), " s) differs from controller 0's (",
                     a.half_cycle_duration(), " s)");
      check_argument(b.period() == a.period(), "walk_script: controller ", c, "'s period (",
                     b.period(), " s) differs from controller 0's (", a.period(), " s)");
      check_argument(b.opts().first_stance == a.opts().first_stance, "walk_script: controller ", c,
                     "'s first stance foot differs from controller 0's");
      check_argument(b.layout().link_body == a.layout().link_body &&
                         b.layout().num_action() == a.layout().num_action(),
                     "walk_script: controller ", c, " was made for another body");
    }
  }

  const std::vector<walk>& controllers() const { return controllers_; }
  const std::vector<walk_script_entry>& script() const { return script_; }
  int free_controller() const { return free_; }

  /// The controller of half-cycle k. No allocation.
  int controller_of(std::int64_t k) const {
    int c = script_[0].controller;
    for (const walk_script_entry& e : script_) {
      if (e.from_half_cycle > k) break;
      c = e.controller;
    }
    return c;
  }

  // ---- parameters: the free controller's ----
  std::size_t num_parameters() const {
    return free_ < 0 ? 0 : controllers_[static_cast<std::size_t>(free_)].num_parameters();
  }
  std::vector<std::string> parameter_names() const {
    return free_ < 0 ? std::vector<std::string>{}
                     : controllers_[static_cast<std::size_t>(free_)].parameter_names();
  }
  std::vector<double> default_parameters() const {
    return free_ < 0 ? std::vector<double>{}
                     : controllers_[static_cast<std::size_t>(free_)].default_parameters();
  }
  void bind(std::span<const double> p) {
    if (free_ < 0) {
      check_parameters(p, 0, "walk_script parameters (no free controller)");
      return;
    }
    controllers_[static_cast<std::size_t>(free_)].bind(p);
  }

  double period() const { return controllers_[0].period(); }
  double half_cycle_duration() const { return controllers_[0].half_cycle_duration(); }
  static constexpr command_kind output_kind() { return command_kind::joint_torque; }
  int command_size(const model<Root>& m) const { return m.num_joint_dofs(); }

  // ---- state: shared, planned_walk's ----
  state_type make_state(const model<Root>& m) const { return controllers_[0].make_state(m); }
  void reset_state(const model<Root>& m, state_type& st) const {
    controllers_[0].reset_state(m, st);
  }

  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    // planned_walk's own schedule (every controller's: they agree on t_h).
    const std::int64_t k = controllers_[0].half_cycle_at(s.t, st);
    controllers_[static_cast<std::size_t>(controller_of(k < 0 ? 0 : k))].command(s, st, cmd);
  }

  /// The stance foot (0 left, 1 right); -1 before the first command.
  int discrete_state(const state_type& st) const { return controllers_[0].discrete_state(st); }
  std::span<const double> report(const state_type& st) const { return st.report; }
  const std::vector<std::string>& report_names() const { return controllers_[0].report_names(); }
  const planned_walk_report_layout& report_layout() const {
    return controllers_[0].report_layout();
  }

  /// The helper force of the current half-cycle's controller (Sec. 8.2).
  void add_external_wrenches(const model<Root>& m, const state_type& st,
                             workspace<Root>& ws) const {
    if (st.half_cycle < 0) return;
    controllers_[static_cast<std::size_t>(controller_of(st.half_cycle))].add_external_wrenches(
        m, st, ws);
  }

 private:
  std::vector<walk> controllers_;
  std::vector<walk_script_entry> script_;
  int free_ = -1;
};

}  // namespace gaitsynth
