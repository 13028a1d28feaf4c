#pragma once
/// \file energy.hpp
/// Kinetic and gravitational potential energy (after forward_kinematics with v).
#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

/// Kinetic energy sum_b 0.5 v_b^T I_b v_b = 0.5 v^T M(q) v, J.
/// \throws std::logic_error if the workspace holds no velocities for its current configuration.
template <root_joint Root>
double kinetic_energy(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  if (detail::planar_path(ws) && s.level < 2) {
    detail::require_kinematics(s.planar.level, 2, "kinetic_energy");
    // The planar fast path leaves the 6D scratch stale: 0.5 v^T I v of its planar inertias.
    const auto& P = s.planar;
    double e = 0.0;
    for (int b = 0; b < m.num_bodies(); ++b) {
      const detail::pvec& V = P.V[s.body_node[b]];
      e += 0.5 * V.dot(detail::sym_mul(P.body_I[b], V));
    }
    return e;
  }
  detail::require_kinematics(s.level, 2, "kinetic_energy");
  double e = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b)
    e += 0.5 * detail::sdot(s.V[s.body_node[b]], s.body_momentum[b]);  // v . I v
  return e;
}

/// Gravitational potential energy -sum_b m_b g . c_b (zero at the world origin), J.
/// \throws std::logic_error if the workspace holds no kinematics yet.
template <root_joint Root>
double potential_energy(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  if (detail::planar_path(ws) && s.level < 1) {
    detail::require_kinematics(s.planar.level, 1, "potential_energy");
    const auto& P = s.planar;
    double e = 0.0;
    for (int b = 0; b < m.num_bodies(); ++b)
      e -= P.body_mass[b] * m.gravity.dot(s.ref + P.body_com[b]);
    return e;
  }
  detail::require_kinematics(s.level, 1, "potential_energy");
  double e = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    const spatial::rigid_inertia& I = s.body_inertia[b];
    e -= I.mass * m.gravity.dot(s.ref + I.com);
  }
  return e;
}

/// kinetic_energy + potential_energy. \throws std::logic_error as kinetic_energy.
template <root_joint Root>
double total_energy(const model<Root>& m, const workspace<Root>& ws) {
  return kinetic_energy(m, ws) + potential_energy(m, ws);
}

}  // namespace gaitsynth
