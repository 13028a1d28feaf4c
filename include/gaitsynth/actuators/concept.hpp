#pragma once
/// \file actuators/concept.hpp
/// The actuator policy (docs/architecture.md): maps a controller command to joint torques.
///
/// Valid expressions (A: actuator type, a: const A&, m: const model<Root>&, s: const sim_state&,
/// cmd: Eigen::Ref<const Eigen::VectorXd>, cst: const A::state_type&, st: A::state_type&,
/// tau: Eigen::Ref<Eigen::VectorXd>):
///
///   A::state_type            its own evolving state (muscle activation, fiber length); an empty
///                            struct (no_actuator_state) for stateless actuators
///   a.make_state(m)          -> A::state_type (set-up; may allocate; validates sizes vs. the
///                            model)
///   a.command_size(m)        -> int, length of the command vector the controller writes
///   a.input_kind()           -> command_kind, what the command means (command_kind.hpp); make
///                            it `static constexpr` when it is fixed by the type, so that
///                            check_command_kinds can compare it at compile time
///   a.torques(m, s, cmd, cst, tau)
///                            writes the joint torques (size num_joint_dofs, N m; the root is
///                            unactuated) for state s and command cmd. A pure function of its
///                            inputs, the actuator state included, which it takes by const
///                            reference (RBDL's Millard2016TorqueMuscle::calcJointTorque is const
///                            with activation as an input); must not allocate. The state changes
///                            only in the hooks below.
///   a.torques(m, s, ws, cmd, cst, tau)
///                            the same for an actuator that reads the kinematics the rollout
///                            already computed (musculotendon paths and moment arms): ws is a
///                            const workspace<Root>& after forward kinematics of (s.q, s.v). An
///                            actuator provides one of the two forms (both: this one is used).
///
/// Optional hooks for actuators with dynamics, detected with requires:
///   a.advance(m, s, cmd, st, dt)       advance st over one physics step (the actuator integrates
///                                      itself, e.g. activation dynamics, exactly or implicitly),
///                                      after the physics step, with the step's command (zero-order
///                                      hold, like the torques) and the state s at the step's end
///   a.derivative(m, s, cmd, cst, dst)  d(st)/dt into dst (same type as st). When A::state_type is
///                                      Eigen::VectorXd and the integrator takes a first-order
///                                      state (integrators/concept.hpp), st is integrated WITH
///                                      (q, v) through the integrator's system: semi-implicit Euler
///                                      keeps its order for the rigid body and takes an explicit
///                                      Euler step of st from the step's start; RK4 takes a
///                                      fourth-order step of the coupled system, the torques
///                                      re-evaluated from (q, v, st) at every stage. Otherwise the
///                                      rollout takes st += dt * dst after the physics step.
///   a.start(m, s, st)                  once per rollout, after the start state s is final and
///                                      before the first step: st to match s (a muscle's fibers
///                                      in equilibrium with its tendon at the start pose); may
///                                      throw std::invalid_argument for a start state the
///                                      actuator cannot take; must not allocate
///   a.sensed_size(m), a.sense(m, cst, out)   values exposed to controllers (see below)
///   a.joint_damping(m, s, cmd, cst, c) c_j >= 0 (N m s / rad), the joint-rate coefficient of each
///                                      DOF's law for (s, cmd): kd_j for a PD servo, before the
///                                      torque limit's clamp (size num_joint_dofs; must not
///                                      allocate). With rollout_options::implicit_joint_damping
///                                      the rollout takes these dampers implicitly (backward
///                                      Euler, rollout.hpp)
#include <Eigen/Core>
#include <concepts>
#include <span>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

/// The state of an actuator that has none.
struct no_actuator_state {};

template <class A, class Root>
concept actuator_with_kinematics = requires(const A& a, const model<Root>& m, const sim_state& s,
                                            const workspace<Root>& ws,
                                            Eigen::Ref<const Eigen::VectorXd> cmd,
                                            const typename A::state_type& cst,
                                            Eigen::Ref<Eigen::VectorXd> tau) {
  a.torques(m, s, ws, cmd, cst, tau);
};

template <class A, class Root>
concept actuator_with_state_only_torques = requires(const A& a, const model<Root>& m,
                                                    const sim_state& s,
                                                    Eigen::Ref<const Eigen::VectorXd> cmd,
                                                    const typename A::state_type& cst,
                                                    Eigen::Ref<Eigen::VectorXd> tau) {
  a.torques(m, s, cmd, cst, tau);
};

template <class A, class Root>
concept actuator = root_joint<Root> && requires(const A& a, const model<Root>& m) {
  typename A::state_type;
  { a.make_state(m) } -> std::same_as<typename A::state_type>;
  { a.command_size(m) } -> std::convertible_to<int>;
  { a.input_kind() } -> std::same_as<command_kind>;
} &&(actuator_with_state_only_torques<A, Root> || actuator_with_kinematics<A, Root>);

/// Joint torques of actuator a: through the kinematics form when it has one (see above).
template <root_joint Root, class A>
void actuator_torques(const A& a, const model<Root>& m, const sim_state& s,
                      const workspace<Root>& ws, Eigen::Ref<const Eigen::VectorXd> cmd,
                      const typename A::state_type& st, Eigen::Ref<Eigen::VectorXd> tau) {
  if constexpr (actuator_with_kinematics<A, Root>)
    a.torques(m, s, ws, cmd, st, tau);
  else
    a.torques(m, s, cmd, st, tau);
}

template <class A, class Root>
concept actuator_with_advance = requires(const A& a, const model<Root>& m, const sim_state& s,
                                         Eigen::Ref<const Eigen::VectorXd> cmd,
                                         typename A::state_type& st, double dt) {
  a.advance(m, s, cmd, st, dt);
};

template <class A, class Root>
concept actuator_with_derivative = requires(const A& a, const model<Root>& m, const sim_state& s,
                                            Eigen::Ref<const Eigen::VectorXd> cmd,
                                            const typename A::state_type& cst,
                                            typename A::state_type& st,
                                            typename A::state_type& dst) {
  a.derivative(m, s, cmd, cst, dst);
  st += 1.0 * dst;
};

/// A derivative actuator whose state is a plain vector: integrated with (q, v) by integrators
/// that take a first-order state (see derivative above).
template <class A, class Root>
concept actuator_with_continuous_state =
    actuator_with_derivative<A, Root> && std::same_as<typename A::state_type, Eigen::VectorXd>;

/// Optional: the actuator's state set from the rollout's start state (see start above).
template <class A, class Root>
concept actuator_with_start = requires(const A& a, const model<Root>& m, const sim_state& s,
                                       typename A::state_type& st) {
  a.start(m, s, st);
};

/// Optional: the joint-rate coefficients of the torques (see joint_damping above).
template <class A, class Root>
concept actuator_with_joint_damping = requires(const A& a, const model<Root>& m, const sim_state& s,
                                               Eigen::Ref<const Eigen::VectorXd> cmd,
                                               const typename A::state_type& cst,
                                               Eigen::Ref<Eigen::VectorXd> c) {
  a.joint_damping(m, s, cmd, cst, c);
};

/// Optional: a.reset_state(m, st) makes st what make_state(m) returns, without allocating (a
/// worker's next rollout: rollout/policy_states.hpp).
template <class A, class Root>
concept actuator_with_reset_state = requires(const A& a, const model<Root>& m,
                                             typename A::state_type& st) {
  a.reset_state(m, st);
};

/// Optional: values the actuator exposes to controllers, now and with neural delays
/// (sensors::sensed, sensors::delayed_sensed): normalized muscle force and fiber length for the
/// reflexes of Wang et al. 2012. sensed_size(m) at set-up; sense(m, st, out) once per physics step
/// before the controller, writing sensed_size(m) values; must not allocate.
template <class A, class Root>
concept actuator_with_sensing = requires(const A& a, const model<Root>& m,
                                         const typename A::state_type& st, std::span<double> out) {
  { a.sensed_size(m) } -> std::convertible_to<int>;
  a.sense(m, st, out);
};

}  // namespace gaitsynth
