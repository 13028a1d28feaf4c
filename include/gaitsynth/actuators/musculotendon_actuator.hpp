#pragma once
/// \file actuators/musculotendon_actuator.hpp
/// Hill-type musculotendon units on some joint DOFs and PD servos on all of them, in one actuator
/// policy (Wang et al. 2012 Sec. 3: sixteen MTUs drive the sagittal hips, knees and ankles; the
/// other DOFs are PD-controlled). Its own state holds each MTU's activation and fiber length.
///
/// Command (command_kind::excitation): M excitations u_i in [0, 1] (clamped), then the mixed
/// block of mixed_pd_actuator (4 num_joint_dofs: targets, kp, kd, feed-forward torques). Torques:
///
///   tau_j = clamp_torque(pd_torque(kp_j, kd_j, target_j, q_j, qdot_j) + tau_ff_j, limit_j)
///           + sum over MTUs spanning j of  s r(phi) F_MTU          (path.hpp; never clamped)
///
/// A DOF driven only by muscles has zero gains and zero torque in the mixed block (the reflex
/// controller writes it so); the soft joint limits of the model (Geyer & Herr 2010) are the
/// rollout's passive torques, not the actuator's.
///
/// The MTU force is the tendon's, F_SE(l_MTU(q) - l_CE): a pure function of q and the state, so
/// torques() is one too. Per physics step, after the rigid-body step (rollout.hpp, 7.), advance()
/// moves a and then l_CE at the step's end configuration (contraction.hpp), and stores what the
/// sensors and the metabolic objective read: F_MTU, F_CE, v_CE, l_MTU and u. start() puts every
/// fiber in isometric equilibrium at the start pose and the initial activation, so a rollout
/// starts without a tendon transient.
///
/// Sensed values (sense(), the reflexes' inputs): F_MTU / F_max for each MTU, then l_CE / l_opt.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// What a musculotendon_actuator keeps per rollout: one entry per MTU in each vector.
struct musculotendon_state {
  Eigen::VectorXd activation;      ///< a in [0, 1]
  Eigen::VectorXd fiber_length;    ///< l_CE, m
  Eigen::VectorXd excitation;      ///< u of the last step, clamped to [0, 1]
  Eigen::VectorXd mtu_length;      ///< l_MTU at the last advance/start, m
  Eigen::VectorXd force;           ///< F_MTU = F_SE, N
  Eigen::VectorXd active_force;    ///< F_CE (the equilibrium's CE share), N
  Eigen::VectorXd fiber_velocity;  ///< v_CE of the last step, m/s (+ lengthening)
  Eigen::VectorXd moment_arm;      ///< r(phi) of each MTU's crossings at the last advance/start
                                   ///< (2 per MTU), m
  Eigen::VectorXd joint_angles;    ///< the joint DOFs at the last advance/start (NaN before)
};

class musculotendon_actuator {
 public:
  using state_type = musculotendon_state;

  /// units: the MTUs (e.g. musculotendon::geyer_herr_leg_muscles(model)); initial_activation: a
  /// at the start of a rollout, in [0, 1].
  explicit musculotendon_actuator(std::vector<musculotendon::unit> units,
                                  double initial_activation = musculotendon::minimum_activation)
      : units_(std::move(units)), initial_activation_(initial_activation) {
    reference_sines_.reserve(units_.size());
    check_argument(initial_activation >= 0.0 && initial_activation <= 1.0,
                   "musculotendon_actuator: initial_activation must be in [0, 1], got ",
                   initial_activation);
    for (const auto& u : units_) {
      const auto& p = u.parameters;
      check_argument(p.max_isometric_force > 0.0 && p.optimal_fiber_length > 0.0 &&
                         p.tendon_slack_length > 0.0 && p.max_shortening_velocity > 0.0,
                     "musculotendon_actuator: MTU '", u.name,
                     "' needs positive F_max, l_opt, l_slack and v_max, got ",
                     p.max_isometric_force, ", ", p.optimal_fiber_length, ", ",
                     p.tendon_slack_length, ", ", p.max_shortening_velocity);
      check_argument(u.num_crossings == 1 || u.num_crossings == 2, "musculotendon_actuator: MTU '",
                     u.name, "' spans 1 or 2 DOFs, got ", u.num_crossings);
      reference_sines_.push_back(u.reference_sines());
    }
  }

  const std::vector<musculotendon::unit>& units() const { return units_; }
  int num_units() const { return static_cast<int>(units_.size()); }
  double initial_activation() const { return initial_activation_; }

  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    const int nj = m.num_joint_dofs();
    for (const auto& u : units_)
      for (int c = 0; c < u.num_crossings; ++c)
        check_argument(u.crossings[c].dof >= 0 && u.crossings[c].dof < nj,
                       "musculotendon_actuator: MTU '", u.name, "' spans DOF ", u.crossings[c].dof,
                       ", the model has ", nj, " joint DOFs");
    const Eigen::Index n = num_units();
    state_type st{Eigen::VectorXd(n), Eigen::VectorXd(n),     Eigen::VectorXd(n),
                  Eigen::VectorXd(n), Eigen::VectorXd(n),     Eigen::VectorXd(n),
                  Eigen::VectorXd(n), Eigen::VectorXd(2 * n), Eigen::VectorXd(nj)};
    reset_state(m, st);
    return st;
  }
  /// As make_state, in place (no allocation). Fiber lengths are NaN until start().
  template <root_joint Root>
  void reset_state(const model<Root>&, state_type& st) const {
    st.activation.setConstant(initial_activation_);
    st.fiber_length.setConstant(std::numeric_limits<double>::quiet_NaN());
    st.excitation.setConstant(initial_activation_);
    st.mtu_length.setZero();
    st.force.setZero();
    st.active_force.setZero();
    st.fiber_velocity.setZero();
    st.moment_arm.setZero();
    st.joint_angles.setConstant(std::numeric_limits<double>::quiet_NaN());
  }

  /// Every fiber in isometric equilibrium at s's pose and the current activation. Throws
  /// std::invalid_argument naming an MTU shorter than its buffer length (a pose outside its
  /// geometry).
  template <root_joint Root>
  void start(const model<Root>&, const sim_state& s, state_type& st) const {
    const auto qj = s.q.tail(s.q.size() - Root::nq);
    for (int i = 0; i < num_units(); ++i) {
      const auto& u = units_[static_cast<std::size_t>(i)];
      const auto& p = u.parameters;
      const double l_mtu = path(i, qj, st);
      check_argument(l_mtu > musculotendon::hill_constants::buffer_length * p.optimal_fiber_length,
                     "musculotendon_actuator: MTU '", u.name, "' is ", l_mtu,
                     " m long at the start pose, shorter than its fiber can be");
      st.fiber_length[i] = musculotendon::isometric_fiber_length(p, st.activation[i], l_mtu);
      store(i, p, l_mtu, 0.0, st);
    }
    st.joint_angles = qj;
  }

  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return num_units() + 4 * m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::excitation; }

  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type& st, Eigen::Ref<Eigen::VectorXd> tau) const {
    const int nj = m.num_joint_dofs();
    const int M = num_units();
    for (int j = 0; j < nj; ++j) {
      const double t = pd_torque(cmd[M + nj + j], cmd[M + 2 * nj + j], cmd[M + j],
                                 s.q[Root::nq + j], s.v[Root::nv + j]) +
                       cmd[M + 3 * nj + j];
      tau[j] = clamp_torque(t, m.dofs[j].torque_limit);
    }
    const auto qj = s.q.tail(nj);
    // At the configuration of the last advance (the rollout's case: advance, then the next step's
    // torques) the stored force and arms are these torques' to the bit; elsewhere, recomputed.
    if ((st.joint_angles.array() == qj.array()).all()) {
      for (int i = 0; i < M; ++i) {
        const auto& u = units_[static_cast<std::size_t>(i)];
        for (int c = 0; c < u.num_crossings; ++c)
          tau[u.crossings[c].dof] +=
              u.crossings[c].torque_with_arm(st.moment_arm[2 * i + c], st.force[i]);
      }
      return;
    }
    for (int i = 0; i < M; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const auto& u = units_[k];
      std::array<double, 2> arms{};
      const double l_mtu = u.length_and_arms(qj, reference_sines_[k], arms);
      const double force = musculotendon::forces_at(u.parameters, l_mtu, st.fiber_length[i]).tendon;
      for (int c = 0; c < u.num_crossings; ++c)
        tau[u.crossings[c].dof] += u.crossings[c].torque_with_arm(arms[c], force);
    }
  }

  /// kd_j of the mixed block (as mixed_pd_actuator::joint_damping); the muscles add none.
  template <root_joint Root>
  void joint_damping(const model<Root>& m, const sim_state&, Eigen::Ref<const Eigen::VectorXd> cmd,
                     const state_type&, Eigen::Ref<Eigen::VectorXd> c) const {
    const int nj = m.num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      const double kd = cmd[num_units() + 2 * nj + j];
      c[j] = (kd > 0.0 && kd < std::numeric_limits<double>::infinity()) ? kd : 0.0;
    }
  }

  /// One physics step h: activation from the step's excitation, then the fiber at the end pose s.
  template <root_joint Root>
  void advance(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               state_type& st, double h) const {
    const auto qj = s.q.tail(m.num_joint_dofs());
    for (int i = 0; i < num_units(); ++i) {
      const auto& u = units_[static_cast<std::size_t>(i)];
      const auto& p = u.parameters;
      st.excitation[i] = std::clamp(cmd[i], 0.0, 1.0);
      st.activation[i] = musculotendon::advance_activation(st.activation[i], cmd[i], h);
      const double l_mtu = path(i, qj, st);
      const double l_old = st.fiber_length[i];
      st.fiber_length[i] =
          musculotendon::advance_fiber(p, st.activation[i], l_mtu, l_old, h, st.fiber_velocity[i]);
      store(i, p, l_mtu, (st.fiber_length[i] - l_old) / h, st);
    }
    st.joint_angles = qj;
  }

  template <root_joint Root>
  int sensed_size(const model<Root>&) const {
    return 2 * num_units();
  }
  /// F_MTU / F_max per MTU, then l_CE / l_opt per MTU.
  template <root_joint Root>
  void sense(const model<Root>&, const state_type& st, std::span<double> out) const {
    const int M = num_units();
    for (int i = 0; i < M; ++i) {
      const auto& p = units_[static_cast<std::size_t>(i)].parameters;
      out[static_cast<std::size_t>(i)] = st.force[i] / p.max_isometric_force;
      out[static_cast<std::size_t>(M + i)] = st.fiber_length[i] / p.optimal_fiber_length;
    }
  }

 private:
  /// l_MTU of MTU i at joint angles qj, with its crossings' arms written to st.moment_arm.
  template <class Joints>
  double path(int i, const Joints& qj, state_type& st) const {
    const auto k = static_cast<std::size_t>(i);
    std::array<double, 2> arms{};
    const double l = units_[k].length_and_arms(qj, reference_sines_[k], arms);
    st.moment_arm[2 * i] = arms[0];
    st.moment_arm[2 * i + 1] = arms[1];
    return l;
  }

  static void store(int i, const musculotendon::unit_parameters& p, double l_mtu, double v,
                    state_type& st) {
    const auto f = musculotendon::forces_at(p, l_mtu, st.fiber_length[i]);
    st.mtu_length[i] = l_mtu;
    st.force[i] = f.tendon;
    st.active_force[i] = f.contractile();
    st.fiber_velocity[i] = v;
  }

  std::vector<musculotendon::unit> units_;
  /// Per MTU, its crossings' reference_sine(): constant, so computed once here.
  std::vector<std::array<double, 2>> reference_sines_;
  double initial_activation_;
};

}  // namespace gaitsynth
