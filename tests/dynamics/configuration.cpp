// Configuration operations: quaternion integration with body-frame angular velocity, the
// difference as its inverse, normalization and random configurations.
#include <catch2/catch.hpp>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "gaitsynth/detail/standard_normal.hpp"
#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

TEMPLATE_TEST_CASE("integrate and difference are inverse", "[dynamics][configuration]", planar_root,
                   floating_root, fixed_root) {
  std::mt19937 rng(8);
  std::mt19937_64 configuration_rng(8);  // random_configuration takes the portable engine
  const auto m = gaitsynth::testing::random_model<TestType>(rng);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 1.0);
    Eigen::VectorXd q1(m.nq()), v1(m.nv());
    integrate_configuration(m, q, v, 0.7, q1);
    difference_configuration(m, q, q1, v1);
    REQUIRE_THAT(v1, is_approx(0.7 * v, 1e-12, 1e-12));
    if constexpr (std::is_same_v<TestType, floating_root>)
      REQUIRE(q1.segment<4>(3).norm() == Approx(1.0).epsilon(1e-15));
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
  REQUIRE_THAT(Eigen::VectorXd(ws.body_linear_velocity[0]),
               is_approx(vec3(0.1, 0.2, 0.3), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[0]),
               is_approx(r0.toRotationMatrix() * vec3(0.4, 0, 0), 1e-15, 1e-15));
}

TEST_CASE("normalize_configuration and random_configuration", "[dynamics][configuration]") {
  std::mt19937_64 rng(9);
  model_builder<floating_root> b("limited");
  b.add_body({.name = "pelvis", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  b.add_body({.name = "leg",
              .parent = "pelvis",
              .mass = 1,
              .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "hip", .limit = {.lower = -0.5, .upper = 1.0}},
                       {.name = "knee", .limit = {.lower = -2.0, .upper = 4.0}},
                       {.name = "free"}}});
  const auto m = b.build();
  constexpr double pi = std::numbers::pi;
  for (int i = 0; i < 100; ++i) {
    const Eigen::VectorXd q = random_configuration(m, rng);
    REQUIRE(q.segment<4>(3).norm() == Approx(1.0).epsilon(1e-15));
    REQUIRE(q.head<3>().cwiseAbs().maxCoeff() <= 1.0);
    REQUIRE(q[7] >= -0.5);
    REQUIRE(q[7] <= 1.0);
    REQUIRE(q[8] >= -2.0);  // limit [-2, 4] clipped to [-2, pi]
    REQUIRE(q[8] <= pi);
    REQUIRE(q[9] >= -pi);  // default limits (+-1e9) clipped to [-pi, pi]
    REQUIRE(q[9] <= pi);
  }
  Eigen::VectorXd q = neutral_configuration(m);
  q.segment<4>(3) << 2, 0, 0, 0;
  normalize_configuration(m, q);
  REQUIRE(q.segment<4>(3) == Eigen::Vector4d(1, 0, 0, 0));
  q.segment<4>(3).setZero();
  REQUIRE_THROWS_WITH(normalize_configuration(m, q), Catch::Contains("quaternion has norm 0"));
}

namespace {
/// A root body and one link below it with the DOFs `dofs`: the smallest model whose
/// random_configuration draws are easy to follow.
template <root_joint Root>
model<Root> root_and_link(std::vector<dof_spec> dofs) {
  model_builder<Root> b("root_and_link");
  b.add_body({.name = "root", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  b.add_body({.name = "link",
              .parent = "root",
              .mass = 1,
              .inertia = 0.1 * mat3::Identity(),
              .dofs = std::move(dofs)});
  return b.build();
}
}  // namespace

// random_configuration must give the same numbers for the same seed on every standard library, so
// its values are pinned to the engine's raw output (fixed by the standard) through the documented
// formula u = (raw >> 11) 2^-53, never to a std:: distribution.
TEST_CASE("random_configuration draws are pinned to the engine's raw output",
          "[dynamics][configuration]") {
  constexpr double pi = std::numbers::pi;
  auto uniform01_of = [](std::uint64_t raw) { return static_cast<double>(raw >> 11) * 0x1.0p-53; };

  SECTION("the standard's own check value") {
    // [rand.predef]: the 10000th output of a default-constructed std::mt19937_64 is
    // 9981545732273789042, so this value holds whatever engine implementation is linked.
    const auto m =
        root_and_link<fixed_root>({{.name = "hinge", .limit = {.lower = -0.5, .upper = 1.0}}});
    std::mt19937_64 rng;
    rng.discard(9999);
    const Eigen::VectorXd q = random_configuration(m, rng);
    const double u = uniform01_of(9981545732273789042ull);
    REQUIRE(u == 0x1.150b25eb02fdbp-1);  // 4873801627086811 * 2^-53 = 0.54110067838473...
    REQUIRE(q[0] == -0.5 + 1.5 * u);
  }

  SECTION("planar root: x, z, pitch, then the joints, one raw draw each") {
    const auto m =
        root_and_link<planar_root>({{.name = "hip", .limit = {.lower = -0.5, .upper = 1.0}},
                                    {.name = "knee", .limit = {.lower = -2.5, .upper = 0.0}}});
    std::mt19937_64 rng(2009), raw(2009);
    const Eigen::VectorXd q = random_configuration(m, rng);
    REQUIRE(q[0] == -1.0 + 2.0 * uniform01_of(raw()));
    REQUIRE(q[1] == -1.0 + 2.0 * uniform01_of(raw()));
    REQUIRE(q[2] == pi * (-1.0 + 2.0 * uniform01_of(raw())));
    REQUIRE(q[3] == -0.5 + 1.5 * uniform01_of(raw()));
    REQUIRE(q[4] == -2.5 + 2.5 * uniform01_of(raw()));
    REQUIRE(rng == raw);  // nothing else was drawn
  }

  SECTION("floating root: translation, the shared normal draw for the quaternion, joints") {
    const auto m =
        root_and_link<floating_root>({{.name = "hip", .limit = {.lower = -0.5, .upper = 1.0}}});
    std::mt19937_64 rng(7), raw(7);
    const Eigen::VectorXd q = random_configuration(m, rng);
    for (int i = 0; i < 3; ++i) REQUIRE(q[i] == -1.0 + 2.0 * uniform01_of(raw()));
    // The optimizers' Box-Muller draw (two raw outputs per pair of normals), normalized.
    Eigen::Vector4d gauss;
    detail::fill_standard_normal(raw, gauss);
    const Eigen::Vector4d unit = gauss.normalized();
    REQUIRE(q.segment<4>(3) == unit);
    REQUIRE(q[7] == -0.5 + 1.5 * uniform01_of(raw()));
    REQUIRE(rng == raw);
  }
}
