#pragma once
/// \file actuators/musculotendon/contraction.hpp
/// One Hill-type musculotendon unit's dynamics (Wang et al. 2012 Sec. 3.1, Geyer & Herr 2010):
/// the contractile element (CE) with the parallel (PE) and buffer (BE) elements in parallel, in
/// series with an elastic tendon (SE). The tendon force is the MTU force:
///
///   F_MTU = F_SE(l_MTU - l_CE) = F_CE + F_PE - F_BE,   F_CE = a F_max f_L(l_CE) f_V(v_CE)
///
/// so the fiber velocity is what balances the tendon (Geyer & Herr 2010):
///   v_CE = l_opt f_V^-1((F_SE - F_PE + F_BE) / (a F_max f_L))            (equilibrium_velocity)
/// and the state (activation a, fiber length l_CE) advances per physics step h by
///   a   <- a + (h / tau_act) (u - a),  tau_act = 0.01 s                  (Wang et al. Sec. 3.1)
///   l_CE <- l_CE + h v(l_CE after the step)                               (advance_fiber)
/// The fiber step is a backward Euler step, solved to round-off, our choice: the fiber-tendon
/// equilibrium is stiff (a passive, stretched VAS moves its fiber at up to 10 vmax for a 60 N
/// imbalance), so explicit and linearly implicit steps at 2400 Hz chatter between the velocity
/// bounds; the backward step is stable at any h and keeps the equilibrium at the step's end.
///
/// Guards, so that no input gives a NaN (ours, named in docs/models.md): the ratio f is clamped
/// to [0, force_velocity(10 vmax)] (the fiber shortens at most at vmax and lengthens at most at
/// 10 vmax), and a f_L below 1e-6 is taken as 1e-6. The contractile element works with an
/// activation of at least minimum_activation (Geyer & Herr's pre-stimulation, 0.01), in the
/// velocity and in the isometric start alike. No function allocates.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gaitsynth/actuators/musculotendon/hill_curves.hpp"

namespace gaitsynth::musculotendon {

/// The muscle-specific values of one MTU (Geyer & Herr 2010 Table I).
struct unit_parameters {
  double max_isometric_force = 1000.0;    ///< F_max, N
  double optimal_fiber_length = 0.1;      ///< l_opt, m
  double tendon_slack_length = 0.2;       ///< l_slack, m
  double max_shortening_velocity = 12.0;  ///< v_max, optimal fiber lengths per second
};

/// Activation time constant: a_{t+1} = a_t + 100 h (u_t - a_t) (Wang et al. 2012 Sec. 3.1).
inline constexpr double activation_time_constant = 0.01;  // s
/// The least activation the fiber's velocity is computed with (Geyer & Herr 2010 pre-stimulation).
inline constexpr double minimum_activation = 0.01;

/// The forces of the elements at MTU length l_mtu and fiber length l_ce (N).
struct element_forces {
  double tendon = 0.0;    ///< F_SE = F_MTU
  double parallel = 0.0;  ///< F_PE
  double buffer = 0.0;    ///< F_BE
  /// What the contractile element carries in equilibrium: F_SE - F_PE + F_BE.
  double contractile() const { return tendon - parallel + buffer; }
};

inline element_forces forces_at(const unit_parameters& p, double l_mtu, double l_ce) noexcept {
  const double l = l_ce / p.optimal_fiber_length;
  const double strain = (l_mtu - l_ce - p.tendon_slack_length) / p.tendon_slack_length;
  return {.tendon = p.max_isometric_force * tendon_force(strain),
          .parallel = p.max_isometric_force * parallel_force(l),
          .buffer = p.max_isometric_force * buffer_force(l)};
}

/// force_velocity at 10 vmax: the largest ratio equilibrium_velocity inverts (see the guards).
inline constexpr double max_velocity_ratio = force_velocity(10.0, 1.0);

/// The equilibrium fiber velocity v (m/s) and its slope dv/dl_CE (1/s; 0 where a guard clamps).
struct velocity_and_slope {
  double velocity = 0.0;
  double slope = 0.0;
};

/// v_CE (m/s, + lengthening) that balances the tendon at (l_mtu, l_ce) with activation a, with
/// its derivative in l_ce (analytic: the Newton iteration of advance_fiber).
inline velocity_and_slope equilibrium_velocity_and_slope(const unit_parameters& p, double a,
                                                         double l_mtu, double l_ce) noexcept {
  const double F = p.max_isometric_force, lo = p.optimal_fiber_length;
  const double ls = p.tendon_slack_length, V = p.max_shortening_velocity;
  const double l = l_ce / lo;
  const double e = (l_mtu - l_ce - ls) / ls;
  // What the CE must carry (F_SE - F_PE + F_BE) and what it can at this length and activation.
  const double demand = F * (tendon_force(e) - parallel_force(l) + buffer_force(l));
  const double a_ce = std::max(a, minimum_activation);
  const force_length_and_slope fl = force_length_with_slope(l);
  const double strength = a_ce * fl.value;
  const double capacity = F * std::max(strength, 1e-6);
  const double ratio = demand / capacity;
  if (!(ratio > 0.0)) return {lo * fiber_velocity(0.0, V), 0.0};
  if (ratio >= max_velocity_ratio) return {lo * fiber_velocity(max_velocity_ratio, V), 0.0};
  const double d_demand =
      F * (-tendon_stiffness(e) / ls + (buffer_force_slope(l) - parallel_force_slope(l)) / lo);
  const double d_capacity = strength > 1e-6 ? F * a_ce * fl.slope / lo : 0.0;
  const double d_ratio = (d_demand * capacity - demand * d_capacity) / (capacity * capacity);
  return {lo * fiber_velocity(ratio, V), lo * fiber_velocity_slope(ratio, V) * d_ratio};
}

/// v_CE (m/s, + lengthening) that balances the tendon at (l_mtu, l_ce) with activation a.
inline double equilibrium_velocity(const unit_parameters& p, double a, double l_mtu,
                                   double l_ce) noexcept {
  return equilibrium_velocity_and_slope(p, a, l_mtu, l_ce).velocity;
}

/// The fiber length after one step h of the fiber at (a, l_mtu): the backward Euler step, the
/// root of l_new = l_ce + h v(l_new), by Newton's method (analytic slope) on the bracket
/// [l_ce - h vmax l_opt, l_ce + 10 h vmax l_opt] that the velocity's bounds guarantee, halving
/// the bracket whenever a Newton step leaves it or the slope is not positive. It starts from
/// l_ce + h v_guess (the last step's velocity: the fiber's velocity changes little per step), or
/// from the explicit step when v_guess is not finite. Converges to 1e-12 l_opt, in 1-3
/// iterations when the fiber is near equilibrium; 60 at most.
inline double advance_fiber(const unit_parameters& p, double a, double l_mtu, double l_ce, double h,
                            double v_guess = std::numeric_limits<double>::quiet_NaN()) noexcept {
  const double reach = h * p.max_shortening_velocity * p.optimal_fiber_length;
  double lo = l_ce - reach, hi = l_ce + 10.0 * reach;
  const double tol = 1e-12 * p.optimal_fiber_length;
  const double v0 = std::isfinite(v_guess) ? v_guess : equilibrium_velocity(p, a, l_mtu, l_ce);
  double x = std::clamp(l_ce + h * v0, lo, hi);
  for (int it = 0; it < 60; ++it) {
    const velocity_and_slope vs = equilibrium_velocity_and_slope(p, a, l_mtu, x);
    const double r = x - l_ce - h * vs.velocity;  // increasing in x wherever v falls with l
    if (std::abs(r) <= tol) break;
    (r > 0.0 ? hi : lo) = x;
    const double slope = 1.0 - h * vs.slope;
    double next = slope > 1e-3 ? x - r / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = next;
  }
  return x;
}

/// The activation after one step h with excitation u (clamped to [0, 1]).
inline double advance_activation(double a, double u, double h) noexcept {
  return a + (h / activation_time_constant) * (std::clamp(u, 0.0, 1.0) - a);
}

/// The fiber length at which the unit is in isometric equilibrium (v_CE = 0) at MTU length l_mtu
/// and activation a: F_SE = max(a, minimum_activation) F_max f_L + F_PE - F_BE, by bisection on [0,
/// l_mtu] (64 halvings, to the last bits; for the start of a rollout, not the step loop). Needs
/// l_mtu >= l_min l_opt (a shorter MTU is a geometry error), which the caller checks.
inline double isometric_fiber_length(const unit_parameters& p, double a, double l_mtu) noexcept {
  const double a_ce = std::max(a, minimum_activation);
  auto residual = [&](double l_ce) {
    const element_forces f = forces_at(p, l_mtu, l_ce);
    return f.contractile() -
           a_ce * p.max_isometric_force * force_length(l_ce / p.optimal_fiber_length);
  };
  double lo = 0.0, hi = l_mtu;  // residual(lo) > 0 (buffer), residual(hi) < 0 (slack tendon)
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace gaitsynth::musculotendon
