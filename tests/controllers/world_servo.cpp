// World-frame servos (controllers/fsm/world_servo.hpp): per axis kp (target - angle) - kd omega
// in the heading frame, checked against the formula written out here, for full servos and for
// servos with free axes (the coronal-only servos of Wang et al. 2012 Sec. 4.4, the feet of Wang et
// al. 2009 without transverse stiffness), whose free axes skip their atan2.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <vector>

#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/wang2009.hpp"
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

TEST_CASE("body_coronal_angle and body_sagittal_angle are body_world_angles' angles to the bit",
          "[spatial]") {
  for (double heading : {0.0, 0.7, -2.1})
    for (double a : {-0.9, -0.1, 0.0, 0.3, 1.2}) {
      const mat3 R = rot(2, heading + 0.2) * rot(1, 0.5 * a) * rot(0, a);
      CHECK(same_bits_unless_fused(body_coronal_angle(R, heading),
                                   body_world_angles(R, heading).coronal));
      CHECK(same_bits_unless_fused(body_sagittal_angle(R, heading),
                                   body_world_angles(R, heading).sagittal));
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
  world_servo_gains foot = full;         // a foot servo: no transverse stiffness
  foot.kp[2] = 0.0;
  world_servo_gains transverse = full;  // the transverse angle alone
  transverse.kp[0] = transverse.kp[1] = 0.0;
  for (double heading : {0.0, 0.4}) {
    for (const world_servo_gains& g : {full, coronal, coronal_damped, foot, transverse}) {
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

TEST_CASE("dof_world_axis: a DOF turns its body about that world axis, the dynamics' axis",
          "[controllers][world_servo]") {
  // Independent of the composition: moving DOF j by d turns its body by d about the DOF's world
  // axis (R_b(q + d e_j) R_b(q)^T is that rotation exactly), read back as angle-axis. The
  // kinematics' motion axis S_j (its angular part) is the same axis to rounding.
  const floating_model m = wang2009_humanoid();
  sim_state st = make_state(m);
  st.q[2] = 1.0;
  const Eigen::Vector4d root = Eigen::Vector4d(0.9, 0.2, -0.3, 0.25).normalized();
  st.q.segment<4>(3) = root;
  const int nj = m.num_joint_dofs();
  for (int j = 0; j < nj; ++j) st.q[floating_root::nq + j] = 0.4 * std::sin(1.7 * j + 0.3);
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, st.q, st.v);
  sensors<floating_root> s{};
  s.model_ptr = &m;
  s.q_ptr = &st.q;
  s.v_ptr = &st.v;
  s.body_rotation = ws.body_rotation;
  auto turned_ws = make_workspace(m);
  const double d = 1e-6;
  for (int j = 0; j < nj; ++j) {
    sim_state turned = st;
    turned.q[floating_root::nq + j] += d;
    forward_kinematics(m, turned_ws, turned.q, turned.v);
    const int b = m.dofs[j].body;
    const Eigen::AngleAxisd turn(turned_ws.body_rotation[b] * ws.body_rotation[b].transpose());
    const vec3 expected = turn.axis() * (turn.angle() / d);
    INFO("DOF " << j << " (" << m.dofs[j].name << ")");
    CHECK((dof_world_axis(s, j) - expected).norm() < 1e-8);
    const vec3 dynamics_axis = detail::ang(ws.scratch.S[static_cast<std::size_t>(j) + 1]);
    CHECK((dof_world_axis(s, j) - dynamics_axis).norm() < 1e-14);
  }
}
