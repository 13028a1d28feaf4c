#pragma once
/// \file controllers/end_effector/upper_body_path.hpp
/// The upper-body path of Wu & Popovic 2010, appendix A.3 (Fig. 7c, 7d), over the half-cycle time
/// s_h in [0, 1] (duration t_h):
///
///   position     w_ub(s) = B(s, 0, w_ub1, w_ub2, (1, 0)) in (u, v)                    (type II)
///                plus the linear height slope between the start and target heights:
///                z(s) = z_start + (z_eh - z_start) u(s) + v(s)                         (Fig. 7d)
///   orientation  R(s) = slerp(R_start, R_eh, C(s, 0, 1))                               (type I)
///
/// The (u, v) frame is the swing foot's (swing_foot_path.hpp): u along the horizontal chord from
/// q_ub,start to q_ub,eh, v vertical in metres; control points are (u, l, v) with a lateral l
/// (ours, 0 is the paper's 2D case). Which plane the paper's w_ub lies in is not said; ours is the
/// vertical one through the chord, as for the swing foot ("the construction process is similar"),
/// with the slope added linearly in u. The slerp is the geodesic R(s) = exp(C(s) phi) R_start,
/// phi = log(R_eh R_start^T) (world axes), so omega = C'(s) phi.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/path_curves.hpp"
#include "gaitsynth/controllers/end_effector/planner_timing.hpp"
#include "gaitsynth/controllers/end_effector/swing_foot_path.hpp"

namespace gaitsynth {

struct upper_body_path {
  path_chord chord;
  double z_start = 0.0, z_end = 0.0;
  vec3 w1 = vec3::Zero(), w2 = vec3::Zero();
  double duration = 1.0;  ///< t_h, s
  mat3 rotation_start = mat3::Identity();
  vec3 rotation_change = vec3::Zero();  ///< phi = log(R_eh R_start^T), world axes

  /// The planned point's pose and twist at half-cycle time s (clamped to [0, 1]; velocities zero
  /// outside (0, 1)), given ds/dt.
  link_target at_s(double s_raw, double ds_dt) const {
    const double s = clamp_unit(s_raw);
    const double rate = (s_raw > 0.0 && s_raw < 1.0) ? ds_dt : 0.0;
    const vec3 a3(1.0, 0.0, 0.0);
    const vec3 c = bezier(s, vec3::Zero().eval(), w1, w2, a3);
    const vec3 dc = bezier_derivative(s, vec3::Zero().eval(), w1, w2, a3);
    const vec2 q = chord.point(c.x(), c.y());
    const vec2 dq = chord.rate(dc.x(), dc.y());
    const double dz = z_end - z_start;
    link_target out;
    out.position = vec3(q.x(), q.y(), z_start + dz * c.x() + c.z());
    out.velocity = rate * vec3(dq.x(), dq.y(), dz * dc.x() + dc.z());
    const double lambda = slow_in_out(s, 0.0, 1.0);
    const double dlambda = slow_in_out_derivative(s, 0.0, 1.0);
    const double angle = rotation_change.norm();
    out.rotation =
        angle > 0.0
            ? mat3(Eigen::AngleAxisd(lambda * angle, rotation_change / angle).toRotationMatrix() *
                   rotation_start)
            : rotation_start;
    out.angular_velocity = rate * dlambda * rotation_change;
    return out;
  }

  /// At time t since the start of the half-cycle.
  link_target at(double t) const { return at_s(t / duration, 1.0 / duration); }
};

/// Builds the path from the upper body's planned point and rotation now to the targets of eqs. 9
/// and 10, over `duration` = t_h.
/// \throws std::invalid_argument naming the value for a non-positive or non-finite duration.
inline upper_body_path make_upper_body_path(const vec3& start, const mat3& rotation_start,
                                            const vec3& target, const mat3& rotation_target,
                                            const planner_parameters& p, double duration,
                                            double fallback_heading) {
  check_argument(std::isfinite(duration) && duration > 0.0,
                 "make_upper_body_path: duration must be finite and > 0, got ", duration);
  upper_body_path path;
  path.chord = path_chord::make(start.head<2>(), target.head<2>(), fallback_heading);
  path.z_start = start.z();
  path.z_end = target.z();
  path.w1 = p.w_ub1;
  path.w2 = p.w_ub2;
  path.duration = duration;
  path.rotation_start = rotation_start;
  const Eigen::AngleAxisd aa(mat3(rotation_target * rotation_start.transpose()));
  path.rotation_change = aa.angle() * aa.axis();
  return path;
}

}  // namespace gaitsynth
