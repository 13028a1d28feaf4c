#pragma once
/// \file actuators/command_kind.hpp
/// What a command vector means (command_kind), its name (to_string), and the check that a
/// controller's output kind is its actuator's input kind (check_command_kinds).
///
/// A kind is *static* when the type fixes it: an actuator's `input_kind()` or a controller's
/// `output_kind()` declared `static constexpr` (torque_actuator, pd_actuator, mixed_pd_actuator).
/// It is *dynamic* when the object decides (pose_hold and nearest_neighbor take it as an option).
/// check_command_kinds compares two static kinds at compile time (static_assert) and otherwise
/// compares at run time and throws std::invalid_argument naming both kinds; the rollout calls it
/// at set-up. A controller without output_kind() is not checked.
#include <concepts>
#include <string_view>
#include <type_traits>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// What an actuator command vector means.
enum class command_kind {
  joint_torque,  ///< N m per joint DOF
  joint_target,  ///< target angle per joint DOF (rad), optionally followed by feed-forward torques
  excitation,    ///< neural excitation per muscle in [0, 1]
  mixed          ///< per joint DOF target, gains and torque (mixed_pd_actuator, mixed_pd.hpp)
};

/// The enumerator's name ("joint_torque", "joint_target", "excitation", "mixed"), as messages and
/// files spell it; "unknown" for a value outside the enumeration.
constexpr std::string_view to_string(command_kind k) {
  switch (k) {
    case command_kind::joint_torque:
      return "joint_torque";
    case command_kind::joint_target:
      return "joint_target";
    case command_kind::excitation:
      return "excitation";
    case command_kind::mixed:
      return "mixed";
  }
  return "unknown";
}

/// The controller declares what its commands mean (checked against the actuator at set-up).
template <class C>
concept controller_with_output_kind = requires(const C& c) {
  { c.output_kind() } -> std::same_as<command_kind>;
};

/// C::output_kind() is a constant expression: the type fixes its kind.
template <class C>
concept controller_with_static_output_kind = controller_with_output_kind<C> && requires {
  typename std::integral_constant<command_kind, C::output_kind()>;
};

/// A::input_kind() is a constant expression: the type fixes its kind.
template <class A>
concept actuator_with_static_input_kind = requires(const A& a) {
  { a.input_kind() } -> std::same_as<command_kind>;
  typename std::integral_constant<command_kind, A::input_kind()>;
};

/// Both kinds are known at compile time, so check_command_kinds decides at compile time.
template <class C, class A>
inline constexpr bool command_kinds_static =
    controller_with_static_output_kind<C>&& actuator_with_static_input_kind<A>;

namespace detail {
template <class C, class A>
consteval bool command_kinds_compatible_impl() {
  if constexpr (command_kinds_static<C, A>)
    return C::output_kind() == A::input_kind();
  else
    return true;  // decided at run time (or, without output_kind(), not checked)
}
}  // namespace detail

/// False exactly when both kinds are static and differ: a controller of type C can then never
/// drive an actuator of type A. True when they match or when a kind is only known at run time.
template <class C, class A>
inline constexpr bool command_kinds_compatible = detail::command_kinds_compatible_impl<C, A>();

/// Checks that ctrl's commands mean what act expects. Static kinds: a compile error when they
/// differ. Otherwise, when C has output_kind(): throws std::invalid_argument naming both kinds,
/// e.g. "command kinds differ: controller outputs joint_target, actuator expects joint_torque".
template <class C, class A>
void check_command_kinds([[maybe_unused]] const C& ctrl, [[maybe_unused]] const A& act) {
  if constexpr (command_kinds_static<C, A>) {
    static_assert(command_kinds_compatible<C, A>,
                  "the controller's static output_kind() differs from the actuator's static "
                  "input_kind(): its commands mean something else (see to_string(command_kind))");
  } else if constexpr (controller_with_output_kind<C>) {
    const command_kind out = ctrl.output_kind(), in = act.input_kind();
    check_argument(out == in, "command kinds differ: controller outputs ", to_string(out),
                   ", actuator expects ", to_string(in),
                   " (a controller's output kind must be its actuator's input kind)");
  }
}

}  // namespace gaitsynth
