// Centre of mass, centroidal momentum and energy: finite differences in time, conservation laws in
// free flight, and the energy budget of passive motion integrated with RK4.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

TEMPLATE_TEST_CASE("com_velocity is d/dt center_of_mass and momentum.linear = m com_velocity",
                   "[dynamics][com]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(21);
  std::mt19937_64 configuration_rng(21);  // random_configuration takes the portable engine
  for (int trial = 0; trial < 5; ++trial) {
    const auto m = gaitsynth::testing::random_model<TestType>(rng);
    auto ws = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 1.5);
    const double h = 1e-6;
    Eigen::VectorXd qp(m.nq()), qm(m.nq());
    integrate_configuration(m, q, v, h, qp);
    integrate_configuration(m, q, v, -h, qm);
    forward_kinematics(m, ws, qp);
    const vec3 cp = center_of_mass(m, ws);
    forward_kinematics(m, ws, qm);
    const vec3 cm = center_of_mass(m, ws);
    forward_kinematics(m, ws, q, v);
    REQUIRE_THAT(Eigen::VectorXd(com_velocity(m, ws)), is_approx((cp - cm) / (2 * h), 1e-7, 1e-8));
    const momentum hm = centroidal_momentum(m, ws);
    REQUIRE_THAT(Eigen::VectorXd(hm.linear),
                 is_approx(m.total_mass() * com_velocity(m, ws), 1e-12, 1e-12));
    // COM by its definition.
    vec3 c = vec3::Zero();
    for (int b = 0; b < m.num_bodies(); ++b)
      c += m.bodies[b].mass * point_position(m, ws, b, m.bodies[b].com);
    REQUIRE_THAT(Eigen::VectorXd(center_of_mass(m, ws)), is_approx(c / m.total_mass(), 1e-13, 1e-13));
  }
}

TEST_CASE("momentum changes at the rate of the external forces (Newton-Euler for the whole body)",
          "[dynamics][momentum]") {
  // d/dt h_linear = m g + sum f;  d/dt h_angular(COM) = sum of external moments about the COM.
  std::mt19937 rng(31);
  std::mt19937_64 configuration_rng(31);  // random_configuration takes the portable engine
  // At most 2 DOFs per body: three hinges in one body have gimbal-lock configurations where M(q)
  // is singular and accelerations (and finite differences) blow up.
  gaitsynth::testing::random_model_options o;
  o.max_dofs_per_body = 2;
  for (int trial = 0; trial < 5; ++trial) {
    const auto m = gaitsynth::testing::random_model<floating_root>(rng, o);
    auto ws = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 1.5);
    const Eigen::VectorXd tau = gaitsynth::testing::random_vector(rng, m.nv(), 5.0);
    Eigen::VectorXd tau_int = tau;
    tau_int.head<6>().setZero();  // internal joint torques only
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    const vec3 f(10, -5, 30);
    const vec3 x = point_position(m, ws, 1, vec3(0.1, 0.1, 0.1));
    add_point_force(m, ws, 1, x, f);
    const vec3 com = center_of_mass(m, ws);
    const Eigen::VectorXd ddq = aba(m, ws, q, v, tau_int);
    const double h = 1e-5;
    auto mom_at = [&](double s) {
      Eigen::VectorXd qs(m.nq());
      const Eigen::VectorXd vs = v + s * ddq;
      // Second-order accurate state at time s along the trajectory.
      integrate_configuration(m, q, v + 0.5 * s * ddq, s, qs);
      auto w = make_workspace(m);
      forward_kinematics(m, w, qs, vs);
      return centroidal_momentum(m, w);
    };
    const momentum hp = mom_at(h), hmn = mom_at(-h);
    const vec3 dlin = (hp.linear - hmn.linear) / (2 * h);
    const vec3 dang = (hp.angular - hmn.angular) / (2 * h);
    REQUIRE_THAT(Eigen::VectorXd(dlin), is_approx(m.total_mass() * m.gravity + f, 1e-6, 1e-6));
    REQUIRE_THAT(Eigen::VectorXd(dang), is_approx((x - com).cross(f), 1e-6, 1e-6));
  }
}

namespace {
template <root_joint Root>
auto passive_system(const model<Root>& m, workspace<Root>& ws, const Eigen::VectorXd& tau) {
  return [&m, &ws, &tau](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double,
                         Eigen::VectorXd& ddq) { ddq = aba(m, ws, q, v, tau); };
}
}  // namespace

TEST_CASE("momentum is conserved in free flight without gravity (RK4)", "[dynamics][momentum]") {
  std::mt19937 rng(41);
  std::mt19937_64 configuration_rng(41);  // random_configuration takes the portable engine
  gaitsynth::testing::random_model_options o;
  o.num_bodies = 6;
  auto m = gaitsynth::testing::random_model<floating_root>(rng, o);
  m.gravity.setZero();
  auto ws = make_workspace(m);
  sim_state s{random_configuration(m, configuration_rng),
              gaitsynth::testing::random_vector(rng, m.nv(), 2.0), 0};
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  forward_kinematics(m, ws, s.q, s.v);
  const momentum h0 = centroidal_momentum(m, ws);
  const vec3 c0 = center_of_mass(m, ws);
  odeint_rk4 rk(m);
  auto sys = passive_system(m, ws, tau);
  const double dt = 1e-3;
  for (int k = 0; k < 2000; ++k) rk.step(m, s, dt, sys);
  forward_kinematics(m, ws, s.q, s.v);
  const momentum h1 = centroidal_momentum(m, ws);
  const double scale = std::max(1.0, h0.angular.norm());
  REQUIRE((h1.linear - h0.linear).norm() <= 1e-9 * std::max(1.0, h0.linear.norm()));
  REQUIRE((h1.angular - h0.angular).norm() <= 1e-7 * scale);
  // The COM moves uniformly.
  REQUIRE_THAT(Eigen::VectorXd(center_of_mass(m, ws)),
               is_approx(c0 + s.t * h0.linear / m.total_mass(), 1e-9, 1e-9));
}

TEMPLATE_TEST_CASE("total energy drifts < 1e-6 (relative) over 10 s of passive motion with RK4",
                   "[dynamics][energy]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(51);
  std::mt19937_64 configuration_rng(51);  // random_configuration takes the portable engine
  gaitsynth::testing::random_model_options o;
  o.num_bodies = 5;
  o.max_dofs_per_body = 2;  // no gimbal lock on the way (see above)
  const auto m = gaitsynth::testing::random_model<TestType>(rng, o);
  auto ws = make_workspace(m);
  sim_state s{random_configuration(m, configuration_rng),
              gaitsynth::testing::random_vector(rng, m.nv(), 1.0), 0};
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  forward_kinematics(m, ws, s.q, s.v);
  const double e0 = total_energy(m, ws);
  // Energy scale: kinetic + the potential swing of the bodies over the motion (m g l).
  const double scale = kinetic_energy(m, ws) + m.total_mass() * m.gravity.norm() * 1.0;
  odeint_rk4 rk(m);
  auto sys = passive_system(m, ws, tau);
  const double dt = 5e-4;
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    rk.step(m, s, dt, sys);
    if (k % 100 == 99) {
      forward_kinematics(m, ws, s.q, s.v);
      worst = std::max(worst, std::abs(total_energy(m, ws) - e0) / scale);
    }
  }
  CAPTURE(worst, e0, scale);
  REQUIRE(s.t == Approx(10.0));
  REQUIRE(worst < 1e-6);
}

TEST_CASE("potential energy is -m g . com", "[dynamics][energy]") {
  std::mt19937 rng(61);
  std::mt19937_64 configuration_rng(61);  // random_configuration takes the portable engine
  const auto m = gaitsynth::testing::random_model<floating_root>(rng);
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, random_configuration(m, configuration_rng),
                     Eigen::VectorXd::Zero(m.nv()));
  REQUIRE(potential_energy(m, ws) ==
          Approx(-m.total_mass() * m.gravity.dot(center_of_mass(m, ws))).epsilon(1e-12));
  REQUIRE(kinetic_energy(m, ws) == 0.0);
}
