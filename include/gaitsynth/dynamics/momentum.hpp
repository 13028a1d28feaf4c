#pragma once
/// \file momentum.hpp
/// Whole-body (centroidal) momentum: linear momentum and angular momentum about the centre of mass,
/// world axes (Orin & Goswami's centroidal momentum; Featherstone 2008, eq. 2.60 summed over
/// bodies).
#include "gaitsynth/dynamics/center_of_mass.hpp"

namespace gaitsynth {

struct momentum {
  vec3 linear = vec3::Zero();   ///< kg m/s, world
  vec3 angular = vec3::Zero();  ///< kg m^2/s, about the COM, world axes
};

/// Centroidal momentum (after forward_kinematics with v).
/// \throws std::logic_error if the workspace holds no velocities for its current configuration.
template <root_joint Root>
momentum centroidal_momentum(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  if (detail::planar_path(ws) && s.level < 2) {
    detail::require_kinematics(s.planar.level, 2, "centroidal_momentum");
    // The planar fast path leaves the 6D scratch stale: sum over bodies from the public outputs
    // (each body's COM velocity v_o + omega x R c and its spin R Ic R^T omega).
    const vec3 com = center_of_mass(m, ws);
    momentum out;
    for (int b = 0; b < m.num_bodies(); ++b) {
      const body& bd = m.bodies[b];
      const mat3& R = ws.body_rotation[b];
      const vec3& w = ws.body_angular_velocity[b];
      const vec3 rc = R * bd.com;
      const vec3 pl = bd.mass * (ws.body_linear_velocity[b] + w.cross(rc));
      out.linear += pl;
      out.angular +=
          R * (bd.inertia * (R.transpose() * w)) + (ws.body_position[b] + rc - com).cross(pl);
    }
    return out;
  }
  detail::require_kinematics(s.level, 2, "centroidal_momentum");
  vec6 h = vec6::Zero();  // about the reference point
  vec3 c = vec3::Zero();
  double mass = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    const spatial::rigid_inertia& I = s.body_inertia[b];
    h += detail::to_vec6(s.body_momentum[b]);  // I v, kept by the velocity pass
    c += I.mass * I.com;
    mass += I.mass;
  }
  c /= mass;
  momentum out;
  out.linear = h.template tail<3>();
  out.angular = h.template head<3>() - c.cross(out.linear);  // shift from the reference to the COM
  return out;
}

}  // namespace gaitsynth
