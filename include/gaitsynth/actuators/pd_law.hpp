#pragma once
/// \file actuators/pd_law.hpp
/// The PD servo law (Wang et al. 2009, Eq. 1), written once for every actuator and controller that
/// applies or inverts it:
///
///   pd_torque(kp, kd, target, q, qdot)          = kp (target - q) - kd qdot
///   pd_target_for_torque(kp, kd, tau, q, qdot)  = q + (tau + kd qdot) / kp   (kp != 0)
///   clamp_torque(t, limit)                      = t clamped to [-limit, limit]; NaN stays NaN
///
/// Each is exactly the floating-point expression written above, evaluated in that order (the saved
/// Sharon 2005 controllers depend on bit-exact rollouts, docs/performance.md "Rounding"). The
/// vector form of pd_torque is the same law per coefficient as one Eigen expression,
/// kp.cwiseProduct(target - q) - kd.cwiseProduct(qdot), for callers that servo a whole pose at
/// once; it returns the unevaluated expression (no temporary, no allocation). Feed-forward
/// torques are added by the caller after the law and before the clamp.
#include <Eigen/Core>

namespace gaitsynth {

/// kp (target - q) - kd qdot: N m for gains in N m / rad and N m s / rad, angles in rad.
constexpr double pd_torque(double kp, double kd, double target, double q, double qdot) noexcept {
  return kp * (target - q) - kd * qdot;
}

/// The same law per coefficient: kp.cwiseProduct(target - q) - kd.cwiseProduct(qdot), returned
/// as an Eigen expression (assign it; its operands must outlive the assignment).
template <class Kp, class Kd, class Target, class Q, class Qdot>
auto pd_torque(const Eigen::MatrixBase<Kp>& kp, const Eigen::MatrixBase<Kd>& kd,
               const Eigen::MatrixBase<Target>& target, const Eigen::MatrixBase<Q>& q,
               const Eigen::MatrixBase<Qdot>& qdot) {
  return kp.cwiseProduct(target - q) - kd.cwiseProduct(qdot);
}

/// The inverse of pd_torque in the target: the target whose PD torque at (q, qdot) is tau,
/// q + (tau + kd qdot) / kp. Needs kp != 0 (the caller checks; kp = 0 gives +-inf or NaN).
/// pd_torque(kp, kd, pd_target_for_torque(kp, kd, tau, q, qdot), q, qdot) equals tau up to
/// rounding.
constexpr double pd_target_for_torque(double kp, double kd, double tau, double q,
                                      double qdot) noexcept {
  return q + (tau + kd * qdot) / kp;
}

/// t clamped to [-limit, limit] (limit >= 0), as the actuators apply each DOF's torque limit.
/// A NaN torque stays NaN (the rollout then reports a non-finite state instead of silently
/// clamping garbage to a limit).
constexpr double clamp_torque(double t, double limit) noexcept {
  return t > limit ? limit : (t < -limit ? -limit : t);
}

}  // namespace gaitsynth
