#pragma once
/// \file standing.hpp
/// Geometry of a character in its neutral pose (q = 0), without the dynamics module: every body
/// frame has its parent's orientation at q = 0 (model.hpp), so a body origin is the sum of the
/// joint offsets along its chain. Used to stand a character on the ground and by the tests that
/// measure standing height.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

/// Body origins (root frame = world frame at the identity root pose) at q = 0.
template <root_joint Root>
std::vector<Eigen::Vector3d> neutral_body_origins(const model<Root>& m) {
  std::vector<Eigen::Vector3d> o(m.bodies.size(), Eigen::Vector3d::Zero());
  for (int i = 1; i < m.num_bodies(); ++i) o[i] = o[m.bodies[i].parent] + m.bodies[i].joint_offset;
  return o;
}

/// Lowest contact point at q = 0, root frame (m). Throws if the model has no contact points.
template <root_joint Root>
double neutral_lowest_contact(const model<Root>& m) {
  check_argument(!m.contact_points.empty(), "model '", m.name, "' has no contact points");
  const auto o = neutral_body_origins(m);
  double zmin = std::numeric_limits<double>::infinity();
  for (const contact_point& c : m.contact_points)
    zmin = std::min(zmin, o[c.body].z() + c.position.z());
  return zmin;
}

/// Standing height at q = 0: the highest body origin or segment end (the head's segment end is
/// the vertex) above the lowest contact point (the sole), m.
template <root_joint Root>
double standing_height(const model<Root>& m) {
  const auto o = neutral_body_origins(m);
  double zmax = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.num_bodies(); ++i)
    zmax = std::max({zmax, o[i].z(), o[i].z() + m.bodies[i].segment_end.z()});
  return zmax - neutral_lowest_contact(m);
}

/// The neutral configuration (all joint angles 0, upright) lifted so that the lowest contact point
/// is at height `ground` (m): the character stands on flat ground at z = ground, feet flat.
template <root_joint Root>
Eigen::VectorXd standing_configuration(const model<Root>& m, double ground = 0.0) {
  check_argument(std::isfinite(ground),
                 "standing_configuration: ground height must be finite, got ", ground);
  Eigen::VectorXd q = neutral_configuration(m);
  const double z = ground - neutral_lowest_contact(m);
  if constexpr (Root::nq == 3) q[1] = z;  // planar: [x, z, pitch]
  if constexpr (Root::nq == 7) q[2] = z;  // floating: [p, quat]
  return q;
}

}  // namespace gaitsynth
