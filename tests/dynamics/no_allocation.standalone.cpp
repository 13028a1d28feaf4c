// No heap allocation after make_workspace: every per-step algorithm and both integrators run with a
// counting global operator new (own test binary, so the replacement affects nothing else).
#include "support/counting_allocations.hpp"  // first: it configures Eigen

#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;

namespace {
template <root_joint Root>
void check_no_allocation(const model<Root>& m, std::mt19937& rng) {
  auto ws = make_workspace(m);
  std::mt19937_64 configuration_rng(rng());  // random_configuration takes the portable engine
  const Eigen::VectorXd q = random_configuration(m, configuration_rng);
  const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv());
  const Eigen::VectorXd tau = gaitsynth::testing::random_vector(rng, m.nv());
  Eigen::VectorXd q2(m.nq()), tau_lim = Eigen::VectorXd::Zero(m.nv());
  Eigen::MatrixXd J(3, m.nv());
  sim_state s{q, v, 0.0};
  semi_implicit_euler se(m);
  odeint_rk4 rk(m);
  auto sys = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv, double,
                 Eigen::VectorXd& ddq) { ddq = aba(m, ws, qq, vv, tau); };

  const long before = g_news.load();
  for (int k = 0; k < 3; ++k) {
    forward_kinematics(m, ws, q);
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    add_point_force(m, ws, m.num_bodies() - 1, ws.body_position.back(), vec3(1, 2, 3));
    aba(m, ws, q, v, tau);
    rnea(m, ws, q, v, tau);
    rnea_with_external(m, ws, q, v, tau);
    nonlinear_effects(m, ws, q, v);
    gravity_forces(m, ws, q);
    crba(m, ws, q);
    point_jacobian(m, ws, q, m.num_bodies() - 1, vec3(0.1, 0, 0), J);
    body_orientation_jacobian(m, ws, q, 0, J);
    (void)center_of_mass(m, ws);
    (void)com_velocity(m, ws);
    (void)centroidal_momentum(m, ws);
    (void)total_energy(m, ws);
    integrate_configuration(m, q, v, 1e-3, q2);
    joint_limit_torques(m, q, v, tau_lim);
    se.step(m, s, 1e-3, sys);
    rk.step(m, s, 1e-3, sys);
  }
  REQUIRE(g_news.load() == before);
}
}  // namespace

TEST_CASE("the counters see allocations (the test is not vacuous)", "[dynamics][allocation]") {
  CHECK(counters_see_allocations());
}

TEMPLATE_TEST_CASE("dynamics algorithms and integrator steps do not allocate",
                   "[dynamics][allocation]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(5);
  check_no_allocation(gaitsynth::testing::random_model<TestType>(rng, {.num_bodies = 7}), rng);
}

TEST_CASE("the planar fast path does not allocate either", "[dynamics][allocation]") {
  std::mt19937 rng(6);
  const auto m = sharon2005_human7();
  REQUIRE(make_workspace(m).scratch.planar.enabled);
  check_no_allocation(m, rng);
}
