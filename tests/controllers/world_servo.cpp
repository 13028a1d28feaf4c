// World-frame servos (controllers/fsm/world_servo.hpp): per axis kp (target - angle) - kd omega
// in the heading frame, checked against the formula written out here, for full servos and for
// the coronal-only servos of Wang et al. 2012 Sec. 4.4, whose free axes skip their atan2.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <vector>

#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "support/same_bits.hpp"

using namespace gaitsynth;
using gaitsynth_test::same_bits_unless_fused;

namespace {
mat3 rot(int axis, double a) {
  return Eigen::AngleAxisd(a, vec3::Unit(axis)).toRotationMatrix();
}

/// The servo's definition with every angle computed.
vec3 servo_by_definition(const mat3& R, const vec3& omega, const world_servo_gains& g,
                         double heading) {
  const world_angles th = body_world_angles(R, heading);
  const vec3 w = to_heading_frame(omega, heading);
  vec3 t;
  for (int a = 0; a < 3; ++a) t[a] = g.kp[a] * (g.target[a] - th[a]) - g.kd[a] * w[a];
  return to_heading_frame(t, -heading);
}
}  // namespace

TEST_CASE("body_coronal_angle is body_world_angles' coronal angle to the bit", "[spatial]") {
  for (double heading : {0.0, 0.7, -2.1})
    for (double a : {-0.9, -0.1, 0.0, 0.3, 1.2}) {
      const mat3 R = rot(2, heading + 0.2) * rot(1, 0.5 * a) * rot(0, a);
      CHECK(same_bits_unless_fused(body_coronal_angle(R, heading),
                                   body_world_angles(R, heading).coronal));
    }
}

TEST_CASE("world servos: full and coronal-only gains give the definition's torque",
          "[controllers][world_servo]") {
  std::vector<mat3> rotations{rot(2, 0.4) * rot(1, -0.3) * rot(0, 0.2)};
  std::vector<vec3> omegas{vec3(0.3, -1.1, 0.6)};
  sensors<floating_root> s{};
  s.body_rotation = rotations;
  s.body_angular_velocity = omegas;
  world_servo_gains full;
  full.kp = {300.0, 500.0, 100.0};
  full.kd = {30.0, 40.0, 10.0};
  full.target = {0.1, -0.2, 0.05};
  world_servo_gains coronal;
  coronal.kp = {400.0, 0.0, 0.0};
  coronal.kd = {0.0, 0.0, 0.0};
  coronal.target = {-0.15, 0.3, 0.0};  // a free axis' target does nothing
  world_servo_gains coronal_damped = coronal;
  coronal_damped.kd = {20.0, 5.0, 2.0};  // damping still acts on the free axes
  for (double heading : {0.0, 0.4}) {
    for (const world_servo_gains& g : {full, coronal, coronal_damped}) {
      const vec3 t = world_servo_torque(s, 0, g, heading);
      const vec3 expected = servo_by_definition(rotations[0], omegas[0], g, heading);
      INFO("heading " << heading << ", kp " << g.kp[0] << " " << g.kp[1] << " " << g.kp[2]);
      // Equal but for the sign of a zero (0 * (target - angle) is -0 or +0 by the angle's sign).
      for (int a = 0; a < 3; ++a) CHECK(same_bits_unless_fused(t[a], expected[a]));
      CHECK(t.norm() > 1.0);
    }
  }
  // The coronal servo's torque lies along the heading frame's x axis plus the damping.
  const vec3 t = world_servo_torque(s, 0, coronal, 0.0);
  CHECK(t.y() == 0.0);
  CHECK(t.z() == 0.0);
}
