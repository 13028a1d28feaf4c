#pragma once
/// \file fingerprint.hpp
/// A 64-bit fingerprint of everything in a model that the dynamics, contact and rollout algorithms
/// read: topology, joint offsets, axes, inertial parameters, limits, contact points and gravity
/// (not names, shapes or nominal lengths, which only the viewers and objectives read).
///
/// Why: per-thread scratch (workspace, contact_state) caches model data at set-up (body masses of
/// the planar path, inverse masses and inertias of the contact damping). A scratch reused for
/// another body of the same size (Sharon 2005's Figure 8 variants: torso 40 -> 28 kg) must be
/// rebuilt, and the model's address cannot tell: a model destroyed and rebuilt in the same stack
/// slot has the same address. prepare_rollout_scratch compares fingerprints instead (FNV-1a over
/// the values' bytes: a few hundred ns, against milliseconds for a rollout).
#include <Eigen/Core>
#include <cstdint>
#include <cstring>

#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

namespace detail {
struct fnv1a {
  std::uint64_t h = 14695981039346656037ull;
  void bytes(const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  }
  void value(double x) { bytes(&x, sizeof x); }
  void value(int x) { bytes(&x, sizeof x); }
  template <class Derived>
  void value(const Eigen::MatrixBase<Derived>& m) {
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) value(static_cast<double>(m(i, j)));
  }
};
}  // namespace detail

/// Fingerprint of m's dynamic content (see the file comment). Equal models give equal values;
/// models that differ in any dynamic quantity differ with overwhelming probability.
template <root_joint Root>
std::uint64_t model_fingerprint(const model<Root>& m) {
  detail::fnv1a f;
  f.value(m.num_bodies());
  f.value(m.num_joint_dofs());
  f.value(static_cast<int>(m.contact_points.size()));
  f.value(m.gravity);
  for (const body& b : m.bodies) {
    f.value(b.parent);
    f.value(b.first_dof);
    f.value(b.num_dofs);
    f.value(b.joint_offset);
    f.value(b.mass);
    f.value(b.com);
    f.value(b.inertia);
  }
  for (const joint_dof& d : m.dofs) {
    f.value(d.body);
    f.value(d.axis);
    f.value(d.limit.lower);
    f.value(d.limit.upper);
    f.value(d.limit.stiffness);
    f.value(d.limit.damping);
    f.value(d.limit.sharpness);
    f.value(static_cast<int>(d.limit.model));
    f.value(d.torque_limit);
  }
  for (const contact_point& c : m.contact_points) {
    f.value(c.body);
    f.value(c.position);
    f.value(static_cast<int>(c.role));
  }
  return f.h;
}

}  // namespace gaitsynth
