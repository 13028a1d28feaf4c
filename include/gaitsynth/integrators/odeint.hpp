#pragma once
/// \file odeint.hpp
/// Boost.Odeint steppers over the same (q, v) state, for accuracy checks and smooth problems.
/// This is the ONLY gaitsynth header that includes Odeint's Eigen adapter (it adds operators to
/// namespace Eigen; style-anchors.md, sec. 2).
///
/// The first-order state is x = [q; v] (size nq + nv) with dx/dt = [qdot(q, v); ddq]; for a
/// floating root, d(quaternion)/dt = 0.5 quaternion * (0, omega_body) (Hamilton product), so the
/// stepper stays a true fourth-order method; the quaternion is renormalized after each step (a
/// projection that does not reduce the order).
#include <Eigen/Core>
#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/external/eigen/eigen.hpp>

#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/integrators/concept.hpp"

namespace gaitsynth {

namespace detail {
/// qdot from (q, v): the time derivative of the generalized positions.
template <root_joint Root, class X, class Vv, class Out>
void configuration_rate(const model<Root>& m, const X& q, const Vv& v, Out&& qdot) {
  constexpr int nqr = Root::nq, nvr = Root::nv;
  if constexpr (std::is_same_v<Root, floating_root>) {
    qdot.template head<3>() = v.template head<3>();
    const double w = q[3], x = q[4], y = q[5], z = q[6];
    const double ox = v[3], oy = v[4], oz = v[5];
    // 0.5 * q (x) (0, omega)
    qdot[3] = 0.5 * (-x * ox - y * oy - z * oz);
    qdot[4] = 0.5 * (w * ox + y * oz - z * oy);
    qdot[5] = 0.5 * (w * oy + z * ox - x * oz);
    qdot[6] = 0.5 * (w * oz + x * oy - y * ox);
  } else if constexpr (nqr > 0) {
    qdot.template head<nqr>() = v.template head<nvr>();
  }
  const int nj = m.num_joint_dofs();
  qdot.segment(nqr, nj) = v.segment(nvr, nj);
}
}  // namespace detail

/// Classic fixed-step fourth-order Runge-Kutta (boost::numeric::odeint::runge_kutta4) on Eigen
/// vectors with Odeint's vector_space_algebra.
struct odeint_rk4 {
  static constexpr int order = 4;
  using state_type = Eigen::VectorXd;
  using stepper_type =
      boost::numeric::odeint::runge_kutta4<state_type, double, state_type, double,
                                           boost::numeric::odeint::vector_space_algebra>;

  odeint_rk4() = default;
  template <root_joint Root>
  explicit odeint_rk4(const model<Root>& m) {
    prepare(m);
  }

  /// Sizes the scratch (and Odeint's internal stages) so that step() does not allocate.
  template <root_joint Root>
  void prepare(const model<Root>& m) {
    const int nq = m.nq(), nv = m.nv();
    x_.setZero(nq + nv);
    q_.setZero(nq);
    v_.setZero(nv);
    ddq_.setZero(nv);
    // Odeint resizes its stage vectors on the first do_step (initially_resizer): do it now.
    if constexpr (std::is_same_v<Root, floating_root>) x_[3] = 1.0;
    stepper_.do_step([](const state_type& x, state_type& dxdt, double) { dxdt.setZero(x.size()); },
                     x_, 0.0, 0.0);
  }

  /// The same, for steps that also advance a first-order state of nz values (a stepper of its
  /// own: Odeint sizes its stages once).
  template <root_joint Root>
  void prepare(const model<Root>& m, Eigen::Index nz) {
    prepare(m);
    const Eigen::Index n = m.nq() + m.nv() + nz;
    xz_.setZero(n);
    z_.setZero(nz);
    zdot_.setZero(nz);
    if constexpr (std::is_same_v<Root, floating_root>) xz_[3] = 1.0;
    coupled_stepper_.do_step(
        [](const state_type& x, state_type& dxdt, double) { dxdt.setZero(x.size()); }, xz_, 0.0,
        0.0);
  }

  /// Advances s by dt. \throws std::invalid_argument if dt is not finite and > 0 or s has the wrong
  /// sizes.
  template <root_joint Root, second_order_system Sys>
  void step(const model<Root>& m, sim_state& s, double dt, Sys&& sys) {
    check_positive(dt, "dt (time step, s)");
    const int nq = m.nq(), nv = m.nv();
    check_size(s.q.size(), nq, "state.q (generalized positions)");
    check_size(s.v.size(), nv, "state.v (generalized velocities)");
    if (x_.size() != nq + nv) prepare(m);
    x_.head(nq) = s.q;
    x_.tail(nv) = s.v;
    auto rhs = [&](const state_type& x, state_type& dxdt, double t) {
      q_ = x.head(nq);
      v_ = x.tail(nv);
      sys(static_cast<const Eigen::VectorXd&>(q_), static_cast<const Eigen::VectorXd&>(v_), t,
          ddq_);
      detail::configuration_rate(m, q_, v_, dxdt.head(nq));
      dxdt.tail(nv) = ddq_;
    };
    stepper_.do_step(std::ref(rhs), x_, s.t, dt);
    s.q = x_.head(nq);
    s.v = x_.tail(nv);
    // A diverged step stays as it is, for the rollout to report as a failed rollout
    // (normalizing a non-finite quaternion throws).
    if (s.q.allFinite()) normalize_configuration(m, s.q);
    s.t += dt;
  }

  /// Advances s and a first-order state z together: one RK4 step of x = [q; v; z] with
  /// dx/dt = [qdot(q, v); ddq(q, v, z); zdot(q, v, z)] (integrators/concept.hpp).
  template <root_joint Root, coupled_system Sys>
  void step(const model<Root>& m, sim_state& s, Eigen::VectorXd& z, double dt, Sys&& sys) {
    check_positive(dt, "dt (time step, s)");
    const int nq = m.nq(), nv = m.nv();
    const Eigen::Index nz = z.size();
    check_size(s.q.size(), nq, "state.q (generalized positions)");
    check_size(s.v.size(), nv, "state.v (generalized velocities)");
    check_argument(xz_.size() == nq + nv + nz,
                   "odeint_rk4: prepare(model, nz) must size the coupled state first (nz = ", nz,
                   ")");
    xz_.head(nq) = s.q;
    xz_.segment(nq, nv) = s.v;
    xz_.tail(nz) = z;
    auto rhs = [&](const state_type& x, state_type& dxdt, double t) {
      q_ = x.head(nq);
      v_ = x.segment(nq, nv);
      z_ = x.tail(nz);
      sys(static_cast<const Eigen::VectorXd&>(q_), static_cast<const Eigen::VectorXd&>(v_),
          static_cast<const Eigen::VectorXd&>(z_), t, ddq_, zdot_);
      detail::configuration_rate(m, q_, v_, dxdt.head(nq));
      dxdt.segment(nq, nv) = ddq_;
      dxdt.tail(nz) = zdot_;
    };
    coupled_stepper_.do_step(std::ref(rhs), xz_, s.t, dt);
    s.q = xz_.head(nq);
    s.v = xz_.segment(nq, nv);
    z = xz_.tail(nz);
    // A diverged step stays as it is, for the rollout to report as a failed rollout
    // (normalizing a non-finite quaternion throws).
    if (s.q.allFinite()) normalize_configuration(m, s.q);
    s.t += dt;
  }

 private:
  stepper_type stepper_, coupled_stepper_;
  state_type x_, q_, v_, ddq_, xz_, z_, zdot_;
};

}  // namespace gaitsynth
