#pragma once
/// \file trajectory_csv/metadata.hpp
/// The '#' lines above the header: what a trajectory holds besides its frames (model name, planar
/// flag, frame count, body tree, contact points, terrain samples), written and read back.
///
///   # gaitsynth trajectory csv 1
///   # model: walker2d
///   # planar: 1
///   # frames: 2400
///   # body: 0 -1 pelvis            (index, parent index, name: the rest of the line)
///   # contact: 0 5 lheel           (index, body index, name)
///   # terrain: x0 y0 dx dy nx ny   (and "# terrain_heights: h ..." when nx * ny > 0)
///
/// Other "# key: value" lines and '#' lines without a colon are comments.
#include <charconv>
#include <cstddef>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/io/trajectory_csv/tokenizer.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth::detail::trajectory_csv {

inline constexpr std::string_view magic_line = "# gaitsynth trajectory csv 1";

/// Appends x in the shortest form that reads back to the same double, or with `precision`
/// significant digits (> 0).
inline void append_number(std::string& out, double x, int precision = 0) {
  char buf[64];
  const std::to_chars_result r =
      precision > 0 ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, precision)
                    : std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

/// The metadata lines of t (t is checked: names without line breaks, terrain sizes).
inline void write_metadata(const trajectory& t, std::string& out) {
  out += std::string(magic_line) + "\n# model: " + t.model_name +
         "\n# planar: " + (t.planar ? "1" : "0") +
         "\n# frames: " + std::to_string(t.frames.size()) + "\n";
  for (std::size_t b = 0; b < t.body_names.size(); ++b)
    out += "# body: " + std::to_string(b) + " " + std::to_string(t.body_parents[b]) + " " +
           t.body_names[b] + "\n";
  for (std::size_t c = 0; c < t.contact_names.size(); ++c)
    out += "# contact: " + std::to_string(c) + " " + std::to_string(t.contact_bodies[c]) + " " +
           t.contact_names[c] + "\n";
  const terrain_samples& ts = t.terrain;
  out += "# terrain: ";
  for (double x : {ts.x0, ts.y0, ts.dx, ts.dy}) {
    append_number(out, x);
    out += ' ';
  }
  out += std::to_string(ts.nx) + " " + std::to_string(ts.ny) + "\n";
  if (!ts.height.empty()) {
    out += "# terrain_heights:";
    for (double h : ts.height) {
      out += ' ';
      append_number(out, h);
    }
    out += '\n';
  }
}

/// Reads the '#' lines from lines[1] (lines[0] is the magic line) into t; returns the index of
/// the first line after them (the header) and the "# frames:" count in `declared_frames`.
inline std::size_t read_metadata(const std::vector<std::string_view>& lines, trajectory& t,
                                 long long& declared_frames, const locator& fail) {
  auto real = [&](std::string_view s, int ln, const char* what) {
    double x = 0;
    if (!parse_all(s, x)) throw fail(ln, 0, unreadable(s, "a number", what));
    return x;
  };
  auto integer = [&](std::string_view s, int ln, const char* what) {
    long long x = 0;
    if (!parse_all(s, x)) throw fail(ln, 0, unreadable(s, "an integer", what));
    return x;
  };
  declared_frames = -1;
  std::size_t li = 1;
  for (; li < lines.size() && !lines[li].empty() && lines[li][0] == '#'; ++li) {
    const int ln = static_cast<int>(li) + 1;
    std::string_view l = lines[li].substr(1);
    while (!l.empty() && l.front() == ' ') l.remove_prefix(1);
    const auto colon = l.find(':');
    if (colon == std::string_view::npos) continue;  // a free comment
    const std::string_view key = l.substr(0, colon);
    std::string_view val = l.substr(colon + 1);
    if (!val.empty() && val.front() == ' ') val.remove_prefix(1);
    if (key == "model") {
      t.model_name = std::string(val);
    } else if (key == "planar") {
      t.planar = integer(val, ln, "planar") != 0;
    } else if (key == "frames") {
      declared_frames = integer(val, ln, "frames");
    } else if (key == "body" || key == "contact") {
      // "<index> <other> <name>": the name is the rest of the line (it may contain spaces).
      const auto s1 = val.find(' ');
      const auto s2 = s1 == std::string_view::npos ? s1 : val.find(' ', s1 + 1);
      if (s1 == std::string_view::npos || (s2 == std::string_view::npos && s1 + 1 == val.size()))
        throw fail(
            ln, 0,
            "metadata '" + std::string(key) + "' has too few fields: '" + std::string(val) + "'");
      const long long idx = integer(val.substr(0, s1), ln, "index");
      const long long other =
          integer(val.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1), ln,
                  key == "body" ? "parent" : "body");
      const std::string name(s2 == std::string_view::npos ? "" : val.substr(s2 + 1));
      auto& names = key == "body" ? t.body_names : t.contact_names;
      auto& ids = key == "body" ? t.body_parents : t.contact_bodies;
      if (idx != static_cast<long long>(names.size()))
        throw fail(ln, 0,
                   std::string(key) + " index " + std::to_string(idx) + " out of order (expected " +
                       std::to_string(names.size()) + ")");
      if (name.empty())
        throw fail(ln, 0, std::string(key) + " " + std::to_string(idx) + " has no name");
      names.push_back(name);
      ids.push_back(static_cast<int>(other));
    } else if (key == "terrain") {
      std::istringstream s{std::string(val)};
      std::string a[6];
      for (auto& x : a)
        if (!(s >> x))
          throw fail(ln, 0, "terrain needs x0 y0 dx dy nx ny, got '" + std::string(val) + "'");
      t.terrain.x0 = real(a[0], ln, "terrain x0");
      t.terrain.y0 = real(a[1], ln, "terrain y0");
      t.terrain.dx = real(a[2], ln, "terrain dx");
      t.terrain.dy = real(a[3], ln, "terrain dy");
      t.terrain.nx = static_cast<int>(integer(a[4], ln, "terrain nx"));
      t.terrain.ny = static_cast<int>(integer(a[5], ln, "terrain ny"));
    } else if (key == "terrain_heights") {
      std::istringstream s{std::string(val)};
      std::string h;
      while (s >> h) t.terrain.height.push_back(real(h, ln, "terrain height"));
    }
  }
  const terrain_samples& ts = t.terrain;
  if (ts.nx < 0 || ts.ny < 0 ||
      ts.height.size() != static_cast<std::size_t>(ts.nx) * static_cast<std::size_t>(ts.ny))
    throw fail(0, 0,
               "terrain declares " + std::to_string(ts.nx) + " x " + std::to_string(ts.ny) +
                   " samples but lists " + std::to_string(ts.height.size()) + " heights");
  if (declared_frames < 0) throw fail(0, 0, "no '# frames: N' metadata line");
  return li;
}

}  // namespace gaitsynth::detail::trajectory_csv
