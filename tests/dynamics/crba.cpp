// CRBA: symmetry, positive definiteness, columns against RNEA, and 0.5 v^T M v = kinetic energy.
#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

TEMPLATE_TEST_CASE("crba is symmetric positive definite and agrees with rnea and the kinetic energy",
                   "[dynamics][crba]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(4321);
  std::mt19937_64 configuration_rng(4321);  // random_configuration takes the portable engine
  for (int trial = 0; trial < 10; ++trial) {
    gaitsynth::testing::random_model_options o;
    o.num_bodies = 2 + trial;
    o.branching = trial % 2 == 1;
    const auto m = gaitsynth::testing::random_model<TestType>(rng, o);
    auto ws = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const Eigen::MatrixXd M = crba(m, ws, q);
    CAPTURE(trial, m.nv());
    REQUIRE(M.rows() == m.nv());
    REQUIRE((M - M.transpose()).cwiseAbs().maxCoeff() == 0.0);  // both triangles written equal
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M);
    REQUIRE(es.eigenvalues().minCoeff() > 0.0);

    // Column i of M is rnea(q, 0, e_i) - rnea(q, 0, 0) (Featherstone eq. 6.1 with v = 0).
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nv());
    const Eigen::VectorXd g = rnea(m, ws, q, zero, zero);
    for (int i = 0; i < m.nv(); ++i) {
      const Eigen::VectorXd col = rnea(m, ws, q, zero, Eigen::VectorXd::Unit(m.nv(), i)) - g;
      REQUIRE_THAT(col, is_approx(M.col(i), 1e-10, 1e-12));
    }
    REQUIRE_THAT(Eigen::VectorXd(gravity_forces(m, ws, q)), is_approx(g, 1e-12, 1e-12));

    // Kinetic energy.
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 2.0);
    forward_kinematics(m, ws, q, v);
    REQUIRE(kinetic_energy(m, ws) == Approx(0.5 * v.dot(M * v)).epsilon(1e-12));
  }
}

TEST_CASE("crba of a single free body is its mass and rotational inertia", "[dynamics][crba]") {
  std::mt19937 rng(5);
  std::mt19937_64 configuration_rng(5);  // random_configuration takes the portable engine
  const mat3 I = gaitsynth::testing::random_inertia(rng, 0.5);
  model_builder<floating_root> b("brick");
  b.add_body({.name = "brick", .mass = 3.0, .inertia = I});
  const auto m = b.build();
  auto ws = make_workspace(m);
  const Eigen::MatrixXd M = crba(m, ws, random_configuration(m, configuration_rng));
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 6);
  expected.topLeftCorner(3, 3) = 3.0 * Eigen::Matrix3d::Identity();
  expected.bottomRightCorner(3, 3) = I;  // body-frame angular velocity: the body-frame inertia
  REQUIRE_THAT(M, is_approx(expected, 1e-12, 1e-14));
}
