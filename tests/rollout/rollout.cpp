// The rollout loop's behaviour: standing, falling, divergence, the controller's rate, what the
// sensors report, what the objective sees, passive limits, actuator-state hooks, recording, and
// bad input. References are independent: closed forms, a separately computed forward kinematics,
// the controller's own records.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "support/rollout_e2.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_e2;

namespace {

constexpr double dt = 1.0 / 2400.0;
constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

rollout_options standing_options(const auto& m, double duration) {
  rollout_options o;
  o.dt = dt;
  o.duration = duration;
  o.initial_state = make_state(m);
  o.initial_state.q.tail(m.num_joint_dofs()) = standing_pose(m);
  place_on_terrain(m, flat_terrain(), o.initial_state.q);
  return o;
}

/// What probe_controller saw (owned by the test, preallocated, so the rollout does not allocate).
struct probe_log {
  std::vector<double> call_times;
  std::vector<std::int64_t> call_steps;
  std::vector<Eigen::VectorXd> q_seen;  ///< q at every call, for the delay check
  double max_com_error = 0, max_com_velocity_error = 0, max_delay_error = 0, max_time_error = 0;
  int contact_count_mismatches = 0, delayed_checks = 0, touching_calls = 0;
  explicit probe_log(int capacity, int nq) {
    call_times.reserve(capacity);
    call_steps.reserve(capacity);
    q_seen.assign(capacity, Eigen::VectorXd::Zero(nq));
  }
};

/// A controller that records when it was called and checks every sensor against an independent
/// computation (its own forward kinematics, its own delay line). It holds the pose like pose_hold.
template <root_joint Root>
struct probe_controller {
  struct state_type {
    workspace<Root> ws;  // independent kinematics
  };
  const model<Root>* m = nullptr;
  probe_log* log = nullptr;
  double period_s = 0;
  double delay = 0;  ///< s; 0: no delayed reads
  pose_hold inner;

  probe_controller(const model<Root>& mm, probe_log& l, double period, double delay_s)
      : m(&mm), log(&l), period_s(period), delay(delay_s), inner(mm) {}
  std::size_t num_parameters() const { return inner.num_parameters(); }
  void bind(std::span<const double> p) { inner.bind(p); }
  double period() const { return period_s; }
  double max_sensor_delay() const { return delay; }
  command_kind output_kind() const { return command_kind::joint_target; }
  state_type make_state(const model<Root>& mm) const { return {make_workspace(mm)}; }
  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    probe_log& L = *log;
    const std::size_t n = L.call_times.size();
    L.call_times.push_back(s.t);
    L.call_steps.push_back(s.step);
    if (n < L.q_seen.size()) L.q_seen[n] = s.q();
    L.max_time_error = std::max(L.max_time_error, std::abs(s.t - s.step * s.dt));
    forward_kinematics(*m, st.ws, s.q(), s.v());
    L.max_com_error = std::max(L.max_com_error, (center_of_mass(*m, st.ws) - s.com).norm());
    L.max_com_velocity_error =
        std::max(L.max_com_velocity_error, (com_velocity(*m, st.ws) - s.com_velocity).norm());
    bool any = false;
    for (int b = 0; b < m->num_bodies(); ++b) {
      int k = 0;
      for (std::size_t c = 0; c < m->contact_points.size(); ++c)
        if (m->contact_points[c].body == b && s.contact_active[c]) ++k;
      if (k != s.contact_count[b]) ++L.contact_count_mismatches;
      any = any || s.touching(b);
    }
    if (any) ++L.touching_calls;
    if (delay > 0 && n < L.q_seen.size()) {  // called every step: the sample delay/dt calls ago
      const auto back = static_cast<std::size_t>(std::lround(delay / s.dt));
      const std::size_t idx = n >= back ? n - back : 0;
      L.max_delay_error =
          std::max(L.max_delay_error, (s.delayed_q(delay) - L.q_seen[idx]).cwiseAbs().maxCoeff());
      ++L.delayed_checks;
    }
    pose_hold::state_type unused;
    inner.command(s, unused, cmd);
  }
};

/// An objective that remembers what it was shown.
struct probe_objective {
  struct accumulator_type {
    int count = 0;
    double first_t = k_nan, last_t = k_nan;
    int stop_after = -1;
  };
  int stop_after = -1;  ///< done() after this many views (-1: never)
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    accumulator_type a;
    a.stop_after = stop_after;
    return a;
  }
  template <root_joint Root>
  void accumulate(accumulator_type& a, const step_view<Root>& v) const {
    if (a.count == 0) a.first_t = v.t;
    a.last_t = v.t;
    ++a.count;
  }
  bool done(const accumulator_type& a) const {
    return a.stop_after >= 0 && a.count >= a.stop_after;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.count; }
};

/// A planar two-body chain (torso + leg) without contact points, for loop tests that need no
/// character.
planar_model small_chain(const Eigen::Vector3d& gravity = {0, 0, -9.81}, joint_limit limit = {}) {
  model_builder<planar_root> b("chain2");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "torso", .mass = 10, .inertia = I});
  b.add_body({.name = "leg",
              .parent = "torso",
              .joint_offset = {0, 0, -0.1},
              .mass = 2,
              .com = {0, 0, -0.2},
              .inertia = 0.1 * I,
              .dofs = {{.name = "hip", .limit = limit, .torque_limit = 500}}});
  b.set_gravity(gravity);
  return b.build();
}

/// First-order lag actuator: its state a follows the command u with time constant T and the
/// torque is a. Either with advance() (exact recursion of explicit Euler) or derivative().
template <bool UseAdvance>
struct lag_actuator {
  using state_type = Eigen::VectorXd;
  double T = 0.05;
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return Eigen::VectorXd::Zero(m.num_joint_dofs());
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_torque; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
               const state_type& a, Eigen::Ref<Eigen::VectorXd> tau) const {
    tau = a;
  }
  template <root_joint Root>
  void advance(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd> u,
               state_type& a, double h) const requires UseAdvance {
    a += h * (u - a) / T;
  }
  template <root_joint Root>
  void derivative(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd> u,
                  const state_type& a, state_type& da) const requires(!UseAdvance) {
    da = (u - a) / T;
  }
};

/// Commands a constant torque u.
struct constant_torque {
  struct state_type {};
  double u = 1.0;
  std::size_t num_parameters() const { return 0; }
  void bind(std::span<const double> p) { check_parameters(p, 0, "constant_torque"); }
  double period() const { return 0; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void command(const sensors<Root>&, state_type&, Eigen::Ref<Eigen::VectorXd> cmd) const {
    cmd.setConstant(u);
  }
};

/// Remembers the passive torque of joint DOF 0 at the first step.
struct first_passive {
  struct accumulator_type {
    double tau = k_nan;
  };
  accumulator_type make_accumulator(const planar_model&) const { return {}; }
  void accumulate(accumulator_type& a, const step_view<planar_root>& v) const {
    if (std::isnan(a.tau)) a.tau = v.tau_passive()[3];
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.tau; }
};

/// Remembers the actuator torque of joint DOF 0 at the last step.
struct last_torque {
  struct accumulator_type {
    double tau = 0;
  };
  accumulator_type make_accumulator(const planar_model&) const { return {}; }
  void accumulate(accumulator_type& a, const step_view<planar_root>& v) const {
    a.tau = v.tau()[3];
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.tau; }
};
}  // namespace

static_assert(controller<probe_controller<floating_root>, floating_root>);
static_assert(objective<probe_objective, planar_root>);
static_assert(actuator_with_advance<lag_actuator<true>, planar_root>);
static_assert(actuator_with_derivative<lag_actuator<false>, planar_root>);

TEST_CASE("a PD pose hold keeps the 3D humanoid standing on flat ground for 2 s",
          "[rollout][standing]") {
  const auto m = wang2009_humanoid();
  auto scr = make_rollout_scratch(m);
  const auto opt = standing_options(m, 2.0);
  const auto r = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
                         semi_implicit_euler(), standing_pose(m), opt, scr);
  REQUIRE(r.reason == stop_reason::horizon);
  CHECK(r.time == Approx(2.0));
  CHECK(r.steps == 4800);
  // Stands still: the COM sinks only by the contact springs' compression (a few mm) and stays
  // over the feet.
  CHECK(std::abs(r.com_final.z() - r.com_initial.z()) < 0.01);
  CHECK((r.com_final - r.com_initial).head<2>().norm() < 0.03);
  CHECK(scr.state.v.cwiseAbs().maxCoeff() < 0.1);
  // Both feet flat: all 8 sole points (heel and ball, lateral and medial) of each foot touch.
  for (const char* foot : {"lfoot", "rfoot"})
    CHECK(scr.contacts.points_touching[m.body_index(foot)] == 4);
}

TEST_CASE("a passive character falls and the fall is detected", "[rollout][fall]") {
  SECTION("3D humanoid") {
    const auto m = wang2009_humanoid();
    auto scr = make_rollout_scratch(m);
    const auto opt = standing_options(m, 3.0);
    const auto r =
        rollout(m, torque_actuator{}, pose_hold(m, {.output = command_kind::joint_torque}),
                time_to_fall{}, flat_terrain(), semi_implicit_euler(), standing_pose(m), opt, scr);
    REQUIRE(r.reason == stop_reason::fell);
    CHECK(r.failed());
    CHECK(r.time < 3.0);
    CHECK(r.fall_height == Approx(0.5 * r.com_initial.z()));
    // Detected at the first state below the threshold (and not before).
    CHECK(r.com_final.z() < r.fall_height);
    CHECK(r.com_final.z() > r.fall_height - 0.05);
    CHECK(r.cost == Approx(3.0 - r.time));  // time_to_fall: the time lost
  }
  SECTION("7-link planar human, absolute fall height") {
    const auto m = sharon2005_human7();
    auto scr = make_rollout_scratch(m);
    auto opt = standing_options(m, 3.0);
    opt.fall_height = 0.6;
    const auto r =
        rollout(m, torque_actuator{}, pose_hold(m, {.output = command_kind::joint_torque}),
                time_to_fall{}, flat_terrain(), semi_implicit_euler(), standing_pose(m), opt, scr);
    REQUIRE(r.reason == stop_reason::fell);
    CHECK(r.fall_height == 0.6);
    CHECK(r.com_final.z() < 0.6);
  }
  SECTION("fall detection can be switched off") {
    const auto m = sharon2005_human7();
    auto scr = make_rollout_scratch(m);
    auto opt = standing_options(m, 1.5);
    opt.detect_falls = false;
    const auto r =
        rollout(m, torque_actuator{}, pose_hold(m, {.output = command_kind::joint_torque}),
                time_to_fall{}, flat_terrain(), semi_implicit_euler(), standing_pose(m), opt, scr);
    CHECK(r.reason == stop_reason::horizon);
    CHECK(r.cost == 0.0);
  }
}

TEST_CASE("a diverging simulation is a failed rollout with cost +infinity, not an exception",
          "[rollout][divergence]") {
  auto m = wang2009_humanoid();
  for (auto& d : m.dofs) d.torque_limit = 1e12;  // no clamp to hide the divergence
  auto scr = make_rollout_scratch(m);
  auto opt = standing_options(m, 1.0);
  opt.detect_falls = false;  // an exploding state may pass below the fall height first
  opt.dt = 0.01;             // with gains 1e7 N m/rad: kp dt^2 / I ~ 1e5 >> 4
  const Eigen::VectorXd kp = Eigen::VectorXd::Constant(m.num_joint_dofs(), 1e7);
  Eigen::VectorXd target = standing_pose(m);
  target.setConstant(0.5);
  auto check = [&](auto integ) {
    rollout_result r;
    REQUIRE_NOTHROW(r = rollout(m, pd_actuator(kp, 0.1 * kp), pose_hold(m), distance_objective(),
                                flat_terrain(), integ, target, opt, scr));
    CHECK(r.reason == stop_reason::non_finite);
    CHECK(r.diverged());
    CHECK(r.failed());
    CHECK(r.cost == std::numeric_limits<double>::infinity());
    CHECK(std::isnan(r.objective_value));  // finish() was not called
    CHECK(r.time < 1.0);
    CHECK(r.com_final.allFinite());
  };
  SECTION("semi-implicit Euler") {
    check(semi_implicit_euler());
  }
  // RK4 renormalizes the root quaternion after each step; a diverged quaternion used to make
  // that throw instead of ending the rollout as failed.
  SECTION("RK4") {
    check(odeint_rk4());
  }
}

namespace {

/// Counts the steps it accumulated (and whether each saw a finite state) and charges 1000 per
/// second of the horizon left: a fall guard.
struct steps_and_rest {
  struct accumulator_type {
    std::int64_t steps = 0;
    bool all_finite = true;
  };
  accumulator_type make_accumulator(const floating_model&) const { return {}; }
  void accumulate(accumulator_type& a, const auto& v) const {
    ++a.steps;
    a.all_finite = a.all_finite && v.q().allFinite() && v.v().allFinite();
  }
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    if (!a.all_finite || out.reason != stop_reason::non_finite) return -1.0;
    return static_cast<double>(a.steps) + 1000.0 * (out.duration - out.time);
  }
};

}  // namespace

TEST_CASE("score_divergence: a diverged rollout scored like an early stop at its last sane step",
          "[rollout][divergence]") {
  // The divergence above under steps_and_rest: finish() sees non_finite, the time the rollout
  // lasted, and only finite states.
  auto m = wang2009_humanoid();
  for (auto& d : m.dofs) d.torque_limit = 1e12;
  auto scr = make_rollout_scratch(m);
  auto opt = standing_options(m, 1.0);
  opt.detect_falls = false;
  opt.dt = 0.01;
  const Eigen::VectorXd kp = Eigen::VectorXd::Constant(m.num_joint_dofs(), 1e7);
  Eigen::VectorXd target = standing_pose(m);
  target.setConstant(0.5);
  auto run = [&] {
    return rollout(m, pd_actuator(kp, 0.1 * kp), pose_hold(m), steps_and_rest{}, flat_terrain(),
                   semi_implicit_euler(), target, opt, scr);
  };
  const rollout_result off = run();
  CHECK(off.cost == std::numeric_limits<double>::infinity());
  opt.score_divergence = true;
  const rollout_result on = run();
  CHECK(on.diverged());
  CHECK(on.time == off.time);
  REQUIRE(on.time < 1.0);
  // Every step it simulated was accumulated, each from a finite state (the step that blew up
  // started from one), and the rest of the horizon charged.
  CHECK(on.cost == Approx(static_cast<double>(on.steps) + 1000.0 * (1.0 - on.time)));
  CHECK(on.objective_value == on.cost);
}

TEST_CASE("a blow-up is reported as a divergence, not as a fall far away",
          "[rollout][divergence]") {
  auto m = wang2009_humanoid();
  for (auto& d : m.dofs) d.torque_limit = 1e12;
  auto scr = make_rollout_scratch(m);
  auto opt = standing_options(m, 1.0);  // fall detection on
  opt.dt = 0.01;
  const Eigen::VectorXd kp = Eigen::VectorXd::Constant(m.num_joint_dofs(), 1e7);
  Eigen::VectorXd target = standing_pose(m);
  target.setConstant(0.5);
  auto run = [&] {
    return rollout(m, pd_actuator(kp, 0.1 * kp), pose_hold(m), distance_objective(), flat_terrain(),
                   semi_implicit_euler(), target, opt, scr);
  };
  // The exploding state is huge but finite for a step: the fall test used to see it first and
  // report a "fall" with the COM 1e10 m away.
  const rollout_result r = run();
  CHECK(r.reason == stop_reason::non_finite);
  CHECK(r.cost == std::numeric_limits<double>::infinity());
  CHECK((r.com_final - r.com_initial).norm() < 2.0);  // the last sane COM
  SECTION("the threshold: a start at 150 m/s is a divergence at 100 m/s, not at infinity") {
    opt.dt = 1.0 / 2400.0;
    opt.duration = 0.01;
    opt.initial_state.v[2] = 150.0;  // launched upward (MuJoCo's free joint: linear velocity first)
    const Eigen::VectorXd held = standing_pose(m);
    auto fly = [&] {
      const Eigen::VectorXd off = Eigen::VectorXd::Zero(m.num_joint_dofs());  // a passive body
      return rollout(m, pd_actuator(off, off), pose_hold(m), distance_objective(), flat_terrain(),
                     semi_implicit_euler(), held, opt, scr);
    };
    const rollout_result fast = fly();
    CHECK(fast.reason == stop_reason::non_finite);
    CHECK(fast.steps == 0);
    opt.divergence_com_speed = std::numeric_limits<double>::infinity();
    CHECK(fly().reason == stop_reason::horizon);
  }
  SECTION("a threshold that is not > 0 is refused, naming it") {
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
      opt.divergence_com_speed = bad;
      CHECK_THROWS_WITH(run(), Catch::Contains("divergence_com_speed"));
    }
  }
}

TEST_CASE("the controller runs at its own period", "[rollout][controller][period]") {
  const auto m = wang2009_humanoid();
  auto scr = make_rollout_scratch(m);
  const auto opt = standing_options(m, 1.0);
  const pd_actuator pd = standing_pd(m, dt);

  SECTION("64 Hz over 2400 Hz physics (Wu & Popovic 2010): not a whole number of steps") {
    probe_log log(100, m.nq());
    const auto r = rollout(m, pd, probe_controller<floating_root>(m, log, 1.0 / 64.0, 0.0),
                           distance_objective(), flat_terrain(), semi_implicit_euler(),
                           standing_pose(m), opt, scr);
    REQUIRE(r.reason == stop_reason::horizon);
    // Calls at the first step at or after n / 64 s, n = 0 .. 63 (64 / 64 s is the horizon).
    REQUIRE(r.controller_calls == 64);
    REQUIRE(log.call_times.size() == 64);
    for (std::size_t n = 0; n < 64; ++n) {
      const double due = static_cast<double>(n) / 64.0;
      CHECK(log.call_times[n] >= due - 1e-12);
      CHECK(log.call_times[n] < due + dt);
      CHECK(log.call_steps[n] == static_cast<std::int64_t>(std::ceil(n * 2400.0 / 64.0)));
    }
  }
  SECTION("period 0: every physics step") {
    const auto r = rollout(m, pd, pose_hold(m), distance_objective(), flat_terrain(),
                           semi_implicit_euler(), standing_pose(m), opt, scr);
    CHECK(r.controller_calls == 2400);
  }
  SECTION("100 Hz, a whole number of steps: every 24th step") {
    probe_log log(200, m.nq());
    const auto r =
        rollout(m, pd, probe_controller<floating_root>(m, log, 0.01, 0.0), distance_objective(),
                flat_terrain(), semi_implicit_euler(), standing_pose(m), opt, scr);
    REQUIRE(r.controller_calls == 100);
    for (std::size_t n = 0; n < log.call_steps.size(); ++n)
      CHECK(log.call_steps[n] == static_cast<std::int64_t>(24 * n));
  }
}

TEST_CASE("sensors report the state, COM, contacts and delayed values consistently",
          "[rollout][sensors]") {
  const auto m = wang2009_humanoid();
  auto scr = make_rollout_scratch(m);
  const auto opt = standing_options(m, 0.25);  // 600 steps
  probe_log log(600, m.nq());
  const double delay = 0.02;  // 20 ms, the ankle reflex delay of Wang et al. 2012 (48 steps)
  const auto r = rollout(m, standing_pd(m, dt), probe_controller<floating_root>(m, log, 0, delay),
                         distance_objective(), flat_terrain(), semi_implicit_euler(),
                         standing_pose(m), opt, scr);
  REQUIRE(r.reason == stop_reason::horizon);
  REQUIRE(log.call_times.size() == 600);
  CHECK(log.max_time_error < 1e-12);
  CHECK(log.max_com_error < 1e-12);
  CHECK(log.max_com_velocity_error < 1e-12);
  CHECK(log.contact_count_mismatches == 0);
  CHECK(log.touching_calls >= 590);  // contact is sensed in the step it starts (feet on the ground)
  CHECK(log.delayed_checks == 600);
  CHECK(log.max_delay_error == 0.0);  // exactly the sample 48 steps back (or the first)
  CHECK((log.q_seen[100] - log.q_seen[52]).norm() > 0.0);  // the check is not vacuous
}

TEST_CASE("the objective sees every step once, in order, and can stop the rollout",
          "[rollout][objective]") {
  // No gravity, no contact points: a body drifting at constant velocity.
  const auto m = small_chain(Eigen::Vector3d::Zero());
  auto scr = make_rollout_scratch(m);
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 1.0;
  opt.detect_falls = false;
  opt.initial_state = make_state(m);
  opt.initial_state.q[1] = 1.0;
  opt.initial_state.v[0] = 1.5;  // m/s along +x
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
  const torque_actuator ta;
  const pose_hold passive(m, {.output = command_kind::joint_torque});

  SECTION("every step once") {
    const auto r = rollout(m, ta, passive, probe_objective{}, flat_terrain(), semi_implicit_euler(),
                           zero, opt, scr);
    CHECK(r.reason == stop_reason::horizon);
    CHECK(r.cost == 2400.0);  // accumulate count
  }
  SECTION("distance travelled is exact for uniform motion") {
    const auto r = rollout(m, ta, passive, distance_travelled(), flat_terrain(),
                           semi_implicit_euler(), zero, opt, scr);
    CHECK(r.cost == Approx(-1.5).epsilon(1e-12));
    const auto r2 = rollout(m, ta, passive, distance_travelled(vec3(0, 0, -1)), flat_terrain(),
                            semi_implicit_euler(), zero, opt, scr);
    CHECK(r2.cost == Approx(0.0).margin(1e-12));
  }
  SECTION("early stop") {
    const auto r = rollout(m, ta, passive, probe_objective{.stop_after = 100}, flat_terrain(),
                           semi_implicit_euler(), zero, opt, scr);
    CHECK(r.reason == stop_reason::objective);
    CHECK_FALSE(r.failed());
    CHECK(r.cost == 100.0);  // views of steps 0..99
    CHECK(r.steps == 99);    // stopped at t_99 before integrating it
    CHECK(r.time == Approx(99 * dt));
  }
}

TEST_CASE("passive joint-limit torques act in the rollout", "[rollout][limits]") {
  joint_limit lim;
  lim.lower = -0.5;
  lim.upper = 0.2;
  lim.stiffness = 300;
  lim.damping = 3;
  lim.model = limit_model::spring_damper;
  const auto m = small_chain(Eigen::Vector3d::Zero(), lim);
  auto scr = make_rollout_scratch(m);
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.01;
  opt.detect_falls = false;
  opt.initial_state = make_state(m);
  opt.initial_state.q[3] = 0.5;   // 0.3 rad past the upper bound
  opt.initial_state.v[3] = 0.25;  // and moving further
  // The spring-damper law of joint_limits.hpp: -k (q - upper) - d qdot.
  const auto r3 = rollout(
      m, torque_actuator{}, pose_hold(m, {.output = command_kind::joint_torque}), first_passive{},
      flat_terrain(), semi_implicit_euler(), Eigen::VectorXd::Zero(1), opt, scr);
  CHECK(r3.cost == Approx(-300 * 0.3 - 3 * 0.25));
  // And it decelerates the joint: it moves back towards the limit.
  CHECK(scr.state.v[3] < 0.25);
}

TEST_CASE("an actuator's own state evolves through advance() or derivative()",
          "[rollout][actuator_state]") {
  const auto m = small_chain(Eigen::Vector3d::Zero());
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.1;  // 240 steps
  opt.detect_falls = false;
  opt.initial_state = make_state(m);
  // The torque seen at step k is the lag state a_k = u (1 - (1 - dt / T)^k); the last view is
  // k = 239.
  const double T = 0.05, u = 2.0;
  const double expected = u * (1.0 - std::pow(1.0 - dt / T, 239));
  auto scr = make_rollout_scratch(m);
  const auto ra =
      rollout(m, lag_actuator<true>{.T = T}, constant_torque{.u = u}, last_torque{}, flat_terrain(),
              semi_implicit_euler(), std::span<const double>(), opt, scr);
  const auto rd =
      rollout(m, lag_actuator<false>{.T = T}, constant_torque{.u = u}, last_torque{},
              flat_terrain(), semi_implicit_euler(), std::span<const double>(), opt, scr);
  CHECK(ra.cost == Approx(expected).epsilon(1e-12));
  CHECK(rd.cost == Approx(expected).epsilon(1e-12));
}

TEST_CASE("the recorder fills a trajectory every N steps", "[rollout][recorder]") {
  const auto m = sharon2005_human7();
  auto scr = make_rollout_scratch(m);
  auto opt = standing_options(m, 0.5);
  trajectory tr;
  opt.record = &tr;
  opt.record_every = 40;  // 60 frames per second
  opt.pushes = {push{0, vec3(50, 0, 0), 0.1, 0.1}};
  const auto r = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
                         semi_implicit_euler(), standing_pose(m), opt, scr);
  REQUIRE(r.reason == stop_reason::horizon);
  REQUIRE(tr.frames.size() == 31);  // steps 0, 40, ..., 1160 and the final state at 1200
  CHECK(tr.model_name == m.name);
  CHECK(tr.planar);
  CHECK(tr.q_names.size() == static_cast<std::size_t>(m.nq()));
  CHECK(tr.q_names[0] == "root_x");
  CHECK(tr.q_names[3] == m.dofs[0].name);
  CHECK(tr.body_names.size() == static_cast<std::size_t>(m.num_bodies()));
  CHECK(tr.contact_names.size() == m.contact_points.size());
  for (std::size_t i = 0; i < tr.frames.size(); ++i) {
    const auto& f = tr.frames[i];
    CHECK(f.t == Approx(i * 40 * dt));
    CHECK(f.q.size() == m.nq());
    // body 0's recorded position is the root's: x and z of q
    CHECK(f.body_position[0].x() == Approx(f.q[0] + m.bodies[0].joint_offset.x()));
    // pushes are recorded while active, [0.1, 0.2)
    const bool active = f.t >= 0.1 && f.t < 0.2;
    CHECK(f.pushes.size() == (active ? 1u : 0u));
  }
  CHECK(tr.frames[0].q == opt.initial_state.q);
  // contact forces of the standing character carry its weight
  double fz = 0;
  for (const auto& F : tr.frames.back().contact_force) fz += F.z();
  CHECK(fz == Approx(m.total_mass() * 9.81).epsilon(0.05));
  CHECK(tr.terrain.nx > 0);
}

TEST_CASE("rollouts are deterministic and reuse their scratch", "[rollout][determinism]") {
  const auto m = wang2009_humanoid();
  auto scr = make_rollout_scratch(m);
  auto opt = standing_options(m, 0.2);
  opt.pushes = {push{0, vec3(100, 30, 0), 0.05, 0.1}};
  const Eigen::VectorXd p = standing_pose(m);
  const auto a = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
                         semi_implicit_euler(), p, opt, scr);
  const Eigen::VectorXd qa = scr.state.q;
  auto scr2 = make_rollout_scratch(m);
  const auto b =
      rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
              semi_implicit_euler(),
              std::span<const double>(p.data(), static_cast<std::size_t>(p.size())), opt, scr2);
  const auto c = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
                         semi_implicit_euler(), p, opt, scr);  // reused scratch
  CHECK(a.cost == b.cost);
  CHECK(a.cost == c.cost);
  CHECK(qa == scr2.state.q);
  CHECK(qa == scr.state.q);
  CHECK(a.cost < 0.0);  // the push moved it forward
}

TEST_CASE("bad input to a rollout throws std::invalid_argument naming the value",
          "[rollout][bad_input]") {
  const auto m = wang2009_humanoid();
  auto scr = make_rollout_scratch(m);
  const auto good = standing_options(m, 0.01);
  const pd_actuator pd = standing_pd(m, dt);
  const Eigen::VectorXd p = standing_pose(m);
  auto run = [&](const rollout_options& o, const Eigen::VectorXd& params) {
    return rollout(m, pd, pose_hold(m), distance_objective(), flat_terrain(), semi_implicit_euler(),
                   params, o, scr);
  };
  for (double bad : {0.0, -0.001, k_nan, std::numeric_limits<double>::infinity()}) {
    auto o = good;
    o.dt = bad;
    CHECK_THROWS_AS(run(o, p), std::invalid_argument);
  }
  {
    auto o = good;
    o.dt = -0.001;
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("dt") && Catch::Contains("-0.001"));
  }
  {
    auto o = good;
    o.duration = -1;
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("duration") && Catch::Contains("-1"));
  }
  CHECK_THROWS_WITH(run(good, Eigen::VectorXd::Zero(29)), Catch::Contains("expected 30, got 29"));
  {
    Eigen::VectorXd q = p;
    q[3] = k_nan;
    CHECK_THROWS_WITH(run(good, q), Catch::Contains("parameter 3") && Catch::Contains("nan"));
  }
  {
    auto o = good;
    o.initial_state.q.resize(5);
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("initial_state.q") && Catch::Contains("got 5"));
  }
  {
    auto o = good;
    o.initial_state.v[2] = k_nan;
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("initial_state.v"));
  }
  {
    auto o = good;
    trajectory tr;
    o.record = &tr;
    o.record_every = 0;
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("record_every"));
  }
  {
    auto o = good;
    o.pushes = {push{99, vec3(1, 0, 0), 0, 1}};
    CHECK_THROWS_WITH(run(o, p), Catch::Contains("body 99"));
  }
  // A controller that outputs targets cannot drive a torque actuator.
  CHECK_THROWS_WITH(rollout(m, torque_actuator{}, pose_hold(m), distance_objective(),
                            flat_terrain(), semi_implicit_euler(), p, good, scr),
                    Catch::Contains("output kind"));
  // And a good rollout after all that still works with the same scratch.
  CHECK(run(good, p).reason == stop_reason::horizon);
}

namespace {
/// Counts, per step, whether body 1's toe top touched, and any disagreement between the per-body
/// flags, the any-toe flag and the per-body contact counts.
struct toe_top_probe {
  struct accumulator_type {
    int toe_top_steps = 0, foot_toe_top_steps = 0, mismatches = 0;
  };
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void accumulate(accumulator_type& a, const step_view<Root>& v) const {
    bool any = false;
    for (std::size_t b = 0; b < v.toe_top_touching.size(); ++b) {
      if (v.toe_top_touching[b] && v.contact_count[b] == 0) ++a.mismatches;
      any = any || v.toe_top_touching[b];
    }
    if (any != v.toe_top_contact) ++a.mismatches;
    a.toe_top_steps += v.toe_top_touching[1];
    a.foot_toe_top_steps += v.toe_top_touching[0];
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    return a.mismatches == 0 ? a.toe_top_steps - 1e6 * a.foot_toe_top_steps : -1e9;
  }
};
}  // namespace

TEST_CASE("the objective sees which body's toe top touches", "[rollout][objective][contact]") {
  // A foot with a toe on a hinge; the toe's top point is its only toe_top point. Foot flat on the
  // ground: the toe top is 3 cm up and never touches. Toe bent 90 degrees down (its top now faces
  // forward) and the foot tipped forward onto it: the toe top is pressed into the ground.
  model_builder<floating_root> b("foot_and_toe");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal();
  b.add_body({.name = "foot", .mass = 1.0, .inertia = I});
  b.add_body({.name = "toe",
              .parent = "foot",
              .joint_offset = {0.1, 0, -0.03},
              .mass = 0.2,
              .com = {0.03, 0, 0},
              .inertia = 0.1 * I,
              .dofs = {{.name = "toe_y", .axis = {0, 1, 0}}}});
  for (double x : {-0.1, 0.1})
    b.add_contact_point(
        {.name = "heel" + std::to_string(x > 0), .body = "foot", .position = {x, 0, -0.03}});
  b.add_contact_point({.name = "toe_bottom",
                       .body = "toe",
                       .position = {0.06, 0, 0},
                       .role = contact_point::kind::toe});
  b.add_contact_point({.name = "toe_top",
                       .body = "toe",
                       .position = {0.06, 0, 0.03},
                       .role = contact_point::kind::toe_top});
  const floating_model m = b.build();
  auto scr = make_rollout_scratch(m);
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.05;
  opt.detect_falls = false;
  opt.initial_state = make_state(m);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
  const torque_actuator ta;
  const pose_hold passive(m, {.output = command_kind::joint_torque});

  SECTION("flat foot: no toe-top contact") {
    opt.initial_state.q[2] = 0.0299;  // soles 0.1 mm into the ground
    const auto r = rollout(m, ta, passive, toe_top_probe{}, flat_terrain(), semi_implicit_euler(),
                           zero, opt, scr);
    CHECK(r.cost == 0.0);  // no mismatch, no toe-top step
  }
  SECTION("toe bent under: the toe body's flag, not the foot's") {
    // Toe hinge at 90 degrees (toe pointing down, its top facing +x), then the whole foot pitched
    // forward by 90 degrees: the toe's top face is now the lowest point.
    const double half = std::numbers::pi / 4;
    opt.initial_state.q.segment<4>(3) << std::cos(half), 0.0, std::sin(half), 0.0;  // pitch +90
    opt.initial_state.q[7] = std::numbers::pi / 2;
    auto ws = make_workspace(m);
    forward_kinematics(m, ws, opt.initial_state.q);
    double lowest = 1e9;
    int lowest_point = -1;
    for (int k = 0; k < static_cast<int>(m.contact_points.size()); ++k) {
      const double z =
          point_position(m, ws, m.contact_points[k].body, m.contact_points[k].position).z();
      if (z < lowest) lowest = z, lowest_point = k;
    }
    REQUIRE(m.contact_points[lowest_point].role == contact_point::kind::toe_top);
    opt.initial_state.q[2] -= lowest + 0.001;  // toe top 1 mm into the ground
    const auto r = rollout(m, ta, passive, toe_top_probe{}, flat_terrain(), semi_implicit_euler(),
                           zero, opt, scr);
    CHECK(r.cost > 0.0);  // toe-top steps on the toe body, none on the foot, no mismatch
  }
}

namespace {
/// semi_implicit_euler without its evaluates_state_first promise: the rollout must then compare
/// the state with the workspace's cache before every ABA.
struct euler_without_promise : semi_implicit_euler {
  static constexpr bool evaluates_state_first = false;
};
/// Position-first (kick-drift in the other order) Euler: q moves before sys is called on the
/// state vectors themselves, so kinematics of the step's start would be stale. It makes no
/// promise; the rollout must not reuse them.
struct drift_then_kick {
  static constexpr int order = 1;
  Eigen::VectorXd ddq;
  template <root_joint Root>
  void prepare(const model<Root>& m) {
    ddq.setZero(m.nv());
  }
  template <root_joint Root, class Sys>
  void step(const model<Root>& m, sim_state& s, double dt, Sys&& sys) {
    integrate_configuration(m, s.q, s.v, dt, s.q);
    sys(static_cast<const Eigen::VectorXd&>(s.q), static_cast<const Eigen::VectorXd&>(s.v), s.t,
        ddq);
    s.v += dt * ddq;
    s.t += dt;
  }
};
}  // namespace

TEST_CASE("reusing the step's kinematics for ABA changes nothing", "[rollout][integrator]") {
  static_assert(integrator_evaluating_state_first<semi_implicit_euler>);
  static_assert(!integrator_evaluating_state_first<euler_without_promise>);
  static_assert(!integrator_evaluating_state_first<drift_then_kick>);
  const auto run = [](const auto& m, auto integ) {
    auto scr = make_rollout_scratch(m);
    auto opt = standing_options(m, 0.3);
    opt.pushes = {push{0, vec3(150, 40, 0), 0.05, 0.1}};
    const Eigen::VectorXd p = standing_pose(m);
    const rollout_result r = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(),
                                     flat_terrain(), integ, p, opt, scr);
    return std::pair{r, scr.state};
  };
  SECTION("3D humanoid") {
    const auto m = wang2009_humanoid();
    const auto [a, sa] = run(m, semi_implicit_euler());
    const auto [b, sb] = run(m, euler_without_promise());
    CHECK(a.steps == b.steps);
    CHECK(a.cost == b.cost);  // the same arithmetic on the same kinematics: bit-identical
    CHECK(sa.q == sb.q);
    CHECK(sa.v == sb.v);
  }
  SECTION("7-link planar human (planar fast path)") {
    const auto m = sharon2005_human7();
    const auto [a, sa] = run(m, semi_implicit_euler());
    const auto [b, sb] = run(m, euler_without_promise());
    CHECK(a.cost == b.cost);
    CHECK(sa.q == sb.q);
    CHECK(sa.v == sb.v);
  }
  SECTION("an integrator that moves q before evaluating gets fresh kinematics") {
    // Reference: the same drift-then-kick scheme written out with the public algorithms.
    const auto m = sharon2005_human7();
    const auto [r, sr] = run(m, drift_then_kick());
    auto opt = standing_options(m, 0.3);
    opt.pushes = {push{0, vec3(150, 40, 0), 0.05, 0.1}};
    const pd_actuator act = standing_pd(m, dt);
    auto act_state = act.make_state(m);
    const Eigen::VectorXd target = standing_pose(m);
    auto ws = make_workspace(m);
    auto cs = make_contact_state(m);
    sim_state s = opt.initial_state;
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
    for (std::int64_t k = 0; k < r.steps; ++k) {
      s.t = static_cast<double>(k) * dt;
      forward_kinematics(m, ws, s.q, s.v);
      clear_external_wrenches(ws);
      apply_contact_forces(m, ws, flat_terrain(), opt.contact, cs, dt);
      apply_pushes(m, ws, std::span<const push>(opt.pushes), s.t);
      tau.setZero();
      act.torques(m, s, target, act_state, tau.tail(m.num_joint_dofs()));
      joint_limit_torques(m, s.q, s.v, tau);
      integrate_configuration(m, s.q, s.v, dt, s.q);
      s.v += dt * aba(m, ws, s.q, s.v, tau);
    }
    CHECK(sr.q == s.q);
    CHECK(sr.v == s.v);
  }
}
