#pragma once
/// \file rollout.hpp
/// The fused rollout loop: simulate one character under one controller for one parameter vector
/// and return the objective's cost. Every policy is a template parameter constrained by its concept
/// (docs/architecture.md), so the step loop is one inlined function: no virtual call, no
/// std::function, and no heap allocation after set-up (tests/rollout/no_allocation.standalone.cpp).
///
///   auto scratch = make_rollout_scratch(model);          // once per thread
///   rollout_result r = rollout(model, pd_actuator::uniform(model, 300, 30), pose_hold(model),
///                              distance_objective(), flat_terrain(), semi_implicit_euler(),
///                              params, options, scratch);
///
/// Set-up (may allocate, may throw std::invalid_argument naming the bad value): validate dt and the
/// options, controller.bind(params), check the command kinds, rebuild the scratch if the model's
/// fingerprint changed, make or reset the policies' states (rollout/policy_states.hpp), size the
/// command, place the initial state, let an actuator with a start hook match its state to it,
/// size the sensor history, start the observers.
///
/// Step k (t = t0 + k dt, computed, never accumulated, as Odeint's integrate_const does):
///   1. forward kinematics of (q, v); COM and COM velocity;
///   2. stop if fallen (COM below the fall height above the terrain), stalled (options.stall) or
///      k reached the horizon;
///   3. clear external wrenches; penalty contact against the terrain; self-collision (options.
///      self_contact, when it has pairs); pushes (into ws.f_ext) — done
///      before sensing so that controllers see this step's contact flags;
///   4. the actuator's sensed values; push the sample into the delay history; once per controller
///      period, the controller writes the command (held in between). Controllers read the step's
///      workspace and contact state through const views; a controller with
///      add_external_wrenches then adds its wrenches to ws.f_ext (every step);
///   5. the actuator maps the command to joint torques (optionally reading the workspace);
///      passive joint-limit torques are added; with options.implicit_joint_damping the joint
///      dampers are solved for implicitly here (ABA with an armature) and the torques become the
///      applied ones (rollout/options.hpp);
///   6. the objective accumulates this step (its view: state at t, torques and contact forces held
///      over [t, t + dt), the controller's phase and report after this step's command); the
///      observers observe it (the recorder stores a frame if due); stop if the objective is done;
///   7. the integrator advances (q, v) with accelerations from ABA (torques and external wrenches
///      held constant over the step: zero-order hold, also for the stages of RK4). An actuator with
///      continuous dynamics (a derivative and a vector state) is integrated with (q, v) in the
///      same system, its torques re-evaluated at every stage; otherwise its state advances after
///      the step (advance, or an explicit Euler step of derivative);
///   8. stop if q or v is no longer finite (cost +infinity, or with options.score_divergence the
///      objective's score of an early stop; rollout/result.hpp).
/// After the loop the observers see the state it stopped in, with the result.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/integrators/concept.hpp"
#include "gaitsynth/model/fingerprint.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/rollout/observer.hpp"
#include "gaitsynth/rollout/options.hpp"
#include "gaitsynth/rollout/policy_states.hpp"
#include "gaitsynth/rollout/recorder.hpp"
#include "gaitsynth/rollout/result.hpp"
#include "gaitsynth/rollout/termination.hpp"

namespace gaitsynth {

/// Per-thread memory of rollout(): the dynamics workspace, the simulated state and every buffer
/// the step loop writes. Made once (make_rollout_scratch) and reused by every rollout of a thread;
/// rollout() rebuilds it when the model differs from the one it was made for (by fingerprint:
/// the workspace and the contact state cache model data, model/fingerprint.hpp).
template <root_joint Root>
struct rollout_scratch {
  workspace<Root> ws;
  sim_state state;
  Eigen::VectorXd tau;          ///< nv: actuator torques (root entries 0), N m
  Eigen::VectorXd tau_passive;  ///< nv: passive joint-limit torques, N m
  Eigen::VectorXd tau_total;    ///< nv: what ABA receives
  Eigen::VectorXd command;      ///< actuator command (its size is the actuator's command_size)
  contact_state contacts;       ///< penalty contact anchors, flags, forces, counts per body
  sensor_history history;       ///< delayed sensor samples
  Eigen::VectorXd sensed;       ///< the actuator's sensed values this step (actuator_with_sensing)
  sim_state stage;              ///< an integrator stage's state (coupled actuator dynamics)
  Eigen::VectorXd stage_tau;    ///< nv: total torques at that stage, N m
  /// num_joint_dofs each: the actuator's and the joint limits' damping coefficients this step
  /// (N m s / rad) and the armature dt (their sum) (rollout_options::implicit_joint_damping)
  Eigen::VectorXd damping_actuator, damping_passive, armature;
  std::uint64_t model_fingerprint = 0;  ///< of the model ws and contacts were made for
  bool prepared = false;
};

/// Sizes a scratch for model m, unless it was made for a model with the same fingerprint
/// (allocates only then; set-up).
template <root_joint Root>
void prepare_rollout_scratch(const model<Root>& m, rollout_scratch<Root>& s) {
  const std::uint64_t fp = model_fingerprint(m);
  if (s.prepared && s.model_fingerprint == fp) return;
  s.ws = make_workspace(m);
  s.state = make_state(m);
  s.tau = Eigen::VectorXd::Zero(m.nv());
  s.tau_passive = Eigen::VectorXd::Zero(m.nv());
  s.tau_total = Eigen::VectorXd::Zero(m.nv());
  s.contacts = make_contact_state(m);
  s.stage = make_state(m);
  s.stage_tau = Eigen::VectorXd::Zero(m.nv());
  s.damping_actuator = Eigen::VectorXd::Zero(m.num_joint_dofs());
  s.damping_passive = Eigen::VectorXd::Zero(m.num_joint_dofs());
  s.armature = Eigen::VectorXd::Zero(m.num_joint_dofs());
  s.model_fingerprint = fp;
  s.prepared = true;
}

template <root_joint Root>
rollout_scratch<Root> make_rollout_scratch(const model<Root>& m) {
  rollout_scratch<Root> s;
  prepare_rollout_scratch(m, s);
  return s;
}

/// Lifts (or lowers) the root of configuration q so that the lowest contact point of m (or body
/// origin, if m has no contact points) touches terrain `ground`. Set-up helper (allocates).
template <root_joint Root, terrain T>
void place_on_terrain(const model<Root>& m, const T& ground, Eigen::VectorXd& q) {
  static_assert(Root::nq > 0, "place_on_terrain needs a root that can move vertically");
  check_size(q.size(), m.nq(), "place_on_terrain: q (generalized positions)");
  check_finite(q, "place_on_terrain: q");
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, q);
  double gap = std::numeric_limits<double>::infinity();
  auto consider = [&](const vec3& p) { gap = std::min(gap, p.z() - ground.height(p.x(), p.y())); };
  if (m.contact_points.empty()) {
    for (int b = 0; b < m.num_bodies(); ++b) consider(ws.body_position[b]);
  } else {
    for (const auto& c : m.contact_points) consider(point_position(m, ws, c.body, c.position));
  }
  constexpr int z_index = std::is_same_v<Root, planar_root> ? 1 : 2;
  q[z_index] -= gap;
}

namespace detail {

/// Physics step at which controller call n happens: the first step at or after t0 + n period.
inline std::int64_t command_step(std::int64_t n, double period, double dt) {
  if (period <= 0.0) return n;
  return static_cast<std::int64_t>(std::ceil(static_cast<double>(n) * period / dt - 1e-9));
}

template <class C>
double sensor_delay_of(const C& c) {
  if constexpr (controller_with_sensor_delay<C>)
    return static_cast<double>(c.max_sensor_delay());
  else
    return 0.0;
}

/// True when every entry of x is finite: x * 0 is 0 for finite entries and NaN otherwise. One
/// branch for the whole vector, and the in-order sum is a short side chain that nothing waits on
/// (Eigen's allFinite branches on every entry, every step).
inline bool all_finite(const Eigen::VectorXd& x) {
  double zero = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) zero += x[i] * 0.0;
  return zero == 0.0;
}

inline std::int64_t horizon_steps(double duration, double dt) {
  return static_cast<std::int64_t>(std::ceil(duration / dt - 1e-9));
}

}  // namespace detail

namespace detail {
/// The rollout itself (rollout() below forwards here with a mutable controller).
template <root_joint Root, class Actuator, class C, class Objective, terrain Terrain,
          class Integrator, class Observer>
rollout_result rollout_impl(const model<Root>& m, const Actuator& act, C& ctrl,
                            const Objective& obj, const Terrain& ground, Integrator& integ,
                            std::span<const double> params, const rollout_options& opt,
                            rollout_scratch<Root>& scr,
                            rollout_policy_states<Actuator, C, Objective>& states,
                            Observer& user_observer) {
  using actuator_state = typename Actuator::state_type;
  // ---------------------------------------------------------------- set-up (may allocate/throw)
  check_positive(opt.dt, "rollout_options::dt (physics timestep, s)");
  check_argument(std::isfinite(opt.duration) && opt.duration >= 0.0,
                 "rollout_options::duration must be finite and >= 0 s, got ", opt.duration);
  check_argument(!opt.detect_falls || (std::isfinite(opt.fall_height) &&
                                       std::isfinite(opt.fall_fraction) && opt.fall_fraction >= 0),
                 "rollout_options: fall_height and fall_fraction must be finite (fraction >= 0), "
                 "got ",
                 opt.fall_height, " and ", opt.fall_fraction);
  check_argument(opt.divergence_com_speed > 0.0,
                 "rollout_options::divergence_com_speed must be > 0 m/s, got ",
                 opt.divergence_com_speed);
  check_argument(std::isfinite(opt.stall.window) && opt.stall.window >= 0.0,
                 "rollout_options::stall.window must be finite and >= 0 s, got ", opt.stall.window);
  check_argument(std::isfinite(opt.stall.min_progress),
                 "rollout_options::stall.min_progress must be finite, got ",
                 opt.stall.min_progress);
  // The horizon in steps must be a count the loop can reach (an int64; a rollout of 1e15 steps
  // would not end anyway): a tiny dt or a huge duration is refused here, not overflowed.
  check_argument(opt.duration / opt.dt < 1e15,
                 "rollout_options: duration / dt must be < 1e15 steps, got ", opt.duration, " s / ",
                 opt.dt, " s = ", opt.duration / opt.dt, " steps");
  const double dt = opt.dt;
  ctrl.bind(params);
  const double period = static_cast<double>(ctrl.period());
  check_argument(std::isfinite(period) && period >= 0.0,
                 "controller period must be finite and >= 0 s, got ", period);
  prepare_rollout_scratch(m, scr);
  // Static kinds (static constexpr output_kind() / input_kind()): a compile error when they
  // differ; otherwise a run-time check that names both kinds.
  check_command_kinds(ctrl, act);

  workspace<Root>& ws = scr.ws;
  sim_state& s = scr.state;
  if (opt.initial_state.q.size() == 0) {
    // An empty q means "the neutral pose at rest at t = 0": a v or t given with it would be
    // silently dropped.
    check_argument(opt.initial_state.v.size() == 0 && opt.initial_state.t == 0.0,
                   "rollout_options::initial_state: v (size ", opt.initial_state.v.size(),
                   ") and t (", opt.initial_state.t,
                   ") given without q; give q too, or none of them for the neutral pose at rest");
    s.q = neutral_configuration(m);
    if constexpr (Root::nq > 0) place_on_terrain(m, ground, s.q);
    s.v.setZero();
    s.t = 0.0;
  } else {
    check_size(opt.initial_state.q.size(), m.nq(), "rollout_options::initial_state.q");
    check_size(opt.initial_state.v.size(), m.nv(), "rollout_options::initial_state.v");
    check_finite(opt.initial_state.q, "rollout_options::initial_state.q");
    check_finite(opt.initial_state.v, "rollout_options::initial_state.v");
    check_argument(std::isfinite(opt.initial_state.t),
                   "rollout_options::initial_state.t is not "
                   "finite (",
                   opt.initial_state.t, ")");
    s.q = opt.initial_state.q;
    s.v = opt.initial_state.v;
    s.t = opt.initial_state.t;
  }
  if constexpr (controller_with_initial_state<C, Root>) ctrl.initial_state(m, s);
  if (opt.initial_velocity_offset.size() > 0) {
    check_size(opt.initial_velocity_offset.size(), m.nv(),
               "rollout_options::initial_velocity_offset");
    check_finite(opt.initial_velocity_offset, "rollout_options::initial_velocity_offset");
    s.v += opt.initial_velocity_offset;
  }
  normalize_configuration(m, s.q);
  const double t0 = s.t;

  states.prepare(m, scr.model_fingerprint, act, ctrl, obj);
  actuator_state& act_state = *states.actuator;
  // d(actuator state)/dt (used only by actuators with a derivative hook).
  [[maybe_unused]] actuator_state& act_rate = *states.actuator_rate;
  if constexpr (actuator_with_start<Actuator, Root>) act.start(m, std::as_const(s), act_state);
  typename C::state_type& ctrl_state = *states.controller;
  typename Objective::accumulator_type& acc = *states.objective;
  const int ncmd = static_cast<int>(act.command_size(m));
  check_argument(ncmd >= 0, "actuator command_size must be >= 0, got ", ncmd);
  if constexpr (controller_with_command_size<C, Root>) {
    const int written = static_cast<int>(ctrl.command_size(m));
    check_argument(written < 0 || written == ncmd, "the controller writes ", written,
                   " command entries, the actuator takes ", ncmd);
  }
  if (scr.command.size() != ncmd) scr.command.resize(ncmd);
  scr.command.setZero();
  scr.tau.setZero();
  scr.tau_passive.setZero();
  scr.tau_total.setZero();
  validate(opt.contact);
  validate(m, opt.self_contact);
  scr.contacts.reset();
  // An actuator with continuous dynamics is integrated with (q, v) when the integrator can
  // (actuators/concept.hpp, derivative): one ODE, the torques re-evaluated at every stage.
  constexpr bool coupled = actuator_with_continuous_state<Actuator, Root> &&
                           integrator_with_first_order_state<Integrator, Root>;
  if constexpr (coupled)
    integ.prepare(m, act_state.size());
  else
    integ.prepare(m);
  const bool implicit_damping = opt.implicit_joint_damping;
  if (implicit_damping) {
    check_argument(!coupled,
                   "rollout_options::implicit_joint_damping: not with an actuator integrated with "
                   "(q, v) (its torques are re-evaluated at the integrator's stages)");
    check_argument(!detail::planar_path(ws),
                   "rollout_options::implicit_joint_damping: the planar fast path has no "
                   "armature; call disable_planar_path(scratch.ws) first");
    scr.damping_actuator.setZero();
    scr.damping_passive.setZero();
    scr.armature.setZero();
  }
  validate_pushes(m, std::span<const push>(opt.pushes));

  const int nj = m.num_joint_dofs();
  const std::int64_t n_steps = detail::horizon_steps(opt.duration, dt);
  const double delay = detail::sensor_delay_of(ctrl);
  check_argument(std::isfinite(delay) && delay >= 0.0,
                 "controller max_sensor_delay must be finite and >= 0 s, got ", delay);
  int num_sensed = 0;
  if constexpr (actuator_with_sensing<Actuator, Root>) {
    num_sensed = static_cast<int>(act.sensed_size(m));
    check_argument(num_sensed >= 0, "actuator sensed_size must be >= 0, got ", num_sensed);
  }
  if (scr.sensed.size() != num_sensed) scr.sensed.resize(num_sensed);
  scr.sensed.setZero();
  scr.history.reset(m.nq(), m.nv(), m.num_bodies(), history_capacity(delay, dt), num_sensed);

  // Observers: the recorder of options.record (off when null) and the caller's.
  trajectory_observer recorder(opt.record, opt.record_every);
  observer_pair<trajectory_observer, Observer> obs{recorder, user_observer};
  constexpr bool user_observes = !std::is_same_v<std::remove_cv_t<Observer>, null_observer>;
  if (opt.record != nullptr || user_observes) {
    observer_setup setup;  // (allocates only when observed: a worker's rollouts allocate nothing)
    setup.dt = dt;
    setup.horizon_steps = n_steps;
    setup.max_pushes = opt.pushes.size();
    if constexpr (objective_with_terms<Objective>)
      for (const auto& n : obj.term_names()) setup.objective_term_names.emplace_back(n);
    obs.start(m, setup);
  }

  forward_kinematics(m, ws, s.q, s.v);
  rollout_result res;
  res.com_initial = center_of_mass(m, ws);
  {
    const double h0 = res.com_initial.z() - ground.height(res.com_initial.x(), res.com_initial.y());
    res.fall_height = opt.fall_height > 0.0 ? opt.fall_height : opt.fall_fraction * h0;
  }
  // What the history stores each step (the pointers and spans stay valid: no reallocation).
  sensor_sample sample;
  sample.q = &s.q;
  sample.v = &s.v;
  sample.contact_count = scr.contacts.points_touching;
  sample.body_rotation = ws.body_rotation;
  sample.sensed =
      std::span<const double>(scr.sensed.data(), static_cast<std::size_t>(scr.sensed.size()));
  auto sense_actuator = [&] {
    if constexpr (actuator_with_sensing<Actuator, Root>)
      act.sense(m, std::as_const(act_state),
                std::span<double>(scr.sensed.data(), static_cast<std::size_t>(num_sensed)));
  };
  if (scr.history.capacity() > 0) {  // as if the character had been still before t0
    // ...and standing where it stands at t0: the history's contact counts are the start pose's
    // points within 1 mm of the terrain (a start placed on the terrain touches with depth 0,
    // which the contact model does not count), so a delayed contact sensor sees a foot placed on
    // the ground as on the ground. Counts only: step 0 evaluates the contact anew.
    detail::reset_counts(scr.contacts);
    for (int k = 0; k < static_cast<int>(m.contact_points.size()); ++k) {
      const contact_point& cp = m.contact_points[static_cast<std::size_t>(k)];
      const vec3 p = ws.body_position[cp.body] + ws.body_rotation[cp.body] * cp.position;
      detail::record_point(cp, k, p - vec3(0.0, 0.0, 1e-3), ground, scr.contacts);
    }
    sense_actuator();
    sample.com = res.com_initial;
    sample.com_velocity = com_velocity(m, ws);
    for (int i = 0; i < scr.history.capacity(); ++i) scr.history.push(sample);
  }

  sensors_with<Root, actuator_state> sen;
  sen.model_ptr = &m;
  sen.dt = dt;
  sen.q_ptr = &s.q;
  sen.v_ptr = &s.v;
  sen.body_rotation = ws.body_rotation;
  sen.body_position = ws.body_position;
  sen.body_angular_velocity = ws.body_angular_velocity;
  sen.body_linear_velocity = ws.body_linear_velocity;
  sen.contact_count = scr.contacts.points_touching;
  sen.contact_active = scr.contacts.active;
  sen.history = scr.history.capacity() > 0 ? &scr.history : nullptr;
  sen.workspace_ptr = &ws;
  sen.contacts_ptr = &scr.contacts;
  sen.sensed = sample.sensed;
  sen.actuator_state_ptr = &act_state;

  observation<Root, Objective, C, actuator_state, Terrain> view;  // the objective's step view too
  view.model_ptr = &m;
  view.dt = dt;
  view.q_ptr = &s.q;
  view.v_ptr = &s.v;
  view.tau_ptr = &scr.tau;
  view.tau_passive_ptr = &scr.tau_passive;
  view.command_ptr = &scr.command;
  view.body_rotation = ws.body_rotation;
  view.body_position = ws.body_position;
  view.body_angular_velocity = ws.body_angular_velocity;
  view.body_linear_velocity = ws.body_linear_velocity;
  view.external_wrench = ws.f_ext;
  view.contact_count = scr.contacts.points_touching;
  view.contact_active = scr.contacts.active;
  view.contact_force = scr.contacts.force;
  view.toe_top_touching = scr.contacts.toe_top_touching;  // per body (Wang 2009: the swing toe's)
  view.workspace_ptr = &ws;
  view.contacts_ptr = &scr.contacts;
  view.actuator_state_ptr = &act_state;
  view.objective_ptr = &obj;
  view.accumulator_ptr = &acc;
  view.controller_ptr = &ctrl;
  view.controller_state_ptr = &ctrl_state;
  view.terrain_ptr = &ground;
  view.pushes = std::span<const push>(opt.pushes);

  // The system the integrator steps: ABA with the held torques and external wrenches. An
  // integrator that evaluates it first on the unchanged state (integrator_evaluating_state_first)
  // gets ABA on the kinematics of step 1, which are still current: nothing between step 1 and the
  // integrator can change s or ws's kinematics (controllers, actuators and objectives see them
  // through const views; add_external_wrenches writes only ws.f_ext), so aba()'s comparison of q
  // and v with its cache is skipped.
  bool kinematics_current = false;
  // With implicit joint damping, step 5 has solved the step's accelerations already (ws.ddq, for
  // the applied torques tau_total): the first evaluation on the step's state takes them.
  bool implicit_ddq = false;
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double, Eigen::VectorXd& ddq) {
    if (kinematics_current && &q == &s.q && &v == &s.v) {
      kinematics_current = false;  // the first evaluation only
      if (implicit_ddq)
        ddq = ws.ddq;
      else
        ddq = detail::aba_with_current_kinematics(m, ws, scr.tau_total);
    } else {
      ddq = aba(m, ws, q, v, scr.tau_total);
    }
  };

  // The coupled system (q, v, z = actuator state). On the step's own vectors it is the step's
  // start: the torques of step 5 and the kinematics of step 1. At another stage (RK4) the
  // actuator and passive torques are evaluated anew from (q, v, z); contact and pushes stay
  // held over the step, as for every integrator.
  [[maybe_unused]] auto coupled_sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                          const auto& z, double t, Eigen::VectorXd& ddq,
                                          Eigen::VectorXd& zdot) {
    if constexpr (coupled) {
      const auto cmd = Eigen::Ref<const Eigen::VectorXd>(scr.command);
      if (&q == &s.q && &v == &s.v && &z == &act_state) {
        sys(q, v, t, ddq);
        act.derivative(m, std::as_const(s), cmd, z, zdot);
        return;
      }
      sim_state& st = scr.stage;
      st.q = q;
      st.v = v;
      st.t = t;
      forward_kinematics(m, ws, q, v);
      Eigen::VectorXd& tau = scr.stage_tau;
      for (int i = 0; i < Root::nv; ++i) tau[i] = 0.0;
      actuator_torques(act, m, std::as_const(st), std::as_const(ws), cmd, z,
                       Eigen::Ref<Eigen::VectorXd>(tau.tail(nj)));
      for (int j = 0; j < nj; ++j) {
        const joint_limit& L = m.dofs[j].limit;
        if (L.model != limit_model::none)
          tau[Root::nv + j] += joint_limit_torque(L, q[Root::nq + j], v[Root::nv + j]);
      }
      ddq = aba(m, ws, q, v, tau);
      act.derivative(m, std::as_const(st), cmd, z, zdot);
    }
  };

  // ---------------------------------------------------------------- the step loop: no allocation
  std::int64_t k = 0, calls = 0, next_call = 0;
  stop_reason reason = stop_reason::horizon;
  vec3 com = res.com_initial, com_v = vec3::Zero();
  // Stall windows (rollout_options::stall): the COM's x at the last window's end.
  const std::int64_t stall_steps =
      opt.stall.window > 0.0 ? std::max<std::int64_t>(1, std::llround(opt.stall.window / dt)) : 0;
  std::int64_t next_stall_check = stall_steps > 0 ? stall_steps : -1;
  double stall_x = res.com_initial.x();
  const double divergence_speed_squared = opt.divergence_com_speed * opt.divergence_com_speed;
  for (;; ++k) {
    const double t = t0 + static_cast<double>(k) * dt;
    s.t = t;
    // 1. kinematics (cached by the workspace when already current)
    forward_kinematics(m, ws, s.q, s.v);
    kinematics_current = integrator_evaluating_state_first<std::remove_cvref_t<Integrator>>;
    com = center_of_mass(m, ws);
    com_v = com_velocity(m, ws);
    // 2. stop conditions on the current state; a diverging state keeps the last sane COM
    if (!(com_v.squaredNorm() <= divergence_speed_squared)) {
      reason = stop_reason::non_finite;
      break;
    }
    res.com_final = com;
    if (opt.detect_falls &&
        has_fallen(com.z() - ground.height(com.x(), com.y()), res.fall_height)) {
      reason = stop_reason::fell;
      break;
    }
    if (k == next_stall_check) {
      if (com.x() - stall_x < opt.stall.min_progress) {
        reason = stop_reason::stalled;
        break;
      }
      stall_x = com.x();
      next_stall_check += stall_steps;
    }
    if (k >= n_steps) break;
    // 3. contact, self-collision and pushes
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, ground, opt.contact, scr.contacts, dt);
    if (!opt.self_contact.pairs.empty()) apply_self_contact_forces(m, ws, opt.self_contact);
    if (!opt.pushes.empty()) apply_pushes(m, ws, std::span<const push>(opt.pushes), t);
    // 4. sense and command
    if (num_sensed > 0) sense_actuator();
    if (scr.history.capacity() > 0) {
      sample.com = com;
      sample.com_velocity = com_v;
      scr.history.push(sample);
    }
    if (k >= next_call) {
      sen.t = t;
      sen.step = static_cast<int>(k);
      sen.com = com;
      sen.com_velocity = com_v;
      ctrl.command(static_cast<const sensors_with<Root, actuator_state>&>(sen), ctrl_state,
                   Eigen::Ref<Eigen::VectorXd>(scr.command));
      ++calls;
      next_call = detail::command_step(calls, period, dt);
    }
    // The controller's own external wrenches (Wu & Popovic 2010's helper force), every step
    // since step 3 cleared ws.f_ext.
    if constexpr (controller_with_external_wrenches<C, Root>)
      ctrl.add_external_wrenches(m, std::as_const(ctrl_state), ws);
    // 5. actuator and passive torques
    actuator_torques(act, m, s, std::as_const(ws), Eigen::Ref<const Eigen::VectorXd>(scr.command),
                     std::as_const(act_state), Eigen::Ref<Eigen::VectorXd>(scr.tau.tail(nj)));
    // Passive limit torques and the total, in one scalar loop (joint_limit_torques on a zeroed
    // vector, then tau + tau_passive): tau was just written entry by entry, and whole-vector
    // operations here would load it before those stores can forward.
    for (int i = 0; i < Root::nv; ++i) {
      scr.tau_passive[i] = 0.0;
      scr.tau_total[i] = scr.tau[i] + 0.0;
    }
    for (int j = 0; j < nj; ++j) {
      const int i = Root::nv + j;
      const joint_limit& L = m.dofs[j].limit;
      const double passive = L.model == limit_model::none
                                 ? 0.0
                                 : 0.0 + joint_limit_torque(L, s.q[Root::nq + j], s.v[i]);
      scr.tau_passive[i] = passive;
      scr.tau_total[i] = scr.tau[i] + passive;
    }
    // Implicit joint damping (rollout_options::implicit_joint_damping): solve
    // (M + dt diag(c)) ddq = tau_total - C with the dampers' coefficients c, and apply the dampers
    // at the end of the step: tau -= c_actuator dt ddq, tau_passive -= c_limit dt ddq. Then
    // M ddq = tau_total - C for the applied torques, and the integrator takes this ddq.
    if (implicit_damping) {
      if constexpr (actuator_with_joint_damping<Actuator, Root>)
        act.joint_damping(m, std::as_const(s), Eigen::Ref<const Eigen::VectorXd>(scr.command),
                          std::as_const(act_state),
                          Eigen::Ref<Eigen::VectorXd>(scr.damping_actuator));
      for (int j = 0; j < nj; ++j) {
        const double c_limit = joint_limit_damping(m.dofs[j].limit, s.q[Root::nq + j]);
        scr.damping_passive[j] = c_limit;
        scr.armature[j] = dt * (scr.damping_actuator[j] + c_limit);
      }
      const Eigen::VectorXd& a =
          detail::aba_with_current_kinematics(m, ws, scr.tau_total, scr.armature.data());
      for (int j = 0; j < nj; ++j) {
        const int i = Root::nv + j;
        const double dv = dt * a[i];
        scr.tau[i] -= scr.damping_actuator[j] * dv;
        scr.tau_passive[i] -= scr.damping_passive[j] * dv;
        scr.tau_total[i] = scr.tau[i] + scr.tau_passive[i];
      }
      implicit_ddq = true;
    }
    // 6. objective and recorder
    view.t = t;
    view.step = k;
    view.com = com;
    view.com_velocity = com_v;
    view.toe_top_contact = scr.contacts.any_toe_top_touching;
    if constexpr (controller_with_discrete_state<C>)
      view.controller_phase = static_cast<int>(ctrl.discrete_state(std::as_const(ctrl_state)));
    if constexpr (controller_with_report<C>)
      view.controller_report = std::span<const double>(ctrl.report(std::as_const(ctrl_state)));
    obj.accumulate(acc, static_cast<const step_view_with<Root, actuator_state>&>(view));
    if constexpr (user_observes)
      obs.observe(std::as_const(view));
    else
      recorder.observe(std::as_const(view));
    if constexpr (objective_with_done<Objective>) {
      if (obj.done(acc)) {
        reason = stop_reason::objective;
        break;
      }
    }
    // 7. integrate
    if constexpr (coupled)
      integ.step(m, s, act_state, dt, coupled_sys);
    else
      integ.step(m, s, dt, sys);
    kinematics_current = false;
    implicit_ddq = false;
    if constexpr (coupled) {
      // integrated above, with (q, v)
    } else if constexpr (actuator_with_advance<Actuator, Root>) {
      act.advance(m, s, Eigen::Ref<const Eigen::VectorXd>(scr.command), act_state, dt);
    } else if constexpr (actuator_with_derivative<Actuator, Root>) {
      act.derivative(m, s, Eigen::Ref<const Eigen::VectorXd>(scr.command), act_state, act_rate);
      act_state += dt * act_rate;
    }
    // 8. divergence
    if (!detail::all_finite(s.q) || !detail::all_finite(s.v)) {
      reason = stop_reason::non_finite;
      ++k;
      break;
    }
  }

  // ---------------------------------------------------------------- result
  res.reason = reason;
  res.steps = k;
  res.time = static_cast<double>(k) * dt;
  s.t = t0 + res.time;
  res.controller_calls = calls;
  // The observers see the state the rollout stopped in (a fall ends on the ground).
  auto finish_observers = [&] {
    if (opt.record == nullptr && !user_observes) return;
    view.t = t0 + res.time;
    view.step = k;
    view.com = res.com_final;
    view.final_state_valid = reason != stop_reason::non_finite;
    obs.finish(std::as_const(view), std::as_const(res));
  };
  if (reason == stop_reason::non_finite && !opt.score_divergence) {
    res.cost = failed_rollout_cost;
    finish_observers();
    return res;
  }
  rollout_outcome out;
  out.reason = reason;
  out.time = res.time;
  out.duration = static_cast<double>(n_steps) * dt;
  out.steps = k;
  out.com_initial = res.com_initial;
  out.com_final = res.com_final;
  res.objective_value = static_cast<double>(obj.finish(std::as_const(acc), out));
  const bool unusable = reason == stop_reason::non_finite ? !std::isfinite(res.objective_value)
                                                          : std::isnan(res.objective_value);
  res.cost = unusable ? failed_rollout_cost : res.objective_value;
  finish_observers();
  return res;
}
}  // namespace detail

/// The observation type a rollout hands its observers (rollout/observer.hpp).
template <root_joint Root, class Actuator, class Controller, class Objective, class Terrain>
using observation_for = observation<Root, Objective, std::remove_cvref_t<Controller>,
                                    typename Actuator::state_type, Terrain>;

/// Runs one rollout. See the file comment for the step order and result.hpp for the cost
/// convention. The controller is bound to `params` in place (pass one controller per thread); a
/// const controller is copied first. `observer` watches every step (rollout/observer.hpp; the
/// default observes nothing at no cost). \throws std::invalid_argument for a bad timestep,
/// duration, option, initial state, or parameter vector (wrong size, NaN), naming the value. A
/// diverging or falling rollout is a result, not an exception.
template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator, class Observer = null_observer>
requires actuator<Actuator, Root> &&
    controller<std::remove_cvref_t<Controller>, Root,
               sensors_with<Root, typename Actuator::state_type>> &&
    objective<Objective, Root, step_view_with<Root, typename Actuator::state_type>> &&
    integrator<std::remove_cvref_t<Integrator>, Root> &&
    rollout_observer<std::remove_reference_t<Observer>,
                     observation_for<Root, Actuator, Controller, Objective, Terrain>>
        rollout_result rollout(const model<Root>& m, const Actuator& act, Controller&& ctrl,
                               const Objective& obj, const Terrain& ground, Integrator&& integ,
                               std::span<const double> params, const rollout_options& opt,
                               rollout_scratch<Root>& scr, Observer&& observer = {}) {
  using C = std::remove_cvref_t<Controller>;
  using I = std::remove_cvref_t<Integrator>;
  rollout_policy_states<Actuator, C, Objective> states;  // made anew: set-up, may allocate
  if constexpr (std::is_const_v<std::remove_reference_t<Controller>> ||
                std::is_const_v<std::remove_reference_t<Integrator>>) {
    // bind() changes the controller and step() the integrator's scratch: work on copies of
    // const ones (set-up; may allocate).
    C c(ctrl);
    I i(integ);
    return detail::rollout_impl(m, act, c, obj, ground, i, params, opt, scr, states, observer);
  } else {
    return detail::rollout_impl(m, act, ctrl, obj, ground, integ, params, opt, scr, states,
                                observer);
  }
}

/// Runs one rollout with the policies' states kept in `states` from earlier rollouts (reset in
/// place where the policies allow it: rollout/policy_states.hpp), so that repeated rollouts of a
/// worker allocate nothing. The controller and integrator are used in place (not const).
template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator, class Observer = null_observer>
requires actuator<Actuator, Root> &&
    controller<Controller, Root, sensors_with<Root, typename Actuator::state_type>> &&
    objective<Objective, Root, step_view_with<Root, typename Actuator::state_type>> &&
    integrator<Integrator, Root> &&
    rollout_observer<std::remove_reference_t<Observer>,
                     observation_for<Root, Actuator, Controller, Objective, Terrain>>
        rollout_result rollout(const model<Root>& m, const Actuator& act, Controller& ctrl,
                               const Objective& obj, const Terrain& ground, Integrator& integ,
                               std::span<const double> params, const rollout_options& opt,
                               rollout_scratch<Root>& scr,
                               rollout_policy_states<Actuator, Controller, Objective>& states,
                               Observer&& observer = {}) {
  return detail::rollout_impl(m, act, ctrl, obj, ground, integ, params, opt, scr, states, observer);
}

/// Convenience overload for an Eigen parameter vector.
template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator, class Observer = null_observer>
rollout_result rollout(const model<Root>& m, const Actuator& act, Controller&& ctrl,
                       const Objective& obj, const Terrain& ground, Integrator&& integ,
                       const Eigen::VectorXd& params, const rollout_options& opt,
                       rollout_scratch<Root>& scr, Observer&& observer = {}) {
  return rollout(m, act, std::forward<Controller>(ctrl), obj, ground,
                 std::forward<Integrator>(integ),
                 std::span<const double>(params.data(), static_cast<std::size_t>(params.size())),
                 opt, scr, std::forward<Observer>(observer));
}

}  // namespace gaitsynth
