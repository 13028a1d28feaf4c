#pragma once
/// \file actuators/pd.hpp
/// Proportional-derivative servos at every joint DOF (Wang et al. 2009, Eq. 1):
///   tau_j = kp_j (theta_d_j - q_j) - kd_j qdot_j  [+ tau_ff_j],  clamped to +-torque_limit_j.
/// The command is the target angles theta_d (num_joint_dofs, rad); with `feedforward`, it is
/// followed by a feed-forward torque per DOF (2 num_joint_dofs), which SIMBICON-style controllers
/// use for torques computed in the world frame. Gains are fixed per actuator; a controller whose
/// gains are optimized computes its torques itself and uses torque_actuator.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// Effective inertia (kg m^2) of each joint DOF at the neutral configuration: 1 / (M^-1)_jj, with
/// M the joint-space inertia (crba). It is the inertia a torque at DOF j meets when every other
/// coordinate, the floating root included, is free: the relative inertia of the two segments the
/// joint connects (a foot and the rest of the body), smaller than M_jj, which locks the rest.
template <root_joint Root>
Eigen::VectorXd joint_effective_inertia(const model<Root>& m) {
  auto ws = make_workspace(m);
  const Eigen::MatrixXd& M = crba(m, ws, neutral_configuration(m));
  const Eigen::MatrixXd Minv = M.ldlt().solve(Eigen::MatrixXd::Identity(m.nv(), m.nv()));
  return Minv.diagonal().tail(m.num_joint_dofs()).cwiseInverse();
}

struct pd_actuator {
  using state_type = no_actuator_state;

  Eigen::VectorXd kp;  ///< N m / rad, per joint DOF
  Eigen::VectorXd kd;  ///< N m s / rad, per joint DOF
  bool feedforward = false;

  pd_actuator() = default;
  pd_actuator(Eigen::VectorXd kp_, Eigen::VectorXd kd_, bool feedforward_ = false)
      : kp(std::move(kp_)), kd(std::move(kd_)), feedforward(feedforward_) {}

  /// The same gains at every joint DOF of m.
  /// \throws std::invalid_argument naming a gain that is not finite and >= 0.
  template <root_joint Root>
  static pd_actuator uniform(const model<Root>& m, double kp, double kd, bool feedforward = false) {
    check_argument(std::isfinite(kp) && kp >= 0.0,
                   "pd_actuator::uniform: kp must be finite and >= 0, got ", kp);
    check_argument(std::isfinite(kd) && kd >= 0.0,
                   "pd_actuator::uniform: kd must be finite and >= 0, got ", kd);
    const int nj = m.num_joint_dofs();
    return pd_actuator(Eigen::VectorXd::Constant(nj, kp), Eigen::VectorXd::Constant(nj, kd),
                       feedforward);
  }

  /// Gains kp, kd capped so that explicit PD servos stay stable at timestep dt.
  ///
  /// Why: the PD torque is explicit. One joint of inertia I under semi-implicit Euler is stable iff
  /// kp dt^2 / I + 2 kd dt / I < 4 (Jury's test on its 2 x 2 step matrix). For the whole tree the
  /// matrix form is lambda_max(M^-1 (Kp dt^2 + 2 Kd dt)) < 4 with M the joint-space inertia, and
  /// the light distal joints couple: with the published SIMBICON gains (ankle kp 300, kd 30, toe kd
  /// 2, Wang et al. 2009 Table 2), the Wang 2009 humanoid's feet and toes chatter at the Nyquist
  /// frequency at 2400 Hz (its ankle_y has I = 3.5e-3 kg m^2: 2 kd dt / I = 7). ODE, which the
  /// papers used, pinned the feet with hard contact constraints, which hid this.
  ///
  /// How: every DOF j gets kd_j <= c I_j / dt and kp_j <= c I_j / dt^2, I_j its effective inertia
  /// (joint_effective_inertia), with the largest c (bisection) for which
  /// lambda_max(M^-1 (Kp dt^2 + 2 Kd dt)) <= 2 margin at the neutral configuration. Heavy joints
  /// keep their gains; only the light ones are softened. margin 1 keeps half the stable range.
  template <root_joint Root>
  static pd_actuator capped(const model<Root>& m, const Eigen::VectorXd& kp,
                            const Eigen::VectorXd& kd, double dt, double margin = 1.0,
                            bool feedforward = false) {
    check_positive(dt, "pd_actuator::capped: dt (s)");
    check_positive(margin, "pd_actuator::capped: margin");
    const int nj = m.num_joint_dofs(), nv = m.nv();
    check_size(kp.size(), nj, "pd_actuator::capped: kp (one gain per joint DOF)");
    check_size(kd.size(), nj, "pd_actuator::capped: kd (one gain per joint DOF)");
    pd_actuator(kp, kd).make_state(m);  // validates finite, >= 0
    auto ws = make_workspace(m);
    const Eigen::MatrixXd M = crba(m, ws, neutral_configuration(m));
    const Eigen::MatrixXd Minv = M.ldlt().solve(Eigen::MatrixXd::Identity(nv, nv));
    const Eigen::VectorXd I = Minv.diagonal().tail(nj).cwiseInverse();
    auto gains_at = [&](double c, Eigen::VectorXd& kp_c, Eigen::VectorXd& kd_c) {
      kp_c = kp.cwiseMin(c / (dt * dt) * I);
      kd_c = kd.cwiseMin(c / dt * I);
    };
    auto rate = [&](const Eigen::VectorXd& kp_c, const Eigen::VectorXd& kd_c) {
      Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv, nv);
      K.diagonal().tail(nj) = kp_c * (dt * dt) + 2.0 * dt * kd_c;
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
      return es.eigenvalues().maxCoeff();
    };
    Eigen::VectorXd kp_c = kp, kd_c = kd;
    if (rate(kp_c, kd_c) > 2.0 * margin) {
      double lo = 0.0, hi = 4.0;  // c = 4 caps nothing a stable single joint could have
      for (int it = 0; it < 40; ++it) {
        const double c = 0.5 * (lo + hi);
        gains_at(c, kp_c, kd_c);
        (rate(kp_c, kd_c) <= 2.0 * margin ? lo : hi) = c;
      }
      gains_at(lo, kp_c, kd_c);
    }
    return pd_actuator(std::move(kp_c), std::move(kd_c), feedforward);
  }

  /// Validates the gains against the model (sizes, finite, >= 0); throws std::invalid_argument
  /// naming the DOF and value.
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    const int nj = m.num_joint_dofs();
    check_size(kp.size(), nj, "pd_actuator kp (one gain per joint DOF)");
    check_size(kd.size(), nj, "pd_actuator kd (one gain per joint DOF)");
    for (int j = 0; j < nj; ++j) {
      check_argument(std::isfinite(kp[j]) && kp[j] >= 0, "pd_actuator: kp of DOF ", j, " ('",
                     m.dofs[j].name, "') must be finite and >= 0, got ", kp[j]);
      check_argument(std::isfinite(kd[j]) && kd[j] >= 0, "pd_actuator: kd of DOF ", j, " ('",
                     m.dofs[j].name, "') must be finite and >= 0, got ", kd[j]);
    }
    return {};
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return (feedforward ? 2 : 1) * m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_target; }

  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type&, Eigen::Ref<Eigen::VectorXd> tau) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      double t = pd_torque(kp[j], kd[j], cmd[j], s.q[Root::nq + j], s.v[Root::nv + j]);
      if (feedforward) t += cmd[nj + j];
      tau[j] = clamp_torque(t, m.dofs[j].torque_limit);
    }
  }

  /// The joint-rate coefficient of each DOF's law (actuators/concept.hpp, joint_damping): kd_j,
  /// also where the torque is clamped (see mixed_pd_actuator::joint_damping).
  template <root_joint Root>
  void joint_damping(const model<Root>& m, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
                     const state_type&, Eigen::Ref<Eigen::VectorXd> c) const {
    c = kd.head(m.num_joint_dofs());
  }
};

/// PD servos that hold a biped in a standing pose at timestep dt (tests, benchmarks, demos):
/// kp = 1000 N m/rad at hips, knees, ankles and back (above the m g h ~ 600 N m/rad a 70 kg
/// body toppling about its ankles needs), 20 at toes (Wang et al. 2009 Table 2), 100 elsewhere
/// (neck, arms), kd = 0.1 kp (Table 2), then capped for stability (pd_actuator::capped). DOFs are
/// recognized by name ("hip", "knee", "ankle", "back", "toe"), as the built-in characters name
/// them; `scale` multiplies every gain before the caps.
template <root_joint Root>
pd_actuator standing_pd(const model<Root>& m, double dt, double scale = 1.0) {
  check_positive(scale, "standing_pd: scale");
  Eigen::VectorXd kp(m.num_joint_dofs());
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const std::string& n = m.dofs[j].name;
    auto has = [&](const char* s) { return n.find(s) != std::string::npos; };
    kp[j] = has("toe")                                                   ? 20.0
            : (has("hip") || has("knee") || has("ankle") || has("back")) ? 1000.0
                                                                         : 100.0;
  }
  kp *= scale;
  return pd_actuator::capped(m, kp, 0.1 * kp, dt);
}

}  // namespace gaitsynth
