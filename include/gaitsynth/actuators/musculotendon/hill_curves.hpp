#pragma once
/// \file actuators/musculotendon/hill_curves.hpp
/// The normalized curves of the Hill-type musculotendon unit of Geyer & Herr 2010 (IEEE TNSRE
/// 18(3), Appendix; the force-velocity relation from Geyer, Seyfarth & Blickhan 2003), the model
/// Wang et al. 2012 Sec. 3.1 defers to. Lengths are normalized by the optimal fiber length l_opt
/// (fiber) or the tendon slack length l_slack (tendon), velocities by l_opt per second, forces by
/// the maximum isometric force F_max. Fiber velocity is positive when the fiber lengthens.
///
///   force_length(l)        f_L = exp(c |(l - 1) / w|^3)                         (CE)
///   force_velocity(v, V)   f_V = (V + v) / (V - K v)                     v < 0  (shortening)
///                              = N + (N - 1) (v - V) / (7.56 K v + V)     v >= 0 (lengthening)
///   fiber_velocity(f, V)   the inverse of force_velocity in v (f below its asymptote)
///   tendon_force(e)        f_SE = (e / e_ref)^2 for tendon strain e > 0, else 0
///   parallel_force(l)      f_PE = ((l - 1) / w)^2 for l > 1, else 0
///   buffer_force(l)        f_BE = ((l_min - l) / (w / 2))^2 for l < l_min = 1 - w, else 0
///   *_slope, tendon_stiffness   their derivatives (the fiber step's Newton iteration)
///   force_length_with_slope     f_L and its slope from one exp
///
/// with w = 0.56, c = ln 0.05, N = 1.5, K = 5, e_ref = 0.04 (Geyer & Herr 2010, Table I's shared
/// values), and V = v_max in l_opt / s (6 for SOL, 12 for the others). The parallel element
/// stretches beyond l_opt; the buffer element keeps a slack fiber from collapsing to zero length.
/// Each function is a pure scalar expression (no allocation, no branches on anything but the
/// curve's own piece).
#include <cmath>

namespace gaitsynth::musculotendon {

/// The shared constants of Geyer & Herr 2010 (Table I).
struct hill_constants {
  static constexpr double width = 0.56;                    ///< w, of the force-length curve (l_opt)
  static constexpr double residual_force = 0.05;           ///< f_L at l = 1 +- w (so c = ln 0.05)
  static constexpr double eccentric_enhancement = 1.5;     ///< N, f_V's limit when lengthening fast
  static constexpr double shape_factor = 5.0;              ///< K, of the force-velocity curve
  static constexpr double tendon_reference_strain = 0.04;  ///< e_ref: f_SE = 1 at this strain
  static constexpr double buffer_length = 1.0 - width;     ///< l_min (l_opt)
  static constexpr double buffer_strain = 0.5 * width;     ///< of the buffer element (l_opt)
};

/// f_L(l): active force at normalized fiber length l (1 at l = 1, 0.05 at 1 +- w).
inline double force_length(double l) noexcept {
  const double x = std::abs((l - 1.0) / hill_constants::width);
  return std::exp(std::log(hill_constants::residual_force) * x * x * x);
}

/// f_L and d f_L / d l together, with one exp (the fiber step's Newton iteration needs both).
struct force_length_and_slope {
  double value = 0.0;
  double slope = 0.0;
};

inline force_length_and_slope force_length_with_slope(double l) noexcept {
  const double f = force_length(l);
  const double x = (l - 1.0) / hill_constants::width;
  return {f, f * std::log(hill_constants::residual_force) * 3.0 * x * std::abs(x) /
                 hill_constants::width};
}

/// d f_L / d l.
inline double force_length_slope(double l) noexcept {
  return force_length_with_slope(l).slope;
}

/// f_V(v): active force at normalized fiber velocity v (l_opt / s, + lengthening) for a muscle
/// of maximum shortening velocity vmax (l_opt / s, > 0): 0 at v = -vmax, 1 at 0, rising toward
/// N + (N - 1) / (7.56 K) when lengthening. Below -vmax it is negative (callers clamp v).
constexpr double force_velocity(double v, double vmax) noexcept {
  constexpr double N = hill_constants::eccentric_enhancement;
  constexpr double K = hill_constants::shape_factor;
  if (v < 0.0) return (vmax + v) / (vmax - K * v);
  return N + (N - 1.0) * (v - vmax) / (7.56 * K * v + vmax);
}

/// The supremum of force_velocity (approached as v -> infinity): N + (N - 1) / (7.56 K).
inline constexpr double force_velocity_limit =
    hill_constants::eccentric_enhancement +
    (hill_constants::eccentric_enhancement - 1.0) / (7.56 * hill_constants::shape_factor);

/// The inverse of force_velocity: the normalized velocity v with f_V(v) = f, for
/// 0 <= f < force_velocity_limit (f < 0 gives v < -vmax; f at or beyond the limit +inf).
constexpr double fiber_velocity(double f, double vmax) noexcept {
  constexpr double N = hill_constants::eccentric_enhancement;
  constexpr double K = hill_constants::shape_factor;
  if (f < 1.0) return vmax * (f - 1.0) / (1.0 + K * f);
  return vmax * (f - 1.0) / ((N - 1.0) - 7.56 * K * (f - N));
}

/// d v / d f of fiber_velocity (same domain).
constexpr double fiber_velocity_slope(double f, double vmax) noexcept {
  constexpr double N = hill_constants::eccentric_enhancement;
  constexpr double K = hill_constants::shape_factor;
  if (f < 1.0) return vmax * (1.0 + K) / ((1.0 + K * f) * (1.0 + K * f));
  const double d = (N - 1.0) - 7.56 * K * (f - N);
  return vmax * (d + 7.56 * K * (f - 1.0)) / (d * d);
}

/// f_SE(e): tendon force at strain e = (l_SE - l_slack) / l_slack (1 at e = e_ref).
constexpr double tendon_force(double e) noexcept {
  if (e <= 0.0) return 0.0;
  const double x = e / hill_constants::tendon_reference_strain;
  return x * x;
}

/// d f_SE / d e: the tendon's normalized stiffness.
constexpr double tendon_stiffness(double e) noexcept {
  if (e <= 0.0) return 0.0;
  constexpr double er = hill_constants::tendon_reference_strain;
  return 2.0 * e / (er * er);
}

/// f_PE(l): the parallel element's force at normalized fiber length l.
constexpr double parallel_force(double l) noexcept {
  if (l <= 1.0) return 0.0;
  const double x = (l - 1.0) / hill_constants::width;
  return x * x;
}

/// d f_PE / d l.
constexpr double parallel_force_slope(double l) noexcept {
  if (l <= 1.0) return 0.0;
  return 2.0 * (l - 1.0) / (hill_constants::width * hill_constants::width);
}

/// f_BE(l): the buffer element's force, pushing a fiber shorter than l_min back out.
constexpr double buffer_force(double l) noexcept {
  if (l >= hill_constants::buffer_length) return 0.0;
  const double x = (hill_constants::buffer_length - l) / hill_constants::buffer_strain;
  return x * x;
}

/// d f_BE / d l (<= 0).
constexpr double buffer_force_slope(double l) noexcept {
  if (l >= hill_constants::buffer_length) return 0.0;
  return -2.0 * (hill_constants::buffer_length - l) /
         (hill_constants::buffer_strain * hill_constants::buffer_strain);
}

}  // namespace gaitsynth::musculotendon
