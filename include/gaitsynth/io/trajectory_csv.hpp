#pragma once
/// \file trajectory_csv.hpp
/// A recorded trajectory (rollout/trajectory.hpp) as CSV: one row per frame, a header naming every
/// column and its unit, and '#' metadata lines above it (model name, planar flag, frame count, body
/// tree, contact points, terrain samples) so that the file reads back into the same trajectory.
/// pandas: `pd.read_csv(path, comment='#')`; spreadsheets: skip the '#' lines. docs/viewer.md.
///
///   # gaitsynth trajectory csv 1
///   # model: walker2d
///   # planar: 1
///   # frames: 2400
///   # body: 0 -1 pelvis            (index, parent index, name)
///   # contact: 0 5 lheel           (index, body index, name)
///   # terrain: x0 y0 dx dy nx ny   (and "# terrain_heights: h ..." when nx * ny > 0)
///   t [s],q:root_x [m],...,controller_state [1]
///
/// Columns, in this order (a group is left out when every frame leaves it empty):
///   t [s]; q:<name> (root_x/y/z [m], root_pitch [rad], root_qw..qz [1], joints [rad]);
///   v:<name> ([m/s] root translation, [rad/s] otherwise); tau:<name> ([N] root translation,
///   [N m] otherwise); body:<name>:x/y/z [m] and :qw/qx/qy/qz [1] (world pose);
///   com:x/y/z [m]; contact:<name>:x/y/z [m], :fx/fy/fz [N], :active [1];
///   push:<body>:fx/fy/fz [N] (only bodies pushed in some frame: the sum of that frame's pushes on
///   the body; a frame's pushes read back in body order, zero forces are not pushes);
///   obj:<name> [-] (objective terms, in the units of their definition); controller_state [1].
///
/// Numbers are written in the shortest form that reads back to the same double (std::to_chars), so
/// write-then-read is exact; `precision` > 0 writes that many significant digits instead.
///
/// Reading checks everything and throws trajectory_csv_error (a std::runtime_error) whose message
/// names the source, the line and, for a bad value, the column number and name: a missing or
/// foreign first line, a header cell without a [unit] or of unknown kind, a row with too few or too
/// many fields, a value that is not a number, a last line without its end-of-line, or fewer rows
/// than the "# frames:" line declares (a truncated file).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <iterator>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// A malformed or truncated trajectory CSV. line / column are 1-based (0: not applicable).
class trajectory_csv_error : public std::runtime_error {
 public:
  trajectory_csv_error(const std::string& what, int line, int column)
      : std::runtime_error(what), line_(line), column_(column) {}
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_, column_;
};

struct trajectory_csv_options {
  int precision = 0;  ///< significant digits; 0: shortest exact round trip
};

namespace detail::trajectory_csv {

inline void append_number(std::string& out, double x, int precision) {
  char buf[64];
  std::to_chars_result r =
      precision > 0 ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, precision)
                    : std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

inline bool is_root_translation(std::string_view n) {
  return n == "root_x" || n == "root_y" || n == "root_z";
}
inline const char* q_unit(std::string_view n) {
  if (is_root_translation(n)) return "m";
  if (n == "root_qw" || n == "root_qx" || n == "root_qy" || n == "root_qz") return "1";
  return "rad";
}
inline const char* v_unit(std::string_view n) {
  return is_root_translation(n) ? "m/s" : "rad/s";
}
inline const char* tau_unit(std::string_view n) {
  return is_root_translation(n) ? "N" : "N m";
}

/// Names go into CSV header cells: no separators, quotes or line breaks.
inline void check_name(const std::string& n, const char* what) {
  check_argument(!n.empty(), "write_trajectory_csv: an empty ", what, " name");
  check_argument(n.find_first_of(",\"\n\r") == std::string::npos, "write_trajectory_csv: ", what,
                 " name '", n, "' contains a comma, quote or line break");
}

/// Whether every frame has `size` entries (true), none (false); throws when mixed.
/// With no frames at all, `if_no_frames` decides (names alone still give the columns).
template <class Get>
bool group_present(const trajectory& traj, std::size_t size, const char* what, Get get,
                   bool if_no_frames = false) {
  if (size == 0) return false;
  if (traj.frames.empty()) return if_no_frames;
  const bool first = get(traj.frames[0]) == size;
  for (std::size_t f = 0; f < traj.frames.size(); ++f) {
    const std::size_t s = get(traj.frames[f]);
    check_argument((first && s == size) || (!first && s == 0), "write_trajectory_csv: frame ", f,
                   ": ", what, " has ", s, " entries, expected ", first ? size : 0,
                   first ? "" : " (frame 0 has none)", " (names give ", size, ")");
  }
  return first;
}

struct column {
  enum class kind { t, q, v, tau, body, com, contact, push, obj, state } type;
  int index = 0;      ///< q/v/tau/obj index, body, contact or push body index
  int component = 0;  ///< x, y, z, qw, qx, qy, qz / x y z fx fy fz active
};

}  // namespace detail::trajectory_csv

/// Writes the trajectory as CSV (see the file comment). Throws std::invalid_argument when the
/// trajectory is inconsistent (a frame's vector size differs from its names, names with commas).
inline void write_trajectory_csv(const trajectory& traj, std::ostream& os,
                                 const trajectory_csv_options& opt = {}) {
  using namespace detail::trajectory_csv;
  check_argument(opt.precision >= 0 && opt.precision <= 17,
                 "write_trajectory_csv: precision must be in [0, 17], got ", opt.precision);
  const std::size_t nq = traj.q_names.size(), nv = traj.v_names.size();
  const std::size_t nb = traj.body_names.size(), nc = traj.contact_names.size();
  const std::size_t no = traj.objective_term_names.size();
  check_argument(traj.body_parents.size() == nb, "write_trajectory_csv: ", nb, " body names but ",
                 traj.body_parents.size(), " body parents");
  check_argument(traj.contact_bodies.size() == nc, "write_trajectory_csv: ", nc,
                 " contact names but ", traj.contact_bodies.size(), " contact bodies");
  check_argument(traj.model_name.find_first_of("\n\r") == std::string::npos,
                 "write_trajectory_csv: model name contains a line break");
  for (const auto& n : traj.q_names) check_name(n, "q");
  for (const auto& n : traj.v_names) check_name(n, "v");
  for (const auto& n : traj.body_names) check_name(n, "body");
  for (const auto& n : traj.contact_names) check_name(n, "contact");
  for (const auto& n : traj.objective_term_names) check_name(n, "objective term");
  const terrain_samples& ts = traj.terrain;
  const std::size_t nh =
      static_cast<std::size_t>(std::max(ts.nx, 0)) * static_cast<std::size_t>(std::max(ts.ny, 0));
  check_argument(ts.nx >= 0 && ts.ny >= 0 && ts.height.size() == nh,
                 "write_trajectory_csv: terrain has nx = ", ts.nx, ", ny = ", ts.ny, " but ",
                 ts.height.size(), " heights");

  const bool has_q = group_present(
      traj, nq, "q", [](const trajectory_frame& f) { return static_cast<std::size_t>(f.q.size()); },
      true);
  check_argument(nq == 0 || traj.frames.empty() || has_q,
                 "write_trajectory_csv: frames have no q but there are q names");
  const bool has_v = group_present(
      traj, nv, "v", [](const trajectory_frame& f) { return static_cast<std::size_t>(f.v.size()); },
      true);
  const bool has_tau = group_present(traj, nv, "tau", [](const trajectory_frame& f) {
    return static_cast<std::size_t>(f.tau.size());
  });
  const bool has_body = group_present(
      traj, nb, "body_position", [](const trajectory_frame& f) { return f.body_position.size(); });
  group_present(traj, has_body ? nb : 0, "body_orientation",
                [](const trajectory_frame& f) { return f.body_orientation.size(); });
  if (!has_body)
    for (std::size_t f = 0; f < traj.frames.size(); ++f)
      check_argument(traj.frames[f].body_orientation.empty(), "write_trajectory_csv: frame ", f,
                     ": body_orientation without body_position");
  const bool has_cpos = group_present(traj, nc, "contact_position", [](const trajectory_frame& f) {
    return f.contact_position.size();
  });
  const bool has_cforce = group_present(
      traj, nc, "contact_force", [](const trajectory_frame& f) { return f.contact_force.size(); });
  const bool has_cact = group_present(traj, nc, "contact_active", [](const trajectory_frame& f) {
    return f.contact_active.size();
  });
  for (std::size_t f = 0; f < traj.frames.size(); ++f)
    check_argument(traj.frames[f].objective_terms.size() == no, "write_trajectory_csv: frame ", f,
                   ": ", traj.frames[f].objective_terms.size(), " objective terms, but ", no,
                   " objective term names");
  std::vector<int> pushed;
  for (std::size_t f = 0; f < traj.frames.size(); ++f)
    for (const auto& p : traj.frames[f].pushes) {
      check_argument(p.first >= 0 && static_cast<std::size_t>(p.first) < nb,
                     "write_trajectory_csv: frame ", f, ": push on body ", p.first, " of ", nb);
      if (std::find(pushed.begin(), pushed.end(), p.first) == pushed.end())
        pushed.push_back(p.first);
    }
  std::sort(pushed.begin(), pushed.end());

  std::string out;
  out += "# gaitsynth trajectory csv 1\n# model: " + traj.model_name +
         "\n# planar: " + (traj.planar ? "1" : "0") +
         "\n# frames: " + std::to_string(traj.frames.size()) + "\n";
  for (std::size_t b = 0; b < nb; ++b)
    out += "# body: " + std::to_string(b) + " " + std::to_string(traj.body_parents[b]) + " " +
           traj.body_names[b] + "\n";
  for (std::size_t c = 0; c < nc; ++c)
    out += "# contact: " + std::to_string(c) + " " + std::to_string(traj.contact_bodies[c]) + " " +
           traj.contact_names[c] + "\n";
  out += "# terrain: ";
  for (double x : {ts.x0, ts.y0, ts.dx, ts.dy}) {
    append_number(out, x, 0);
    out += ' ';
  }
  out += std::to_string(ts.nx) + " " + std::to_string(ts.ny) + "\n";
  if (nh > 0) {
    out += "# terrain_heights:";
    for (double h : ts.height) {
      out += ' ';
      append_number(out, h, 0);
    }
    out += '\n';
  }
  // Header.
  std::vector<std::string> head{"t [s]"};
  if (has_q)
    for (const auto& n : traj.q_names) head.push_back("q:" + n + " [" + q_unit(n) + "]");
  if (has_v)
    for (const auto& n : traj.v_names) head.push_back("v:" + n + " [" + v_unit(n) + "]");
  if (has_tau)
    for (const auto& n : traj.v_names) head.push_back("tau:" + n + " [" + tau_unit(n) + "]");
  if (has_body)
    for (const auto& n : traj.body_names) {
      for (const char* c : {"x", "y", "z"}) head.push_back("body:" + n + ":" + c + " [m]");
      for (const char* c : {"qw", "qx", "qy", "qz"}) head.push_back("body:" + n + ":" + c + " [1]");
    }
  for (const char* c : {"x", "y", "z"}) head.push_back(std::string("com:") + c + " [m]");
  for (const auto& n : traj.contact_names) {
    if (has_cpos)
      for (const char* c : {"x", "y", "z"}) head.push_back("contact:" + n + ":" + c + " [m]");
    if (has_cforce)
      for (const char* c : {"fx", "fy", "fz"}) head.push_back("contact:" + n + ":" + c + " [N]");
    if (has_cact) head.push_back("contact:" + n + ":active [1]");
  }
  for (int b : pushed)
    for (const char* c : {"fx", "fy", "fz"})
      head.push_back("push:" + traj.body_names[b] + ":" + c + " [N]");
  for (const auto& n : traj.objective_term_names) head.push_back("obj:" + n + " [-]");
  head.push_back("controller_state [1]");
  for (std::size_t i = 0; i < head.size(); ++i) out += (i ? "," : "") + head[i];
  out += '\n';
  os << out;
  // Rows.
  const int p = opt.precision;
  for (const trajectory_frame& fr : traj.frames) {
    out.clear();
    auto num = [&](double x) {
      out += ',';
      append_number(out, x, p);
    };
    append_number(out, fr.t, p);
    if (has_q)
      for (Eigen::Index i = 0; i < fr.q.size(); ++i) num(fr.q[i]);
    if (has_v)
      for (Eigen::Index i = 0; i < fr.v.size(); ++i) num(fr.v[i]);
    if (has_tau)
      for (Eigen::Index i = 0; i < fr.tau.size(); ++i) num(fr.tau[i]);
    if (has_body)
      for (std::size_t b = 0; b < nb; ++b) {
        for (int k = 0; k < 3; ++k) num(fr.body_position[b][k]);
        const Eigen::Quaterniond& r = fr.body_orientation[b];
        for (double x : {r.w(), r.x(), r.y(), r.z()}) num(x);
      }
    for (int k = 0; k < 3; ++k) num(fr.com[k]);
    for (std::size_t c = 0; c < nc; ++c) {
      if (has_cpos)
        for (int k = 0; k < 3; ++k) num(fr.contact_position[c][k]);
      if (has_cforce)
        for (int k = 0; k < 3; ++k) num(fr.contact_force[c][k]);
      if (has_cact) out += fr.contact_active[c] ? ",1" : ",0";
    }
    for (int b : pushed) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const auto& pu : fr.pushes)
        if (pu.first == b) sum += pu.second;
      for (int k = 0; k < 3; ++k) num(sum[k]);
    }
    for (double o : fr.objective_terms) num(o);
    out += ',' + std::to_string(fr.controller_state) + '\n';
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

/// Reads a trajectory CSV written by write_trajectory_csv. Throws trajectory_csv_error naming the
/// source, line and column of the first problem (see the file comment).
inline trajectory read_trajectory_csv(std::istream& is, const std::string& source = "<stream>") {
  using namespace detail::trajectory_csv;
  const std::string text((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  auto fail = [&](int line, int col, const std::string& msg) -> trajectory_csv_error {
    std::string where = "trajectory csv '" + source + "'";
    if (line > 0) where += ", line " + std::to_string(line);
    if (col > 0) where += ", column " + std::to_string(col);
    return trajectory_csv_error(where + ": " + msg, line, col);
  };
  // Split into lines, remembering whether the last one was terminated.
  std::vector<std::string_view> lines;
  bool last_terminated = true;
  {
    std::size_t a = 0;
    const std::string_view all(text);
    while (a < all.size()) {
      std::size_t e = all.find('\n', a);
      if (e == std::string_view::npos) {
        lines.push_back(all.substr(a));
        last_terminated = false;
        break;
      }
      std::string_view l = all.substr(a, e - a);
      if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
      lines.push_back(l);
      a = e + 1;
    }
  }
  if (lines.empty()) throw fail(0, 0, "empty file");
  const std::string_view magic = "# gaitsynth trajectory csv 1";
  if (lines[0] != magic)
    throw fail(1, 0,
               "not a gaitsynth trajectory CSV (first line must be '" + std::string(magic) +
                   "', got '" + std::string(lines[0].substr(0, 60)) + "')");
  auto parse_number = [&](std::string_view s, int line, int col, const std::string& colname) {
    double x = 0;
    if (s.empty()) throw fail(line, col, "empty value in column '" + colname + "'");
    const char* b = s.data();
    const char* e = s.data() + s.size();
    auto r = std::from_chars(b, e, x);
    if (r.ec != std::errc() || r.ptr != e)
      throw fail(line, col,
                 "cannot read '" + std::string(s.substr(0, 40)) + "' as a number (column '" +
                     colname + "')");
    return x;
  };
  auto parse_int = [&](std::string_view s, int line, const char* what) {
    long long x = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), x);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size())
      throw fail(line, 0,
                 std::string("cannot read '") + std::string(s) + "' as an integer (" + what + ")");
    return x;
  };
  trajectory traj;
  long long declared_frames = -1;
  std::size_t li = 1;
  // Metadata.
  for (; li < lines.size() && !lines[li].empty() && lines[li][0] == '#'; ++li) {
    const int ln = static_cast<int>(li) + 1;
    std::string_view l = lines[li].substr(1);
    while (!l.empty() && l.front() == ' ') l.remove_prefix(1);
    const auto colon = l.find(':');
    if (colon == std::string_view::npos) continue;  // a free comment
    const std::string_view key = l.substr(0, colon);
    std::string_view val = l.substr(colon + 1);
    if (!val.empty() && val.front() == ' ') val.remove_prefix(1);
    auto words = [&](int n, std::string& rest) {
      // First n space-separated words, and the rest of the line (a name may contain spaces).
      std::vector<std::string_view> w;
      std::string_view v = val;
      for (int k = 0; k < n; ++k) {
        const auto sp = v.find(' ');
        if (sp == std::string_view::npos) {
          if (k + 1 == n && !v.empty()) {
            w.push_back(v);
            v = {};
            continue;
          }
          throw fail(
              ln, 0,
              "metadata '" + std::string(key) + "' has too few fields: '" + std::string(val) + "'");
        }
        w.push_back(v.substr(0, sp));
        v = v.substr(sp + 1);
      }
      rest = std::string(v);
      return w;
    };
    std::string rest;
    if (key == "model") {
      traj.model_name = std::string(val);
    } else if (key == "planar") {
      traj.planar = parse_int(val, ln, "planar") != 0;
    } else if (key == "frames") {
      declared_frames = parse_int(val, ln, "frames");
    } else if (key == "body" || key == "contact") {
      const auto w = words(2, rest);
      const long long idx = parse_int(w[0], ln, "index");
      const long long other = parse_int(w[1], ln, key == "body" ? "parent" : "body");
      auto& names = key == "body" ? traj.body_names : traj.contact_names;
      auto& ids = key == "body" ? traj.body_parents : traj.contact_bodies;
      if (idx != static_cast<long long>(names.size()))
        throw fail(ln, 0,
                   std::string(key) + " index " + std::to_string(idx) + " out of order (expected " +
                       std::to_string(names.size()) + ")");
      if (rest.empty())
        throw fail(ln, 0, std::string(key) + " " + std::to_string(idx) + " has no name");
      names.push_back(rest);
      ids.push_back(static_cast<int>(other));
    } else if (key == "terrain") {
      std::istringstream s{std::string(val)};
      std::string a[6];
      for (auto& x : a)
        if (!(s >> x))
          throw fail(ln, 0, "terrain needs x0 y0 dx dy nx ny, got '" + std::string(val) + "'");
      traj.terrain.x0 = parse_number(a[0], ln, 0, "terrain x0");
      traj.terrain.y0 = parse_number(a[1], ln, 0, "terrain y0");
      traj.terrain.dx = parse_number(a[2], ln, 0, "terrain dx");
      traj.terrain.dy = parse_number(a[3], ln, 0, "terrain dy");
      traj.terrain.nx = static_cast<int>(parse_int(a[4], ln, "terrain nx"));
      traj.terrain.ny = static_cast<int>(parse_int(a[5], ln, "terrain ny"));
    } else if (key == "terrain_heights") {
      std::istringstream s{std::string(val)};
      std::string h;
      while (s >> h) traj.terrain.height.push_back(parse_number(h, ln, 0, "terrain height"));
    }
  }
  if (traj.terrain.nx < 0 || traj.terrain.ny < 0 ||
      traj.terrain.height.size() !=
          static_cast<std::size_t>(traj.terrain.nx) * static_cast<std::size_t>(traj.terrain.ny))
    throw fail(0, 0,
               "terrain declares " + std::to_string(traj.terrain.nx) + " x " +
                   std::to_string(traj.terrain.ny) + " samples but lists " +
                   std::to_string(traj.terrain.height.size()) + " heights");
  if (declared_frames < 0) throw fail(0, 0, "no '# frames: N' metadata line");
  if (li >= lines.size())
    throw fail(static_cast<int>(li) + 1, 0, "missing header line (truncated file?)");
  // Header.
  const int header_line = static_cast<int>(li) + 1;
  std::vector<std::string> names;
  {
    std::string_view h = lines[li];
    std::size_t a = 0;
    while (true) {
      const auto e = h.find(',', a);
      names.emplace_back(h.substr(a, e == std::string_view::npos ? std::string_view::npos : e - a));
      if (e == std::string_view::npos) break;
      a = e + 1;
    }
  }
  const std::size_t nb = traj.body_names.size(), nc = traj.contact_names.size();
  std::vector<column> cols;
  std::map<std::string, int> body_id, contact_id;
  for (std::size_t b = 0; b < nb; ++b) body_id[traj.body_names[b]] = static_cast<int>(b);
  for (std::size_t c = 0; c < nc; ++c) contact_id[traj.contact_names[c]] = static_cast<int>(c);
  std::vector<int> body_cols(nb, 0), pushed;
  std::vector<int> cpos(nc, 0), cforce(nc, 0), cact(nc, 0);
  int ntau = 0, com_cols = 0;
  std::vector<std::string> tau_names;
  bool has_t = false, has_state = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int cn = static_cast<int>(i) + 1;
    const std::string& full = names[i];
    const auto ub = full.rfind(" [");
    if (ub == std::string::npos || full.back() != ']')
      throw fail(header_line, cn, "header cell '" + full + "' has no unit in [brackets]");
    const std::string name = full.substr(0, ub);
    const auto c1 = name.find(':');
    const std::string kind = name.substr(0, c1);
    const std::string rest = c1 == std::string::npos ? "" : name.substr(c1 + 1);
    auto split_comp = [&](std::string& who, std::string& comp) {
      const auto c2 = rest.rfind(':');
      if (c2 == std::string::npos)
        throw fail(header_line, cn, "header cell '" + full + "' needs <kind>:<name>:<component>");
      who = rest.substr(0, c2);
      comp = rest.substr(c2 + 1);
    };
    auto comp_index = [&](const std::string& comp, std::initializer_list<const char*> list) {
      int k = 0;
      for (const char* c : list) {
        if (comp == c) return k;
        ++k;
      }
      throw fail(header_line, cn, "unknown component '" + comp + "' in header cell '" + full + "'");
    };
    column c{column::kind::t, 0, 0};
    if (name == "t") {
      has_t = true;
      if (i != 0) throw fail(header_line, cn, "'t [s]' must be the first column");
    } else if (name == "controller_state") {
      c.type = column::kind::state;
      has_state = true;
    } else if (kind == "q" && !rest.empty()) {
      c.type = column::kind::q;
      c.index = static_cast<int>(traj.q_names.size());
      traj.q_names.push_back(rest);
    } else if (kind == "v" && !rest.empty()) {
      c.type = column::kind::v;
      c.index = static_cast<int>(traj.v_names.size());
      traj.v_names.push_back(rest);
    } else if (kind == "tau" && !rest.empty()) {
      c.type = column::kind::tau;
      c.index = ntau++;
      tau_names.push_back(rest);
    } else if (kind == "obj" && !rest.empty()) {
      c.type = column::kind::obj;
      c.index = static_cast<int>(traj.objective_term_names.size());
      traj.objective_term_names.push_back(rest);
    } else if (kind == "com") {
      c.type = column::kind::com;
      c.component = comp_index(rest, {"x", "y", "z"});
      ++com_cols;
    } else if (kind == "body" || kind == "push") {
      std::string who, comp;
      split_comp(who, comp);
      const auto it = body_id.find(who);
      if (it == body_id.end())
        throw fail(
            header_line, cn,
            "header cell '" + full + "' names body '" + who + "', not in the '# body:' lines");
      c.index = it->second;
      if (kind == "body") {
        c.type = column::kind::body;
        c.component = comp_index(comp, {"x", "y", "z", "qw", "qx", "qy", "qz"});
        ++body_cols[c.index];
      } else {
        c.type = column::kind::push;
        c.component = comp_index(comp, {"fx", "fy", "fz"});
        if (c.component == 0) pushed.push_back(c.index);
      }
    } else if (kind == "contact") {
      std::string who, comp;
      split_comp(who, comp);
      const auto it = contact_id.find(who);
      if (it == contact_id.end())
        throw fail(header_line, cn,
                   "header cell '" + full + "' names contact point '" + who +
                       "', not in the '# contact:' lines");
      c.type = column::kind::contact;
      c.index = it->second;
      c.component = comp_index(comp, {"x", "y", "z", "fx", "fy", "fz", "active"});
      (c.component < 3 ? cpos : c.component < 6 ? cforce : cact)[c.index]++;
    } else {
      throw fail(header_line, cn, "unknown column '" + full + "'");
    }
    cols.push_back(c);
  }
  if (!has_t) throw fail(header_line, 1, "the first column must be 't [s]'");
  const bool has_v = !traj.v_names.empty();
  if (!has_v) traj.v_names = tau_names;  // torques without velocities
  if (ntau != 0 && tau_names != traj.v_names)
    throw fail(header_line, 0,
               "the tau columns (" + std::to_string(ntau) +
                   ") do not name the same coordinates as the v columns (" +
                   std::to_string(traj.v_names.size()) + ")");
  if (com_cols != 3)
    throw fail(header_line, 0, "expected 3 com columns, got " + std::to_string(com_cols));
  const bool has_body = nb > 0 && body_cols[0] > 0;
  for (std::size_t b = 0; b < nb; ++b)
    if (body_cols[b] != (has_body ? 7 : 0))
      throw fail(header_line, 0,
                 "body '" + traj.body_names[b] + "' has " + std::to_string(body_cols[b]) +
                     " pose columns, expected " + (has_body ? "7" : "0"));
  auto uniform = [&](const std::vector<int>& v, int per, const char* what) {
    const bool present = !v.empty() && v[0] > 0;
    for (std::size_t c = 0; c < v.size(); ++c)
      if (v[c] != (present ? per : 0))
        throw fail(header_line, 0,
                   "contact point '" + traj.contact_names[c] + "' has " + std::to_string(v[c]) +
                       " " + what + " columns, expected " + std::to_string(present ? per : 0));
    return present;
  };
  const bool has_cpos = uniform(cpos, 3, "position");
  const bool has_cforce = uniform(cforce, 3, "force");
  const bool has_cact = uniform(cact, 1, "active");
  (void)has_state;
  // Rows.
  const std::size_t nq = traj.q_names.size(), nv = traj.v_names.size();
  const std::size_t no = traj.objective_term_names.size();
  std::vector<std::string_view> fields;
  for (++li; li < lines.size(); ++li) {
    const int ln = static_cast<int>(li) + 1;
    const std::string_view l = lines[li];
    if (l.empty()) {
      if (li + 1 == lines.size()) break;
      throw fail(ln, 0, "empty line inside the data");
    }
    if (l[0] == '#') continue;
    if (li + 1 == lines.size() && !last_terminated)
      throw fail(ln, 0, "the last line has no end-of-line (truncated file?)");
    fields.clear();
    std::size_t a = 0;
    while (true) {
      const auto e = l.find(',', a);
      fields.push_back(l.substr(a, e == std::string_view::npos ? std::string_view::npos : e - a));
      if (e == std::string_view::npos) break;
      a = e + 1;
    }
    if (fields.size() != cols.size())
      throw fail(ln, 0,
                 "expected " + std::to_string(cols.size()) + " fields, got " +
                     std::to_string(fields.size()) +
                     (fields.size() < cols.size() ? " (truncated line?)" : ""));
    trajectory_frame fr;
    fr.q.resize(static_cast<Eigen::Index>(nq));
    if (has_v) fr.v.resize(static_cast<Eigen::Index>(nv));
    if (ntau > 0) fr.tau.resize(ntau);
    if (has_body) {
      fr.body_position.assign(nb, Eigen::Vector3d::Zero());
      fr.body_orientation.assign(nb, Eigen::Quaterniond::Identity());
    }
    if (has_cpos) fr.contact_position.assign(nc, Eigen::Vector3d::Zero());
    if (has_cforce) fr.contact_force.assign(nc, Eigen::Vector3d::Zero());
    if (has_cact) fr.contact_active.assign(nc, 0);
    fr.objective_terms.assign(no, 0.0);
    std::vector<Eigen::Vector3d> push_force(nb, Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < cols.size(); ++i) {
      const column& c = cols[i];
      const int cn = static_cast<int>(i) + 1;
      if (c.type == column::kind::state) {
        const auto s = fields[i];
        long long x = 0;
        auto r = std::from_chars(s.data(), s.data() + s.size(), x);
        if (s.empty() || r.ec != std::errc() || r.ptr != s.data() + s.size())
          throw fail(ln, cn,
                     "cannot read '" + std::string(s.substr(0, 40)) + "' as an integer (column '" +
                         names[i] + "')");
        fr.controller_state = static_cast<int>(x);
        continue;
      }
      const double x = parse_number(fields[i], ln, cn, names[i]);
      switch (c.type) {
        case column::kind::t:
          fr.t = x;
          break;
        case column::kind::q:
          fr.q[c.index] = x;
          break;
        case column::kind::v:
          fr.v[c.index] = x;
          break;
        case column::kind::tau:
          fr.tau[c.index] = x;
          break;
        case column::kind::obj:
          fr.objective_terms[c.index] = x;
          break;
        case column::kind::com:
          fr.com[c.component] = x;
          break;
        case column::kind::body:
          if (c.component < 3)
            fr.body_position[c.index][c.component] = x;
          else if (c.component == 3)
            fr.body_orientation[c.index].w() = x;
          else
            fr.body_orientation[c.index].vec()[c.component - 4] = x;
          break;
        case column::kind::contact:
          if (c.component < 3)
            fr.contact_position[c.index][c.component] = x;
          else if (c.component < 6)
            fr.contact_force[c.index][c.component - 3] = x;
          else {
            if (x != 0 && x != 1)
              throw fail(ln, cn,
                         "'active' must be 0 or 1, got '" + std::string(fields[i]) + "' (column '" +
                             names[i] + "')");
            fr.contact_active[c.index] = static_cast<unsigned char>(x);
          }
          break;
        case column::kind::push:
          push_force[c.index][c.component] = x;
          break;
        case column::kind::state:
          break;
      }
    }
    std::sort(pushed.begin(), pushed.end());
    for (int b : pushed)
      if (!push_force[b].isZero(0.0)) fr.pushes.emplace_back(b, push_force[b]);
    traj.frames.push_back(std::move(fr));
  }
  if (static_cast<long long>(traj.frames.size()) != declared_frames)
    throw fail(static_cast<int>(lines.size()), 0,
               "truncated or padded file: the metadata declares " +
                   std::to_string(declared_frames) + " frames, found " +
                   std::to_string(traj.frames.size()) + " data rows");
  return traj;
}

/// Reads the trajectory CSV at `path`; std::runtime_error when it cannot be opened.
inline trajectory load_trajectory_csv(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("load_trajectory_csv: cannot open '" + path + "'");
  return read_trajectory_csv(f, path);
}

}  // namespace gaitsynth
