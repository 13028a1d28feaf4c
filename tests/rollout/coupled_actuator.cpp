// Actuator dynamics integrated with the rigid body (actuators/concept.hpp, derivative): on a
// pendulum driven through a first-order lag (tau = z, dz/dt = (u(q, v) - z) / T, so the actuator
// state and the body feed back on each other), the coupled system converges at the integrator's
// order against a reference with a 64 times smaller step: 4 for RK4, 1 for semi-implicit Euler.
// The same actuator stepped outside the integrator (advance, after the physics step) drags RK4
// down to first order, which is what the coupling fixes.
#include <catch2/catch.hpp>

#include <cmath>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

model<fixed_root> pendulum() {
  model_builder<fixed_root> b("pendulum");
  b.add_body({.name = "base", .mass = 1, .inertia = mat3::Identity()});
  b.add_body({.name = "arm",
              .parent = "base",
              .mass = 2,
              .com = vec3(0, 0, -0.5),
              .inertia = 0.05 * mat3::Identity(),
              .dofs = {{.name = "hinge", .axis = vec3(0, 1, 0)}}});
  return b.build();
}

/// tau = z; dz/dt = (u - z) / T with u = -kp q - kd qdot (a servo behind a first-order lag).
/// Integrated with the body (derivative) or by itself after each physics step (advance).
template <bool Coupled>
struct lagged_servo {
  using state_type = Eigen::VectorXd;
  double T = 0.05, kp = 40.0, kd = 4.0;
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return Eigen::VectorXd::Constant(m.num_joint_dofs(), 1.0);
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_torque; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
               const state_type& z, Eigen::Ref<Eigen::VectorXd> tau) const {
    tau = z;
  }
  template <root_joint Root>
  void derivative(const model<Root>&, const sim_state& s, Eigen::Ref<const Eigen::VectorXd>,
                  const state_type& z, state_type& dz) const requires Coupled {
    dz[0] = (-kp * s.q[Root::nq] - kd * s.v[Root::nv] - z[0]) / T;
  }
  template <root_joint Root>
  void advance(const model<Root>&, const sim_state& s, Eigen::Ref<const Eigen::VectorXd>,
               state_type& z, double h) const requires(!Coupled) {
    z[0] += h * (-kp * s.q[Root::nq] - kd * s.v[Root::nv] - z[0]) / T;
  }
};

struct no_command {
  struct state_type {};
  std::size_t num_parameters() const { return 0; }
  void bind(std::span<const double> p) { check_parameters(p, 0, "no_command"); }
  double period() const { return 0.0; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <class S>
  void command(const S&, state_type&, Eigen::Ref<Eigen::VectorXd> cmd) const {
    cmd.setZero();
  }
};

struct nothing {
  struct accumulator_type {};
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type&, const View&) const {}
  double finish(const accumulator_type&, const rollout_outcome&) const { return 0.0; }
};

struct final_state {
  Eigen::VectorXd q, v, z;
};

/// (q, v, z) after 1 s from q = 0.6 rad, at rest, actuator state 1 N m.
template <bool Coupled, class Integrator>
final_state run(double dt) {
  const auto m = pendulum();
  rollout_options o;
  o.dt = dt;
  o.duration = 1.0;
  o.detect_falls = false;
  o.initial_state = make_state(m);
  o.initial_state.q[0] = 0.6;
  auto scr = make_rollout_scratch(m);
  using A = lagged_servo<Coupled>;
  rollout_policy_states<A, no_command, nothing> states;
  no_command c;
  Integrator integ;
  const auto r = rollout(m, A{}, c, nothing{}, flat_terrain(-10.0), integ,
                         std::span<const double>(), o, scr, states);
  REQUIRE(r.reason == stop_reason::horizon);
  REQUIRE(r.time == Approx(1.0).epsilon(1e-12));
  return {scr.state.q, scr.state.v, *states.actuator};
}

double distance(const final_state& a, const final_state& b) {
  return (a.q - b.q).cwiseAbs().maxCoeff() + (a.v - b.v).cwiseAbs().maxCoeff() +
         (a.z - b.z).cwiseAbs().maxCoeff();
}

}  // namespace

static_assert(actuator_with_continuous_state<lagged_servo<true>, fixed_root>);
static_assert(!actuator_with_continuous_state<lagged_servo<false>, fixed_root>);
static_assert(integrator_with_first_order_state<odeint_rk4, fixed_root>);
static_assert(integrator_with_first_order_state<semi_implicit_euler, fixed_root>);

TEST_CASE("actuator dynamics integrated with the body converge at the integrator's order",
          "[rollout][actuator_state][integrators]") {
  const final_state ref = run<true, odeint_rk4>(1.0 / 6400.0);
  REQUIRE(std::abs(ref.q[0] - 0.6) > 0.1);  // the servo moved the arm: the test has content
  SECTION("RK4: fourth order for the coupled system") {
    const double e1 = distance(run<true, odeint_rk4>(1.0 / 50.0), ref);
    const double e2 = distance(run<true, odeint_rk4>(1.0 / 100.0), ref);
    const double e3 = distance(run<true, odeint_rk4>(1.0 / 200.0), ref);
    CAPTURE(e1, e2, e3);
    CHECK(e1 / e2 == Approx(16.0).epsilon(0.2));
    CHECK(e2 / e3 == Approx(16.0).epsilon(0.2));
  }
  SECTION("semi-implicit Euler: first order, the rigid body's order kept") {
    const double e1 = distance(run<true, semi_implicit_euler>(1.0 / 400.0), ref);
    const double e2 = distance(run<true, semi_implicit_euler>(1.0 / 800.0), ref);
    const double e3 = distance(run<true, semi_implicit_euler>(1.0 / 1600.0), ref);
    CAPTURE(e1, e2, e3);
    CHECK(e1 / e2 == Approx(2.0).epsilon(0.1));
    CHECK(e2 / e3 == Approx(2.0).epsilon(0.1));
  }
  SECTION("stepped outside the integrator, RK4 falls to first order") {
    const double e1 = distance(run<false, odeint_rk4>(1.0 / 400.0), ref);
    const double e2 = distance(run<false, odeint_rk4>(1.0 / 800.0), ref);
    CAPTURE(e1, e2);
    CHECK(e1 / e2 == Approx(2.0).epsilon(0.15));
  }
}
