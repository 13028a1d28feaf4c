#pragma once
/// \file controllers/reflex/reflex_laws.hpp
/// The building blocks of the muscle-reflex controller of Wang et al. 2012 Sec. 4.1 (after Geyer &
/// Herr 2010): each maps a time-delayed feature of the body to a muscle excitation. The caller
/// reads the delayed feature (sensors::delayed_sensed for MTU force and fiber length,
/// sensors::delayed_joint_angle, delayed body rotations) with the MTU's neural delay
/// (reflex_delays) and sums the laws with the pre-stimulation; the actuator clamps the sum to
/// [0, 1].
///
///   force_feedback(G, F)            u^F = G F~(t - dt_m)                     positive force
///   feedback length_feedback(G, l, H)        u^L = {G (l~(t - dt_m) - H)}+            positive
///   length feedback muscle_pd(K, D, th, thd, th_m, opposes)
///                                   u^th = |{K (th(t - dt_m) - th_m) + D thd(t - dt_m)}+-|
///                                   + when the MTU's torque opposes th (a hip extensor and the
///                                   hip flexion angle), - otherwise: each MTU pulls one way only
///   knee_extension_suppression(k, th_k, thd_k, th_off)
///                                   {k (th_k - th_off)}-, only while the knee extends (thd_k < 0)
///                                   (the VAS law of Sec. 4.2; th_k the knee flexion angle)
#include <algorithm>

namespace gaitsynth::reflex {

/// The neural delays of Geyer & Herr 2010 that Wang et al. 2012 Sec. 4.1 use (s).
struct reflex_delays {
  static constexpr double hip = 0.005;      ///< MTUs on the hip (GLU, HFL, HAM, RF)
  static constexpr double knee = 0.010;     ///< VAS, and ground contact
  static constexpr double contact = 0.010;  ///< ground contact
  static constexpr double ankle = 0.020;    ///< MTUs on the ankle (SOL, TA, GAS)
};

/// u^F = G F~ (F~: the MTU force over F_max, delayed).
constexpr double force_feedback(double gain, double normalized_force) noexcept {
  return gain * normalized_force;
}

/// u^L = max(G (l~ - H), 0) (l~: the fiber length over l_opt, delayed).
constexpr double length_feedback(double gain, double normalized_length, double offset) noexcept {
  return std::max(gain * (normalized_length - offset), 0.0);
}

/// u^th of a muscle-driven PD law on angle th (rad) and rate thd (rad/s), delayed.
constexpr double muscle_pd(double kp, double kd, double angle, double rate, double target,
                           bool opposes_angle) noexcept {
  const double x = kp * (angle - target) + kd * rate;
  return opposes_angle ? std::max(x, 0.0) : std::max(-x, 0.0);
}

/// The VAS's suppression of Sec. 4.2: min(k (th_k - th_off), 0) while the knee extends
/// (knee_rate < 0), else 0 (th_k: knee flexion, rad).
constexpr double knee_extension_suppression(double gain, double knee_flexion, double knee_rate,
                                            double offset) noexcept {
  return knee_rate < 0.0 ? std::min(gain * (knee_flexion - offset), 0.0) : 0.0;
}

}  // namespace gaitsynth::reflex
