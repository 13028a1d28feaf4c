#pragma once
/// \file convergence_plot_svg.hpp
/// Optimizer convergence plot (SVG) from the optimizer's CSV log: objective values (best, median,
/// mean, worst: whichever the log has) against evaluations (or generations), and the step size
/// sigma in a second panel; restarts (a change in a "restart"/"run" column) as dashed lines.
///
/// The reader is tolerant by design (logs come from several optimizers and versions): columns are
/// found by header name, case-insensitively and ignoring a unit suffix such as " [s]" or "(s)", in
/// any order; extra columns are ignored; '#' lines and blank lines are skipped; ',' is the
/// separator (';' or tab if the header has no comma), cells may be quoted ("a,b", "" for a quote);
/// a non-numeric cell reads as NaN and is not drawn. The log of optimizers/minimize.hpp (columns
/// stage, restart, iteration, evaluations, best, iteration_median, iteration_worst, step_size,
/// ..., then one per parameter) is read as it is. A row with the wrong number of cells throws
/// std::runtime_error naming the line.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/viz/svg.hpp"

namespace gaitsynth {

/// A parsed optimizer log: header names and numeric rows (NaN for non-numeric cells).
struct convergence_log {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  /// Header name normalized for matching: lower case, unit suffix removed, spaces and '-' -> '_'.
  static std::string normalize(std::string_view name) {
    std::string s(name);
    for (char open : {'[', '('}) {
      const auto p = s.find(open);
      if (p != std::string::npos && p > 0) s.erase(p);
    }
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    std::string o;
    for (char c : s) {
      if (c == ' ' || c == '-')
        o += '_';
      else
        o += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return o;
  }
  /// Index of the first column whose normalized name is one of `aliases`; -1 when none is.
  int find(std::initializer_list<std::string_view> aliases) const {
    for (std::string_view a : aliases)
      for (std::size_t c = 0; c < columns.size(); ++c)
        if (normalize(columns[c]) == a) return static_cast<int>(c);
    return -1;
  }
  int find(const std::string& name) const {
    const std::string n = normalize(name);
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (normalize(columns[c]) == n) return static_cast<int>(c);
    return -1;
  }
  std::vector<double> column(int c) const {
    std::vector<double> v;
    v.reserve(rows.size());
    for (const auto& r : rows) v.push_back(r[c]);
    return v;
  }
};

namespace viz_detail {
inline std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  std::string o(s.substr(a, b - a));
  if (o.size() >= 2 && o.front() == '"' && o.back() == '"') o = o.substr(1, o.size() - 2);
  return o;
}
/// Cells of one CSV line: separated by `sep`, a cell in double quotes may hold the separator and
/// "" for a quote (RFC 4180, as optimizers/minimize.hpp escapes parameter names). Spaces around
/// cells are trimmed.
inline std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false, was_quoted = false;
  auto push = [&] {
    out.push_back(was_quoted ? cur : trim(cur));
    cur.clear();
    was_quoted = false;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"' && trim(cur).empty()) {
      quoted = was_quoted = true;
      cur.clear();
    } else if (c == sep) {
      push();
    } else if (!(was_quoted && std::isspace(static_cast<unsigned char>(c)))) {
      cur += c;
    }
  }
  push();
  return out;
}
}  // namespace viz_detail

/// Reads an optimizer CSV log (see the file comment). `source` names the input in messages.
inline convergence_log read_convergence_csv(std::istream& is,
                                            const std::string& source = "<stream>") {
  using namespace viz_detail;
  convergence_log log;
  std::string line;
  int lineno = 0;
  char sep = ',';
  bool have_header = false;
  while (std::getline(is, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    if (!have_header) {
      if (line.find(',') == std::string::npos)
        sep = line.find(';') != std::string::npos
                  ? ';'
                  : (line.find('\t') != std::string::npos ? '\t' : ',');
      log.columns = split(line, sep);
      have_header = true;
      continue;
    }
    const auto cells = split(line, sep);
    if (cells.size() != log.columns.size())
      throw std::runtime_error("convergence log '" + source + "', line " + std::to_string(lineno) +
                               ": expected " + std::to_string(log.columns.size()) +
                               " cells (header), got " + std::to_string(cells.size()) +
                               (cells.size() < log.columns.size() ? " (truncated line?)" : ""));
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      row[c] =
          (!cells[c].empty() && end && *end == '\0') ? v : std::numeric_limits<double>::quiet_NaN();
    }
    log.rows.push_back(std::move(row));
  }
  if (!have_header)
    throw std::runtime_error("convergence log '" + source + "': no header line (empty file?)");
  return log;
}

inline convergence_log load_convergence_csv(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("load_convergence_csv: cannot open '" + path + "'");
  return read_convergence_csv(f, path);
}

struct convergence_plot_options {
  std::string x_column;                ///< empty: evaluations, else generation, else row number
  std::vector<std::string> y_columns;  ///< empty: best, median, mean, worst (those present)
  std::string sigma_column;            ///< empty: sigma / step_size if present; "-" for none
  int log_y = -1;  ///< 1 log, 0 linear, -1 auto (log when all > 0 and span > 50x)
  std::string title = "Optimizer convergence";
  double width = 720, height = 300;  ///< objective panel size, px (sigma panel: height / 2)
};

/// Draws the convergence plot. Throws std::invalid_argument naming a requested column the log lacks
/// (listing the columns it has), or when no objective column is found.
inline void write_convergence_plot_svg(const convergence_log& log, std::ostream& os,
                                       const convergence_plot_options& opt = {}) {
  using namespace viz_detail;
  check_positive(opt.width, "write_convergence_plot_svg: width");
  check_positive(opt.height, "write_convergence_plot_svg: height");
  std::string have;
  for (const auto& c : log.columns) have += (have.empty() ? "" : ", ") + ("'" + c + "'");
  auto require = [&](const std::string& n) {
    const int c = log.find(n);
    check_argument(c >= 0, "write_convergence_plot_svg: the log has no column '", n, "'; it has ",
                   have);
    return c;
  };
  int xc = -1;
  std::string xlabel = "row";
  if (!opt.x_column.empty()) {
    xc = require(opt.x_column);
  } else {
    xc = log.find({"evaluations", "evals", "evaluation", "nevals", "n_evals", "fevals",
                   "num_evaluations", "function_evaluations"});
    if (xc < 0)
      xc = log.find({"generation", "generations", "gen", "iteration", "iter", "iterations"});
  }
  if (xc >= 0) xlabel = log.columns[xc];
  std::vector<int> yc;
  if (!opt.y_columns.empty()) {
    for (const auto& n : opt.y_columns) yc.push_back(require(n));
  } else {
    for (auto aliases : {std::initializer_list<std::string_view>{
                             "best", "best_f", "f_best", "fbest", "best_fitness", "best_cost",
                             "best_value", "best_so_far", "best_ever"},
                         std::initializer_list<std::string_view>{"median", "median_f", "f_median",
                                                                 "median_fitness", "median_cost",
                                                                 "iteration_median"},
                         std::initializer_list<std::string_view>{"mean", "mean_f", "f_mean",
                                                                 "mean_fitness", "mean_cost"},
                         std::initializer_list<std::string_view>{"worst", "worst_f", "f_worst",
                                                                 "iteration_worst"}}) {
      const int c = log.find(aliases);
      if (c >= 0) yc.push_back(c);
    }
    check_argument(!yc.empty(),
                   "write_convergence_plot_svg: no objective column (best/median/mean/worst) in ",
                   have, "; name them in convergence_plot_options::y_columns");
  }
  int sc = -1;
  if (opt.sigma_column == "-")
    sc = -1;
  else if (!opt.sigma_column.empty())
    sc = require(opt.sigma_column);
  else
    sc = log.find({"sigma", "step_size", "stepsize", "step"});
  // Restarts (and continuation stages) are marked where the column's value changes.
  const int rc = log.find({"restart", "restarts", "run"});
  const int stc = log.find({"stage"});

  std::vector<double> x(log.rows.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = xc >= 0 ? log.rows[i][xc] : static_cast<double>(i);
  double xlo = 1e300, xhi = -1e300;
  finite_range(x, xlo, xhi);
  if (xlo > xhi) {
    xlo = 0;
    xhi = 1;
  } else if (xhi <= xlo) {
    xhi = xlo + 1;
  }
  double ylo = 1e300, yhi = -1e300;
  bool all_positive = true;
  for (int c : yc)
    for (const auto& r : log.rows)
      if (std::isfinite(r[c])) {
        ylo = std::min(ylo, r[c]);
        yhi = std::max(yhi, r[c]);
        all_positive = all_positive && r[c] > 0;
      }
  const bool log_y = opt.log_y == 1   ? (all_positive && ylo <= yhi)
                     : opt.log_y == 0 ? false
                                      : (all_positive && ylo <= yhi && yhi > 50 * ylo);
  if (log_y) {
    ylo = std::pow(10.0, std::floor(std::log10(ylo)));
    yhi = std::pow(10.0, std::ceil(std::log10(yhi)));
    if (yhi <= ylo) yhi = ylo * 10;
  } else {
    pad_range(ylo, yhi);
  }
  const double ml = 80, mr = 150, mt = 44, gap = 60, mb = 46;
  const double sh = sc >= 0 ? opt.height / 2 : 0.0;
  const double W = ml + opt.width + mr;
  const double H = mt + opt.height + (sc >= 0 ? gap + sh : 0.0) + mb;
  svg_open(os, W, H, opt.title);
  plot_panel P;
  P.left = ml;
  P.top = mt;
  P.width = opt.width;
  P.height = opt.height;
  P.xlo = xlo;
  P.xhi = xhi;
  P.ylo = ylo;
  P.yhi = yhi;
  P.log_y = log_y;
  P.draw_axes(os, sc >= 0 ? "" : xlabel, log_y ? "objective (log)" : "objective", opt.title);
  auto restarts = [&](const plot_panel& Q) {
    auto changed = [&](int c, std::size_t i) {
      return c >= 0 && log.rows[i][c] != log.rows[i - 1][c];
    };
    for (std::size_t i = 1; i < log.rows.size(); ++i)
      if ((changed(rc, i) || changed(stc, i)) && std::isfinite(x[i]))
        os << "<line class=\"restart\" x1=\"" << fnum(Q.X(x[i])) << "\" y1=\"" << fnum(Q.top)
           << "\" x2=\"" << fnum(Q.X(x[i])) << "\" y2=\"" << fnum(Q.top + Q.height)
           << "\" stroke=\"#999\" stroke-dasharray=\"5 4\"/>\n";
  };
  restarts(P);
  for (std::size_t k = 0; k < yc.size(); ++k) {
    P.draw_line(os, x, log.column(yc[k]), palette(k), k == 0 ? 2.0 : 1.4,
                "class=\"series\" data-column=\"" + xml_escape(log.columns[yc[k]]) + "\"");
    const double ly = mt + 16 + 18 * k;
    os << "<line x1=\"" << fnum(ml + opt.width + 14) << "\" y1=\"" << fnum(ly) << "\" x2=\""
       << fnum(ml + opt.width + 38) << "\" y2=\"" << fnum(ly) << "\" stroke=\"" << palette(k)
       << "\" stroke-width=\"2\"/>\n<text x=\"" << fnum(ml + opt.width + 44) << "\" y=\""
       << fnum(ly + 4) << "\" font-family=\"sans-serif\" font-size=\"12\">"
       << xml_escape(log.columns[yc[k]]) << "</text>\n";
  }
  if (log.rows.empty())
    os << "<text x=\"" << fnum(ml + opt.width / 2) << "\" y=\"" << fnum(mt + opt.height / 2)
       << "\" text-anchor=\"middle\" font-family=\"sans-serif\" fill=\"#a00\">no rows</text>\n";
  if (sc >= 0) {
    plot_panel S = P;
    S.top = mt + opt.height + gap;
    S.height = sh;
    double slo = 1e300, shi = -1e300;
    bool pos = true;
    for (const auto& r : log.rows)
      if (std::isfinite(r[sc])) {
        slo = std::min(slo, r[sc]);
        shi = std::max(shi, r[sc]);
        pos = pos && r[sc] > 0;
      }
    S.log_y = pos && slo <= shi;
    if (S.log_y) {
      S.ylo = std::pow(10.0, std::floor(std::log10(slo)));
      S.yhi = std::pow(10.0, std::ceil(std::log10(shi)));
      if (S.yhi <= S.ylo) S.yhi = S.ylo * 10;
    } else {
      pad_range(slo, shi);
      S.ylo = slo;
      S.yhi = shi;
    }
    S.draw_axes(os, xlabel, log.columns[sc], "");
    restarts(S);
    S.draw_line(os, x, log.column(sc), "#444", 1.5,
                "class=\"series\" data-column=\"" + xml_escape(log.columns[sc]) + "\"");
  }
  svg_close(os);
}

/// Reads the CSV log at `csv_path` and writes the plot to `svg_path`.
inline void save_convergence_plot_svg(const std::string& csv_path, const std::string& svg_path,
                                      const convergence_plot_options& opt = {}) {
  const convergence_log log = load_convergence_csv(csv_path);
  std::ostringstream s;
  write_convergence_plot_svg(log, s, opt);
  viz_detail::save_text(svg_path, s.str(), "save_convergence_plot_svg");
}

}  // namespace gaitsynth
