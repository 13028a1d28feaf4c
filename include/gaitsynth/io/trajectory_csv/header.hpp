#pragma once
/// \file trajectory_csv/header.hpp
/// The reader's header part: parses each header cell "<name>[:<item>][:<component>] [<unit>]"
/// back into a column of trajectory_channels, takes the q, v and objective term names from the
/// cells, and checks the whole against the writer's layout (schema.hpp), so that a missing,
/// repeated or misspelt column is reported by its header text before any row is read.
#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "gaitsynth/io/trajectory_csv/schema.hpp"
#include "gaitsynth/io/trajectory_csv/tokenizer.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth::detail::trajectory_csv {

/// What a header line declares: its columns in file order, the channels they belong to, and the
/// pushed bodies. The names from the header are stored into the trajectory.
struct header {
  std::vector<column> columns;
  std::vector<bool> present;        ///< per channel
  std::vector<std::size_t> pushed;  ///< sorted body indices
};

/// The first channel of the group named `kind`, or channel_count.
inline std::size_t find_group(std::string_view kind) {
  for (std::size_t g = 0; g < channel_count; g = group_end(g))
    if (trajectory_channels[g].name == kind) return g;
  return channel_count;
}

/// Parses cell number cn (1-based) of the header at line ln into a column; q/v/objective term
/// names go into `header_names` (per channel), bodies and contact points are looked up in t.
inline column parse_cell(const std::string& full, int ln, int cn, const trajectory& t,
                         std::vector<std::vector<std::string>>& header_names, const locator& fail) {
  const auto ub = full.rfind(" [");
  if (ub == std::string::npos || full.back() != ']')
    throw fail(ln, cn, "header cell '" + full + "' has no unit in [brackets]");
  const std::string_view name = std::string_view(full).substr(0, ub);
  const std::string_view unit = std::string_view(full).substr(ub + 2, full.size() - ub - 3);
  const auto c1 = name.find(':');
  const std::string_view kind = name.substr(0, c1);
  const std::string_view rest = c1 == std::string_view::npos ? "" : name.substr(c1 + 1);
  const std::size_t g = find_group(kind);
  if (g == channel_count) throw fail(ln, cn, "unknown column '" + full + "'");
  const channel& first = trajectory_channels[g];
  // Split the rest into item and component (an item name may itself contain ':').
  std::string_view who, comp = rest;
  if (first.items != per::frame) {
    const auto c2 = first.components.empty() ? std::string_view::npos : rest.rfind(':');
    if (!first.components.empty() && c2 == std::string_view::npos)
      throw fail(ln, cn,
                 "header cell '" + full + "' needs " + std::string(kind) + ":<" +
                     item_word(first.items) + " name>:<component>");
    who = rest.substr(0, c2);
    comp = c2 == std::string_view::npos ? "" : rest.substr(c2 + 1);
    if (who.empty())
      throw fail(ln, cn,
                 "header cell '" + full + "' names no " + item_word(first.items) + " (" +
                     std::string(kind) + ":<name>)");
  }
  column col{channel_count, 0, 0, full};
  for (std::size_t c = g; c < group_end(g) && col.channel == channel_count; ++c)
    for (int k = 0; k < component_count(trajectory_channels[c]); ++k)
      if (component(trajectory_channels[c], k) == comp) col = {c, 0, k, full};
  if (col.channel == channel_count)
    throw fail(ln, cn,
               "unknown component '" + std::string(comp) + "' in header cell '" + full + "'");
  const channel& ch = trajectory_channels[col.channel];
  // Rows are keyed on the time: it comes first, and only there.
  const std::string time = cell(trajectory_channels[0], {}, {});
  if (cn == 1 && col.channel != 0)
    throw fail(ln, 1, "the first column must be '" + time + "', not '" + full + "'");
  if (cn > 1 && col.channel == 0) throw fail(ln, cn, "'" + time + "' must be the first column");
  if (unit != unit_of(ch, who))
    throw fail(ln, cn,
               "header cell '" + full + "': " + std::string(ch.member) + " is in [" +
                   std::string(unit_of(ch, who)) + "], not [" + std::string(unit) + "]");
  if (named_in_header(ch.items)) {
    header_names[col.channel].emplace_back(who);
    col.item = header_names[col.channel].size() - 1;
  } else if (ch.items != per::frame) {
    const std::vector<std::string>& names = *names_of(t, ch.items);
    std::size_t i = 0;
    while (i < names.size() && names[i] != who) ++i;
    if (i == names.size()) {
      const bool contact = ch.items == per::contact_point;
      throw fail(ln, cn,
                 "header cell '" + full + "' names " + (contact ? "contact point" : "body") + " '" +
                     std::string(who) + "', not in the '# " + (contact ? "contact" : "body") +
                     ":' lines");
    }
    col.item = i;
  }
  return col;
}

/// Why two channels over the same items (tau and v) disagree on their names.
inline std::string mismatch(std::string_view a, const std::vector<std::string>& an,
                            std::string_view b, const std::vector<std::string>& bn) {
  std::size_t k = 0;
  while (k < an.size() && k < bn.size() && an[k] == bn[k]) ++k;
  const std::string sa(a), sb(b);
  if (k < an.size() && k < bn.size())
    return "the " + sa + " columns must name the " + sb + " columns' items in order: " + sa +
           " item " + std::to_string(k + 1) + " is '" + an[k] + "', " + sb + " item " +
           std::to_string(k + 1) + " is '" + bn[k] + "'";
  return "the " + sa + " columns must name the " + sb + " columns' items in order: " + sa +
         " has " + std::to_string(an.size()) + ", " + sb + " has " + std::to_string(bn.size());
}

/// Reads the header at line ln (1-based) of a file whose metadata is already in t.
inline header read_header(std::string_view line, int ln, trajectory& t, const locator& fail) {
  std::vector<std::string_view> cells;
  split_fields(line, cells);
  header h;
  h.present.assign(channel_count, false);
  std::vector<std::vector<std::string>> header_names(channel_count);
  std::map<std::tuple<std::size_t, std::size_t, int>, int> seen;  // -> column number
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int cn = static_cast<int>(i) + 1;
    column c = parse_cell(std::string(cells[i]), ln, cn, t, header_names, fail);
    const auto [it, fresh] = seen.try_emplace({c.channel, c.item, c.component}, cn);
    if (!fresh)
      throw fail(ln, cn, "column '" + c.cell + "' repeats column " + std::to_string(it->second));
    h.present[c.channel] = true;
    if (trajectory_channels[c.channel].items == per::pushed_body) h.pushed.push_back(c.item);
    h.columns.push_back(std::move(c));
  }
  // Names from the header: the first channel of a kind gives them, the others must agree (tau
  // columns name the v coordinates).
  for (std::size_t c = 0; c < channel_count; ++c) {
    const per p = trajectory_channels[c].items;
    if (!named_in_header(p) || !h.present[c]) continue;
    std::size_t d = 0;
    while (!(h.present[d] && trajectory_channels[d].items == p)) ++d;
    if (d == c)
      *names_of(t, p) = header_names[c];
    else if (header_names[c] != header_names[d])
      throw fail(ln, 0,
                 mismatch(trajectory_channels[c].name, header_names[c], trajectory_channels[d].name,
                          header_names[d]));
  }
  // What the writer would have written for these channels must all be there.
  for (std::size_t c = 0; c < channel_count; ++c) {
    const channel& ch = trajectory_channels[c];
    if (ch.when == channel::presence::always && ch.items == per::frame) h.present[c] = true;
    if (ch.when == channel::presence::with_previous)
      h.present[c] = h.present[c - 1] = h.present[c] || h.present[c - 1];
  }
  std::sort(h.pushed.begin(), h.pushed.end());
  h.pushed.erase(std::unique(h.pushed.begin(), h.pushed.end()), h.pushed.end());
  for (const column& c : layout(t, h.present, h.pushed))
    if (!seen.count({c.channel, c.item, c.component}))
      throw fail(ln, 0, "missing column '" + c.cell + "'");
  return h;
}

}  // namespace gaitsynth::detail::trajectory_csv
