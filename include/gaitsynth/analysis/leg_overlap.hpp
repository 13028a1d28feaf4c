#pragma once
/// \file analysis/leg_overlap.hpp
/// Whether a recorded walk passes one leg through the other. The Wang 2009 and 2012 humanoids
/// simulate without collisions between their own bodies (only Wu's legs collide,
/// contact/self_contact.hpp), so nothing stops a walker from crossing its legs through each other,
/// a gait no body can walk; this measures how far it does:
///
///   const leg_overlap_report o = leg_overlap(m, tr, leg_capsule_pairs(m), 2.0);
///   o.max_depth;            // m: the deepest overlap of any pair in any frame
///   o.overlapping_fraction; // of the frames, those in which some pair overlaps
///
/// The usual pairs: contact/self_contact.hpp's leg_capsule_pairs(m). Per pair and frame the
/// depth is r_a + r_b - d, d the distance between the capsules' segments
/// (contact/self_contact.hpp's closest points) in the recorded body poses; it overlaps when > 0.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

struct leg_overlap_report {
  int frames = 0;                     ///< frames from t_begin on
  double max_depth = 0.0;             ///< m, deepest overlap (0: none)
  double overlapping_fraction = 0.0;  ///< of the frames, those with a pair overlapping
  int worst_pair = -1;                ///< index of the deepest pair (-1: none overlaps)
  double worst_time = 0.0;            ///< s, when it was deepest
};

/// "<body a>-<body b>" of pairs[i] ("lshin-rshin"); "" for i = -1 (leg_overlap_report's
/// worst_pair when nothing overlaps). \throws std::invalid_argument for another index.
template <root_joint Root>
std::string leg_overlap_pair_name(const model<Root>& m, std::span<const self_collision_pair> pairs,
                                  int i) {
  if (i == -1) return "";
  check_argument(i >= 0 && static_cast<std::size_t>(i) < pairs.size(),
                 "leg_overlap_pair_name: pair ", i, " of ", pairs.size());
  const self_collision_pair& q = pairs[static_cast<std::size_t>(i)];
  return m.bodies[static_cast<std::size_t>(q.a.body)].name + "-" +
         m.bodies[static_cast<std::size_t>(q.b.body)].name;
}

/// The overlap of `pairs` over the frames of tr (recorded with body poses) from t_begin (s) on.
/// \throws std::invalid_argument for pairs validate() refuses, a frame without body poses (naming
/// it) or a non-finite t_begin.
template <root_joint Root>
leg_overlap_report leg_overlap(const model<Root>& m, const trajectory& tr,
                               std::span<const self_collision_pair> pairs, double t_begin = 0.0) {
  check_argument(std::isfinite(t_begin), "leg_overlap: t_begin is not finite");
  self_contact_parameters check;
  check.pairs.assign(pairs.begin(), pairs.end());
  validate(m, check);
  const auto nb = static_cast<std::size_t>(m.num_bodies());
  leg_overlap_report r;
  int overlapping = 0;
  for (const trajectory_frame& f : tr.frames) {
    if (f.t < t_begin) continue;
    check_argument(f.body_position.size() == nb && f.body_orientation.size() == nb,
                   "leg_overlap: the frame at t = ", f.t, " has ", f.body_position.size(),
                   " body poses, model '", m.name, "' has ", nb, " bodies (record body poses)");
    ++r.frames;
    bool any = false;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto world = [&](const collision_capsule& c, const vec3& x) -> vec3 {
        const auto b = static_cast<std::size_t>(c.body);
        return f.body_position[b] + f.body_orientation[b].normalized() * x;
      };
      const self_collision_pair& q = pairs[i];
      const vec3 a0 = world(q.a, q.a.p0), a1 = world(q.a, q.a.p1);
      const vec3 b0 = world(q.b, q.b.p0), b1 = world(q.b, q.b.p1);
      const auto [s, t] = closest_segment_parameters(a0, a1, b0, b1);
      const double depth =
          q.a.radius + q.b.radius - ((b0 + t * (b1 - b0)) - (a0 + s * (a1 - a0))).norm();
      if (depth <= 0.0) continue;
      any = true;
      if (depth > r.max_depth) {
        r.max_depth = depth;
        r.worst_pair = static_cast<int>(i);
        r.worst_time = f.t;
      }
    }
    overlapping += any;
  }
  if (r.frames > 0) r.overlapping_fraction = static_cast<double>(overlapping) / r.frames;
  return r;
}

}  // namespace gaitsynth
