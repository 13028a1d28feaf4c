#pragma once
/// \file trajectory_csv/rows.hpp
/// The reader's row part: one data line into one trajectory_frame, field by field through the
/// header's columns and trajectory_channels' set(), each value checked (a number, a 0/1 flag, an
/// int; the time finite) and a bad one reported with its line, column number and header cell.
#include <climits>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/io/trajectory_csv/header.hpp"
#include "gaitsynth/io/trajectory_csv/schema.hpp"
#include "gaitsynth/io/trajectory_csv/tokenizer.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth::detail::trajectory_csv {

/// A frame with room for every item of the channels the header has (copied for each row).
inline trajectory_frame empty_frame(const header& h, const trajectory& t) {
  trajectory_frame f;
  for (std::size_t c = 0; c < channel_count; ++c) {
    const channel& ch = trajectory_channels[c];
    if (h.present[c] && ch.resize != nullptr) ch.resize(f, items_of(t, ch.items, h.pushed).size());
  }
  return f;
}

/// Reads data line ln (1-based) into `frame` (which starts as empty_frame()). `fields` is scratch.
inline void read_row(std::string_view line, int ln, const header& h, trajectory_frame& frame,
                     std::vector<std::string_view>& fields, const locator& fail) {
  split_fields(line, fields);
  if (fields.size() != h.columns.size())
    throw fail(ln, 0,
               "expected " + std::to_string(h.columns.size()) + " fields, got " +
                   std::to_string(fields.size()) +
                   (fields.size() < h.columns.size() ? " (truncated line?)" : ""));
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const column& c = h.columns[i];
    const channel& ch = trajectory_channels[c.channel];
    const std::string_view s = fields[i];
    const int cn = static_cast<int>(i) + 1;
    double x = 0;
    if (ch.type == channel::value::integer) {
      long long k = 0;
      if (!parse_all(s, k))
        throw fail(ln, cn, unreadable(s, "an integer", "column '" + c.cell + "'"));
      if (k < INT_MIN || k > INT_MAX)
        throw fail(ln, cn,
                   "'" + std::string(s) + "' is out of range for an int (column '" + c.cell + "')");
      x = static_cast<double>(k);
    } else {
      if (!parse_all(s, x))
        throw fail(ln, cn, unreadable(s, "a number", "column '" + c.cell + "'"));
      // Values may be nan or inf (a diverged simulation records them), the time may not.
      if (c.channel == 0 && !std::isfinite(x))
        throw fail(ln, cn, "the time must be finite, got '" + std::string(s) + "'");
      if (ch.type == channel::value::flag && x != 0 && x != 1)
        throw fail(ln, cn,
                   "'" + std::string(component(ch, c.component)) + "' must be 0 or 1, got '" +
                       std::string(s.substr(0, 40)) + "' (column '" + c.cell + "')");
    }
    ch.set(frame, c.item, c.component, x);
  }
  for (std::size_t c = 0; c < channel_count; ++c)
    if (h.present[c] && trajectory_channels[c].finish != nullptr)
      trajectory_channels[c].finish(frame);
}

}  // namespace gaitsynth::detail::trajectory_csv
