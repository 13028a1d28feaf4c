#pragma once
/// \file spatial.hpp
/// Spatial (6D) vector algebra on fixed-size Eigen types, in Featherstone's notation
/// ("Rigid Body Dynamics Algorithms", 2008, chapter 2; docs/dynamics.md):
///
///   motion vector  m = [omega; v]  (angular first; v is the velocity of the body-fixed point that
///                                   currently coincides with the frame origin)
///   force vector   f = [n; f]      (moment about the frame origin first, then the force)
///
/// A Plücker transform B_X_A (struct transform) is stored as a rotation E (A coordinates -> B
/// coordinates) and the position r of B's origin relative to A's origin, in A coordinates
/// (Featherstone eq. 2.24-2.28). Rigid-body inertias are stored in the compact form mass, centre of
/// mass and rotational inertia about the centre of mass (eq. 2.62-2.63) and expanded to a 6x6 matrix
/// only where the articulated-body algorithm needs general symmetric 6x6 operators.
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth::spatial {

/// Skew-symmetric matrix: skew(a) * b == a.cross(b).
inline mat3 skew(const vec3& a) {
  mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

inline vec6 make_vec6(const vec3& top, const vec3& bottom) {
  vec6 x;
  x << top, bottom;
  return x;
}

/// Motion cross product v x m (Featherstone eq. 2.31): the rate of change of a motion vector m fixed
/// in a body moving with spatial velocity v.
inline vec6 cross_motion(const vec6& v, const vec6& m) {
  const vec3 w = v.head<3>(), vo = v.tail<3>();
  const vec3 mw = m.head<3>(), mv = m.tail<3>();
  return make_vec6(w.cross(mw), w.cross(mv) + vo.cross(mw));
}

/// Force cross product v x* f (Featherstone eq. 2.32).
inline vec6 cross_force(const vec6& v, const vec6& f) {
  const vec3 w = v.head<3>(), vo = v.tail<3>();
  const vec3 n = f.head<3>(), fl = f.tail<3>();
  return make_vec6(w.cross(n) + vo.cross(fl), w.cross(fl));
}

/// 6x6 matrix of the motion cross operator, crm(v) * m == cross_motion(v, m).
inline mat6 crm(const vec6& v) {
  mat6 x = mat6::Zero();
  const mat3 w = skew(v.head<3>());
  x.topLeftCorner<3, 3>() = w;
  x.bottomRightCorner<3, 3>() = w;
  x.bottomLeftCorner<3, 3>() = skew(v.tail<3>());
  return x;
}

/// 6x6 matrix of the force cross operator, crf(v) == -crm(v)^T.
inline mat6 crf(const vec6& v) { return -crm(v).transpose(); }

/// Plücker transform B_X_A: E rotates A coordinates into B coordinates, r is B's origin relative to
/// A's origin expressed in A coordinates (Featherstone eq. 2.24).
struct transform {
  mat3 E = mat3::Identity();
  vec3 r = vec3::Zero();

  static transform identity() { return {}; }
  static transform rotation(const mat3& E) { return {E, vec3::Zero()}; }
  static transform translation(const vec3& r) { return {mat3::Identity(), r}; }

  /// B_X_A * m for a motion vector m in A coordinates.
  vec6 apply_motion(const vec6& m) const {
    const vec3 w = m.head<3>();
    return make_vec6(E * w, E * (m.tail<3>() - r.cross(w)));
  }
  /// B_X_A^* f for a force vector f in A coordinates.
  vec6 apply_force(const vec6& f) const {
    const vec3 fl = f.tail<3>();
    return make_vec6(E * (f.head<3>() - r.cross(fl)), E * fl);
  }
  /// A_X_B * m (the inverse transform) for a motion vector m in B coordinates.
  vec6 inverse_motion(const vec6& m) const {
    const vec3 w = E.transpose() * m.head<3>();
    return make_vec6(w, E.transpose() * m.tail<3>() + r.cross(w));
  }
  /// A_X_B^* f for a force vector f in B coordinates.
  vec6 inverse_force(const vec6& f) const {
    const vec3 fl = E.transpose() * f.tail<3>();
    return make_vec6(E.transpose() * f.head<3>() + r.cross(fl), fl);
  }
  /// Composition C_X_A = (*this = C_X_B) * (b = B_X_A).
  transform operator*(const transform& b) const { return {E * b.E, b.r + b.E.transpose() * r}; }
  transform inverse() const { return {E.transpose(), -(E * r)}; }

  /// The 6x6 motion transform matrix (eq. 2.24).
  mat6 motion_matrix() const {
    mat6 x = mat6::Zero();
    x.topLeftCorner<3, 3>() = E;
    x.bottomRightCorner<3, 3>() = E;
    x.bottomLeftCorner<3, 3>() = -E * skew(r);
    return x;
  }
  /// The 6x6 force transform matrix, X^* = X^{-T}.
  mat6 force_matrix() const {
    mat6 x = mat6::Zero();
    x.topLeftCorner<3, 3>() = E;
    x.bottomRightCorner<3, 3>() = E;
    x.topRightCorner<3, 3>() = -E * skew(r);
    return x;
  }
};

/// Rigid-body inertia in compact form: mass m, centre of mass c (relative to the frame origin) and
/// rotational inertia Ic about the centre of mass, all in the frame's coordinates (eq. 2.62).
struct rigid_inertia {
  double mass = 0.0;
  vec3 com = vec3::Zero();
  mat3 inertia_com = mat3::Zero();

  /// Expanded 6x6 spatial inertia about the frame origin (Featherstone eq. 2.63):
  ///   [Ic + m cx cx^T, m cx; m cx^T, m 1].
  mat6 matrix() const {
    mat6 I;
    const mat3 cx = skew(com);
    I.topLeftCorner<3, 3>() = inertia_com - mass * cx * cx;
    I.topRightCorner<3, 3>() = mass * cx;
    I.bottomLeftCorner<3, 3>() = -mass * cx;
    I.bottomRightCorner<3, 3>() = mass * mat3::Identity();
    return I;
  }
  /// Momentum I * v, without forming the 6x6 matrix.
  vec6 momentum(const vec6& v) const {
    const vec3 w = v.head<3>();
    const vec3 lin = mass * (v.tail<3>() + w.cross(com));  // m * velocity of the COM
    return make_vec6(inertia_com * w + com.cross(lin), lin);
  }
  /// Kinetic energy 0.5 v^T I v.
  double kinetic_energy(const vec6& v) const { return 0.5 * v.dot(momentum(v)); }

  /// The same inertia expressed in A coordinates when *this is in B coordinates and X = B_X_A
  /// (I_A = X^T I_B X, eq. 2.66 in compact form).
  rigid_inertia transformed_to_parent(const transform& X) const {
    const mat3 Et = X.E.transpose();
    return {mass, Et * com + X.r, Et * inertia_com * X.E};
  }
  rigid_inertia operator+(const rigid_inertia& o) const {
    const double m = mass + o.mass;
    const vec3 c = (mass * com + o.mass * o.com) / m;
    const mat3 d1 = skew(com - c), d2 = skew(o.com - c);
    return {m, c, inertia_com - mass * d1 * d1 + o.inertia_com - o.mass * d2 * d2};
  }
};

}  // namespace gaitsynth::spatial
