#pragma once
/// \file objectives/concept.hpp
/// The objective policy (docs/architecture.md): accumulates a cost over a rollout. Lower is better.
///
/// Valid expressions (O: objective type, o: const O&, m: const model<Root>&, acc:
/// O::accumulator_type&, v: the rollout's step view (derived from step_view<Root>), out: const
/// rollout_outcome&):
///
///   O::accumulator_type      running sums (a copyable value; created at set-up)
///   o.make_accumulator(m)    -> O::accumulator_type
///   o.accumulate(acc, v)     once per physics step, after contact, the controller and the
///                            actuator and before the integration step; the view describes the
///                            interval [t, t + dt): the state at its start, the torques and
///                            contact forces applied over it (zero-order hold). So a rectangle
///                            rule sum_k f(view_k) dt integrates over the rollout.
///                            Must not allocate.
///   o.finish(acc, out)       -> double, the cost. Called once; out says why and when the rollout
///                            stopped (a fall, reached horizon) and where the COM started and
///                            ended.
///
/// Optional hooks, detected with requires:
///   o.done(acc) -> bool                 stop early (stop_reason::objective) when true
///   o.term_names() -> range of strings  names of running terms the recorder stores per frame
///   o.terms(acc, std::span<double>)     their current values
///   o.reset_accumulator(m, acc)         acc as make_accumulator(m) makes it, without allocating
///                                       (a worker's next rollout; rollout/policy_states.hpp)
///
/// Failed rollouts: when the state stops being finite the rollout does NOT call finish and sets the
/// cost to +infinity (rollout/result.hpp); an objective never needs to handle NaN state. A
/// finish() returning NaN is also reported as +infinity, so an optimizer never ranks NaN.
#include <Eigen/Core>
#include <concepts>
#include <cstdint>
#include <span>
#include <utility>

#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/termination.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// One physics step as the objective sees it. Non-owning; filled by the rollout.
template <root_joint Root>
struct step_view {
  const gaitsynth::model<Root>* model_ptr = nullptr;
  double t = 0.0;   ///< start of the interval, s
  double dt = 0.0;  ///< s
  std::int64_t step = 0;
  const Eigen::VectorXd* q_ptr = nullptr;            ///< nq, at t
  const Eigen::VectorXd* v_ptr = nullptr;            ///< nv, at t
  const Eigen::VectorXd* tau_ptr = nullptr;          ///< nv: actuator torques (root entries 0), N m
  const Eigen::VectorXd* tau_passive_ptr = nullptr;  ///< nv: joint-limit springs, N m
  /// The actuator command held over [t, t + dt) (its size is the actuator's command_size: the
  /// excitations u a metabolic objective charges, Wang et al. 2012 Sec. 5.1).
  const Eigen::VectorXd* command_ptr = nullptr;
  std::span<const mat3> body_rotation;            ///< R_world_body
  std::span<const vec3> body_position;            ///< body origins, world, m
  std::span<const vec3> body_angular_velocity;    ///< world axes, rad/s
  std::span<const vec3> body_linear_velocity;     ///< body origin velocity, world, m/s
  std::span<const vec6> external_wrench;          ///< per body: [torque about origin; force], world
  std::span<const int> contact_count;             ///< per body: contact points touching
  std::span<const unsigned char> contact_active;  ///< per contact point
  std::span<const vec3> contact_force;            ///< per contact point, world, N
  std::span<const std::uint8_t> toe_top_touching;  ///< per body: 1 if its toe-top point touches
  bool toe_top_contact = false;                    ///< the top of some toe touches (a stumble)
  vec3 com = vec3::Zero();                         ///< world, m
  vec3 com_velocity = vec3::Zero();                ///< world, m/s
  /// The controller's discrete state over [t, t + dt) (its discrete_state(): the FSM phase of
  /// Wang et al. 2009 Fig. 2, which E_land and E_sym read), -1 if it has none.
  int controller_phase = -1;
  /// The controller's report over [t, t + dt) (its report(st) after this step's command: per-step
  /// quantities such as Wu & Popovic 2010's frame-tracking errors, Sec. 8.1); empty if it has none.
  /// Its layout is the controller's (report_names()).
  std::span<const double> controller_report;
  const gaitsynth::workspace<Root>* workspace_ptr =
      nullptr;                                  ///< kinematics of (q, v) at t (read only)
  const contact_state* contacts_ptr = nullptr;  ///< contact evaluation at t (read only)

  const gaitsynth::model<Root>& model() const { return *model_ptr; }
  /// The rollout's workspace after forward kinematics of (q, v) at t: body poses and
  /// velocities, and the spatial momenta that centroidal_momentum and kinetic_energy sum, so an
  /// objective (E_ang of Wang et al. 2009) reads them without recomputing the kinematics.
  const gaitsynth::workspace<Root>& workspace() const { return *workspace_ptr; }
  const contact_state& contacts() const { return *contacts_ptr; }
  const Eigen::VectorXd& q() const { return *q_ptr; }
  const Eigen::VectorXd& v() const { return *v_ptr; }
  const Eigen::VectorXd& tau() const { return *tau_ptr; }
  const Eigen::VectorXd& tau_passive() const { return *tau_passive_ptr; }
  const Eigen::VectorXd& command() const { return *command_ptr; }
  /// Actuator torques of the joint DOFs only (num_joint_dofs).
  auto joint_torques() const { return tau_ptr->tail(model_ptr->num_joint_dofs()); }
  auto joint_velocities() const { return v_ptr->tail(model_ptr->num_joint_dofs()); }
  /// Mechanical power of joint DOF j, W (torque times joint rate).
  double joint_power(int j) const { return (*tau_ptr)[Root::nv + j] * (*v_ptr)[Root::nv + j]; }
};

/// Step view plus read access to the actuator's own state (metabolic objectives read muscle
/// activations). Derives from step_view<Root>, so objectives written for step_view accept it.
template <root_joint Root, class ActuatorState>
struct step_view_with : step_view<Root> {
  const ActuatorState* actuator_state_ptr = nullptr;
  const ActuatorState& actuator_state() const { return *actuator_state_ptr; }
};

/// How a rollout ended, given to objective::finish.
struct rollout_outcome {
  stop_reason reason = stop_reason::horizon;
  double time = 0.0;      ///< simulated time, s (t_end - t0)
  double duration = 0.0;  ///< requested horizon, s
  std::int64_t steps = 0;
  vec3 com_initial = vec3::Zero();  ///< world, m
  vec3 com_final = vec3::Zero();    ///< world, m (at the last finite state)
};

template <class O, class Root, class V = step_view<Root>>
concept objective = root_joint<Root> && std::derived_from<V, step_view<Root>> &&
    requires(const O& o, const model<Root>& m, typename O::accumulator_type& acc, const V& v,
             const rollout_outcome& out) {
  typename O::accumulator_type;
  { o.make_accumulator(m) } -> std::same_as<typename O::accumulator_type>;
  o.accumulate(acc, v);
  { o.finish(std::as_const(acc), out) } -> std::convertible_to<double>;
};

template <class O>
concept objective_with_done = requires(const O& o, const typename O::accumulator_type& acc) {
  { o.done(acc) } -> std::convertible_to<bool>;
};

template <class O>
concept objective_with_terms = requires(const O& o, const typename O::accumulator_type& acc,
                                        std::span<double> out) {
  o.term_names();
  o.terms(acc, out);
};

template <class O, class Root>
concept objective_with_reset = requires(const O& o, const model<Root>& m,
                                        typename O::accumulator_type& acc) {
  o.reset_accumulator(m, acc);
};

}  // namespace gaitsynth
