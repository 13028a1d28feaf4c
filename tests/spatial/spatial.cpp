// Spatial algebra identities (Featherstone 2008, chapter 2).
#include <catch2/catch.hpp>

#include "gaitsynth/spatial/sincos.hpp"
#include "gaitsynth/spatial/spatial.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using namespace gaitsynth::spatial;
using gaitsynth::testing::is_approx;

namespace {
transform random_transform(std::mt19937& rng) {
  std::normal_distribution<double> g;
  const quat r = quat(Eigen::Vector4d(g(rng), g(rng), g(rng), g(rng)).normalized());
  return {r.toRotationMatrix(), gaitsynth::testing::random_vec3(rng, 1.0)};
}
vec6 rv6(std::mt19937& rng) { return gaitsynth::testing::random_vector(rng, 6, 1.0); }
}  // namespace

TEST_CASE("transforms: matrices, inverses, composition and power invariance", "[spatial]") {
  std::mt19937 rng(1);
  for (int i = 0; i < 20; ++i) {
    const transform X = random_transform(rng), Y = random_transform(rng);
    const vec6 m = rv6(rng), f = rv6(rng);
    REQUIRE_THAT(Eigen::VectorXd(X.apply_motion(m)), is_approx(X.motion_matrix() * m, 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::VectorXd(X.apply_force(f)), is_approx(X.force_matrix() * f, 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::MatrixXd(X.force_matrix()),
                 is_approx(X.motion_matrix().inverse().transpose(), 1e-13, 1e-13));
    REQUIRE_THAT(Eigen::VectorXd(X.inverse_motion(X.apply_motion(m))), is_approx(m, 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::VectorXd(X.inverse_force(X.apply_force(f))), is_approx(f, 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::VectorXd(X.inverse().apply_motion(m)), is_approx(X.inverse_motion(m), 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::MatrixXd((Y * X).motion_matrix()),
                 is_approx(Y.motion_matrix() * X.motion_matrix(), 1e-13, 1e-13));
    // Power f . m is frame independent (eq. 2.37).
    REQUIRE(X.apply_force(f).dot(X.apply_motion(m)) == Approx(f.dot(m)).epsilon(1e-13));
  }
}

TEST_CASE("cross products: matrices, duality and the transform rule", "[spatial]") {
  std::mt19937 rng(2);
  for (int i = 0; i < 20; ++i) {
    const vec6 v = rv6(rng), m = rv6(rng), f = rv6(rng);
    REQUIRE_THAT(Eigen::VectorXd(cross_motion(v, m)), is_approx(crm(v) * m, 1e-15, 1e-15));
    REQUIRE_THAT(Eigen::VectorXd(cross_force(v, f)), is_approx(crf(v) * f, 1e-15, 1e-15));
    REQUIRE(cross_motion(v, v).norm() < 1e-15);
    // (v x m) . f = - m . (v x* f)
    REQUIRE(cross_motion(v, m).dot(f) == Approx(-m.dot(cross_force(v, f))).epsilon(1e-13));
    const transform X = random_transform(rng);
    REQUIRE_THAT(Eigen::VectorXd(X.apply_motion(cross_motion(v, m))),
                 is_approx(cross_motion(X.apply_motion(v), X.apply_motion(m)), 1e-13, 1e-13));
  }
}

TEST_CASE("rigid-body inertia: matrix, momentum, energy, transform and sum", "[spatial]") {
  std::mt19937 rng(3);
  for (int i = 0; i < 20; ++i) {
    const rigid_inertia I{2.5, gaitsynth::testing::random_vec3(rng, 0.5),
                          gaitsynth::testing::random_inertia(rng, 0.3)};
    const vec6 v = rv6(rng);
    const mat6 M = I.matrix();
    REQUIRE_THAT(Eigen::MatrixXd(M), is_approx(M.transpose(), 1e-15, 1e-15));
    REQUIRE(Eigen::SelfAdjointEigenSolver<mat6>(M).eigenvalues().minCoeff() > 0);
    REQUIRE_THAT(Eigen::VectorXd(I.momentum(v)), is_approx(M * v, 1e-14, 1e-14));
    REQUIRE(I.kinetic_energy(v) == Approx(0.5 * v.dot(M * v)).epsilon(1e-14));
    // Kinetic energy of the body by integrating over its COM motion: 0.5 m |v_c|^2 + 0.5 w.Ic w.
    const vec3 w = v.head<3>(), vc = v.tail<3>() + w.cross(I.com);
    REQUIRE(I.kinetic_energy(v) ==
            Approx(0.5 * I.mass * vc.squaredNorm() + 0.5 * w.dot(I.inertia_com * w)).epsilon(1e-13));
    // I_A = X^T I_B X with X = B_X_A.
    const transform X = random_transform(rng);
    REQUIRE_THAT(Eigen::MatrixXd(I.transformed_to_parent(X).matrix()),
                 is_approx(X.motion_matrix().transpose() * M * X.motion_matrix(), 1e-13, 1e-13));
    // Inertias add as 6x6 matrices (eq. 2.65).
    const rigid_inertia J{0.7, gaitsynth::testing::random_vec3(rng, 0.5),
                          gaitsynth::testing::random_inertia(rng, 0.2)};
    REQUIRE_THAT(Eigen::MatrixXd((I + J).matrix()), is_approx(M + J.matrix(), 1e-13, 1e-13));
  }
}

TEST_CASE("sincos_batch agrees with libm to rounding and falls back outside its range", "[spatial]") {
  std::mt19937 rng(4);
  for (double range : {0.5, 4.0, 100.0, 1e5, 1e7}) {
    std::uniform_real_distribution<double> u(-range, range);
    std::vector<double> x(2000), s(x.size()), c(x.size());
    for (auto& xi : x) xi = u(rng);
    sincos_batch(x.data(), s.data(), c.data(), static_cast<int>(x.size()));
    for (std::size_t i = 0; i < x.size(); ++i) {
      CAPTURE(x[i]);
      REQUIRE(std::abs(s[i] - std::sin(x[i])) <= 2.3e-16);
      REQUIRE(std::abs(c[i] - std::cos(x[i])) <= 2.3e-16);
    }
  }
  // Quadrant boundaries and special values.
  const double pi = 3.14159265358979323846;
  std::vector<double> x{0.0, pi / 4, pi / 2, 3 * pi / 4, pi, -pi / 2, 2 * pi, 1e300,
                        std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::quiet_NaN()};
  std::vector<double> s(x.size()), c(x.size());
  sincos_batch(x.data(), s.data(), c.data(), static_cast<int>(x.size()));
  for (std::size_t i = 0; i + 2 < x.size(); ++i) {
    REQUIRE(std::abs(s[i] - std::sin(x[i])) <= 2.3e-16);
    REQUIRE(std::abs(c[i] - std::cos(x[i])) <= 2.3e-16);
  }
  REQUIRE(std::isnan(s[8]));
  REQUIRE(std::isnan(c[9]));
}
