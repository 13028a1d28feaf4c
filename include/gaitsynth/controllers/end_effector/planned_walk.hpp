#pragma once
/// \file controllers/end_effector/planned_walk.hpp
/// The cyclical locomotion controller of Wu & Popovic 2010 (Sec. 7): the end-effector path
/// planner (Sec. 4, appendix A; half_cycle_plan.hpp) over the lower level (Sec. 5, 6, appendix B;
/// lower_level.hpp), with the parameters P_c = (Omega_0, Omega_1, Pi_0, Pi_1), one planner set
/// and one lower-level set per half-cycle.
///
/// Schedule (Sec. 3, "planning occurs at the start of each half-cycle"; A.1: a half-cycle lasts
/// t_h): half-cycle k starts at t_0 + k t_h, t_0 the time of the first command; at the first
/// command at or after that time (1e-9 s tolerance) the controller swaps stance and swing (k even:
/// options.first_stance stands; k odd: the other foot) and plans it with plan_half_cycle from the
/// goal G (options.goal_schedule's for half-cycle k), Omega_{k mod 2}, the current poses of the
/// upper body (its planned point) and feet, the previous half-cycle's plan (its swing becomes this
/// stance foot's tail; its target gives dq'_ub,eh) and the terrain. Every command then queries the
/// plan at t - (t_0 + k t_h) and runs the lower level with Pi_{k mod 2}. The first half-cycle has
/// no previous plan: its stance foot stays where it stands and psi_f' is the upper body's yaw.
/// options.stance_target = touchdown (ours) re-targets the stance foot, at its first ground contact
/// after the tail, to where it is (half_cycle_plan.hpp's touchdown_stance_target) instead of the
/// previous swing's planned end. options.timing = touchdown (ours) ends a half-cycle at the first
/// command t_h or more after it began at which the swing foot touches the ground (at the latest
/// max_touchdown_wait after t_h), and the next one begins then, so that the new stance foot stands
/// when its half-cycle starts (docs/reproductions/wu2010.md, "When in the half-cycle ...").
///
/// Terrain: a controller sees no terrain through sensors (controllers/sensors.hpp), so it holds a
/// copy of one, given at construction (template parameter T, default flat_terrain). It must be
/// the rollout's terrain for terrain-aware planning to mean anything; planner_setup's
/// terrain_awareness = false plans terrain-blind instead (the stance foot's ground plane).
///
/// Parameters (bind), one flat vector, in this order (parameter_names() spells them out):
///   Omega_0   25 values, planned_walk_parameters.hpp's planner_vector_names (Table 1's planner
///             unknowns; the others come from options.planner)
///   Omega_1   25 more, only with planned_walk_symmetry::asymmetric
///   Pi_0      12 values, end_effector_gains::names (Table 1's ten coefficients, W's upper-body
///             weight and appendix B's rho)
///   Pi_1      12 more, unless planned_walk_symmetry::mirrored
/// Sizes: asymmetric 74, mirrored_planner 49 (Omega_1 = mirrored(Omega_0), two Pi: the paper's
/// symmetric controllers, whose 46 unknowns are 25 + 2 x 10 + h_max), mirrored 37 (one Pi too:
/// every Pi coefficient is left/right symmetric, so mirroring Pi is the identity).
///
///   h_max     1 more, only with options.helper_force (Sec. 8.2's bound on the helper force, N;
///             Sec. 8.3's bounds [-200, 1000]; <= 0: no helper force)
///
/// Report (controllers/concept.hpp's hook; planned_walk_report.hpp's layout), per command: the
/// squared norms of Sec. 8.1's frame-tracking "forces" (eqs. 1-3 with options.tracking's weights),
/// the half-cycle k, the COM target c_k of Sec. 8.1 and h_max. objectives/wu2010/ reads it.
///
/// Helper force (Sec. 8.2, options.helper_force): h = b - A f, the residual of eq. 5's QP in the
/// frames' wrench space (rows of pinned frames, removed from the QP by Sec. 6.3, get none),
/// clipped to [-{h_max}+, {h_max}+] per entry at each command and held until the next;
/// add_external_wrenches applies it every physics step: the upper body's force at the LA frame
/// and its torque, each action frame's force at the frame.
///
/// Output: joint torques (torque_actuator). Per command: a plan query and a lower-level tick, no
/// allocation; once per half-cycle plan_half_cycle, which allocates nothing either (fixed-size
/// plans; the state holds the current and the previous one).
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/end_effector/half_cycle_plan.hpp"
#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_report.hpp"
#include "gaitsynth/controllers/sensors.hpp"

namespace gaitsynth {

/// Where the stance foot's stationary target is (Fig. 5's stance-foot path, after t_e').
enum class stance_foot_target {
  planned_landing,  ///< the paper: where the previous swing was planned to end
  touchdown,        ///< ours: where the foot touched down (touchdown_stance_target)
  /// ours: the same from its first ground contact in the half-cycle, even during the previous
  /// swing's tail, so a foot that lands early is pinned (Sec. 6.3) from then on
  first_contact,
};

/// When a half-cycle ends (appendix A.1).
enum class half_cycle_end {
  fixed,      ///< the paper: half-cycle k starts at t_0 + k t_h
  touchdown,  ///< ours: t_h or more after it began, once the swing foot touches (or a wait ran out)
};

/// How Omega_1 and Pi_1 relate to Omega_0 and Pi_0.
enum class planned_walk_symmetry {
  asymmetric,        ///< Omega_0, Omega_1, Pi_0, Pi_1 all free (74 parameters)
  mirrored_planner,  ///< Omega_1 = mirrored(Omega_0); Pi_0, Pi_1 free (49)
  mirrored,          ///< Omega_1 = mirrored(Omega_0), Pi_1 = Pi_0 (37)
};

/// A goal change at run time: `goal` applies from half-cycle `from_half_cycle` on.
struct scheduled_goal {
  std::int64_t from_half_cycle = 0;
  task_goal goal;
};

/// The rows of eq. 4 that Sec. 8.2's helper force acts on (planned_walk_options::helper_rows).
enum class helper_scope {
  all,                ///< every row (Sec. 8.2)
  upper_body,         ///< the upper body's force and torque rows
  upper_body_force,   ///< the upper body's force rows
  upper_body_torque,  ///< the upper body's torque rows
  feet                ///< the action frames' rows
};

struct planned_walk_options {
  /// s between commands; 0: every physics step. The paper runs at 64 Hz (appendix C); our lower
  /// level is not stable with commands held over 1/64 s yet (standing_balance.hpp,
  /// docs/reproductions/wu2010.md), so the default is every physics step. Must be < t_h.
  double period = 0.0;
  /// G: Sec. 8.3's forward walk (r = 0.65 m) along +x, facing +x.
  task_goal goal{0.0, 0.0, 0.65};
  /// Goal changes at run time (Sec. 9: "With a cyclical controller, we can also use the task goal
  /// G for small (+-15 deg) facing and movement direction changes"; a larger turn is a sequence of
  /// small ones). Half-cycle k plans with the goal of the last entry whose from_half_cycle <= k,
  /// before the first entry with `goal`. Entries in strictly increasing from_half_cycle >= 0.
  std::vector<scheduled_goal> goal_schedule;
  planner_setup setup{};  ///< t_h = 0.55 s (Sec. 8.3) and the character's geometry
  /// Omega's components outside the parameter vector (l of the control points, v of the upper
  /// body's, alpha_a), and the Table 1 components default_parameters() starts from.
  planner_parameters planner{};
  end_effector_gains gains{};  ///< Pi for default_parameters()
  planned_walk_symmetry symmetry = planned_walk_symmetry::mirrored_planner;
  stance_side first_stance = stance_side::left;  ///< who stands in half-cycle 0 (Omega_0's)
  /// Fig. 5 keeps the stance foot at the previous swing's planned end, so a foot that lands
  /// farther than eps_p from it is never pinned (Sec. 6.3) and eq. 5 drags it over the ground;
  /// touchdown (ours) re-targets it, at its first ground contact after t_e', to where it landed;
  /// first_contact (ours) at its first ground contact in the half-cycle, tail or not.
  stance_foot_target stance_target = stance_foot_target::planned_landing;
  half_cycle_end timing = half_cycle_end::fixed;
  /// timing touchdown: s after t_h that a half-cycle waits for its swing foot to touch (>= 0).
  double max_touchdown_wait = 0.3;
  lower_level_options lower{};
  tracking_weights tracking{};  ///< Sec. 8.1's tracking report (Sec. 8.3's weights)
  /// Sec. 8.2: append h_max to the parameters and apply the helper force (off: the paper's
  /// controller as it runs after the optimization).
  bool helper_force = false;
  double h_max = 0.0;  ///< N, h_max for default_parameters() (0: no helper force)
  /// Which rows of eq. 4 the helper force acts on (ours, for diagnosis: Sec. 8.2 helps every
  /// row; scripts/wu2010_helper_scope.cpp).
  helper_scope helper_rows = helper_scope::all;
};

template <terrain T = flat_terrain, root_joint Root = floating_root>
class planned_walk {
 public:
  struct state_type {
    lower_level_workspace<Root> lower;
    std::vector<link_target> targets;      ///< [upper body, left foot, right foot]
    std::array<half_cycle_plan, 2> plans;  ///< the current plan and the previous one
    int current = -1;                      ///< index of the current plan in plans; -1: none yet
    std::int64_t half_cycle = -1;          ///< k of the current half-cycle; -1 before the first
    double start_time = 0.0;               ///< t_0: time of the first command, s
    double half_cycle_start = 0.0;  ///< t_0 + k t_h, s (timing touchdown: when k was planned)
    double last_plan_time = 0.0;    ///< sensed time of the command that planned, s
    stance_side stance = stance_side::left;
    bool stance_anchored = false;  ///< stance_target touchdown: the foot has touched down
    link_target stance_anchor;     ///< and this is its target since
    std::int64_t plans_made = 0;
    std::int64_t commands = 0;
    std::int64_t qp_failures = 0;  ///< ticks whose eq. 5 QP did not return optimal (torques 0)
    ideal_wrenches tracking;       ///< Sec. 8.1's tracking "forces" (eqs. 1-3, tracking weights)
    Eigen::VectorXd helper;        ///< 3N + 6, eq. 4's rows: the clipped helper force (Sec. 8.2)
    std::vector<double> report;    ///< planned_walk_report_layout

    const half_cycle_plan* plan() const { return current < 0 ? nullptr : &plans[current]; }
  };
  using options = planned_walk_options;
  using terrain_type = T;

  explicit planned_walk(const model<Root>& m, T ground = T{}, options o = {})
      : opt_(std::move(o)),
        terrain_(std::move(ground)),
        layout_(biped_end_effector_layout(m)),
        num_joint_dofs_(m.num_joint_dofs()),
        tracking_gains_(opt_.tracking.as_gains()),
        report_layout_(planned_walk_report_layout::for_action_frames(layout_.num_action())) {
    check_argument(std::isfinite(opt_.period) && opt_.period >= 0.0,
                   "planned_walk: period must be finite and >= 0 s, got ", opt_.period);
    validate(opt_.goal);
    for (std::size_t i = 0; i < opt_.goal_schedule.size(); ++i) {
      const scheduled_goal& e = opt_.goal_schedule[i];
      check_argument(e.from_half_cycle >= 0 &&
                         (i == 0 || e.from_half_cycle > opt_.goal_schedule[i - 1].from_half_cycle),
                     "planned_walk: goal_schedule[", i,
                     "].from_half_cycle must be >= 0 and above "
                     "the previous entry's, got ",
                     e.from_half_cycle);
      try {
        validate(e.goal);
      } catch (const std::invalid_argument& x) {
        throw std::invalid_argument("planned_walk: goal_schedule[" + std::to_string(i) +
                                    "]: " + x.what());
      }
    }
    validate(opt_.setup);
    check_argument(opt_.first_stance != stance_side::none,
                   "planned_walk: first_stance must be left or right, got none");
    check_argument(opt_.period < opt_.setup.t_h, "planned_walk: period (", opt_.period,
                   " s) must be shorter than the half-cycle t_h (", opt_.setup.t_h, " s)");
    check_argument(std::isfinite(opt_.max_touchdown_wait) && opt_.max_touchdown_wait >= 0.0,
                   "planned_walk: max_touchdown_wait must be finite and >= 0, got ",
                   opt_.max_touchdown_wait);
    const lower_level_options& l = opt_.lower;
    check_argument(
        std::isfinite(l.eps_p) && l.eps_p >= 0.0 && std::isfinite(l.eps_pdot) && l.eps_pdot >= 0.0,
        "planned_walk: eps_p and eps_pdot must be finite and >= 0, got ", l.eps_p, " and ",
        l.eps_pdot);
    check_argument(std::isfinite(l.qp.f_max) && l.qp.f_max > 0.0,
                   "planned_walk: f_max must be finite and > 0, got ", l.qp.f_max);
    check_argument(std::isfinite(l.qp.regularization) && l.qp.regularization > 0.0,
                   "planned_walk: regularization must be finite and > 0, got ",
                   l.qp.regularization);
    check_argument(layout_.num_links() == 3, "planned_walk: the layout needs 3 links, has ",
                   layout_.num_links());
    check_argument(std::isfinite(opt_.h_max), "planned_walk: h_max must be finite, got ",
                   opt_.h_max);
    report_names_.reserve(report_layout_.size);
    report_names_.push_back("track.ub_force");
    report_names_.push_back("track.ub_torque");
    for (const action_frame& a : layout_.action) report_names_.push_back("track." + a.name);
    for (const char* n : {"half_cycle", "com_target_x", "com_target_y", "h_max", "helper_max"})
      report_names_.push_back(n);
    bind(default_parameters());
  }

  // ---- parameters ----
  int num_planner_sets() const {
    return opt_.symmetry == planned_walk_symmetry::asymmetric ? 2 : 1;
  }
  int num_gain_sets() const { return opt_.symmetry == planned_walk_symmetry::mirrored ? 1 : 2; }
  std::size_t num_parameters() const {
    return static_cast<std::size_t>(num_planner_sets()) * planner_vector_size +
           static_cast<std::size_t>(num_gain_sets()) * end_effector_gains::size +
           (opt_.helper_force ? 1 : 0);
  }
  /// Index of h_max (only with options.helper_force): the last parameter.
  std::size_t helper_offset() const { return num_parameters() - 1; }
  /// Index of Omega_h's first entry (h < num_planner_sets()) and Pi_h's (h < num_gain_sets()).
  std::size_t planner_offset(int h) const {
    return static_cast<std::size_t>(h) * planner_vector_size;
  }
  std::size_t gains_offset(int h) const {
    return static_cast<std::size_t>(num_planner_sets()) * planner_vector_size +
           static_cast<std::size_t>(h) * end_effector_gains::size;
  }
  /// "omega0.t_e", ..., "pi1.rho", in the vector's order.
  std::vector<std::string> parameter_names() const {
    std::vector<std::string> n;
    n.reserve(num_parameters());
    for (int h = 0; h < num_planner_sets(); ++h)
      for (const char* s : planner_vector_names) n.push_back("omega" + std::to_string(h) + "." + s);
    for (int h = 0; h < num_gain_sets(); ++h)
      for (const char* s : end_effector_gains::names)
        n.push_back("pi" + std::to_string(h) + "." + s);
    if (opt_.helper_force) n.push_back("h_max");
    return n;
  }
  /// options.planner for every Omega (Omega_1 mirrored, which leaves the default unchanged) and
  /// options.gains for every Pi.
  std::vector<double> default_parameters() const {
    std::vector<double> p(num_parameters());
    const auto om = to_planner_vector(opt_.planner);
    const auto om1 = to_planner_vector(mirrored(opt_.planner));
    const auto pi = opt_.gains.to_array();
    for (int h = 0; h < num_planner_sets(); ++h) {
      const auto& src = h == 0 ? om : om1;
      std::copy(src.begin(), src.end(), p.begin() + static_cast<std::ptrdiff_t>(planner_offset(h)));
    }
    for (int h = 0; h < num_gain_sets(); ++h)
      std::copy(pi.begin(), pi.end(), p.begin() + static_cast<std::ptrdiff_t>(gains_offset(h)));
    if (opt_.helper_force) p[helper_offset()] = opt_.h_max;
    return p;
  }

  /// \throws std::invalid_argument naming the parameter (name and index) and its value for a wrong
  /// size, a non-finite value, a negative gain, or a planner value validate(planner_parameters)
  /// refuses (t_e < 0, gamma or a swing control point's u outside [0, 1]). Leaves the controller
  /// unchanged when it throws.
  void bind(std::span<const double> p) {
    check_size(static_cast<std::ptrdiff_t>(p.size()), static_cast<std::ptrdiff_t>(num_parameters()),
               "planned_walk parameters");
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!std::isfinite(p[i]))
        throw std::invalid_argument("planned_walk: parameter " + std::to_string(i) + " (" +
                                    parameter_names()[i] + ") is not finite (" +
                                    std::to_string(p[i]) + ")");
    std::array<planner_parameters, 2> omega;
    for (int h = 0; h < num_planner_sets(); ++h) {
      omega[h] =
          from_planner_vector(p.subspan(planner_offset(h), planner_vector_size), opt_.planner);
      try {
        validate(omega[h]);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("planned_walk: Omega_" + std::to_string(h) + " (parameters " +
                                    std::to_string(planner_offset(h)) + "...): " + e.what());
      }
    }
    if (num_planner_sets() == 1) omega[1] = mirrored(omega[0]);
    std::array<end_effector_gains, 2> pi;
    for (int h = 0; h < num_gain_sets(); ++h) {
      const auto g = p.subspan(gains_offset(h), end_effector_gains::size);
      for (std::size_t i = 0; i < g.size(); ++i)
        check_argument(g[i] >= 0.0, "planned_walk: parameter ", gains_offset(h) + i, " (pi", h, ".",
                       end_effector_gains::names[i], ") must be >= 0, got ", g[i]);
      pi[h] = end_effector_gains::from(g);
    }
    if (num_gain_sets() == 1) pi[1] = pi[0];
    omega_ = omega;
    gains_ = pi;
    h_max_ = opt_.helper_force ? p[helper_offset()] : 0.0;
  }
  /// Sec. 8.2's bound as bound (0 without options.helper_force), N.
  double h_max() const { return h_max_; }
  /// Omega and Pi of half-cycle parity h (0: even half-cycles, first_stance standing).
  const planner_parameters& planner(int h) const { return omega_[h]; }
  const end_effector_gains& gains(int h) const { return gains_[h]; }

  const options& opts() const { return opt_; }
  const T& ground() const { return terrain_; }
  const end_effector_layout& layout() const { return layout_; }
  double half_cycle_duration() const { return opt_.setup.t_h; }
  /// The half-cycle k that a command at time t falls in with timing fixed: k starts at
  /// t_0 + k t_h, t_0 the time of the first command (state_type::start_time; t itself before the
  /// first command). The 1e-9 s slack keeps a command sensed at t_0 + k t_h minus rounding in
  /// half-cycle k.
  std::int64_t half_cycle_at(double t, const state_type& st) const {
    const double t0 = st.half_cycle < 0 ? t : st.start_time;
    const double t_h = opt_.setup.t_h;
    return static_cast<std::int64_t>(std::floor((t - t0) / t_h + 1e-9 / t_h));
  }
  double period() const { return opt_.period; }
  static constexpr command_kind output_kind() { return command_kind::joint_torque; }
  int command_size(const model<Root>& m) const { return m.num_joint_dofs(); }
  /// The stance foot (0 left, 1 right) for the recorder; -1 before the first command.
  int discrete_state(const state_type& st) const {
    return st.half_cycle < 0 ? -1 : (st.stance == stance_side::left ? 0 : 1);
  }

  // ---- report (Sec. 8.1, 8.2) ----
  const planned_walk_report_layout& report_layout() const { return report_layout_; }
  std::span<const double> report(const state_type& st) const { return st.report; }
  const std::vector<std::string>& report_names() const { return report_names_; }

  /// Sec. 8.2: adds the held helper force to ws.f_ext (world, about the body origins), reading the
  /// bodies' poses from ws. Nothing without options.helper_force or with h_max <= 0.
  void add_external_wrenches(const model<Root>& m, const state_type& st,
                             workspace<Root>& ws) const {
    if (!opt_.helper_force || !(h_max_ > 0.0) || st.half_cycle < 0) return;
    const int ub = layout_.link_body[0];
    add_point_force(m, ws, ub, point_position(m, ws, ub, layout_.reaction_point),
                    vec3(st.helper.template head<3>()));
    for (int j = 0; j < layout_.num_action(); ++j) {
      const action_frame& a = layout_.action[static_cast<std::size_t>(j)];
      const int b = layout_.link_body[static_cast<std::size_t>(a.link)];
      add_point_force(m, ws, b, point_position(m, ws, b, a.point),
                      vec3(st.helper.template segment<3>(action_row(j))));
    }
    ws.f_ext[ub].template head<3>() += st.helper.template tail<3>();
  }

  // ---- state ----
  state_type make_state(const model<Root>& m) const {
    check_size(m.num_joint_dofs(), num_joint_dofs_, "planned_walk: model joint DOFs");
    state_type st{make_lower_level_workspace(m, layout_),
                  std::vector<link_target>(layout_.link_body.size()),
                  {}};
    st.stance = opt_.first_stance;
    st.tracking.action_force.assign(layout_.action.size(), vec3::Zero());
    st.helper.setZero(wrench_rows(layout_));
    st.report.assign(report_layout_.size, 0.0);
    clear_report(st);
    return st;
  }
  void reset_state(const model<Root>&, state_type& st) const {
    st.current = -1;
    st.half_cycle = -1;
    st.start_time = st.half_cycle_start = st.last_plan_time = 0.0;
    st.stance = opt_.first_stance;
    st.stance_anchored = false;
    st.plans_made = st.commands = st.qp_failures = 0;
    st.helper.setZero();
    clear_report(st);
  }

  /// Half-cycle k's goal G (options.goal_schedule). No allocation.
  const task_goal& goal_of(std::int64_t k) const {
    const task_goal* g = &opt_.goal;
    for (const scheduled_goal& e : opt_.goal_schedule) {
      if (e.from_half_cycle > k) break;
      g = &e.goal;
    }
    return *g;
  }

  /// Half-cycle k's stance foot.
  stance_side stance_of(std::int64_t k) const {
    const stance_side other =
        opt_.first_stance == stance_side::left ? stance_side::right : stance_side::left;
    return k % 2 == 0 ? opt_.first_stance : other;
  }

  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    ++st.commands;
    if (!s.q().allFinite() || !s.v().allFinite()) {  // a diverged state: nothing to plan from
      cmd.head(num_joint_dofs_).setZero();
      st.helper.setZero();
      return;
    }
    const std::int64_t k = opt_.timing == half_cycle_end::touchdown && st.half_cycle >= 0
                               ? half_cycle_on_touchdown(s, st)
                               : half_cycle_at(s.t, st);
    if (st.half_cycle < 0) st.start_time = s.t;
    if (k != st.half_cycle) plan(s, st, k < 0 ? 0 : k);
    const half_cycle_plan& p = st.plans[static_cast<std::size_t>(st.current)];
    const double t_plan = std::max(0.0, s.t - st.half_cycle_start);
    p.link_targets(t_plan, st.targets);
    if (opt_.stance_target != stance_foot_target::planned_landing) hold_touchdown(s, st, p, t_plan);
    const end_effector_gains& g = gains_[static_cast<std::size_t>(st.half_cycle % 2)];
    const Eigen::VectorXd& tau = lower_level_torques(s.model(), layout_, g, opt_.lower, s.q(),
                                                     s.v(), st.targets, s.contact_active, st.lower);
    if (st.lower.qp.status != qp_status::optimal) ++st.qp_failures;
    cmd.head(num_joint_dofs_) = tau;
    update_report(st);
  }

 private:
  /// Starts half-cycle k: swaps stance and swing, plans from the sensed poses.
  void plan(const sensors<Root>& s, state_type& st, std::int64_t k) const {
    const auto& ws = s.workspace();
    const int ub = layout_.link_body[0];
    const stance_side stance = stance_of(k);
    const int st_body = layout_.link_body[stance == stance_side::left ? 1 : 2];
    const int sw_body = layout_.link_body[stance == stance_side::left ? 2 : 1];
    planner_input in;
    const mat3& R = ws.body_rotation[ub];
    in.upper_body = {ws.body_position[ub] + R * opt_.setup.upper_body_point, R};
    in.stance_foot = {ws.body_position[st_body], ws.body_rotation[st_body]};
    in.swing_foot = {ws.body_position[sw_body], ws.body_rotation[sw_body]};
    in.stance = stance;
    in.previous_facing = std::atan2(R(1, 0), R(0, 0));
    const half_cycle_plan* previous = st.plan();
    if (previous != nullptr)
      in.upper_body_deviation = upper_body_deviation(*previous, in.upper_body.position);
    const int next = st.current < 0 ? 0 : 1 - st.current;
    const task_goal& goal = goal_of(k);
    st.plans[static_cast<std::size_t>(next)] = plan_half_cycle(
        goal, omega_[static_cast<std::size_t>(k % 2)], opt_.setup, in, terrain_, previous);
    st.current = next;
    st.half_cycle = k;
    st.half_cycle_start = opt_.timing == half_cycle_end::touchdown
                              ? s.t
                              : st.start_time + static_cast<double>(k) * opt_.setup.t_h;
    st.last_plan_time = s.t;
    st.stance = stance;
    st.stance_anchored = false;
    ++st.plans_made;
    // Sec. 8.1: c_k = c^_{k-1} + R_z(psi_m) (r x), from the COM sensed as half-cycle k starts.
    const double psi_m = goal.movement, r = goal.step_length;
    st.report[report_layout_.half_cycle] = static_cast<double>(k);
    st.report[report_layout_.com_target] = s.com.x() + r * std::cos(psi_m);
    st.report[report_layout_.com_target + 1] = s.com.y() + r * std::sin(psi_m);
  }

  /// timing touchdown: the next half-cycle once t_h has passed (1e-9 s slack) and a contact point
  /// of the swing foot touches, or max_touchdown_wait after that; else the current one.
  std::int64_t half_cycle_on_touchdown(const sensors<Root>& s, const state_type& st) const {
    const double elapsed = s.t - st.half_cycle_start, t_h = opt_.setup.t_h;
    if (elapsed < t_h - 1e-9) return st.half_cycle;
    if (elapsed >= t_h + opt_.max_touchdown_wait - 1e-9) return st.half_cycle + 1;
    const int swing = st.stance == stance_side::left ? 2 : 1;
    for (const action_frame& a : layout_.action)
      if (a.link == swing && frame_touches(a, s.contact_active)) return st.half_cycle + 1;
    return st.half_cycle;
  }

  /// stance_target touchdown: once the previous swing's tail is over (t >= t_e') and a contact
  /// point of the stance foot touches, its target becomes where it is (touchdown_stance_target)
  /// for the rest of the half-cycle. Before that, the plan's target. first_contact: the same
  /// without waiting for the tail's end.
  void hold_touchdown(const sensors<Root>& s, state_type& st, const half_cycle_plan& p,
                      double t) const {
    const std::size_t link = st.stance == stance_side::left ? 1 : 2;
    if (!st.stance_anchored) {
      if (opt_.stance_target == stance_foot_target::touchdown && p.has_tail && t < p.tail_end)
        return;
      bool touching = false;
      for (const action_frame& a : layout_.action)
        touching = touching ||
                   (static_cast<std::size_t>(a.link) == link && frame_touches(a, s.contact_active));
      if (!touching) return;
      const auto& ws = s.workspace();
      const int b = layout_.link_body[link];
      st.stance_anchor = touchdown_stance_target(
          opt_.setup, end_effector_pose{ws.body_position[b], ws.body_rotation[b]}, p, terrain_);
      st.stance_anchored = true;
    }
    st.targets[link] = st.stance_anchor;
  }

  void clear_report(state_type& st) const {
    std::fill(st.report.begin(), st.report.end(), 0.0);
    st.report[report_layout_.half_cycle] = -1.0;
    st.report[report_layout_.h_max] = h_max_;
  }

  /// After a lower-level tick: the tracking norms (Sec. 8.1) and the helper force (Sec. 8.2).
  void update_report(state_type& st) const {
    const auto& lw = st.lower;
    compute_ideal_wrenches(layout_, tracking_gains_, lw.current, lw.desired, st.tracking);
    const planned_walk_report_layout& R = report_layout_;
    st.report[R.tracking_begin] = st.tracking.reaction_force.squaredNorm();
    st.report[R.tracking_begin + 1] = st.tracking.reaction_torque.squaredNorm();
    for (std::size_t j = 0; j < st.tracking.action_force.size(); ++j)
      st.report[R.tracking_begin + 2 + j] = st.tracking.action_force[j].squaredNorm();
    st.report[R.h_max] = h_max_;
    if (!opt_.helper_force || !(h_max_ > 0.0)) {
      st.report[R.helper_max] = 0.0;
      return;
    }
    // h = b - A f over eq. 4's full rows (A, b unweighted; f = 0 when the QP failed).
    st.helper = lw.qp.b;
    st.helper.noalias() -= lw.qp.A * lw.qp.f;
    for (int j = 0; j < layout_.num_action(); ++j)
      if (lw.pinned[static_cast<std::size_t>(j)])
        st.helper.template segment<3>(action_row(j)).setZero();
    st.helper = st.helper.cwiseMax(-h_max_).cwiseMin(h_max_);
    const helper_scope scope = opt_.helper_rows;
    if (scope != helper_scope::all && scope != helper_scope::feet) {
      st.helper.segment(3, st.helper.size() - 6).setZero();
      if (scope == helper_scope::upper_body_force) st.helper.template tail<3>().setZero();
      if (scope == helper_scope::upper_body_torque) st.helper.template head<3>().setZero();
    } else if (scope == helper_scope::feet) {
      st.helper.template head<3>().setZero();
      st.helper.template tail<3>().setZero();
    }
    st.report[R.helper_max] = st.helper.cwiseAbs().maxCoeff();
  }

  options opt_;
  T terrain_;
  end_effector_layout layout_;
  int num_joint_dofs_ = 0;
  end_effector_gains tracking_gains_;
  planned_walk_report_layout report_layout_;
  std::vector<std::string> report_names_;
  std::array<planner_parameters, 2> omega_{};
  std::array<end_effector_gains, 2> gains_{};
  double h_max_ = 0.0;
};

}  // namespace gaitsynth
