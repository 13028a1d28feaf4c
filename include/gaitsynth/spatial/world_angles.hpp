#pragma once
/// \file world_angles.hpp
/// World-frame orientation angles of a body, Wang et al. 2009 Sec. 3: "The world frame orientation
/// of a body part is defined by measuring angles of their up and forward vectors projected in the
/// coronal, sagittal, and transverse planes." SIMBICON-style controllers servo these angles (the
/// torso, the swing thigh, the feet) and E_head penalizes the head's.
///
/// The planes belong to a heading frame: the world rotated by `heading` (rad) about +z, with x
/// forward, y left, z up (Wang et al. walk along +x: heading 0). With u = R e_z (up) and f = R e_x
/// (forward) expressed in that frame:
///   coronal    (about x): theta_cor   = atan2(-u_y, u_z)   (R_x(a) e_z = (0, -sin a, cos a))
///   sagittal   (about y): theta_sag   = atan2( u_x, u_z)   (R_y(a) e_z = (sin a, 0, cos a))
///   transverse (about z): theta_trans = atan2( f_y, f_x)   (R_z(a) e_x = (cos a, sin a, 0))
/// so each is the right-hand angle about its axis and a rotation about one axis alone reads back
/// exactly (|a| < pi/2 for the first two). Signs match the joints' (docs/models.md): a thigh
/// swung forward has a negative sagittal angle, a foot with its toes down a positive one.
#include <cmath>

#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Coronal, sagittal and transverse angles, rad (x, y, z of the heading frame).
struct world_angles {
  double coronal = 0.0;
  double sagittal = 0.0;
  double transverse = 0.0;

  double operator[](int axis) const {
    return axis == 0 ? coronal : axis == 1 ? sagittal : transverse;
  }
  /// Euclidean norm of the three (Wang et al. 2009 eq. 11: ||Theta_t||).
  double norm() const {
    return std::sqrt(coronal * coronal + sagittal * sagittal + transverse * transverse);
  }
};

/// A world vector in the heading frame (rotated by -heading about z).
inline vec3 to_heading_frame(const vec3& w, double heading) {
  if (heading == 0.0) return w;
  const double c = std::cos(heading), s = std::sin(heading);
  return {c * w.x() + s * w.y(), -s * w.x() + c * w.y(), w.z()};
}

/// The angles of the body whose world rotation is R (R_world_body), in the heading frame.
inline world_angles body_world_angles(const mat3& R, double heading = 0.0) {
  const vec3 up = to_heading_frame(R.col(2), heading);
  const vec3 fwd = to_heading_frame(R.col(0), heading);
  return {std::atan2(-up.y(), up.z()), std::atan2(up.x(), up.z()), std::atan2(fwd.y(), fwd.x())};
}

/// body_world_angles(R, heading).coronal alone (one atan2 instead of three).
inline double body_coronal_angle(const mat3& R, double heading = 0.0) {
  const vec3 up = to_heading_frame(R.col(2), heading);
  return std::atan2(-up.y(), up.z());
}
/// body_world_angles(R, heading).sagittal alone.
inline double body_sagittal_angle(const mat3& R, double heading = 0.0) {
  const vec3 up = to_heading_frame(R.col(2), heading);
  return std::atan2(up.x(), up.z());
}

/// body_world_angles(R).norm() > limit (heading 0), the same answer for every R, with the three
/// atan2 only where cheap bounds cannot decide: for b > 0, x = |a| / b and x <= 1,
/// x - x^3 / 3 <= |atan2(a, b)| <= x, so the sum of the squared ratios bounds the squared norm from
/// above and the sum of the squared lower bounds from below. A relative margin of 1e-9 (far above
/// the rounding of either side) sends every R near the limit to the exact path. E_head counts
/// this once per physics step, and the head is rarely near its 0.1 rad limit.
inline bool world_angles_norm_exceeds(const mat3& R, double limit) {
  const double uz = R(2, 2), fx = R(0, 0);
  if (uz > 0.0 && fx > 0.0) {
    const double x[3] = {std::abs(R(1, 2)) / uz, std::abs(R(0, 2)) / uz, std::abs(R(1, 0)) / fx};
    const double l2 = limit * limit;
    const double upper = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    if (upper <= l2 * (1.0 - 1e-9)) return false;
    if (x[0] <= 1.0 && x[1] <= 1.0 && x[2] <= 1.0) {
      double lower = 0.0;
      for (const double xi : x) {
        const double a = xi - xi * xi * xi / 3.0;
        lower += a * a;
      }
      if (lower >= l2 * (1.0 + 1e-9)) return true;
    }
  }
  return body_world_angles(R).norm() > limit;
}
/// The angle between a body's unit up vector (world; R.col(2)) and the world vertical, rad, in
/// [0, pi]: its tilt, whichever way it leans.
inline double tilt_from_vertical(const vec3& up) {
  return std::atan2(std::sqrt(up.x() * up.x() + up.y() * up.y()), up.z());
}

/// The heading of a body: the transverse angle of its forward vector in the world (rad, 0 = +x).
inline double body_heading(const mat3& R) {
  return std::atan2(R(1, 0), R(0, 0));
}

}  // namespace gaitsynth
