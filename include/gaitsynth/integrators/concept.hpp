#pragma once
/// \file concept.hpp
/// The integrator policy. Following Boost.Odeint's second-order-system concept
/// (doc/concepts/second_order_system.qbk: `sys(x, v, a, t)`), a *system* computes generalized
/// accelerations from positions, velocities and time:
///
///   sys(const Eigen::VectorXd& q, const Eigen::VectorXd& v, double t, Eigen::VectorXd& ddq_out)
///
/// (ddq_out has size nv on entry and must be overwritten). An *integrator* advances a sim_state
/// (q, v, t) of a model<Root> by one step dt:
///
///   integrator.step(model, state, dt, sys)     // throws std::invalid_argument for a bad dt
///
/// Integrators own their scratch vectors; `prepare(model)` sizes them so that no step allocates.
/// The quaternion of a floating root is kept unit length by every integrator.
///
/// Optionally an integrator advances a first-order state z (nz values: muscle activations and
/// fiber lengths) together with (q, v), through a coupled system
///
///   sys(q, v, z, t, ddq_out, zdot_out)
///   integrator.prepare(model, nz);  integrator.step(model, state, z, dt, sys)
///
/// so that the actuator's dynamics and the rigid body are one ODE (actuators/concept.hpp,
/// derivative).
#include <Eigen/Core>
#include <concepts>

#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

/// A callable usable as the second-order system of an integrator.
template <class Sys>
concept second_order_system = requires(Sys& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                       double t, Eigen::VectorXd& ddq) {
  sys(q, v, t, ddq);
};

namespace detail {
/// The minimal system, used to check the integrator concept.
struct system_archetype {
  void operator()(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                  Eigen::VectorXd& ddq) const {
    ddq.setZero();
  }
};
}  // namespace detail

namespace detail {
/// The minimal coupled system (q, v, z), used to check integrator_with_first_order_state.
struct coupled_system_archetype {
  void operator()(const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                  Eigen::VectorXd& ddq, Eigen::VectorXd& zdot) const {
    ddq.setZero();
    zdot.setZero();
  }
};
}  // namespace detail

/// A callable usable as the coupled system of integrator_with_first_order_state.
template <class Sys>
concept coupled_system = requires(Sys& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                  const Eigen::VectorXd& z, double t, Eigen::VectorXd& ddq,
                                  Eigen::VectorXd& zdot) {
  sys(q, v, z, t, ddq, zdot);
};

/// An integrator for models with root joint Root.
template <class I, class Root>
concept integrator = root_joint<Root> && requires(I& integ, const model<Root>& m, sim_state& s,
                                                  double dt, detail::system_archetype sys) {
  integ.step(m, s, dt, sys);
  integ.prepare(m);
  { I::order } -> std::convertible_to<int>;
};

/// An integrator that also advances a first-order state z with (q, v) (see the file comment).
template <class I, class Root>
concept integrator_with_first_order_state = integrator<I, Root> &&
    requires(I& integ, const model<Root>& m, sim_state& s, Eigen::VectorXd& z, double dt,
             detail::coupled_system_archetype sys) {
  integ.prepare(m, 1);
  integ.step(m, s, z, dt, sys);
};

/// Optional promise of an integrator: `static constexpr bool evaluates_state_first = true` means
/// that step() calls sys(state.q, state.v, ...) on the state vectors themselves, unchanged, before
/// anything else. The rollout then reuses the kinematics it computed for that state instead of
/// comparing q and v with the workspace's cache (semi_implicit_euler makes the promise).
template <class I>
concept integrator_evaluating_state_first = requires {
  requires static_cast<bool>(I::evaluates_state_first);
};

}  // namespace gaitsynth
