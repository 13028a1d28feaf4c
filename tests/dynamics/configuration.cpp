// Configuration operations: quaternion integration with body-frame angular velocity, the
// difference as its inverse, normalization and random configurations.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

TEMPLATE_TEST_CASE("integrate and difference are inverse", "[dynamics][configuration]", planar_root,
                   floating_root, fixed_root) {
  std::mt19937 rng(8);
  const auto m = gaitsynth::testing::random_model<TestType>(rng);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = random_configuration(m, rng);
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 1.0);
    Eigen::VectorXd q1(m.nq()), v1(m.nv());
    integrate_configuration(m, q, v, 0.7, q1);
    difference_configuration(m, q, q1, v1);
    REQUIRE_THAT(v1, is_approx(0.7 * v, 1e-12, 1e-12));
    if constexpr (std::is_same_v<TestType, floating_root>) REQUIRE(q1.segment<4>(3).norm() == Approx(1.0).epsilon(1e-15));
    // In place.
    Eigen::VectorXd q2 = q;
    integrate_configuration(m, q2, v, 0.7, q2);
    REQUIRE(q2 == q1);
  }
}

TEST_CASE("floating root: body-frame angular velocity rotates about the body axes",
          "[dynamics][configuration]") {
  model_builder<floating_root> b("brick");
  b.add_body({.name = "brick", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  const auto m = b.build();
  Eigen::VectorXd q(7), v(6), q1(7);
  const quat r0(Eigen::AngleAxisd(0.5, vec3(0, 0, 1)));
  q << 1, 2, 3, r0.w(), r0.x(), r0.y(), r0.z();
  v << 0.1, 0.2, 0.3, 0.4, 0.0, 0.0;  // spin about the body x axis
  integrate_configuration(m, q, v, 2.0, q1);
  const quat expected = r0 * quat(Eigen::AngleAxisd(0.8, vec3(1, 0, 0)));
  REQUIRE_THAT(Eigen::VectorXd(q1.head<3>()), is_approx(vec3(1.2, 2.4, 3.6), 1e-15, 1e-15));
  REQUIRE(std::abs(quat(q1[3], q1[4], q1[5], q1[6]).dot(expected)) == Approx(1.0).epsilon(1e-14));
  REQUIRE(q1[3] == Approx(expected.w()).epsilon(1e-14));
  // Translation velocity is in world axes, independent of the orientation.
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, q, v);
  REQUIRE_THAT(Eigen::VectorXd(ws.body_linear_velocity[0]), is_approx(vec3(0.1, 0.2, 0.3), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[0]),
               is_approx(r0.toRotationMatrix() * vec3(0.4, 0, 0), 1e-15, 1e-15));
}

TEST_CASE("normalize_configuration and random_configuration", "[dynamics][configuration]") {
  std::mt19937 rng(9);
  model_builder<floating_root> b("limited");
  b.add_body({.name = "pelvis", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  b.add_body({.name = "leg", .parent = "pelvis", .mass = 1, .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "hip", .limit = {.lower = -0.5, .upper = 1.0}}}});
  const auto m = b.build();
  for (int i = 0; i < 100; ++i) {
    const Eigen::VectorXd q = random_configuration(m, rng);
    REQUIRE(q.segment<4>(3).norm() == Approx(1.0).epsilon(1e-15));
    REQUIRE(q[7] >= -0.5);
    REQUIRE(q[7] <= 1.0);
  }
  Eigen::VectorXd q = neutral_configuration(m);
  q.segment<4>(3) << 2, 0, 0, 0;
  normalize_configuration(m, q);
  REQUIRE(q.segment<4>(3) == Eigen::Vector4d(1, 0, 0, 0));
  q.segment<4>(3).setZero();
  REQUIRE_THROWS_WITH(normalize_configuration(m, q), Catch::Contains("quaternion has norm 0"));
}
