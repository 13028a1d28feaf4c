// Bad input gives std::invalid_argument naming the value.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;

TEST_CASE("wrong-sized q, v, tau, a and Jacobians are rejected with the sizes", "[dynamics][errors]") {
  std::mt19937 rng(1);
  std::mt19937_64 configuration_rng(1);  // random_configuration takes the portable engine
  const auto m = gaitsynth::testing::random_model<floating_root>(rng);
  auto ws = make_workspace(m);
  const Eigen::VectorXd q = random_configuration(m, configuration_rng);
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(m.nv());
  const Eigen::VectorXd bad(3);
  using Catch::Contains;
  const std::string nv = std::to_string(m.nv()), nq = std::to_string(m.nq());
  REQUIRE_THROWS_AS(aba(m, ws, bad, v, v), std::invalid_argument);
  REQUIRE_THROWS_WITH(aba(m, ws, bad, v, v), Contains("q (generalized positions): wrong size, expected " + nq + ", got 3"));
  REQUIRE_THROWS_WITH(aba(m, ws, q, bad, v), Contains("v (generalized velocities): wrong size, expected " + nv + ", got 3"));
  REQUIRE_THROWS_WITH(aba(m, ws, q, v, bad), Contains("tau (generalized forces): wrong size, expected " + nv + ", got 3"));
  REQUIRE_THROWS_WITH(rnea(m, ws, q, v, bad), Contains("a (generalized accelerations)"));
  REQUIRE_THROWS_WITH(crba(m, ws, bad), Contains("got 3"));
  REQUIRE_THROWS_WITH(forward_kinematics(m, ws, q, bad), Contains("got 3"));
  REQUIRE_THROWS_WITH(nonlinear_effects(m, ws, bad, v), Contains("got 3"));
  Eigen::MatrixXd J(3, 2);
  REQUIRE_THROWS_WITH(point_jacobian(m, ws, q, 1, vec3::Zero(), J), Contains("J: wrong size, expected 3 x " + nv + ", got 3 x 2"));
  J.resize(3, m.nv());
  REQUIRE_THROWS_WITH(point_jacobian(m, ws, q, 99, vec3::Zero(), J), Contains("body index 99"));
  Eigen::VectorXd out(2);
  REQUIRE_THROWS_WITH(integrate_configuration(m, q, v, 0.1, out), Contains("q_out"));

  // A workspace made for another model.
  const auto other = gaitsynth::testing::random_model<floating_root>(rng, {.num_bodies = 2});
  auto ws_other = make_workspace(other);
  REQUIRE_THROWS_WITH(aba(m, ws_other, q, v, v), Contains("workspace was made for a model with 2 bodies"));
}

TEMPLATE_TEST_CASE("integrators reject non-finite and non-positive dt, naming it",
                   "[integrators][errors]", semi_implicit_euler, odeint_rk4) {
  std::mt19937 rng(2);
  const auto m = gaitsynth::testing::random_model<planar_root>(rng, {.num_bodies = 3});
  auto ws = make_workspace(m);
  sim_state s = make_state(m);
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double, Eigen::VectorXd& ddq) {
    ddq = aba(m, ws, q, v, tau);
  };
  TestType integ(m);
  using Catch::Contains;
  for (double dt : {0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(),
                    std::numeric_limits<double>::infinity()}) {
    CAPTURE(dt);
    REQUIRE_THROWS_AS(integ.step(m, s, dt, sys), std::invalid_argument);
    REQUIRE_THROWS_WITH(integ.step(m, s, dt, sys), Contains("dt (time step, s) must be finite and > 0, got"));
  }
  REQUIRE_THROWS_WITH(integ.step(m, s, -2.5, sys), Contains("got -2.5"));
  sim_state wrong{Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(m.nv()), 0};
  REQUIRE_THROWS_WITH(integ.step(m, wrong, 1e-3, sys), Contains("state.q (generalized positions): wrong size"));
  REQUIRE(s.t == 0.0);  // nothing happened
}
