#pragma once
/// \file contact/self_contact.hpp
/// Collisions between a character's own bodies, as capsule pairs with penalty forces. Wu &
/// Popovic 2010 (Sec. 9) simulate in PhysX, where the legs collide: "benign inter-leg collisions
/// that alter non-end effectors' states are allowed to happen", and turning or side-stepping
/// plans must avoid "tangling of the legs". Without them an optimized forward walk may plant
/// each foot on the other's line or across it, a gait no legged body can walk.
///
/// Per pair (capsules a and b on different bodies, in their bodies' frames):
///   c_a, c_b   the closest points of the two segments, d = |c_b - c_a|, n = (c_b - c_a) / d
///   depth      r_a + r_b - d (touching when > 0)
///   p          the midpoint of the two surface points c_a + r_a n and c_b - r_b n
///   f_n        max(0, kp depth - kd n . (v_b(p) - v_a(p)))     (frictionless: ours)
///   body b gets f_n n at p, body a gets -f_n n at p
/// Both forces act along one line, so a pair never changes the total linear or angular momentum.
/// Segments that cross (d = 0) push along the normal of the plane of the two segments (or any
/// direction normal to a when they are parallel, or z when a is a point).
///
/// leg_capsule_pairs(m) gives the 30-DOF humanoids' leg pairs from their capsule shapes (Wu's
/// biped has its own, wu2010_leg_collisions in models/wu2010.hpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

/// A capsule on one body: the segment p0-p1 (body frame, m) swept by a sphere of `radius` (m).
struct collision_capsule {
  int body = -1;
  vec3 p0 = vec3::Zero();
  vec3 p1 = vec3::Zero();
  double radius = 0.0;
};

struct self_collision_pair {
  collision_capsule a, b;
};

/// The pairs that collide and their penalty law. No pairs (the default): no self-collision, and
/// the rollout skips it entirely.
struct self_contact_parameters {
  std::vector<self_collision_pair> pairs;
  double kp = 75000.0;  ///< N/m (Wang et al. 2009's ground stiffness)
  /// N s/m (ours): explicit damping is stable while kd dt / m_eff < 2; a 1 kg foot against
  /// another (m_eff 0.5 kg) at 2400 Hz allows about 2400 N s/m, and 200 keeps far from it.
  double kd = 200.0;
};

/// Parameters s, t in [0, 1] of the closest points p0 + s (p1 - p0) and q0 + t (q1 - q0) of two
/// segments (either may have zero length). Ericson, Real-Time Collision Detection, 5.1.9.
inline std::pair<double, double> closest_segment_parameters(const vec3& p0, const vec3& p1,
                                                            const vec3& q0, const vec3& q1) {
  const vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  constexpr double tiny = 1e-300;
  if (a <= tiny && e <= tiny) return {0.0, 0.0};
  if (a <= tiny) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= tiny) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2), denom = a * e - b * b;
  // Parallel segments (denom 0): any s works; take 0 and let t follow.
  double s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {s, t};
}

/// Throws std::invalid_argument naming the first pair whose body is not one of m's (or is the
/// same on both sides), whose radius is not finite and > 0 or whose end point is not finite, or a
/// gain that is not finite and >= 0.
template <root_joint Root>
void validate(const model<Root>& m, const self_contact_parameters& p) {
  check_argument(std::isfinite(p.kp) && p.kp >= 0.0,
                 "self_contact_parameters::kp must be finite and >= 0, got ", p.kp);
  check_argument(std::isfinite(p.kd) && p.kd >= 0.0,
                 "self_contact_parameters::kd must be finite and >= 0, got ", p.kd);
  for (std::size_t i = 0; i < p.pairs.size(); ++i) {
    const self_collision_pair& q = p.pairs[i];
    for (const collision_capsule* c : {&q.a, &q.b}) {
      check_argument(c->body >= 0 && c->body < m.num_bodies(), "self-collision pair ", i, ": body ",
                     c->body, " is not one of model '", m.name, "''s ", m.num_bodies(), " bodies");
      check_argument(std::isfinite(c->radius) && c->radius > 0.0, "self-collision pair ", i,
                     ": radius must be finite and > 0, got ", c->radius);
      check_argument(c->p0.allFinite() && c->p1.allFinite(), "self-collision pair ", i,
                     ": end points must be finite");
    }
    check_argument(q.a.body != q.b.body, "self-collision pair ", i, ": both capsules are on body ",
                   q.a.body);
  }
}

/// The left leg's capsules against the right's, from the bodies' capsule shapes: thigh against
/// lower leg, lower leg against thigh, and the lower legs (3 pairs; the 30-DOF humanoids' thighs
/// and shins, Wu's biped's thighs and shanks). Not the thighs against each other: their capsules
/// start at the hip joints, closer together than their radii, so they overlap by 1.4 cm even
/// standing (a person's thighs meet there too). \throws std::invalid_argument naming a missing
/// body or a body without a capsule shape.
template <root_joint Root>
std::vector<self_collision_pair> leg_capsule_pairs(const model<Root>& m,
                                                   const std::string& upper = "thigh",
                                                   const std::string& lower = "shin") {
  const auto capsule_of = [&](const std::string& name) -> collision_capsule {
    const int b = m.body_index(name);  // throws naming a missing body
    for (const shape& s : m.bodies[static_cast<std::size_t>(b)].shapes)
      if (s.type == shape::kind::capsule) return {b, s.p0, s.p1, s.radius};
    throw std::invalid_argument("leg_capsule_pairs: body '" + name + "' of model '" + m.name +
                                "' has no capsule shape");
  };
  return {{capsule_of("l" + upper), capsule_of("r" + lower)},
          {capsule_of("l" + lower), capsule_of("r" + upper)},
          {capsule_of("l" + lower), capsule_of("r" + lower)}};
}

/// Adds every touching pair's forces to ws.f_ext (accumulates: clear_external_wrenches first) and
/// returns the number of touching pairs. Needs forward_kinematics(m, ws, q, v) for the current
/// state. Allocates nothing.
template <root_joint Root>
int apply_self_contact_forces(const model<Root>& m, workspace<Root>& ws,
                              const self_contact_parameters& p) {
  int touching = 0;
  for (const self_collision_pair& q : p.pairs) {
    const auto world = [&](const collision_capsule& c, const vec3& x) -> vec3 {
      return ws.body_position[c.body] + ws.body_rotation[c.body] * x;
    };
    const vec3 a0 = world(q.a, q.a.p0), a1 = world(q.a, q.a.p1);
    const vec3 b0 = world(q.b, q.b.p0), b1 = world(q.b, q.b.p1);
    // Broad phase: the segments' bounding spheres.
    const double reach_a = 0.5 * (a1 - a0).norm() + q.a.radius;
    const double reach_b = 0.5 * (b1 - b0).norm() + q.b.radius;
    if ((0.5 * (a0 + a1) - 0.5 * (b0 + b1)).squaredNorm() >
        (reach_a + reach_b) * (reach_a + reach_b))
      continue;
    const auto [s, t] = closest_segment_parameters(a0, a1, b0, b1);
    const vec3 ca = a0 + s * (a1 - a0), cb = b0 + t * (b1 - b0);
    const vec3 gap = cb - ca;
    const double d = gap.norm();
    const double depth = q.a.radius + q.b.radius - d;
    if (!(depth > 0.0)) continue;
    vec3 n;
    if (d > 1e-12) {
      n = gap / d;
    } else {  // crossing segments: the normal of their plane, else any normal to a, else z
      n = (a1 - a0).cross(b1 - b0);
      if (!(n.squaredNorm() > 1e-24))
        n = (a1 - a0).squaredNorm() > 1e-24 ? (a1 - a0).unitOrthogonal() : vec3::UnitZ();
      n.normalize();
    }
    const vec3 pt = 0.5 * (ca + q.a.radius * n + cb - q.b.radius * n);
    const auto velocity = [&](int body) -> vec3 {
      return ws.body_linear_velocity[body] +
             ws.body_angular_velocity[body].cross(pt - ws.body_position[body]);
    };
    const double vn = n.dot(velocity(q.b.body) - velocity(q.a.body));
    const double fn = std::max(0.0, p.kp * depth - p.kd * vn);
    ++touching;
    if (fn == 0.0) continue;
    add_point_force(m, ws, q.b.body, pt, fn * n);
    add_point_force(m, ws, q.a.body, pt, -fn * n);
  }
  return touching;
}

}  // namespace gaitsynth
