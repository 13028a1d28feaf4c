#pragma once
/// \file objectives/wang2012/metabolic_rate.hpp
/// The rate of metabolic energy of one muscle (Wang et al. 2012 Sec. 5.1, after Anderson 1999 and
/// Bhargava, Pandy & Anderson 2004, J Biomech 37:81-88), in W:
///
///   E_dot = A_dot + M_dot + S_dot + W_dot
///   A_dot = m f_A(u)                      activation heat
///   M_dot = m g(l) f_M(a)                 maintenance heat
///   S_dot = 0.25 F_MTU {-v_CE}+           shortening heat        (Wang et al., as printed)
///   W_dot = F_CE {-v_CE}+                 positive work of the contractile element
///
/// with Bhargava et al.'s orderly recruitment (slow-twitch fibers first) for f_A and f_M:
///   f_A(u) = A_s r sin(pi u / 2) + A_f (1 - r)(1 - cos(pi u / 2)),  A_s = 40, A_f = 133 W/kg
///   f_M(a) = M_s r sin(pi a / 2) + M_f (1 - r)(1 - cos(pi a / 2)),  M_s = 74, M_f = 111 W/kg
/// r the fraction of slow-twitch fibers, g(l) Bhargava et al.'s piecewise-linear length
/// dependence through (0, 0.5), (0.5, 0.5), (1, 1), (1.5, 0), 0 beyond; l = l_CE / l_opt. The
/// muscle's mass is m = F_max / sigma * rho * l_opt (specific tension sigma = 0.25 MPa, density
/// rho = 1059.7 kg/m^3). Wang et al. print only the structure (their f_A, f_M and g are in their
/// supplement); these are the published forms they cite. r = 0.5 for every muscle is ours
/// (docs/reproductions/wang2012.md).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gaitsynth/actuators/musculotendon/contraction.hpp"

namespace gaitsynth::wang2012 {

struct metabolic_constants {
  double slow_twitch_ratio = 0.5;   ///< r (ours: the supplement's per-muscle values are unknown)
  double activation_slow = 40.0;    ///< A_s, W/kg
  double activation_fast = 133.0;   ///< A_f, W/kg
  double maintenance_slow = 74.0;   ///< M_s, W/kg
  double maintenance_fast = 111.0;  ///< M_f, W/kg
  double shortening_coefficient = 0.25;  ///< of F_MTU {-v_CE}+
  double specific_tension = 0.25e6;      ///< sigma, Pa
  double muscle_density = 1059.7;        ///< rho, kg / m^3
};

/// m = F_max / sigma * rho * l_opt, kg.
inline double muscle_mass(const musculotendon::unit_parameters& p,
                          const metabolic_constants& c = {}) {
  return p.max_isometric_force / c.specific_tension * c.muscle_density * p.optimal_fiber_length;
}

/// g(l): Bhargava et al.'s length dependence of the maintenance heat.
inline double maintenance_length_dependence(double l) {
  if (l <= 0.5) return 0.5;
  if (l <= 1.0) return l;
  if (l <= 1.5) return 3.0 - 2.0 * l;
  return 0.0;
}

/// Orderly recruitment of a W/kg rate: slow fibers (rate_slow, fraction r) first.
inline double recruited_rate(double x, double rate_slow, double rate_fast, double r) {
  const double s = std::clamp(x, 0.0, 1.0) * (std::numbers::pi / 2.0);
  return rate_slow * r * std::sin(s) + rate_fast * (1.0 - r) * (1.0 - std::cos(s));
}

/// The four rates of one muscle, W.
struct metabolic_rates {
  double activation = 0.0;   ///< A_dot
  double maintenance = 0.0;  ///< M_dot
  double shortening = 0.0;   ///< S_dot
  double work = 0.0;         ///< W_dot
  double total() const { return activation + maintenance + shortening + work; }
};

/// The rates of a muscle of mass `mass` (kg) at excitation u, activation a, normalized fiber
/// length l, fiber velocity v_ce (m/s, + lengthening), MTU force and contractile force (N).
inline metabolic_rates muscle_metabolic_rates(double mass, double u, double a, double l,
                                              double v_ce, double f_mtu, double f_ce,
                                              const metabolic_constants& c = {}) {
  const double shortening_speed = std::max(-v_ce, 0.0);
  const double r = c.slow_twitch_ratio;
  return {.activation = mass * recruited_rate(u, c.activation_slow, c.activation_fast, r),
          .maintenance = mass * maintenance_length_dependence(l) *
                         recruited_rate(a, c.maintenance_slow, c.maintenance_fast, r),
          .shortening = c.shortening_coefficient * std::max(f_mtu, 0.0) * shortening_speed,
          .work = std::max(f_ce, 0.0) * shortening_speed};
}

}  // namespace gaitsynth::wang2012
