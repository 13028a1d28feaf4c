#pragma once
/// \file controllers/end_effector/swing_foot_path.hpp
/// The swing-foot path of Wu & Popovic 2010, appendix A.3 (Fig. 7a, 7b, 8), over the footstep
/// time s_s in [0, 1] (duration t_h + t_e, planner_timing.hpp):
///
///   position     w_sw0(s) = V(s, 0, w_sw1, w_sw2, (1, 0), gamma1, gamma2)  in (u, v)   (type III)
///   orientation  psi_sw(s) = C(s, psi_start, psi_es)                                   (type I)
///                theta_sw(s) = V(s, theta_start, theta_sw1, theta_sw2, theta_es, gamma1, gamma2)
///                R_sw(s) = R_z(psi_sw) R_y(-theta_sw)                 (11), our frame's form
///   terrain      64 samples uniform in u, at each the lowest collision-free height of the foot's
///                box with the path's horizontal position and orientation there; the upper convex
///                hull h(u) of these is added as a vertical offset.
///
/// The (u, v) frame: origin at the start, u along the horizontal chord to the target (u = 1 there),
/// v vertical in metres. Control points are 3D here, (u, l, v) with l a lateral offset in metres
/// to the chord's left (the paper's implementation used 3D points; l = 0 is its 2D case).
///
/// What v means (the paper says only that w_sw0 "assumes that the ground is the xy-plane"; ours):
/// v is the clearance of the foot box's lowest corner above the plane z = 0, so the planned
/// reference point (the foot link's origin) is at
///   z(s) = v(s) + plane_clearance(R_sw(s)) + h(u(s)),
/// where plane_clearance(R) is the reference point's height with the box resting on z = 0
/// (foot_clearance.hpp) and the hull's samples are terrain offsets,
///   g_i = lowest_collision_free_height(terrain, R_i, q_i) - plane_clearance(R_i),
/// zero everywhere on the plane z = 0: there the path is the unadjusted one. Two samples are
/// replaced so the path joins the actual feet: g_0 is the foot's actual start height minus
/// plane_clearance(R_start) (the path starts where the foot is), and g_63 stays the terrain's (the
/// foot lands on the ground at the target). Every hull vertex is a sample and h >= g_i at every
/// sample, so wherever v >= 0 (control points with v >= 0) the box clears the sampled terrain at
/// the 64 sample locations; between them the hull's straight segments keep it clear of convex
/// bumps and steps but not of spikes narrower than a sample spacing (about 1 cm for a 0.65 m step).
///
/// The samples sit at uniform u: u(s) = c_u(w(s)) is nondecreasing when gamma1, gamma2 and the
/// control points' u lie in [0, 1] (planner_parameters.hpp checks it), so s_i is found by
/// bisection. Velocities: d/dt = d/ds / (t_h + t_e); h(u) is piecewise linear, so the vertical
/// velocity jumps at hull vertices (as in the paper). Queries are allocation-free.
#include <Eigen/Core>
#include <array>
#include <cmath>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/controllers/end_effector/foot_clearance.hpp"
#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/height_hull.hpp"
#include "gaitsynth/controllers/end_effector/path_curves.hpp"
#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planner_targets.hpp"
#include "gaitsynth/controllers/end_effector/planner_timing.hpp"

namespace gaitsynth {

inline constexpr int swing_terrain_samples = 64;  ///< A.3: "64 locations"

/// The horizontal chord of a path in its (u, l) coordinates: q = start + u d + l n, n the unit
/// left normal of d (of the heading `fallback_heading` when the chord is shorter than 1e-9 m).
struct path_chord {
  vec2 start = vec2::Zero();
  vec2 d = vec2::Zero();
  vec2 n = vec2(0.0, 1.0);
  static path_chord make(const vec2& from, const vec2& to, double fallback_heading) {
    path_chord c;
    c.start = from;
    c.d = to - from;
    const double len = c.d.norm();
    const vec2 dir = len > 1e-9 ? vec2(c.d / len) : heading2(fallback_heading);
    c.n = vec2(-dir.y(), dir.x());
    return c;
  }
  vec2 point(double u, double l) const { return start + u * d + l * n; }
  vec2 rate(double du, double dl) const { return du * d + dl * n; }
};

/// Where the swing foot starts and where it must go: the inputs of make_swing_foot_path.
struct swing_path_ends {
  vec3 start = vec3::Zero();  ///< the foot link origin now (world)
  double psi_start = 0.0, theta_start = 0.0;
  vec2 target = vec2::Zero();  ///< q_sw,es (eq. 8, after edge avoidance)
  double psi_end = 0.0;        ///< psi_sw,es = psi_f, unwrapped to within pi of psi_start
  double theta_end = 0.0;      ///< theta_sw,es from the terrain slope
};

struct swing_foot_path {
  path_chord chord;
  double psi_start = 0.0, psi_end = 0.0;
  double theta_start = 0.0, theta1 = 0.0, theta2 = 0.0, theta_end = 0.0;
  double gamma1 = 1.0 / 3.0, gamma2 = 2.0 / 3.0;
  vec3 w1 = vec3::Zero(), w2 = vec3::Zero();
  double duration = 1.0;  ///< t_h + t_e, s
  foot_box box;
  height_hull<swing_terrain_samples> hull;
  std::array<double, swing_terrain_samples> sample_u{}, sample_s{}, sample_offset{};

  /// The path's (u, l, v) point c(s) and dc/ds, without terrain.
  void chord_point(double s, vec3& c, vec3& dc) const {
    const double w = bezier_time_warp(s, gamma1, gamma2);
    const double dw = bezier_time_warp_derivative(s, gamma1, gamma2);
    const vec3 a3(1.0, 0.0, 0.0);
    c = bezier(w, vec3::Zero().eval(), w1, w2, a3);
    dc = dw * bezier_derivative(w, vec3::Zero().eval(), w1, w2, a3);
  }

  /// The foot's rotation at s (eq. 11) and its angular velocity per unit s (world axes).
  void orientation(double s, mat3& R, vec3& omega_s) const {
    const double psi = slow_in_out(s, psi_start, psi_end);
    const double dpsi = slow_in_out_derivative(s, psi_start, psi_end);
    const double theta = warped_bezier(s, theta_start, theta1, theta2, theta_end, gamma1, gamma2);
    const double dtheta =
        warped_bezier_derivative(s, theta_start, theta1, theta2, theta_end, gamma1, gamma2);
    R = foot_rotation(psi, theta);
    // d/ds [R_z(psi) R_y(-theta)] = [dpsi z + R_z(psi) (-dtheta y)]_x R.
    omega_s = dpsi * vec3::UnitZ() - dtheta * (rotation_z(psi) * vec3::UnitY());
  }

  /// The planned pose and twist of the foot link's origin at footstep time s (clamped to [0, 1];
  /// velocities are zero outside (0, 1)), given ds/dt.
  link_target at_s(double s_raw, double ds_dt) const {
    const double s = clamp_unit(s_raw);
    const double rate = (s_raw > 0.0 && s_raw < 1.0) ? ds_dt : 0.0;
    vec3 c, dc, omega_s;
    chord_point(s, c, dc);
    link_target out;
    orientation(s, out.rotation, omega_s);
    const plane_clearance_result pc = plane_clearance(box, out.rotation);
    const auto [h, dh_du] = hull.value_and_slope(c.x());
    const vec2 q = chord.point(c.x(), c.y());
    const vec2 dq = chord.rate(dc.x(), dc.y());
    const double dpc = -omega_s.cross(pc.corner).z();
    out.position = vec3(q.x(), q.y(), c.z() + pc.height + h);
    out.velocity = rate * vec3(dq.x(), dq.y(), dc.z() + dpc + dh_du * dc.x());
    out.angular_velocity = rate * omega_s;
    return out;
  }

  /// At time t since the start of the half-cycle the path was planned in.
  link_target at(double t) const { return at_s(t / duration, 1.0 / duration); }

  /// Without the terrain offset h(u): the path over the plane z = 0 (the "unadjusted" path).
  vec3 unadjusted_position(double s) const {
    vec3 c, dc, omega_s;
    mat3 R;
    chord_point(s, c, dc);
    orientation(s, R, omega_s);
    const vec2 q = chord.point(c.x(), c.y());
    return {q.x(), q.y(), c.z() + plane_clearance(box, R).height};
  }
};

/// Builds the path (A.3) for one footstep of `duration` = t_h + t_e s, sampling terrain `t`.
/// \throws std::invalid_argument naming the value for a non-positive or non-finite duration.
template <terrain T>
swing_foot_path make_swing_foot_path(const swing_path_ends& e, const planner_parameters& p,
                                     double duration, const planner_setup& setup, const T& t) {
  check_argument(std::isfinite(duration) && duration > 0.0,
                 "make_swing_foot_path: duration must be finite and > 0, got ", duration);
  swing_foot_path path;
  path.chord = path_chord::make(e.start.head<2>(), e.target, e.psi_end);
  path.psi_start = e.psi_start;
  path.psi_end = e.psi_start + wrap_angle(e.psi_end - e.psi_start);
  path.theta_start = e.theta_start;
  path.theta1 = p.theta_sw1;
  path.theta2 = p.theta_sw2;
  path.theta_end = e.theta_end;
  path.gamma1 = p.gamma1;
  path.gamma2 = p.gamma2;
  path.w1 = p.w_sw1;
  path.w2 = p.w_sw2;
  path.duration = duration;
  path.box = setup.foot;

  constexpr int n = swing_terrain_samples;
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    double s = i == n - 1 ? 1.0 : 0.0;
    if (i > 0 && i < n - 1) {  // u(s) is nondecreasing: bisect for u(s) = u
      double lo = 0.0, hi = 1.0;
      vec3 c, dc;
      for (int it = 0; it < 52; ++it) {
        const double mid = 0.5 * (lo + hi);
        path.chord_point(mid, c, dc);
        (c.x() < u ? lo : hi) = mid;
      }
      s = 0.5 * (lo + hi);
    }
    vec3 c, dc, omega_s;
    mat3 R;
    path.chord_point(s, c, dc);
    path.orientation(s, R, omega_s);
    const double base = plane_clearance(path.box, R).height;
    double g;
    if (i == 0)
      g = e.start.z() - base;
    else
      g = lowest_collision_free_height(t, path.box, R, path.chord.point(c.x(), c.y()),
                                       setup.footprint_along, setup.footprint_across) -
          base;
    path.sample_u[i] = u;
    path.sample_s[i] = s;
    path.sample_offset[i] = g;
  }
  path.hull = upper_convex_hull(path.sample_u, path.sample_offset);
  return path;
}

}  // namespace gaitsynth
