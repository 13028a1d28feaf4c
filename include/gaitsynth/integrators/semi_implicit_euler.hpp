#pragma once
/// \file semi_implicit_euler.hpp
/// Semi-implicit (symplectic) Euler at a fixed step, the default for penalty contact (the papers
/// simulate at 2400 Hz):  v' = v + dt ddq(q, v, t);  q' = q (+) dt v'  (configuration.hpp).
/// First order; energy errors stay bounded for conservative systems.
#include <Eigen/Core>

#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/integrators/concept.hpp"

namespace gaitsynth {

struct semi_implicit_euler {
  static constexpr int order = 1;
  /// step() evaluates sys on the unchanged state first (integrators/concept.hpp).
  static constexpr bool evaluates_state_first = true;

  semi_implicit_euler() = default;
  template <root_joint Root>
  explicit semi_implicit_euler(const model<Root>& m) {
    prepare(m);
  }

  /// Sizes the scratch so that step() does not allocate.
  template <root_joint Root>
  void prepare(const model<Root>& m) {
    ddq_.setZero(m.nv());
  }
  /// The same, for steps that also advance a first-order state of nz values.
  template <root_joint Root>
  void prepare(const model<Root>& m, Eigen::Index nz) {
    prepare(m);
    zdot_.setZero(nz);
  }

  /// Advances s by dt. \throws std::invalid_argument if dt is not finite and > 0 or s has the wrong
  /// sizes.
  template <root_joint Root, second_order_system Sys>
  void step(const model<Root>& m, sim_state& s, double dt, Sys&& sys) {
    check_positive(dt, "dt (time step, s)");
    check_size(s.q.size(), m.nq(), "state.q (generalized positions)");
    check_size(s.v.size(), m.nv(), "state.v (generalized velocities)");
    if (ddq_.size() != m.nv()) ddq_.setZero(m.nv());
    sys(static_cast<const Eigen::VectorXd&>(s.q), static_cast<const Eigen::VectorXd&>(s.v), s.t,
        ddq_);
    advance_rigid_body(m, s, dt);
  }

  /// Advances s and a first-order state z together: one evaluation of sys(q, v, z, t) at the
  /// step's start, then (q, v) exactly as step() above and z' = z + dt zdot (explicit Euler: the
  /// rigid body keeps its semi-implicit order, integrators/concept.hpp).
  template <root_joint Root, coupled_system Sys>
  void step(const model<Root>& m, sim_state& s, Eigen::VectorXd& z, double dt, Sys&& sys) {
    check_positive(dt, "dt (time step, s)");
    check_size(s.q.size(), m.nq(), "state.q (generalized positions)");
    check_size(s.v.size(), m.nv(), "state.v (generalized velocities)");
    if (ddq_.size() != m.nv()) ddq_.setZero(m.nv());
    if (zdot_.size() != z.size()) zdot_.setZero(z.size());
    sys(static_cast<const Eigen::VectorXd&>(s.q), static_cast<const Eigen::VectorXd&>(s.v),
        static_cast<const Eigen::VectorXd&>(z), s.t, ddq_, zdot_);
    for (Eigen::Index i = 0; i < z.size(); ++i) z[i] += dt * zdot_[i];
    advance_rigid_body(m, s, dt);
  }

  /// The accelerations computed in the last step.
  const Eigen::VectorXd& last_acceleration() const { return ddq_; }

 private:
  /// v' = v + dt ddq_; q' = q (+) dt v'; t' = t + dt.
  template <root_joint Root>
  void advance_rigid_body(const model<Root>& m, sim_state& s, double dt) {
    if constexpr (Root::nq == Root::nv) {
      // Vector-space configuration (planar, fixed root): q (+) dt v is q + dt v. One loop over
      // both updates the same values as the two vector statements below, without reloading v
      // across stores of different widths (a store-forwarding stall).
      for (Eigen::Index i = 0; i < s.v.size(); ++i) {
        s.v[i] += dt * ddq_[i];
        s.q[i] += dt * s.v[i];
      }
    } else {
      s.v += dt * ddq_;
      integrate_configuration(m, s.q, s.v, dt, s.q);
    }
    s.t += dt;
  }

  Eigen::VectorXd ddq_, zdot_;
};

}  // namespace gaitsynth
