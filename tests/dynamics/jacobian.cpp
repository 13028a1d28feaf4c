// Point and orientation Jacobians against central finite differences of point_position and of the
// body rotation, perturbing q through integrate_configuration (the floating root's velocity is not
// dq/dt of the quaternion).
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

namespace {
vec3 rotation_vector(const mat3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}
}  // namespace

TEMPLATE_TEST_CASE("point and orientation Jacobians match finite differences",
                   "[dynamics][jacobian]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(77);
  std::mt19937_64 configuration_rng(77);  // random_configuration takes the portable engine
  for (int trial = 0; trial < 6; ++trial) {
    gaitsynth::testing::random_model_options o;
    o.num_bodies = 3 + trial;
    const auto m = gaitsynth::testing::random_model<TestType>(rng, o);
    auto ws = make_workspace(m);
    auto ws2 = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const double h = 1e-6;
    Eigen::MatrixXd J(3, m.nv()), Jr(3, m.nv());
    Eigen::VectorXd qp(m.nq()), qm(m.nq());
    for (int body = 0; body < m.num_bodies(); ++body) {
      const vec3 p = gaitsynth::testing::random_vec3(rng, 0.3);
      point_jacobian(m, ws, q, body, p, J);
      body_orientation_jacobian(m, ws, q, body, Jr);
      Eigen::MatrixXd Jfd(3, m.nv()), Jrfd(3, m.nv());
      for (int i = 0; i < m.nv(); ++i) {
        const Eigen::VectorXd e = Eigen::VectorXd::Unit(m.nv(), i);
        integrate_configuration(m, q, e, h, qp);
        integrate_configuration(m, q, e, -h, qm);
        forward_kinematics(m, ws2, qp);
        const vec3 xp = point_position(m, ws2, body, p);
        const mat3 Rp = ws2.body_rotation[body];
        forward_kinematics(m, ws2, qm);
        const vec3 xm = point_position(m, ws2, body, p);
        const mat3 Rm = ws2.body_rotation[body];
        Jfd.col(i) = (xp - xm) / (2 * h);
        Jrfd.col(i) = rotation_vector(Rp * Rm.transpose()) / (2 * h);  // world-frame rotation
      }
      CAPTURE(trial, body);
      REQUIRE_THAT(J, is_approx(Jfd, 1e-7, 1e-8));
      REQUIRE_THAT(Jr, is_approx(Jrfd, 1e-7, 1e-8));

      // And J v is the point velocity from the velocity kinematics.
      const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv());
      forward_kinematics(m, ws, q, v);
      REQUIRE_THAT(Eigen::VectorXd(point_velocity(m, ws, body, p)), is_approx(J * v, 1e-12, 1e-12));
      REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[body]),
                   is_approx(Jr * v, 1e-12, 1e-12));
    }
  }
}

TEMPLATE_TEST_CASE("relative_point_jacobian is the difference of the two point Jacobians",
                   "[dynamics][jacobian]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(78);
  std::mt19937_64 configuration_rng(78);
  for (int trial = 0; trial < 4; ++trial) {
    gaitsynth::testing::random_model_options o;
    o.num_bodies = 4 + 2 * trial;
    const auto m = gaitsynth::testing::random_model<TestType>(rng, o);
    auto ws = make_workspace(m);
    const Eigen::VectorXd q = random_configuration(m, configuration_rng);
    const int nj = m.num_joint_dofs(), nr = m.nv() - nj;
    Eigen::MatrixXd Jb(3, m.nv()), Jref(3, m.nv()), J(3, nj);
    forward_kinematics(m, ws, q);
    for (int body = 0; body < m.num_bodies(); ++body)
      for (int ref = 0; ref < m.num_bodies(); ++ref) {
        const vec3 p = gaitsynth::testing::random_vec3(rng, 0.3);
        relative_point_jacobian(m, ws, q, body, p, ref, J);
        // The same world point on the reference body.
        const vec3 world = point_position(m, ws, body, p);
        const vec3 p_ref = ws.body_rotation[ref].transpose() * (world - ws.body_position[ref]);
        point_jacobian(m, ws, q, body, p, Jb);
        point_jacobian(m, ws, q, ref, p_ref, Jref);
        CAPTURE(trial, body, ref);
        const Eigen::MatrixXd expected = Jb.rightCols(nj) - Jref.rightCols(nj);
        REQUIRE_THAT(J, is_approx(expected, 1e-12, 1e-12));
        // Joints that both bodies hang from cancel exactly; so do the root's columns (not in J).
        for (int j = 0; j < nj; ++j)
          if (Jb.col(nr + j).squaredNorm() > 0 && Jref.col(nr + j).squaredNorm() > 0)
            REQUIRE(J.col(j).isZero(0.0));
        if (body == ref) REQUIRE(J.isZero(0.0));
      }
  }
  const auto m = gaitsynth::testing::random_model<TestType>(rng, {});
  auto ws = make_workspace(m);
  const Eigen::VectorXd q = neutral_configuration(m);
  Eigen::MatrixXd J(3, m.num_joint_dofs()), wrong(3, m.nv() + 1);
  CHECK_THROWS_WITH(
      relative_point_jacobian(m, ws, q, 0, vec3::Zero(), m.num_bodies(), J),
      Catch::Contains("reference") && Catch::Contains(std::to_string(m.num_bodies())));
  CHECK_THROWS_WITH(relative_point_jacobian(m, ws, q, 0, vec3::Zero(), 0, wrong),
                    Catch::Contains("J must be 3 x"));
}
