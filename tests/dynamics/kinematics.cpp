// Forward kinematics: hand-computed poses, the multi-DOF composition rule, point velocities against
// finite differences in time, and the root conventions.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

namespace {
mat3 rot(const vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }
}  // namespace

TEST_CASE("forward kinematics of a hand-built chain", "[dynamics][kinematics]") {
  model_builder<floating_root> b("chain");
  b.add_body({.name = "pelvis", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  const vec3 a1 = vec3(1, 0, 0), a2 = vec3(0, 1, 1).normalized(), a3 = vec3(0, 0, 1);
  b.add_body({.name = "thigh", .parent = "pelvis", .joint_offset = vec3(0.0, 0.1, -0.1), .mass = 1,
              .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "hx", .axis = a1}, {.name = "hyz", .axis = a2}, {.name = "hz", .axis = a3}}});
  b.add_body({.name = "shin", .parent = "thigh", .joint_offset = vec3(0, 0, -0.4), .mass = 1,
              .inertia = 0.1 * mat3::Identity(), .dofs = {{.name = "knee", .axis = vec3(0, 1, 0)}}});
  const auto m = b.build();
  auto ws = make_workspace(m);
  Eigen::VectorXd q(11);
  const quat r0 = quat(Eigen::AngleAxisd(0.3, vec3(1, 2, 3).normalized()));
  q << 1.0, 2.0, 0.9, r0.w(), r0.x(), r0.y(), r0.z(), 0.2, -0.5, 0.7, 1.1;
  forward_kinematics(m, ws, q);
  const mat3 R0 = r0.toRotationMatrix();
  // Several DOFs in one body compose intrinsically: R = R(a1,q1) R(a2,q2) R(a3,q3) (MuJoCo rule).
  const mat3 R1 = R0 * rot(a1, 0.2) * rot(a2, -0.5) * rot(a3, 0.7);
  const mat3 R2 = R1 * rot(vec3(0, 1, 0), 1.1);
  const vec3 p0(1.0, 2.0, 0.9);
  const vec3 p1 = p0 + R0 * vec3(0, 0.1, -0.1);
  const vec3 p2 = p1 + R1 * vec3(0, 0, -0.4);
  REQUIRE_THAT(Eigen::MatrixXd(ws.body_rotation[0]), is_approx(R0, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::MatrixXd(ws.body_rotation[1]), is_approx(R1, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::MatrixXd(ws.body_rotation[2]), is_approx(R2, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_position[0]), is_approx(p0, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_position[1]), is_approx(p1, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_position[2]), is_approx(p2, 1e-14, 1e-14));
  REQUIRE_THAT(Eigen::VectorXd(point_position(m, ws, 2, vec3(0.1, 0, -0.2))),
               is_approx(p2 + R2 * vec3(0.1, 0, -0.2), 1e-14, 1e-14));
}

TEST_CASE("planar root pose: x, z translation and pitch about +y", "[dynamics][kinematics]") {
  model_builder<planar_root> b("planar");
  b.add_body({.name = "torso", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  b.add_body({.name = "leg", .parent = "torso", .joint_offset = vec3(0, 0, -0.5), .mass = 1,
              .inertia = 0.1 * mat3::Identity(), .dofs = {{.name = "hip"}}});
  const auto m = b.build();
  auto ws = make_workspace(m);
  Eigen::VectorXd q(4), v(4);
  q << 0.5, 1.2, 0.3, -0.4;
  v << 1.0, -0.5, 2.0, 0.7;
  forward_kinematics(m, ws, q, v);
  REQUIRE_THAT(Eigen::VectorXd(ws.body_position[0]), is_approx(vec3(0.5, 0, 1.2), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::MatrixXd(ws.body_rotation[0]), is_approx(rot(vec3::UnitY(), 0.3), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::MatrixXd(ws.body_rotation[1]), is_approx(rot(vec3::UnitY(), -0.1), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_linear_velocity[0]), is_approx(vec3(1.0, 0, -0.5), 1e-15, 1e-15));
  REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[1]), is_approx(vec3(0, 2.7, 0), 1e-15, 1e-15));
}

TEMPLATE_TEST_CASE("body and point velocities are time derivatives of the poses",
                   "[dynamics][kinematics]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(11);
  std::mt19937_64 configuration_rng(11);  // random_configuration takes the portable engine
  for (int trial = 0; trial < 4; ++trial) {
    const auto m = gaitsynth::testing::random_model<TestType>(rng);
    auto ws = make_workspace(m);
    auto ws2 = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv(), 1.5);
    forward_kinematics(m, ws, q, v);
    const double h = 1e-6;
    Eigen::VectorXd qp(m.nq()), qm(m.nq());
    integrate_configuration(m, q, v, h, qp);
    integrate_configuration(m, q, v, -h, qm);
    for (int b = 0; b < m.num_bodies(); ++b) {
      const vec3 p = gaitsynth::testing::random_vec3(rng, 0.2);
      forward_kinematics(m, ws2, qp);
      const vec3 xp = point_position(m, ws2, b, p);
      const mat3 Rp = ws2.body_rotation[b];
      forward_kinematics(m, ws2, qm);
      const vec3 xm = point_position(m, ws2, b, p);
      const mat3 Rm = ws2.body_rotation[b];
      const Eigen::AngleAxisd aa(Rp * Rm.transpose());
      REQUIRE_THAT(Eigen::VectorXd(point_velocity(m, ws, b, p)),
                   is_approx((xp - xm) / (2 * h), 1e-7, 1e-8));
      REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[b]),
                   is_approx(aa.angle() * aa.axis() / (2 * h), 1e-7, 1e-8));
      REQUIRE_THAT(Eigen::VectorXd(ws.body_linear_velocity[b]),
                   is_approx(Eigen::VectorXd(point_velocity(m, ws, b, vec3::Zero())), 1e-15, 1e-15));
    }
  }
}

TEST_CASE("add_point_force stores the torque about the body origin", "[dynamics][kinematics]") {
  std::mt19937 rng(3);
  std::mt19937_64 configuration_rng(3);  // random_configuration takes the portable engine
  const auto m = gaitsynth::testing::random_model<floating_root>(rng);
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, random_configuration(m, configuration_rng));
  clear_external_wrenches(ws);
  const vec3 x = ws.body_position[2] + vec3(0.1, -0.2, 0.3), f(1, 2, 3);
  add_point_force(m, ws, 2, x, f);
  add_point_force(m, ws, 2, x, f);
  vec6 expected;
  expected << 2 * vec3(0.1, -0.2, 0.3).cross(f), 2 * f;
  REQUIRE_THAT(Eigen::VectorXd(ws.f_ext[2]), is_approx(expected, 1e-15, 1e-15));
  clear_external_wrenches(ws);
  for (const auto& w : ws.f_ext) REQUIRE(w.isZero(0.0));
}
