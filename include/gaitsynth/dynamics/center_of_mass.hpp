#pragma once
/// \file center_of_mass.hpp
/// Whole-body centre of mass and its velocity (world frame).
#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

/// Centre of mass of the whole model, world, m (after forward_kinematics).
/// \throws std::logic_error if the workspace holds no kinematics yet.
template <root_joint Root>
vec3 center_of_mass(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  if (detail::planar_path(ws) && s.planar.level >= 1) {
    const auto& P = s.planar;
    vec3 c = vec3::Zero();
    double mass = 0.0;
    for (int b = 0; b < m.num_bodies(); ++b) {
      c += P.body_mass[b] * P.body_com[b];
      mass += P.body_mass[b];
    }
    return s.ref + c / mass;
  }
  detail::require_kinematics(s.level, 1, "center_of_mass");
  vec3 c = vec3::Zero();
  double mass = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    c += s.body_inertia[b].mass * s.body_inertia[b].com;
    mass += s.body_inertia[b].mass;
  }
  return s.ref + c / mass;
}

/// Velocity of the centre of mass, world, m/s (after forward_kinematics with v).
/// \throws std::logic_error if the workspace holds no velocities for its current configuration.
template <root_joint Root>
vec3 com_velocity(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  if (detail::planar_path(ws) && s.planar.level >= 2) {
    // Velocity of the COM c: v + omega x c = (v_x + omega_y c_z, 0, v_z - omega_y c_x).
    const auto& P = s.planar;
    double px = 0.0, pz = 0.0, mass = 0.0;
    for (int b = 0; b < m.num_bodies(); ++b) {
      const detail::pvec& V = P.V[s.body_node[b]];
      const vec3& c = P.body_com[b];
      const double mb = P.body_mass[b];
      px += mb * (V[1] + V[0] * c.z());
      pz += mb * (V[2] - V[0] * c.x());
      mass += mb;
    }
    return vec3(px / mass, 0.0, pz / mass);
  }
  detail::require_kinematics(s.level, 2, "com_velocity");
  // The linear part of each body's spatial momentum I v (kept by update_velocities) is
  // m (v_o + omega x c), its COM velocity times its mass.
  detail::svec p = detail::svec::Zero();
  double mass = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    p += s.body_momentum[b];
    mass += s.body_inertia[b].mass;
  }
  return vec3(detail::lin(p)) / mass;
}

}  // namespace gaitsynth
