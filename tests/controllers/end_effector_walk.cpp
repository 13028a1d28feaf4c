// The cyclical locomotion controller of Wu & Popovic 2010, Sec. 7 (controllers/end_effector/
// planned_walk.hpp): P_c = (Omega_0, Omega_1, Pi_0, Pi_1) as one named vector with Table 1's
// bounds (synthesis/wu2010_search_space.hpp), the mirrored Omega of symmetric controllers, bind's
// refusals, the half-cycle schedule seen through the controller's state, and what the default
// (unoptimized) parameters do on the Table 3 biped.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wu2010_search_space.hpp"
#include "support/joint_rate_chatter.hpp"

using namespace gaitsynth;

namespace {

std::string message_of(const auto& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no exception)";
}

std::size_t index_of(const std::vector<std::string>& names, const std::string& n) {
  const auto it = std::find(names.begin(), names.end(), n);
  REQUIRE(it != names.end());
  return static_cast<std::size_t>(it - names.begin());
}

/// Per physics step: the controller's half-cycle bookkeeping, the COM and the lowest body.
struct walk_log {
  struct plan_event {
    double t = 0.0, last_plan_time = 0.0, half_cycle_start = 0.0;
    std::int64_t half_cycle = -1, plans_made = 0;
    stance_side stance = stance_side::left;
    int discrete = -1;
    task_goal goal;
    vec2 com_target = vec2::Zero();  ///< Sec. 8.1's c_k in the report
    vec3 com = vec3::Zero();         ///< sensed as the half-cycle began
  };
  std::vector<plan_event> plans;
  std::int64_t last_seen = -1;
  vec3 start_com = vec3::Zero(), last_com = vec3::Zero();
  double min_com_z = std::numeric_limits<double>::infinity();
  bool finite = true;
  std::int64_t qp_failures = 0;
  gaitsynth::testing::joint_rate_chatter chatter;
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    chatter.add(ob.t, ob.v_ptr->tail(ob.v_ptr->size() - 6));
    if (ob.step == 0) start_com = ob.com;
    last_com = ob.com;
    min_com_z = std::min(min_com_z, ob.com.z());
    finite = finite && ob.com.allFinite();
    qp_failures = st.qp_failures;
    if (st.plans_made != last_seen) {
      last_seen = st.plans_made;
      if (plans.size() < plans.capacity())  // no allocation while observing
        plans.push_back(
            {ob.t, st.last_plan_time, st.half_cycle_start, st.half_cycle, st.plans_made, st.stance,
             ob.controller_state(), st.plan()->goal,
             vec2(st.report[planned_walk_report_layout::for_action_frames(8).com_target],
                  st.report[planned_walk_report_layout::for_action_frames(8).com_target + 1]),
             ob.com});
    }
  }
};

/// Where the first plan's swing foot lands (ankle height).
struct first_landing {
  double z = std::numeric_limits<double>::quiet_NaN();
  template <class Ob>
  void observe(const Ob& ob) {
    if (ob.step == 0) z = ob.controller_state_ptr->plan()->swing.at_s(1.0, 0.0).position.z();
  }
};

template <class T>
rollout_result walk(const floating_model& m, const planned_walk<T>& c, const T& ground,
                    double duration, bool detect_falls, walk_log& log) {
  rollout_options o;
  o.duration = duration;
  o.detect_falls = detect_falls;
  o.initial_state = make_state(m);  // the neutral pose, feet on the ground below
  place_on_terrain(m, ground, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> p = c.default_parameters();
  log.plans.reserve(64);
  return rollout(m, torque_actuator{}, c, distance_objective(), ground, semi_implicit_euler(), p, o,
                 scratch, log);
}

}  // namespace

TEST_CASE("planned_walk: parameter layout, names and Table 1's bounds",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  for (const auto& [sym, n, omegas, pis] :
       {std::tuple{planned_walk_symmetry::asymmetric, 74u, 2, 2},
        std::tuple{planned_walk_symmetry::mirrored_planner, 49u, 1, 2},
        std::tuple{planned_walk_symmetry::mirrored, 37u, 1, 1}}) {
    planned_walk_options o;
    o.symmetry = sym;
    const planned_walk<> c(m, flat_terrain{}, o);
    INFO("symmetry " << static_cast<int>(sym));
    CHECK(c.num_parameters() == n);
    CHECK(c.num_planner_sets() == omegas);
    CHECK(c.num_gain_sets() == pis);
    const auto names = c.parameter_names();
    REQUIRE(names.size() == n);
    CHECK(std::set<std::string>(names.begin(), names.end()).size() == n);  // unique
    CHECK(names.front() == "omega0.t_e");
    CHECK(names[24] == "omega0.w_ub2.u");
    CHECK(names[c.gains_offset(0)] == "pi0.ub_kp");
    CHECK(names.back() == (pis == 2 ? "pi1.rho" : "pi0.rho"));
    if (omegas == 2) CHECK(names[25] == "omega1.t_e");
    // The defaults lie inside Table 1's bounds (parameter_space refuses an initial value outside).
    const std::vector<double> p0 = c.default_parameters();
    REQUIRE(p0.size() == n);
    const parameter_space s = wu2010_search_space(c, p0);
    REQUIRE(s.size() == static_cast<Eigen::Index>(n));
    for (Eigen::Index i = 0; i < s.size(); ++i) {
      INFO(s[i].name);
      CHECK(s[i].name == names[static_cast<std::size_t>(i)]);
      CHECK(s[i].lower <= p0[static_cast<std::size_t>(i)]);
      CHECK(p0[static_cast<std::size_t>(i)] <= s[i].upper);
    }
    // A few of Table 1's bounds by name.
    const auto bound = [&](const std::string& name) {
      const auto& ps = s[static_cast<Eigen::Index>(index_of(names, name))];
      return std::pair{ps.lower, ps.upper};
    };
    CHECK(bound("omega0.t_e").second == Approx(0.6 * 0.55));
    CHECK(bound("omega0.z_ub").first == Approx(1.15));
    CHECK(bound("omega0.z_ub").second == Approx(1.75));
    CHECK(bound("omega0.psi_ub").second == Approx(30.0 * std::numbers::pi / 180.0));
    CHECK(bound("omega0.theta_sw1").first == Approx(-80.0 * std::numbers::pi / 180.0));
    CHECK(bound("omega0.w_sw2.u").first == Approx(0.2));
    CHECK(bound("omega0.w_ub1.u").second == Approx(0.66));
    CHECK(bound("pi0.ub_cp").second == Approx(140.0 * 9.8));
    CHECK(bound("pi0.toe_heel_kr").second == Approx(8000.0));
    // An initial value outside the bounds is refused, naming the parameter.
    std::vector<double> bad = p0;
    bad[index_of(names, "omega0.c_sw.left")] = 0.5;
    CHECK_THAT(message_of([&] { (void)wu2010_search_space(c, bad); }),
               Catch::Contains("omega0.c_sw.left"));
  }
}

TEST_CASE("planned_walk: Omega_1 of a symmetric controller is Omega_0's mirror image",
          "[controllers][end_effector][walk]") {
  planner_parameters p;
  p.k_sw_plus = vec2(0.1, 0.2);
  p.k_sw_minus = vec2(0.3, 0.4);
  p.c_sw = vec2(0.01, 0.02);
  p.k_ub = vec2(0.5, 0.6);
  p.c_ub = vec2(0.03, 0.04);
  p.theta_ub = 0.05;
  p.phi_ub = 0.06;
  p.psi_ub = 0.07;
  p.w_sw1.y() = 0.08;
  p.w_ub2.y() = 0.09;
  const planner_parameters q = mirrored(p);
  CHECK(q.k_sw_plus == vec2(0.1, 0.4));  // lateral K+ and K- swap
  CHECK(q.k_sw_minus == vec2(0.3, 0.2));
  CHECK(q.c_sw == vec2(0.01, -0.02));
  CHECK(q.k_ub == p.k_ub);
  CHECK(q.c_ub == vec2(0.03, -0.04));
  CHECK(q.theta_ub == 0.05);
  CHECK(q.phi_ub == -0.06);
  CHECK(q.psi_ub == -0.07);
  CHECK(q.w_sw1.y() == -0.08);
  CHECK(q.w_ub2.y() == -0.09);
  const auto twice = to_planner_vector(mirrored(q)), once = to_planner_vector(p);
  CHECK(std::vector<double>(twice.begin(), twice.end()) ==
        std::vector<double>(once.begin(), once.end()));
  // The flat vector round-trips.
  const auto v = to_planner_vector(p);
  const auto back = to_planner_vector(from_planner_vector(v, planner_parameters{}));
  CHECK(std::vector<double>(v.begin(), v.end()) == std::vector<double>(back.begin(), back.end()));

  // Through bind: mirrored_planner takes Omega_0 only and mirrors it for odd half-cycles.
  const floating_model m = wu2010_biped();
  planned_walk<> c(m);
  std::vector<double> x = c.default_parameters();
  std::copy(v.begin(), v.end(), x.begin());
  c.bind(x);
  const auto o1 = to_planner_vector(c.planner(1)), expected = to_planner_vector(q);
  CHECK(std::vector<double>(o1.begin(), o1.end()) ==
        std::vector<double>(expected.begin(), expected.end()));
}

TEST_CASE("planned_walk: bind refuses a wrong size, NaN and bad values, naming the parameter",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  planned_walk_options o;
  o.symmetry = planned_walk_symmetry::asymmetric;
  planned_walk<> c(m, flat_terrain{}, o);
  const auto names = c.parameter_names();
  const std::vector<double> good = c.default_parameters();
  CHECK_NOTHROW(c.bind(good));
  std::vector<double> shorter(good.begin(), good.end() - 1);
  CHECK_THAT(message_of([&] { c.bind(shorter); }), Catch::Contains("74"));

  const auto refused = [&](const std::string& name, double value) {
    std::vector<double> p = good;
    p[index_of(names, name)] = value;
    return message_of([&] { c.bind(p); });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(refused("omega1.gamma2", nan), Catch::Contains("omega1.gamma2"));
  CHECK_THAT(refused("pi0.ub_bo", nan), Catch::Contains("pi0.ub_bo"));
  CHECK_THAT(refused("pi1.ankle_kp", -1.0), Catch::Contains("pi1.ankle_kp"));
  CHECK_THAT(refused("omega0.gamma1", 1.5),
             Catch::Contains("Omega_0") && Catch::Contains("gamma1"));
  CHECK_THAT(refused("omega1.t_e", -0.1), Catch::Contains("Omega_1") && Catch::Contains("t_e"));
  CHECK_THAT(refused("omega0.w_sw2.u", 2.0), Catch::Contains("w_sw2.u"));
  // A refused bind leaves the controller as it was.
  CHECK(c.gains(1).ankle_kp == good[index_of(names, "pi1.ankle_kp")]);
  CHECK(c.planner(1).t_e == good[index_of(names, "omega1.t_e")]);
  // Options.
  planned_walk_options slow;
  slow.period = 0.6;  // longer than t_h = 0.55
  CHECK_THAT(message_of([&] { planned_walk<> d(m, flat_terrain{}, slow); }),
             Catch::Contains("period"));
  planned_walk_options nan_goal;
  nan_goal.goal.step_length = nan;
  CHECK_THAT(message_of([&] { planned_walk<> d(m, flat_terrain{}, nan_goal); }),
             Catch::Contains("step_length"));
  planned_walk_options nobody;
  nobody.first_stance = stance_side::none;
  CHECK_THAT(message_of([&] { planned_walk<> d(m, flat_terrain{}, nobody); }),
             Catch::Contains("first_stance") && Catch::Contains("none"));
}

TEST_CASE("planned_walk: plans at t = 0, t_h, 2 t_h, ... and swaps stance and swing",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  const planned_walk<> c(m);
  const double t_h = c.half_cycle_duration();
  walk_log log;
  // Falls are not detected: the schedule runs on the clock whatever the biped does.
  const rollout_result r = walk(m, c, flat_terrain{}, 2.5 * t_h + 0.01, false, log);
  CHECK_FALSE(r.diverged());
  REQUIRE(log.plans.size() == 3);  // k = 0, 1, 2
  const double dt = 1.0 / 2400.0;
  for (std::size_t k = 0; k < log.plans.size(); ++k) {
    const auto& e = log.plans[k];
    INFO("half-cycle " << k);
    CHECK(e.half_cycle == static_cast<std::int64_t>(k));
    CHECK(e.plans_made == static_cast<std::int64_t>(k + 1));
    CHECK(e.half_cycle_start == Approx(k * t_h).margin(1e-12));
    // Planned at the first physics step at or after k t_h.
    CHECK(e.last_plan_time >= k * t_h - 1e-9);
    CHECK(e.last_plan_time < k * t_h + dt);
    CHECK(e.t == e.last_plan_time);  // observed the step it planned in
    CHECK(e.stance == (k % 2 == 0 ? stance_side::left : stance_side::right));
    CHECK(e.discrete == (k % 2 == 0 ? 0 : 1));
  }

  // first_stance = right starts on the other foot.
  planned_walk_options o;
  o.first_stance = stance_side::right;
  const planned_walk<> d(m, flat_terrain{}, o);
  walk_log log2;
  (void)walk(m, d, flat_terrain{}, 1.5 * t_h, false, log2);
  REQUIRE(log2.plans.size() == 2);
  CHECK(log2.plans[0].stance == stance_side::right);
  CHECK(log2.plans[1].stance == stance_side::left);
}

TEST_CASE("planned_walk: goal_schedule changes G at run time, from the half-cycle it names",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  planned_walk_options o;
  o.goal_schedule = {{1, {0.2, 0.1, 0.5}}, {3, {0.0, 0.0, 0.0}}};
  const planned_walk<> c(m, flat_terrain{}, o);
  const double t_h = c.half_cycle_duration();
  walk_log log;
  (void)walk(m, c, flat_terrain{}, 3.5 * t_h, false, log);
  REQUIRE(log.plans.size() == 4);
  const task_goal expected[] = {o.goal, {0.2, 0.1, 0.5}, {0.2, 0.1, 0.5}, {0.0, 0.0, 0.0}};
  for (std::size_t k = 0; k < 4; ++k) {
    INFO("half-cycle " << k);
    const walk_log::plan_event& e = log.plans[k];
    CHECK(e.goal.facing == expected[k].facing);
    CHECK(e.goal.movement == expected[k].movement);
    CHECK(e.goal.step_length == expected[k].step_length);
    // Sec. 8.1's COM target follows the half-cycle's goal: c^ + R_z(psi_m) (r x).
    CHECK(e.com_target.x() ==
          Approx(e.com.x() + expected[k].step_length * std::cos(expected[k].movement)));
    CHECK(
        e.com_target.y() ==
        Approx(e.com.y() + expected[k].step_length * std::sin(expected[k].movement)).margin(1e-12));
  }

  // Out of order, negative or non-finite entries are refused, naming the entry and the value.
  planned_walk_options bad;
  bad.goal_schedule = {{2, {}}, {2, {}}};
  CHECK_THAT(message_of([&] { planned_walk<>(m, flat_terrain{}, bad); }),
             Catch::Contains("goal_schedule[1].from_half_cycle") && Catch::Contains("got 2"));
  bad.goal_schedule = {{-1, {}}};
  CHECK_THAT(message_of([&] { planned_walk<>(m, flat_terrain{}, bad); }),
             Catch::Contains("goal_schedule[0]") && Catch::Contains("-1"));
  bad.goal_schedule = {{0, {}}, {4, {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.65}}};
  CHECK_THAT(
      message_of([&] { planned_walk<>(m, flat_terrain{}, bad); }),
      Catch::Contains("goal_schedule[1]") && Catch::Contains("facing") && Catch::Contains("nan"));
}

TEST_CASE("planned_walk plans on the terrain it holds, or blind",
          "[controllers][end_effector][walk]") {
  // A 0.1 m step up at x = 0.3: the first swing (left stance, r = 0.65) lands on it.
  const floating_model m = wu2010_biped();
  const steps_terrain step({{0.3, 0.1}}, 0.0);
  for (const bool aware : {true, false}) {
    planned_walk_options o;
    o.setup.terrain_awareness = aware;
    const planned_walk<steps_terrain> c(m, step, o);
    rollout_options ro;
    ro.duration = 0.01;
    ro.initial_state = make_state(m);
    place_on_terrain(m, step, ro.initial_state.q);
    auto scratch = make_rollout_scratch(m);
    first_landing l;
    (void)rollout(m, torque_actuator{}, c, distance_objective(), step, semi_implicit_euler(),
                  c.default_parameters(), ro, scratch, l);
    INFO("terrain awareness " << aware);
    // The ankle lands 0.06 m above the ground it plans on (the foot box's bottom is 0.06 below).
    CHECK(l.z == Approx(aware ? 0.16 : 0.06).margin(1e-3));
  }
}

TEST_CASE("planned_walk: the default (unoptimized) parameters on the Table 3 biped",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  const planned_walk<> c(m);
  walk_log log;
  const rollout_result r = walk(m, c, flat_terrain{}, 2.0, true, log);
  const vec3 moved = log.last_com - log.start_com;
  WARN("default planned_walk, flat ground: "
       << to_string(r.reason) << " at t = " << r.time << " s after " << log.plans.size()
       << " half-cycles; COM moved " << moved.transpose() << " m; lowest COM " << log.min_com_z
       << " m (start " << log.start_com.z() << "); QP failures " << log.qp_failures);
  // Not a walk: the defaults are a neutral plan (no balance feedback, no bias, the upper body
  // planned midway between the feet), not optimized parameters. Measured: the first step (the
  // right foot 0.65 m ahead from standing) lags its path, the upper body lags its target and
  // drifts to the swing side, and the biped falls to the right at t = 1.32 s, early in the third
  // half-cycle, its COM 0.33 m forward; eq. 5's QP never fails. What this test guards: the
  // schedule runs, nothing diverges or goes NaN, no joint chatters.
  CHECK_FALSE(r.diverged());
  CHECK(log.finite);
  CHECK(std::isfinite(r.cost));
  CHECK(log.plans.size() >= 2);
  CHECK(log.qp_failures == 0);
  // No joint rate reverses its change step after step (measured: runs of 11 steps at most; with
  // the null-space damper sent through appendix B's bounded canceling QP, the earlier design,
  // the swing ankle's roll alternated for 1569 steps before the fall: null_space_damper.hpp).
  CHECK(log.chatter.longest_alternation < 40);
}

namespace {

/// Per physics step of half-cycle 1 (the first with a tail, Fig. 5): how often a frame of the
/// stance foot is pinned, and (stance_target touchdown) where the anchor went.
struct stance_log {
  const end_effector_layout* layout = nullptr;
  std::int64_t steps = 0, pinned_steps = 0;
  bool anchored = false;
  double anchor_miss = -1.0;  ///< horizontal distance anchor - foot at the step it was set, m
  double anchor_time = -1.0;
  bool target_is_anchor = true;
  bool pinned_at_anchor = false;  ///< at that step every touching stance-foot frame is pinned
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    if (st.half_cycle != 1) return;
    ++steps;
    const int link = st.stance == stance_side::left ? 1 : 2;
    bool any = false, touching_pinned = true, touching_any = false;
    for (int j = 0; j < layout->num_action(); ++j) {
      const action_frame& a = layout->action[static_cast<std::size_t>(j)];
      if (a.link != link) continue;
      const bool pin = st.lower.pinned[static_cast<std::size_t>(j)] != 0;
      bool touch = false;
      for (const int c : a.contacts)
        touch = touch || ob.contact_active[static_cast<std::size_t>(c)];
      any = any || pin;
      touching_any = touching_any || touch;
      touching_pinned = touching_pinned && (pin || !touch);
    }
    pinned_steps += any ? 1 : 0;
    if (st.stance_anchored && !anchored) {
      anchored = true;
      pinned_at_anchor = touching_any && touching_pinned;
      anchor_time = ob.t;
      const int b = layout->link_body[static_cast<std::size_t>(link)];
      anchor_miss = (st.stance_anchor.position - ob.body_position[b]).template head<2>().norm();
    }
    if (st.stance_anchored)
      target_is_anchor = target_is_anchor && st.targets[static_cast<std::size_t>(link)].position ==
                                                 st.stance_anchor.position;
  }
};

/// The default parameters' first `duration` s from the neutral pose on flat ground, falls not
/// stopped, observed by `log`.
template <class Log>
rollout_result walk_default(const floating_model& m, const planned_walk<>& c, double duration,
                            Log& log) {
  rollout_options ro;
  ro.duration = duration;
  ro.detect_falls = false;
  ro.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, ro.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  return rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                 semi_implicit_euler(), c.default_parameters(), ro, scratch, log);
}

/// The default parameters' first 1.1 s (falls not stopped) with stance target `target`, logged.
stance_log stance_walk(const floating_model& m, stance_foot_target target) {
  planned_walk_options o;
  o.stance_target = target;
  const planned_walk<> c(m, flat_terrain{}, o);
  stance_log log;
  log.layout = &c.layout();
  (void)walk_default(m, c, 1.1, log);
  log.layout = nullptr;  // c's layout ends here
  return log;
}

}  // namespace

TEST_CASE("planned_walk: stance_target touchdown pins the stance foot where it landed",
          "[controllers][end_effector][walk]") {
  // The default parameters' second half-cycle: the right foot lands 0.24 m short of its planned
  // end (the case above), so with Fig. 5's planned landing as its target it is never pinned (Sec.
  // 6.3, eps_p = 0.2 m); re-targeted at touchdown, its touching frames are pinned from then on
  // while they touch. (They do not touch for long here: the upper body lags its target, its PD
  // force pulls the unheld stance foot back off the ground, and the biped falls, as above.)
  const floating_model m = wu2010_biped();
  std::int64_t pinned[2] = {0, 0}, steps[2] = {0, 0};
  for (const bool touchdown : {false, true}) {
    const stance_log log = stance_walk(
        m, touchdown ? stance_foot_target::touchdown : stance_foot_target::planned_landing);
    pinned[touchdown] = log.pinned_steps;
    steps[touchdown] = log.steps;
    INFO("touchdown " << touchdown);
    CHECK(log.anchored == touchdown);
    if (touchdown) {
      // Anchored after the tail (t_e' = 0.1 s into the half-cycle) where the foot was.
      CHECK(log.anchor_time >= 0.55 + 0.1 - 1e-9);
      CHECK(log.anchor_miss < 2e-3);
      CHECK(log.target_is_anchor);
      CHECK(log.pinned_at_anchor);
    }
  }
  WARN("half-cycle 1, steps with a stance-foot frame pinned: planned landing "
       << pinned[0] << " of " << steps[0] << ", touchdown " << pinned[1] << " of " << steps[1]);
  CHECK(pinned[0] == 0);  // measured: 0 of 1320 steps
  CHECK(pinned[1] > 0);   // measured: 94
}

TEST_CASE("planned_walk: stance_target first_contact anchors at the first contact, tail or not",
          "[controllers][end_effector][walk]") {
  // The same walk as above. touchdown waits for the end of the previous swing's tail (t_e' =
  // 0.1 s into half-cycle 1); first_contact anchors at the foot's first ground contact of the
  // half-cycle, which here comes during that tail, and pins it from then on.
  const floating_model m = wu2010_biped();
  const stance_log logs[2] = {stance_walk(m, stance_foot_target::touchdown),
                              stance_walk(m, stance_foot_target::first_contact)};
  INFO("anchored at " << logs[0].anchor_time << " s (touchdown), " << logs[1].anchor_time
                      << " s (first_contact)");
  REQUIRE(logs[1].anchored);
  CHECK(logs[1].anchor_time < 0.55 + 0.1);  // within the tail
  CHECK(logs[1].anchor_time < logs[0].anchor_time);
  CHECK(logs[1].anchor_miss < 2e-3);
  CHECK(logs[1].target_is_anchor);
  CHECK(logs[1].pinned_at_anchor);
  CHECK(logs[1].pinned_steps > logs[0].pinned_steps);
}

namespace {

/// Per physics step with timing touchdown: whether the controller switched half-cycles exactly
/// when options.timing says (t_h or more after the last switch, at the first command whose swing
/// foot touches, or max_touchdown_wait later).
struct touchdown_timing_log {
  const end_effector_layout* layout = nullptr;
  double t_h = 0.0, wait = 0.0;
  std::int64_t half_cycle = -1;
  double start = 0.0;  ///< the current half-cycle's start as the log saw it
  int switches = 0, on_touch = 0, on_wait = 0;
  int early = 0, late = 0, start_mismatch = 0;
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    const auto touches = [&](stance_side side) {
      const int link = side == stance_side::left ? 1 : 2;
      for (const action_frame& a : layout->action)
        if (a.link == link && frame_touches(a, ob.contact_active)) return true;
      return false;
    };
    const double elapsed = ob.t - start;
    if (st.half_cycle != half_cycle) {
      if (half_cycle >= 0) {
        ++switches;
        // The foot that swung is this half-cycle's stance foot.
        const bool touched = touches(st.stance);
        on_touch += touched;
        on_wait += !touched;
        early += elapsed < t_h - 1e-9 || (!touched && elapsed < t_h + wait - 1e-9);
        start_mismatch += st.half_cycle_start != ob.t;
      }
      half_cycle = st.half_cycle;
      start = st.half_cycle_start;
      return;
    }
    if (half_cycle < 0) return;
    // Still in it: it should have ended by now?
    const stance_side swing =
        st.stance == stance_side::left ? stance_side::right : stance_side::left;
    late += elapsed >= t_h - 1e-9 && (touches(swing) || elapsed >= t_h + wait - 1e-9);
  }
};

}  // namespace

TEST_CASE("planned_walk: timing touchdown ends a half-cycle when the swing foot lands after t_h",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  planned_walk_options o;
  o.timing = half_cycle_end::touchdown;
  o.max_touchdown_wait = 0.2;
  const planned_walk<> c(m, flat_terrain{}, o);
  touchdown_timing_log log;
  log.layout = &c.layout();
  log.t_h = c.half_cycle_duration();
  log.wait = o.max_touchdown_wait;
  // The default parameters fall at 1.2 s; the timing runs on regardless until the fallen biped's
  // state diverges (at 1.77 s).
  const rollout_result r = walk_default(m, c, 1.7, log);
  log.layout = nullptr;
  REQUIRE(r.reason == stop_reason::horizon);
  INFO(log.switches << " switches: " << log.on_touch << " on touchdown, " << log.on_wait
                    << " after the wait");
  CHECK(log.switches >= 2);
  CHECK(log.early == 0);
  CHECK(log.late == 0);
  CHECK(log.start_mismatch == 0);
  // Both ways of ending occur in this walk (measured: see the INFO line).
  CHECK(log.on_touch >= 1);
  CHECK(log.on_wait >= 1);
  // Fixed timing is the paper's clock, whatever the feet do (the schedule test above), and a
  // negative wait is refused, named.
  planned_walk_options bad = o;
  bad.max_touchdown_wait = -0.1;
  CHECK_THAT(message_of([&] { planned_walk<> d(m, flat_terrain{}, bad); }),
             Catch::Contains("max_touchdown_wait") && Catch::Contains("-0.1"));
}
