#pragma once
/// \file controllers/end_effector/foot_clearance.hpp
/// The foot against the terrain, for Wu & Popovic 2010's planner: the lowest collision-free height
/// of the foot's oriented bounding box (A.3's terrain sampling) and A.2's edge avoidance.
///
/// Lowest collision-free height. The foot's reference point (its link origin) is at horizontal q
/// with rotation R; the box is free of the terrain when every point of it is at or above the
/// ground under it. We sample the box on a lattice in its own frame: `along` x `across` points
/// over its length and width (corners and edges included, evenly spaced) on both its bottom and
/// its top face; the height is max over lattice points p of [terrain(x_p, y_p) - (R p).z], with
/// (x_p, y_p) = q + (R p)_xy. The top face matters when the box is tilted: it then reaches beyond
/// the bottom face's outline. Terrain features narrower than the lattice spacing (25 cm / 8 for
/// the default 9 x 3 on models/wu2010.hpp's foot) can fall between points; a step edge cannot,
/// since the highest ground under the box is then reached at the box's outline, which is sampled
/// (exactly at its corners).
///
/// Over the plane z = 0 the answer is exact from the 8 corners: plane_clearance(R) = -min over
/// corners of (R p).z.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planner_targets.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Point (i, j, k) of the box lattice in the foot frame: i < along, j < across, k = 0 bottom, 1
/// top.
inline vec3 foot_lattice_point(const foot_box& b, int along, int across, int i, int j, int k) {
  const vec3& e = b.half_extents;
  return b.center + vec3(e.x() * (2.0 * i / (along - 1) - 1.0),
                         e.y() * (2.0 * j / (across - 1) - 1.0), k == 0 ? -e.z() : e.z());
}

/// The box corner (in the foot frame) lowest in the world for rotation R, and its clearance over
/// the plane z = 0: the reference point must be plane_clearance = -(R p).z above the plane.
struct plane_clearance_result {
  double height = 0.0;
  vec3 corner = vec3::Zero();  ///< R p of the lowest corner (world axes, from the reference)
};

inline plane_clearance_result plane_clearance(const foot_box& b, const mat3& R) {
  plane_clearance_result r;
  r.height = -std::numeric_limits<double>::infinity();
  for (int c = 0; c < 8; ++c) {
    const vec3 p = b.center + vec3((c & 1) ? b.half_extents.x() : -b.half_extents.x(),
                                   (c & 2) ? b.half_extents.y() : -b.half_extents.y(),
                                   (c & 4) ? b.half_extents.z() : -b.half_extents.z());
    const vec3 Rp = R * p;
    if (-Rp.z() > r.height) {
      r.height = -Rp.z();
      r.corner = Rp;
    }
  }
  return r;
}

/// The lowest world height of the reference point at which the box (rotation R, reference at
/// horizontal q) is free of terrain `t`, sampled as the file comment says.
template <terrain T>
double lowest_collision_free_height(const T& t, const foot_box& b, const mat3& R, const vec2& q,
                                    int along, int across) {
  double z = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < along; ++i)
      for (int j = 0; j < across; ++j) {
        const vec3 Rp = R * foot_lattice_point(b, along, across, i, j, k);
        z = std::max(z, t.height(q.x() + Rp.x(), q.y() + Rp.y()) - Rp.z());
      }
  return z;
}

/// A.2's "amount of foot rotation" at a candidate landing spot (ours; the paper does not define
/// it): the angle atan((h_max - h_min) / foot length) spanned by the ground heights under the
/// bottom-face lattice of a level foot with yaw psi. Zero on a level tread, the slope on a plane,
/// large when the foot straddles an edge.
template <terrain T>
double landing_rotation(const T& t, const foot_box& b, const vec2& q, double psi, int along,
                        int across) {
  const mat3 R = rotation_z(psi);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const vec3 Rp = R * foot_lattice_point(b, along, across, i, j, 0);
      const double h = t.height(q.x() + Rp.x(), q.y() + Rp.y());
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  return std::atan((hi - lo) / (2.0 * b.half_extents.x()));
}

/// A.2's edge avoidance: landing_rotation at q and at q +- d_s along psi_m, d_s = `fraction` x the
/// foot length; returns dq_a, the move to the candidate with the least rotation (0 when q is as
/// good as the best: ties keep q, then prefer + over -).
template <terrain T>
vec2 edge_avoidance_shift(const T& t, const foot_box& b, const vec2& q, double psi_f, double psi_m,
                          double fraction, int along, int across) {
  const double ds = fraction * 2.0 * b.half_extents.x();
  const std::array<vec2, 3> shifts{vec2::Zero(), ds * heading2(psi_m), -ds * heading2(psi_m)};
  int best = 0;
  double best_rot = landing_rotation(t, b, q, psi_f, along, across);
  for (int c = 1; c < 3; ++c) {
    const double rot = landing_rotation(t, b, vec2(q + shifts[c]), psi_f, along, across);
    if (rot < best_rot - 1e-12) {
      best = c;
      best_rot = rot;
    }
  }
  return shifts[best];
}

}  // namespace gaitsynth
