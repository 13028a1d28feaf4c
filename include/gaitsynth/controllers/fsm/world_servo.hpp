#pragma once
/// \file controllers/fsm/world_servo.hpp
/// PD servos on a body's world-frame orientation (SIMBICON, Yin et al. 2007; Wang et al. 2009
/// Sec. 3): the swing thigh, the torso and the feet are servoed to world angles
/// (spatial/world_angles.hpp), and the resulting world torque is shared out to the joint DOFs
/// that move the body by the transpose of their axes (tau_j = a_j . tau_world: the generalized
/// force of a torque on the child body, by virtual work).
#include <Eigen/Geometry>
#include <array>

#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/types.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

namespace gaitsynth {

/// World axis of joint DOF j in the current pose: a body with DOFs f..l composed intrinsically
/// (model/model.hpp) has R_world_body = R_world_parent R(a_f, q_f) ... R(a_l, q_l), so the axis
/// of DOF k is R_world_body R(a_l, -q_l) ... R(a_k+1, -q_k+1) a_k.
/// (Reading S_j's angular part from the rollout's kinematics would save the angle-axis products
/// here, but rounds differently, and the saved walkers' Table 1 forces move with the rounding:
/// docs/performance.md, "ABA by joints".)
template <root_joint Root>
vec3 dof_world_axis(const sensors<Root>& s, int j) {
  const model<Root>& m = s.model();
  const joint_dof& d = m.dofs[j];
  const body& b = m.bodies[d.body];
  vec3 a = d.axis;
  for (int i = j + 1; i < b.first_dof + b.num_dofs; ++i)
    a = Eigen::AngleAxisd(-s.joint_angle(i), m.dofs[i].axis) * a;
  return s.body_rotation[d.body] * a;
}

/// Per-axis PD gains and targets of a world-frame servo, indexed coronal (x), sagittal (y),
/// transverse (z) of the heading frame. A zero gain leaves that axis free.
struct world_servo_gains {
  std::array<double, 3> kp{};      ///< N m / rad
  std::array<double, 3> kd{};      ///< N m s / rad
  std::array<double, 3> target{};  ///< rad
};

/// The world torque (N m, world axes) that servos body b's world angles to g.target:
/// per axis kp (target - angle) - kd omega, in the heading frame (heading rad about z).
template <root_joint Root>
vec3 world_servo_torque(const sensors<Root>& s, int b, const world_servo_gains& g,
                        double heading = 0.0) {
  const vec3 w = to_heading_frame(s.body_angular_velocity[b], heading);
  // kp (target - angle) is kp target on an axis without stiffness whatever the angle, so only the
  // angles with a gain are measured (one atan2 each; a foot servo has no transverse gain, the
  // coronal servos of Wang et al. 2012 Sec. 4.4 have one axis of three).
  const mat3& R = s.body_rotation[b];
  const vec3 up = to_heading_frame(R.col(2), heading);
  vec3 t;
  for (int a = 0; a < 3; ++a) {
    double angle = 0.0;
    if (g.kp[a] != 0.0) {
      if (a < 2) {
        angle = a == 0 ? std::atan2(-up.y(), up.z()) : std::atan2(up.x(), up.z());
      } else {
        const vec3 fwd = to_heading_frame(R.col(0), heading);
        angle = std::atan2(fwd.y(), fwd.x());
      }
    }
    t[a] = g.kp[a] * (g.target[a] - angle) - g.kd[a] * w[a];
  }
  return to_heading_frame(t, -heading);
}

}  // namespace gaitsynth
