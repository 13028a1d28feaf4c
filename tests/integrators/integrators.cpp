// Integrators: the concept, convergence orders on an analytic oscillator and on a tumbling
// floating-root model (quaternion path), time bookkeeping.
#include <catch2/catch.hpp>
#include <cmath>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;

static_assert(integrator<semi_implicit_euler, planar_root>);
static_assert(integrator<semi_implicit_euler, floating_root>);
static_assert(integrator<semi_implicit_euler, fixed_root>);
static_assert(integrator<odeint_rk4, planar_root>);
static_assert(integrator<odeint_rk4, floating_root>);
static_assert(integrator<odeint_rk4, fixed_root>);
static_assert(!integrator<int, planar_root>);

namespace {
model<fixed_root> one_dof_model() {
  model_builder<fixed_root> b("oscillator");
  b.add_body({.name = "base", .mass = 1, .inertia = mat3::Identity()});
  b.add_body({.name = "arm", .parent = "base", .mass = 1, .inertia = mat3::Identity(),
              .dofs = {{.name = "x"}}});
  return b.build();
}

/// |q(T) - exact| for the oscillator ddq = -w^2 q, q(0) = 1, v(0) = 0, integrated with step dt.
template <class I>
double oscillator_error(double dt) {
  const auto m = one_dof_model();
  const double w = 2.0, T = 1.0;
  sim_state s = make_state(m);
  s.q[0] = 1.0;
  I integ(m);
  auto sys = [w](const Eigen::VectorXd& q, const Eigen::VectorXd&, double, Eigen::VectorXd& ddq) {
    ddq[0] = -w * w * q[0];
  };
  const int n = static_cast<int>(std::lround(T / dt));
  for (int k = 0; k < n; ++k) integ.step(m, s, dt, sys);
  REQUIRE(s.t == Approx(T).epsilon(1e-12));
  return std::abs(s.q[0] - std::cos(w * T)) + std::abs(s.v[0] + w * std::sin(w * T));
}

/// Final state of a tumbling, articulated free body (no gravity) after T with step dt.
template <class I>
sim_state tumble(double dt, double T) {
  std::mt19937 rng(17);
  std::mt19937_64 configuration_rng(17);  // random_configuration takes the portable engine
  auto m = gaitsynth::testing::random_model<floating_root>(rng, {.num_bodies = 4});
  m.gravity = vec3(0, 0, -9.81);
  auto ws = make_workspace(m);
  sim_state s{random_configuration(m, configuration_rng),
              gaitsynth::testing::random_vector(rng, m.nv(), 3.0), 0};
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double, Eigen::VectorXd& ddq) {
    ddq = aba(m, ws, q, v, tau);
  };
  I integ(m);
  const int n = static_cast<int>(std::lround(T / dt));
  for (int k = 0; k < n; ++k) integ.step(m, s, dt, sys);
  return s;
}

double state_distance(const sim_state& a, const sim_state& b) {
  // Quaternion sign is irrelevant here (small steps keep the same hemisphere).
  return (a.q - b.q).cwiseAbs().maxCoeff() + (a.v - b.v).cwiseAbs().maxCoeff();
}
}  // namespace

TEST_CASE("semi-implicit Euler converges at first order", "[integrators]") {
  const double e1 = oscillator_error<semi_implicit_euler>(1e-3);
  const double e2 = oscillator_error<semi_implicit_euler>(5e-4);
  const double e3 = oscillator_error<semi_implicit_euler>(2.5e-4);
  CAPTURE(e1, e2, e3);
  REQUIRE(e1 / e2 == Approx(2.0).epsilon(0.05));
  REQUIRE(e2 / e3 == Approx(2.0).epsilon(0.05));
}

TEST_CASE("odeint RK4 converges at fourth order", "[integrators]") {
  const double e1 = oscillator_error<odeint_rk4>(4e-2);
  const double e2 = oscillator_error<odeint_rk4>(2e-2);
  CAPTURE(e1, e2);
  REQUIRE(e1 / e2 == Approx(16.0).epsilon(0.1));
}

TEST_CASE("orders hold on a tumbling floating-root tree (quaternion integration)", "[integrators]") {
  const double T = 0.5;
  const sim_state ref = tumble<odeint_rk4>(1e-4, T);
  const double se1 = state_distance(tumble<semi_implicit_euler>(2e-3, T), ref);
  const double se2 = state_distance(tumble<semi_implicit_euler>(1e-3, T), ref);
  const double rk1 = state_distance(tumble<odeint_rk4>(1e-2, T), ref);
  const double rk2 = state_distance(tumble<odeint_rk4>(5e-3, T), ref);
  CAPTURE(se1, se2, rk1, rk2);
  REQUIRE(se1 / se2 == Approx(2.0).epsilon(0.15));
  REQUIRE(rk1 / rk2 == Approx(16.0).epsilon(0.25));
  const sim_state s = tumble<semi_implicit_euler>(1e-3, T);
  REQUIRE(s.q.segment<4>(3).norm() == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("integrators pass time to the system and advance it", "[integrators]") {
  const auto m = one_dof_model();
  sim_state s = make_state(m);
  s.t = 2.0;
  std::vector<double> seen;
  auto sys = [&](const Eigen::VectorXd&, const Eigen::VectorXd&, double t, Eigen::VectorXd& ddq) {
    seen.push_back(t);
    ddq.setZero();
  };
  semi_implicit_euler se(m);
  se.step(m, s, 0.1, sys);
  REQUIRE(seen == std::vector<double>{2.0});
  REQUIRE(s.t == Approx(2.1));
  seen.clear();
  odeint_rk4 rk(m);
  rk.step(m, s, 0.1, sys);
  REQUIRE(seen.size() == 4);  // classic RK4: t, t + h/2, t + h/2, t + h
  REQUIRE(seen[0] == Approx(2.1));
  REQUIRE(seen[1] == Approx(2.15));
  REQUIRE(seen[3] == Approx(2.2));
  REQUIRE(s.t == Approx(2.2));
}
