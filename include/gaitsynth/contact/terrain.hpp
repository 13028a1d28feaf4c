#pragma once
/// \file terrain.hpp
/// The terrain policy (docs/contact.md). A terrain is an immutable description of the ground as a
/// height function over the horizontal plane:
///
///   t.height(x, y) -> double   ground height at (x, y), m (world z)
///   t.normal(x, y) -> vec3     unit outward (upward, n.z() > 0) surface normal at (x, y)
///
/// Planar models query y = 0. Both calls must be const, cheap, allocation-free and thread-safe
/// (rollouts running in parallel share one terrain).
///
/// Penalty contact (penalty_contact.hpp) measures how deep a point is with terrain_penetration(),
/// which by default uses the local tangent plane: depth = (height(x, y) - z) * normal.z(), the
/// distance from the point to the plane through (x, y, height) with that normal (exact on planes).
/// A terrain with vertical faces (steps_terrain) instead provides a member
///   t.penetration(p) -> surface_contact
/// so that a foot running into a riser is pushed back horizontally rather than lifted onto the
/// tread; terrain_penetration() prefers that member when it exists (resolved at compile time).
#include <concepts>
#include <limits>

#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Where a point is relative to the ground.
struct surface_contact {
  double depth = 0.0;           ///< penetration depth along `normal`, m (> 0: below the surface)
  vec3 normal = vec3::UnitZ();  ///< unit outward normal of the face the point is pushed through
};

template <class T>
concept terrain = requires(const T& t, double x, double y) {
  { t.height(x, y) } -> std::convertible_to<double>;
  { t.normal(x, y) } -> std::convertible_to<vec3>;
};

/// Terrains that know their own penetration rule (vertical faces).
template <class T>
concept terrain_with_penetration = terrain<T> && requires(const T& t, const vec3& p) {
  { t.penetration(p) } -> std::convertible_to<surface_contact>;
};

/// Terrains that bound their height over a disc (the contact broad phase skips bodies above it).
template <class T>
concept terrain_with_height_bound = terrain<T> && requires(const T& t, double x, double y) {
  { t.max_height(x, y, x) } -> std::convertible_to<double>;
};

/// An upper bound of the height of terrain `t` over the horizontal disc of radius r (m) around
/// (x, y): no point above it is below the terrain. +infinity for a terrain that does not say.
template <terrain T>
inline double terrain_max_height(const T& t, double x, double y, double r) {
  if constexpr (terrain_with_height_bound<T>)
    return t.max_height(x, y, r);
  else
    return std::numeric_limits<double>::infinity();
}

/// Depth of world point `p` below terrain `t` and the direction to push it out.
template <terrain T>
inline surface_contact terrain_penetration(const T& t, const vec3& p) {
  if constexpr (terrain_with_penetration<T>) {
    return t.penetration(p);
  } else {
    surface_contact c;
    c.normal = t.normal(p.x(), p.y());
    // Distance from p to the tangent plane through (x, y, h): (h - z) n_z, exact for planes.
    c.depth = (t.height(p.x(), p.y()) - p.z()) * c.normal.z();
    return c;
  }
}

}  // namespace gaitsynth
