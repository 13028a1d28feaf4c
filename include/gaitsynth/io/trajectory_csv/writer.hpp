#pragma once
/// \file trajectory_csv/writer.hpp
/// write_trajectory_csv / save_trajectory_csv: checks the trajectory, decides which channels it
/// records (schema.hpp's presence rules over its frames), then writes the metadata, the header
/// and one row per frame, every value through trajectory_channels' get().
#include <algorithm>
#include <cstddef>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/io/trajectory_csv/metadata.hpp"
#include "gaitsynth/io/trajectory_csv/schema.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

struct trajectory_csv_options {
  int precision = 0;  ///< significant digits; 0: shortest exact round trip
};

namespace detail::trajectory_csv {

/// Names go into header cells and '#' lines: no separators, quotes or line breaks.
inline void check_names(const trajectory& t) {
  auto check = [](const std::vector<std::string>& names, const char* what) {
    for (const auto& n : names) {
      check_argument(!n.empty(), "write_trajectory_csv: an empty ", what, " name");
      check_argument(n.find_first_of(",\"\n\r") == std::string::npos,
                     "write_trajectory_csv: ", what, " name '", n,
                     "' contains a comma, quote or line break");
    }
  };
  check(t.q_names, "q");
  check(t.v_names, "v");
  check(t.body_names, "body");
  check(t.contact_names, "contact");
  check(t.objective_term_names, "objective term");
  check_argument(t.model_name.find_first_of("\n\r") == std::string::npos,
                 "write_trajectory_csv: model name contains a line break");
  check_argument(t.body_parents.size() == t.body_names.size(),
                 "write_trajectory_csv: ", t.body_names.size(), " body names but ",
                 t.body_parents.size(), " body parents");
  check_argument(t.contact_bodies.size() == t.contact_names.size(),
                 "write_trajectory_csv: ", t.contact_names.size(), " contact names but ",
                 t.contact_bodies.size(), " contact bodies");
  const terrain_samples& ts = t.terrain;
  check_argument(ts.nx >= 0 && ts.ny >= 0 &&
                     ts.height.size() == static_cast<std::size_t>(std::max(ts.nx, 0)) *
                                             static_cast<std::size_t>(std::max(ts.ny, 0)),
                 "write_trajectory_csv: terrain has nx = ", ts.nx, ", ny = ", ts.ny, " but ",
                 ts.height.size(), " heights");
}

/// The bodies pushed in some frame, sorted: the push columns.
inline std::vector<std::size_t> pushed_bodies(const trajectory& t) {
  std::vector<std::size_t> pushed;
  for (std::size_t f = 0; f < t.frames.size(); ++f)
    for (const auto& p : t.frames[f].pushes) {
      check_argument(p.first >= 0 && static_cast<std::size_t>(p.first) < t.body_names.size(),
                     "write_trajectory_csv: frame ", f, ": push on body ", p.first, " of ",
                     t.body_names.size());
      const auto b = static_cast<std::size_t>(p.first);
      if (std::find(pushed.begin(), pushed.end(), b) == pushed.end()) pushed.push_back(b);
    }
  std::sort(pushed.begin(), pushed.end());
  return pushed;
}

/// Which channels t records: `always` ones, `optional` ones that frame 0 has (every frame must
/// then have one entry per item, or none when frame 0 has none), `with_previous` ones with the
/// channel before. With no frames, an optional channel is written when it is the first to carry
/// its item names in the header, so that the names survive (v without tau).
inline std::vector<bool> recorded_channels(const trajectory& t) {
  using presence = channel::presence;
  std::vector<bool> present(channel_count, false);
  for (std::size_t c = 0; c < channel_count; ++c) {
    const channel& ch = trajectory_channels[c];
    const std::vector<std::string>* names = names_of(t, ch.items);
    const std::size_t n = names == nullptr ? 1 : names->size();
    if (ch.when == presence::always) {
      present[c] = true;
    } else if (ch.when == presence::with_previous) {
      present[c] = present[c - 1];
    } else if (t.frames.empty()) {
      bool first_carrier = named_in_header(ch.items) && n > 0;
      for (std::size_t d = 0; d < c; ++d)
        first_carrier = first_carrier && !(present[d] && trajectory_channels[d].items == ch.items);
      present[c] = first_carrier;
    } else {
      const std::size_t s0 = ch.size(t.frames[0]);
      present[c] = n > 0 && s0 == n;
      check_argument(present[c] || s0 == 0 || n == 0, "write_trajectory_csv: frame 0: ", ch.member,
                     " has ", s0, " entries, expected ", n, " (one per ", item_word(ch.items),
                     " name) or none");
    }
    if (ch.size == nullptr) continue;
    const std::size_t expected = present[c] ? n : 0;
    for (std::size_t f = 0; f < t.frames.size(); ++f) {
      const std::size_t s = ch.size(t.frames[f]);
      if (s == expected) continue;
      std::string why = " (one per " + std::string(item_word(ch.items)) + " name)";
      if (n == 0)
        why = " (there are no " + std::string(item_word(ch.items)) + " names)";
      else if (!present[c] && ch.when == presence::with_previous)
        why = " (" + std::string(trajectory_channels[c - 1].member) + " has none)";
      else if (!present[c])
        why = " (frame 0 has none)";
      throw std::invalid_argument("write_trajectory_csv: frame " + std::to_string(f) + ": " +
                                  std::string(ch.member) + " has " + std::to_string(s) +
                                  " entries, expected " + std::to_string(expected) + why);
    }
  }
  return present;
}

}  // namespace detail::trajectory_csv

/// Writes the trajectory as CSV (io/trajectory_csv.hpp). Throws std::invalid_argument when the
/// trajectory is inconsistent (a frame's vector size differs from its names, names with commas).
inline void write_trajectory_csv(const trajectory& traj, std::ostream& os,
                                 const trajectory_csv_options& opt = {}) {
  using namespace detail::trajectory_csv;
  check_argument(opt.precision >= 0 && opt.precision <= 17,
                 "write_trajectory_csv: precision must be in [0, 17], got ", opt.precision);
  check_names(traj);
  const std::vector<std::size_t> pushed = pushed_bodies(traj);
  const std::vector<column> cols = layout(traj, recorded_channels(traj), pushed);
  std::string out;
  write_metadata(traj, out);
  for (std::size_t i = 0; i < cols.size(); ++i) (out += i ? "," : "") += cols[i].cell;
  out += '\n';
  os << out;
  for (const trajectory_frame& fr : traj.frames) {
    out.clear();
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const column& c = cols[i];
      const channel& ch = trajectory_channels[c.channel];
      if (i > 0) out += ',';
      const double x = ch.get(fr, c.item, c.component);
      if (ch.type == channel::value::real)
        append_number(out, x, opt.precision);
      else if (ch.type == channel::value::flag)
        out += x != 0 ? '1' : '0';
      else
        out += std::to_string(static_cast<int>(x));
    }
    out += '\n';
    os << out;
  }
}

/// Writes the CSV to `path` (nothing when the trajectory is invalid); std::runtime_error when the
/// file cannot be written.
inline void save_trajectory_csv(const trajectory& traj, const std::string& path,
                                const trajectory_csv_options& opt = {}) {
  std::ostringstream s;
  write_trajectory_csv(traj, s, opt);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("save_trajectory_csv: cannot open '" + path + "' for writing");
  f << s.str();
  f.close();
  if (!f) throw std::runtime_error("save_trajectory_csv: failed writing '" + path + "'");
}

}  // namespace gaitsynth
