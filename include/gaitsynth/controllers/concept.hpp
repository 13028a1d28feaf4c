#pragma once
/// \file controllers/concept.hpp
/// The controller policy (docs/architecture.md). A controller maps sensors to an actuator command.
///
/// Valid expressions (C: controller type, c: C&, cc: const C&, m: const model<Root>&,
/// p: std::span<const double>, s: the rollout's sensors (derived from sensors<Root>),
/// st: C::state_type&, cmd: Eigen::Ref<Eigen::VectorXd>):
///
///   C::state_type                 its own evolving state (FSM phase, node index, QP workspace,
///                                 filters); a copyable value, created at set-up, so the step loop
///                                 never allocates.
///   cc.num_parameters()           size of the parameter vector (std::size_t convertible)
///   c.bind(p)                     takes the parameters; validates size and finiteness and throws
///                                 std::invalid_argument naming the index and value (use
///                                 check_parameters below). Called once per rollout, at set-up.
///   cc.period()                   seconds between commands; 0 = every physics step. The rollout
///                                 calls command at the first physics step at or after t0 + n
///                                 period (a 64 Hz controller over a 2400 Hz simulation, Wu &
///                                 Popovic 2010), and holds the command in between.
///   cc.make_state(m)              -> C::state_type (set-up; may allocate)
///   cc.command(s, st, cmd)        writes the actuator command (its meaning is the actuator's:
///                                 joint targets for pd, torques for torque, excitations for
///                                 muscles). Must not allocate.
///
/// Optional hooks, detected with requires (a controller without them pays nothing):
///   cc.output_kind() -> command_kind     checked against the actuator's at set-up
///                                        (check_command_kinds, actuators/command_kind.hpp); at
///                                        compile time when it is static constexpr and the
///                                        actuator's input_kind() is too
///   cc.command_size(m) -> int            how many entries it writes; the rollout refuses an
///                                        actuator whose command_size differs (-1: any size)
///   cc.max_sensor_delay() -> double (s)  longest delay it reads through sensors::delayed_*
///   cc.initial_state(m, sim_state&)      overwrite the start state (start-state parameters,
///                                        Wang et al. 2009 Sec. 4 optimize it with the controller)
///   cc.discrete_state(st) -> int         FSM phase / active node, for the recorder
///   cc.report(st) -> std::span<const double>
///                                        per-step quantities the controller computed (a fixed-size
///                                        span into st, no allocation) that an objective reads
///                                        through step_view::controller_report (Wu & Popovic 2010
///                                        Sec. 8.1: the frame-tracking errors)
///   cc.report_names() -> range of strings  their names, report(st).size() of them
///   cc.add_external_wrenches(m, std::as_const(st), ws)
///                                        adds world wrenches to ws.f_ext (add_point_force, as
///                                        contact and pushes) after the command, every physics
///                                        step, reading only the poses of ws (workspace<Root>&,
///                                        kinematics current); Wu & Popovic 2010 Sec. 8.2's helper
///                                        force. Must not allocate.
#include <Eigen/Core>
#include <concepts>
#include <cstddef>
#include <span>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

/// C is a controller usable with the sensors type S (sensors<Root> or sensors_with<Root, AS>).
template <class C, class Root, class S = sensors<Root>>
concept controller = root_joint<Root> && std::derived_from<S, sensors<Root>> &&
    requires(C& c, const C& cc, const model<Root>& m, std::span<const double> p, const S& s,
             typename C::state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) {
  typename C::state_type;
  { cc.num_parameters() } -> std::convertible_to<std::size_t>;
  c.bind(p);
  { cc.period() } -> std::convertible_to<double>;
  { cc.make_state(m) } -> std::same_as<typename C::state_type>;
  cc.command(s, st, cmd);
};

// controller_with_output_kind (and its static form) is in actuators/command_kind.hpp, next to
// check_command_kinds.
template <class C, class Root>
concept controller_with_command_size = requires(const C& c, const model<Root>& m) {
  { c.command_size(m) } -> std::convertible_to<int>;
};

template <class C>
concept controller_with_sensor_delay = requires(const C& c) {
  { c.max_sensor_delay() } -> std::convertible_to<double>;
};
template <class C, class Root>
concept controller_with_initial_state = requires(const C& c, const model<Root>& m, sim_state& s) {
  c.initial_state(m, s);
};
/// Optional: c.reset_state(m, st) makes st what make_state(m) returns, without allocating (a
/// worker's next rollout: rollout/policy_states.hpp).
template <class C, class Root>
concept controller_with_reset_state = requires(const C& c, const model<Root>& m,
                                               typename C::state_type& st) {
  c.reset_state(m, st);
};

template <class C>
concept controller_with_discrete_state = requires(const C& c, const typename C::state_type& st) {
  { c.discrete_state(st) } -> std::convertible_to<int>;
};

template <class C>
concept controller_with_report = requires(const C& c, const typename C::state_type& st) {
  { c.report(st) } -> std::convertible_to<std::span<const double>>;
  c.report_names();
};

template <class C, class Root>
concept controller_with_external_wrenches = requires(const C& c, const model<Root>& m,
                                                     const typename C::state_type& st,
                                                     workspace<Root>& ws) {
  c.add_external_wrenches(m, st, ws);
};

/// The validation every bind() does: size, then finiteness, naming the index and value.
/// `who` names the controller in the message ("pose_hold parameters").
inline void check_parameters(std::span<const double> p, std::size_t expected, const char* who) {
  check_size(static_cast<std::ptrdiff_t>(p.size()), static_cast<std::ptrdiff_t>(expected), who);
  for (std::size_t i = 0; i < p.size(); ++i)
    check_argument(std::isfinite(p[i]), who, ": parameter ", i, " is not finite (", p[i], ")");
}

}  // namespace gaitsynth
