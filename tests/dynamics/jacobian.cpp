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

TEMPLATE_TEST_CASE("point and orientation Jacobians match finite differences", "[dynamics][jacobian]",
                   planar_root, floating_root, fixed_root) {
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
      REQUIRE_THAT(Eigen::VectorXd(point_velocity(m, ws, body, p)),
                   is_approx(J * v, 1e-12, 1e-12));
      REQUIRE_THAT(Eigen::VectorXd(ws.body_angular_velocity[body]),
                   is_approx(Jr * v, 1e-12, 1e-12));
    }
  }
}
