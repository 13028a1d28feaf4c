#pragma once
/// \file push.hpp
/// External pushes: a constant force on a body's centre of mass during [start, start + duration).
/// Wang et al. 2009 test robustness with pushes (F_x, F_y) of 0.4 s on the torso COM every 4 s
/// (periodic_pushes); Wu & Popovic 2010 use 350-700 N pushes of 0.1 s.
#include <cmath>
#include <span>
#include <vector>

#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

struct push {
  int body = 0;               ///< index into model.bodies
  vec3 force = vec3::Zero();  ///< world frame, N (any direction)
  double start = 0.0;         ///< s
  double duration = 0.0;      ///< s (>= 0)

  /// Whether the push acts at time t: start <= t < start + duration.
  bool active(double t) const { return t >= start && t < start + duration; }
};

/// Throws std::invalid_argument naming the first bad push (body out of range, non-finite force or
/// start, negative or non-finite duration).
template <root_joint Root>
void validate_pushes(const model<Root>& m, std::span<const push> pushes) {
  for (std::size_t i = 0; i < pushes.size(); ++i) {
    const push& p = pushes[i];
    check_argument(p.body >= 0 && p.body < m.num_bodies(), "push ", i, ": body ", p.body,
                   " is not a body of model '", m.name, "' (", m.num_bodies(), " bodies)");
    check_argument(p.force.allFinite(), "push ", i, ": force (", p.force.transpose(),
                   ") is not finite");
    check_argument(std::isfinite(p.start), "push ", i, ": start must be finite, got ", p.start);
    check_argument(std::isfinite(p.duration) && p.duration >= 0.0, "push ", i,
                   ": duration must be finite and >= 0, got ", p.duration);
  }
}

/// Adds the force of every push active at time t to ws.f_ext, applied at its body's COM (so it
/// creates no moment about the COM). Needs forward_kinematics for the current q.
/// \throws std::invalid_argument for a bad push (validate_pushes).
template <root_joint Root>
void apply_pushes(const model<Root>& m, workspace<Root>& ws, std::span<const push> pushes,
                  double t) {
  validate_pushes(m, pushes);
  for (const push& p : pushes) {
    if (!p.active(t)) continue;
    const vec3 com = ws.body_position[p.body] + ws.body_rotation[p.body] * m.bodies[p.body].com;
    add_point_force(m, ws, p.body, com, p.force);
  }
}

/// `count` pushes of `force` on `body`, each lasting `duration`, the first at `first_start` and
/// then every `period` seconds (Wang et al. 2009: 0.4 s every 4 s).
inline std::vector<push> periodic_pushes(int body, const vec3& force, double first_start,
                                         double period, double duration, int count) {
  check_argument(count >= 0, "periodic_pushes: count must be >= 0, got ", count);
  check_positive(period, "periodic_pushes: period (s)");
  std::vector<push> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) out.push_back({body, force, first_start + i * period, duration});
  return out;
}

}  // namespace gaitsynth
