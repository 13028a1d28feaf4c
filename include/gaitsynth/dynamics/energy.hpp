#pragma once
/// \file energy.hpp
/// Kinetic and gravitational potential energy (after forward_kinematics with v).
#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

/// Kinetic energy sum_b 0.5 v_b^T I_b v_b = 0.5 v^T M(q) v, J.
template <root_joint Root>
double kinetic_energy(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  double e = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b)
    e += 0.5 * detail::sdot(s.V[s.body_node[b]], detail::momentum_of(s.body_inertia[b], s.V[s.body_node[b]]));
  return e;
}

/// Gravitational potential energy -sum_b m_b g . c_b (zero at the world origin), J.
template <root_joint Root>
double potential_energy(const model<Root>& m, const workspace<Root>& ws) {
  const auto& s = ws.scratch;
  double e = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    const spatial::rigid_inertia& I = s.body_inertia[b];
    e -= I.mass * m.gravity.dot(s.ref + I.com);
  }
  return e;
}

/// kinetic_energy + potential_energy.
template <root_joint Root>
double total_energy(const model<Root>& m, const workspace<Root>& ws) {
  return kinetic_energy(m, ws) + potential_energy(m, ws);
}

}  // namespace gaitsynth
