#pragma once
/// \file controllers/end_effector/planned_walk_names.hpp
/// The names of planned_walk_options' enums, one table per enum, shared by the saved controller
/// (planned_walk_json.hpp), examples/wu2010_walk.cpp's command line and its summaries, so that
/// what is written, what is read back and what the command line accepts cannot drift apart.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"

namespace gaitsynth {

/// One enum value and its saved name.
template <class E>
struct enum_name {
  std::string_view name;
  E value;
};

template <class E, std::size_t N>
using enum_names = std::array<enum_name<E>, N>;

/// Sec. 6.3's stationary target of the stance foot (stance_foot_target).
inline constexpr enum_names<stance_foot_target, 3> stance_foot_target_names{{
    {"planned_landing", stance_foot_target::planned_landing},
    {"touchdown", stance_foot_target::touchdown},
    {"first_contact", stance_foot_target::first_contact},
}};

/// When a half-cycle ends (half_cycle_end).
inline constexpr enum_names<half_cycle_end, 2> half_cycle_end_names{{
    {"fixed", half_cycle_end::fixed},
    {"touchdown", half_cycle_end::touchdown},
}};

/// How Omega_1 and Pi_1 relate to Omega_0 and Pi_0 (planned_walk_symmetry).
inline constexpr enum_names<planned_walk_symmetry, 3> planned_walk_symmetry_names{{
    {"asymmetric", planned_walk_symmetry::asymmetric},
    {"mirrored_planner", planned_walk_symmetry::mirrored_planner},
    {"mirrored", planned_walk_symmetry::mirrored},
}};

/// Sec. 6.3's contact test for pinning (pin_contact).
inline constexpr enum_names<pin_contact, 2> pin_contact_names{{
    {"frame_geometry", pin_contact::frame_geometry},
    {"link", pin_contact::link},
}};

/// The name of `value` in `table` (every value of these enums has one; "" otherwise).
template <class E, std::size_t N>
constexpr std::string_view name_of(const enum_names<E, N>& table, E value) {
  for (const auto& e : table)
    if (e.value == value) return e.name;
  return {};
}

/// The value named `name`, or nothing when no entry has that name.
template <class E, std::size_t N>
constexpr std::optional<E> value_of(const enum_names<E, N>& table, std::string_view name) {
  for (const auto& e : table)
    if (e.name == name) return e.value;
  return std::nullopt;
}

/// Every name, in the table's order (the command line's choices).
template <class E, std::size_t N>
std::vector<std::string> names_of(const enum_names<E, N>& table) {
  std::vector<std::string> out;
  for (const auto& e : table) out.emplace_back(e.name);
  return out;
}

/// The names quoted for an error message: "\"a\", \"b\" or \"c\"".
template <class E, std::size_t N>
std::string quoted_choices(const enum_names<E, N>& table) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += i + 1 < N ? ", " : " or ";
    out += '"';
    out += table[i].name;
    out += '"';
  }
  return out;
}

}  // namespace gaitsynth
