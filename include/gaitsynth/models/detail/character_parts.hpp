#pragma once
/// \file character_parts.hpp
/// Small helpers shared by the built-in characters (models/*.hpp): visual shapes, soft limits and
/// left/right mirroring of limit ranges.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "gaitsynth/model/model.hpp"

namespace gaitsynth::detail::characters {

inline constexpr double deg = std::numbers::pi / 180.0;

inline shape capsule(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double radius) {
  shape s;
  s.type = shape::kind::capsule;
  s.p0 = p0;
  s.p1 = p1;
  s.center = 0.5 * (p0 + p1);
  s.radius = radius;
  return s;
}

inline shape box(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents) {
  shape s;
  s.type = shape::kind::box;
  s.center = center;
  s.half_extents = half_extents;
  return s;
}

inline shape sphere(const Eigen::Vector3d& center, double radius) {
  shape s;
  s.type = shape::kind::sphere;
  s.center = center;
  s.radius = radius;
  return s;
}

/// Exponential soft limit (Sharon & van de Panne 2005): amplitude k (N m), sharpness s (1/rad),
/// damping d (N m s/rad) past the bounds [lo, hi] (rad).
inline joint_limit exponential_limit(double lo, double hi, double k, double s, double d) {
  joint_limit L;
  L.lower = lo;
  L.upper = hi;
  L.stiffness = k;
  L.sharpness = s;
  L.damping = d;
  L.model = limit_model::exponential;
  return L;
}

/// Linear spring-damper soft limit (Wang et al. 2009 / ODE-style stops).
inline joint_limit spring_damper_limit(double lo, double hi, double k, double d) {
  joint_limit L;
  L.lower = lo;
  L.upper = hi;
  L.stiffness = k;
  L.damping = d;
  L.model = limit_model::spring_damper;
  return L;
}

/// The right-side limit of a left-side DOF about `axis`: mirroring across the sagittal plane flips
/// rotations about x and z (model_builder's mirror rule), so [lo, hi] becomes [-hi, -lo] for them.
inline joint_limit mirrored_limit(joint_limit L, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d ma(-axis.x(), axis.y(), -axis.z());
  if (ma.dot(axis) < 0) {
    const double lo = L.lower;
    L.lower = -L.upper;
    L.upper = -lo;
  }
  return L;
}

}  // namespace gaitsynth::detail::characters
