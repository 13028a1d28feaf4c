#pragma once
/// \file trajectory_csv/schema.hpp
/// The columns of a trajectory CSV, all derived from trajectory_channels (rollout/trajectory.hpp):
/// the items a channel has in a trajectory, the header cell of a column ("body:pelvis:qw [1]") and
/// the column order (layout). The writer writes layout()'s columns; the reader parses header cells
/// back into columns (header.hpp) and checks them against layout(), so both follow the list.
#include <cstddef>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth::detail::trajectory_csv {

using channel = trajectory_channel;
using per = trajectory_channel::per;
inline constexpr std::size_t channel_count = std::size(trajectory_channels);

/// Component k of a channel: "x y z" gives "x", "y", "z"; "" gives one unnamed component.
constexpr int component_count(const channel& ch) {
  int n = 1;
  for (char c : ch.components) n += c == ' ';
  return n;
}
constexpr std::string_view component(const channel& ch, int k) {
  std::string_view s = ch.components;
  for (; k > 0; --k) s.remove_prefix(s.find(' ') + 1);
  return s.substr(0, s.find(' '));
}

/// A group is a run of channels of one name; its columns interleave item by item.
constexpr std::size_t group_end(std::size_t c) {
  const std::string_view name = trajectory_channels[c].name;
  while (c < channel_count && trajectory_channels[c].name == name) ++c;
  return c;
}

/// Whether the item names come from the header cells (q, v, objective terms) rather than from the
/// '#' lines (bodies, contact points; pushed bodies are bodies) or nowhere (one per frame).
constexpr bool named_in_header(per p) {
  return p == per::q_name || p == per::v_name || p == per::objective_term;
}

/// What an item is called in messages ("one per body name").
inline const char* item_word(per p) {
  switch (p) {
    case per::frame:
      return "frame";
    case per::q_name:
      return "q coordinate";
    case per::v_name:
      return "v coordinate";
    case per::body:
      return "body";
    case per::contact_point:
      return "contact point";
    case per::pushed_body:
      return "pushed body";
    case per::objective_term:
      return "objective term";
  }
  return "?";
}

/// The trajectory's list of names of one kind of item; null for per::frame.
template <class Trajectory>  // trajectory or const trajectory
auto* names_of(Trajectory& t, per p) {
  using list = decltype(&t.q_names);
  switch (p) {
    case per::frame:
      return list{nullptr};
    case per::q_name:
      return &t.q_names;
    case per::v_name:
      return &t.v_names;
    case per::body:
    case per::pushed_body:
      return &t.body_names;
    case per::contact_point:
      return &t.contact_names;
    case per::objective_term:
      return &t.objective_term_names;
  }
  return list{nullptr};
}

struct item {
  std::size_t index;      ///< into the frame's member (for pushed bodies: the body index)
  std::string_view name;  ///< empty for per::frame
};

/// The items of kind p in t, in column order; `pushed` lists the pushed bodies (sorted).
inline std::vector<item> items_of(const trajectory& t, per p,
                                  const std::vector<std::size_t>& pushed) {
  const std::vector<std::string>* names = names_of(t, p);
  std::vector<item> out;
  if (names == nullptr)
    out.push_back({0, {}});
  else if (p == per::pushed_body)
    for (std::size_t b : pushed) out.push_back({b, (*names)[b]});
  else
    for (std::size_t i = 0; i < names->size(); ++i) out.push_back({i, (*names)[i]});
  return out;
}

inline std::string_view unit_of(const channel& ch, std::string_view item) {
  return ch.unit_of != nullptr ? std::string_view(ch.unit_of(item)) : ch.unit;
}

/// The header cell "<name>[:<item>][:<component>] [<unit>]": "t [s]", "q:lknee [rad]",
/// "com:x [m]", "body:pelvis:qw [1]".
inline std::string cell(const channel& ch, std::string_view item, std::string_view comp) {
  std::string s(ch.name);
  if (!item.empty()) (s += ':') += item;
  if (!comp.empty()) (s += ':') += comp;
  ((s += " [") += unit_of(ch, item)) += ']';
  return s;
}

/// One column: component `component` of item `item` of trajectory_channels[channel].
struct column {
  std::size_t channel;
  std::size_t item;  ///< item::index
  int component;
  std::string cell;
};

/// The columns of the channels marked in `present`, in file order: group after group in list
/// order; within a group item by item, and within an item channel by channel (contact:lheel:x y z
/// fx fy fz active, then contact:rtoe:...).
inline std::vector<column> layout(const trajectory& t, const std::vector<bool>& present,
                                  const std::vector<std::size_t>& pushed) {
  std::vector<column> out;
  for (std::size_t g = 0; g < channel_count; g = group_end(g))
    for (const item& it : items_of(t, trajectory_channels[g].items, pushed))
      for (std::size_t c = g; c < group_end(g); ++c)
        if (present[c])
          for (int k = 0; k < component_count(trajectory_channels[c]); ++k)
            out.push_back(
                {c, it.index, k,
                 cell(trajectory_channels[c], it.name, component(trajectory_channels[c], k))});
  return out;
}

/// What the layout and the header parser rely on; a new channel that breaks it fails to compile.
/// (That get and set are given, and size and resize for optional channels, is checked by
/// tests/io/trajectory_csv.cpp: comparing function pointers is no constant expression under
/// -fsanitize=undefined.)
constexpr bool valid_channel_list() {
  const channel& t = trajectory_channels[0];  // rows are keyed on the time, always first
  if (t.items != per::frame || t.when != channel::presence::always || component_count(t) != 1)
    return false;
  for (std::size_t c = 0; c < channel_count; ++c) {
    const channel& ch = trajectory_channels[c];
    const std::size_t g = [&] {  // first channel of c's group
      std::size_t b = c;
      while (b > 0 && trajectory_channels[b - 1].name == ch.name) --b;
      return b;
    }();
    if (ch.name.empty() || ch.name.find(':') != std::string_view::npos) return false;
    if (ch.when == channel::presence::with_previous && c == g) return false;
    for (std::size_t d = c + 1; d < channel_count; ++d)  // a name forms one run only
      if (trajectory_channels[d].name == ch.name && d >= group_end(c)) return false;
    const channel& first = trajectory_channels[g];
    // Header cells split as name:item:component, so a group needs one kind of item and either
    // named components in all its channels or in none; components name one column per item.
    if (ch.items != first.items || ch.components.empty() != first.components.empty()) return false;
    for (std::size_t d = g; d < group_end(g); ++d)
      for (int k = 0; k < component_count(ch); ++k)
        for (int j = 0; j < component_count(trajectory_channels[d]); ++j)
          if ((d != c || j != k) && component(ch, k) == component(trajectory_channels[d], j))
            return false;
  }
  return true;
}
static_assert(valid_channel_list(), "trajectory_channels: see valid_channel_list()");

}  // namespace gaitsynth::detail::trajectory_csv
