#pragma once
/// \file controllers/end_effector/path_curves.hpp
/// The three curve types of Wu & Popovic 2010, appendix A.3, and their derivatives with respect to
/// the normalized time s (the lower level needs desired velocities: d/dt = (ds/dt) d/ds, with
/// ds/dt = 1 / duration, planner_timing.hpp):
///
///   I   C(s, a0, a1) = (a1 - a0) / 2 (1 - cos(pi s)) + a0            slow-in / slow-out
///   II  B(s, a0, a1, a2, a3) = sum_i b_i(s) a_i                        cubic Bezier (Bernstein
///   b_i) III V(s, a0, ..., a5) = B(B(s, 0, a4, a5, 1), a0, a1, a2, a3)      Bezier with Bezier
///   timing
///
/// Each works on a scalar (double) or on a fixed-size Eigen vector (the control points' type T).
/// The curves are plain polynomials (and a cosine): s outside [0, 1] extrapolates; the paths
/// (swing_foot_path.hpp, upper_body_path.hpp) clamp s. V with the identity warp a4 = 1/3,
/// a5 = 2/3 is B; with a4, a5 in [0, 1] the warp is nondecreasing on [0, 1] (so V traverses B's
/// points in order), because its derivative's Bernstein form a4 (1-s)^2 + 2 (a5 - a4) s (1-s) +
/// (1 - a5) s^2 has discriminant (a5 - a4)^2 - a4 (1 - a5) <= 0 there.
#include <array>
#include <cmath>
#include <numbers>

namespace gaitsynth {

/// The cubic Bernstein polynomials b_0..b_3 at s (A.3, type II).
inline std::array<double, 4> bernstein3(double s) {
  const double r = 1.0 - s;
  return {r * r * r, 3.0 * r * r * s, 3.0 * r * s * s, s * s * s};
}

/// d b_i / ds.
inline std::array<double, 4> bernstein3_derivative(double s) {
  const double r = 1.0 - s;
  return {-3.0 * r * r, 3.0 * r * (r - 2.0 * s), 3.0 * s * (2.0 * r - s), 3.0 * s * s};
}

/// Type I: C(s, a0, a1) = (a1 - a0) / 2 (1 - cos(pi s)) + a0. C(0) = a0, C(1) = a1, zero slope at
/// both ends, C(1 - s) - a0 = a1 - C(s) (point symmetry about s = 1/2).
template <class T>
T slow_in_out(double s, const T& a0, const T& a1) {
  return T(0.5 * (1.0 - std::cos(std::numbers::pi * s)) * (a1 - a0) + a0);
}

/// dC/ds = (a1 - a0) pi / 2 sin(pi s).
template <class T>
T slow_in_out_derivative(double s, const T& a0, const T& a1) {
  return T(0.5 * std::numbers::pi * std::sin(std::numbers::pi * s) * (a1 - a0));
}

/// Type II: B(s, a0, a1, a2, a3) = sum_i b_i(s) a_i.
template <class T>
T bezier(double s, const T& a0, const T& a1, const T& a2, const T& a3) {
  const std::array<double, 4> b = bernstein3(s);
  return T(b[0] * a0 + b[1] * a1 + b[2] * a2 + b[3] * a3);
}

/// dB/ds = 3 [(1-s)^2 (a1 - a0) + 2 (1-s) s (a2 - a1) + s^2 (a3 - a2)].
template <class T>
T bezier_derivative(double s, const T& a0, const T& a1, const T& a2, const T& a3) {
  const std::array<double, 4> d = bernstein3_derivative(s);
  return T(d[0] * a0 + d[1] * a1 + d[2] * a2 + d[3] * a3);
}

/// The time warp of type III, w(s) = B(s, 0, a4, a5, 1).
inline double bezier_time_warp(double s, double a4, double a5) {
  return bezier(s, 0.0, a4, a5, 1.0);
}

/// dw/ds.
inline double bezier_time_warp_derivative(double s, double a4, double a5) {
  return bezier_derivative(s, 0.0, a4, a5, 1.0);
}

/// Type III: V(s, a0..a5) = B(w(s), a0, a1, a2, a3), w(s) = B(s, 0, a4, a5, 1).
template <class T>
T warped_bezier(double s, const T& a0, const T& a1, const T& a2, const T& a3, double a4,
                double a5) {
  return bezier(bezier_time_warp(s, a4, a5), a0, a1, a2, a3);
}

/// dV/ds = B'(w(s)) w'(s) (chain rule).
template <class T>
T warped_bezier_derivative(double s, const T& a0, const T& a1, const T& a2, const T& a3, double a4,
                           double a5) {
  return T(bezier_time_warp_derivative(s, a4, a5) *
           bezier_derivative(bezier_time_warp(s, a4, a5), a0, a1, a2, a3));
}

}  // namespace gaitsynth
