#pragma once
/// \file io/normative_gait.hpp
/// Human reference curves over one gait cycle, read from the table format of
/// data/normative_gait/ (columns speed_mps, percent_gait_cycle, variable, mean, sd, unit; one row
/// per variable and sample; any column order):
///
///   const normative_gait h =
///   load_normative_gait("data/normative_gait/falisse2019_subject1_walking.csv"); const
///   normative_curve& knee = h.curve("knee_flexion_angle");   // deg, flexion positive
///
/// Every defect (a missing or repeated column, a short row, a number that is not finite, a
/// percentage outside [0, 100] or out of order, a negative s.d., a unit that changes within a
/// variable) throws normative_gait_error naming the file, the line and the value; nothing is
/// half-loaded.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gaitsynth {

/// A bad reference file: what() names the file, the line and the bad value.
struct normative_gait_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One variable's mean and standard deviation against percent of the gait cycle.
struct normative_curve {
  std::string variable, unit;
  double speed = 0.0;            ///< m/s, the walking speed the file gives
  std::vector<double> percent;   ///< strictly increasing, in [0, 100]
  std::vector<double> mean, sd;  ///< same size as percent; sd >= 0
};

struct normative_gait {
  std::vector<normative_curve> curves;  ///< in the order of their first row
  /// \throws std::out_of_range naming the variable and the ones there are. Not on a temporary
  /// (`load_normative_gait(f).curve(v)` would dangle): keep the normative_gait.
  const normative_curve& curve(std::string_view variable) const& {
    for (const normative_curve& c : curves)
      if (c.variable == variable) return c;
    std::string names;
    for (const normative_curve& c : curves) names += (names.empty() ? "" : ", ") + c.variable;
    throw std::out_of_range("normative gait: no variable '" + std::string(variable) + "' (has " +
                            names + ")");
  }
  const normative_curve& curve(std::string_view variable) && = delete;
};

namespace normative_detail {

inline std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> f(1);
  for (const char ch : line) {
    if (ch == ',')
      f.emplace_back();
    else if (ch != '\r')
      f.back() += ch;
  }
  return f;
}

}  // namespace normative_detail

/// Reads the table from `in`; `source` names it in errors (a file name).
inline normative_gait read_normative_gait(std::istream& in, const std::string& source) {
  using namespace normative_detail;
  auto fail = [&](long line, const std::string& what) -> void {
    throw normative_gait_error(source + ":" + std::to_string(line) + ": " + what);
  };
  std::string text;
  long line_no = 0;
  if (!std::getline(in, text)) fail(1, "empty: expected a header line");
  ++line_no;
  const std::vector<std::string> header = split_fields(text);
  constexpr std::array<std::string_view, 6> names{
      "speed_mps", "percent_gait_cycle", "variable", "mean", "sd", "unit"};
  for (std::size_t k = 0; k < header.size(); ++k)
    for (std::size_t i = 0; i < k; ++i)
      if (!header[k].empty() && header[i] == header[k])
        fail(1, "header column '" + header[k] + "' appears twice (columns " +
                    std::to_string(i + 1) + " and " + std::to_string(k + 1) + ")");
  std::array<std::size_t, 6> col{};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto it = std::find(header.begin(), header.end(), names[k]);
    if (it == header.end()) {
      std::string has = text.substr(0, 80);
      if (text.size() > 80) has += "...";
      fail(1, "header has no column '" + std::string(names[k]) + "' (header: '" + has + "')");
    }
    col[k] = static_cast<std::size_t>(it - header.begin());
  }
  normative_gait g;
  while (std::getline(in, text)) {
    ++line_no;
    if (text.empty() || text == "\r") continue;
    const std::vector<std::string> f = split_fields(text);
    if (f.size() != header.size())
      fail(line_no,
           std::to_string(f.size()) + " fields, the header has " + std::to_string(header.size()));
    auto number = [&](std::size_t k) {
      const std::string& s = f[col[k]];
      double v = 0;
      const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
        fail(line_no, std::string(names[k]) + " '" +
                          (s.size() <= 40 ? s : s.substr(0, 40) + "...") +
                          "' is not a finite number");
      return v;
    };
    const double speed = number(0), pct = number(1), mean = number(3), sd = number(4);
    const std::string& var = f[col[2]];
    const std::string& unit = f[col[5]];
    if (var.empty()) fail(line_no, "empty variable name");
    if (pct < 0.0 || pct > 100.0)
      fail(line_no, "percent_gait_cycle " + f[col[1]] + " is outside [0, 100]");
    if (sd < 0.0) fail(line_no, "sd " + f[col[4]] + " is negative");
    auto it = std::find_if(g.curves.begin(), g.curves.end(),
                           [&](const normative_curve& c) { return c.variable == var; });
    if (it == g.curves.end()) {
      g.curves.push_back({.variable = var, .unit = unit, .speed = speed});
      it = std::prev(g.curves.end());
    }
    if (it->unit != unit)
      fail(line_no, var + ": unit '" + unit + "', earlier rows say '" + it->unit + "'");
    if (!it->percent.empty() && pct <= it->percent.back())
      fail(line_no, var + ": percent_gait_cycle " + f[col[1]] +
                        " does not follow the previous row's " +
                        std::to_string(it->percent.back()));
    it->percent.push_back(pct);
    it->mean.push_back(mean);
    it->sd.push_back(sd);
  }
  if (g.curves.empty()) fail(line_no, "no data rows");
  for (const normative_curve& c : g.curves)
    if (c.percent.size() < 2)
      fail(line_no, c.variable + ": " + std::to_string(c.percent.size()) +
                        " sample(s), a curve needs at least 2");
  return g;
}

/// Reads the file `path`. \throws normative_gait_error (see the file comment).
inline normative_gait load_normative_gait(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw normative_gait_error("cannot open normative gait file '" + path + "'");
  return read_normative_gait(in, path);
}

}  // namespace gaitsynth
