#pragma once
/// \file svg.hpp
/// Small helpers shared by the SVG writers (filmstrip_svg.hpp, gait_plot_svg.hpp,
/// convergence_plot_svg.hpp) and the HTML player: compact number text, XML / JSON escaping, "nice"
/// axis ticks and a plot panel that maps data to pixels and draws its axes. Not a general SVG
/// library: just what the figures need, written straight to a std::ostream.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gaitsynth::viz_detail {

/// Fixed-point text with at most `decimals` decimals and no trailing zeros ("1.5", "-0.25", "3").
/// Non-finite values give "0" (SVG has no NaN); callers skip such points before drawing.
inline std::string fnum(double x, int decimals = 2) {
  if (!std::isfinite(x)) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  std::string s(buf);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

/// Number as JSON text with `sig` significant digits; NaN and infinities become null.
inline std::string jnum(double x, int sig = 6) {
  if (!std::isfinite(x)) return "null";
  if (x == 0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", sig, x);
  return buf;
}

/// Text escaped for XML content and attribute values.
inline std::string xml_escape(std::string_view s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&apos;";
        break;
      default:
        // Control characters other than tab/newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n')
          o += ' ';
        else
          o += c;
    }
  }
  return o;
}

/// A JSON string literal (with quotes). '<' is escaped too, so the text can sit inside an HTML
/// <script> element without ever closing it.
inline std::string json_string(std::string_view s) {
  std::string o = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"')
      o += "\\\"";
    else if (c == '\\')
      o += "\\\\";
    else if (c == '\n')
      o += "\\n";
    else if (c == '<' || c == '>' || c == '&' || u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      o += buf;
    } else {
      o += c;
    }
  }
  return o + "\"";
}

/// About `target` round tick values (1, 2, 5 times a power of ten) covering [lo, hi].
inline std::vector<double> nice_ticks(double lo, double hi, int target = 5) {
  std::vector<double> t;
  if (!(std::isfinite(lo) && std::isfinite(hi)) || hi <= lo || target < 1) return t;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  const double first = std::ceil(lo / step - 1e-9) * step;
  // Counted, not stepped: when the step is below the values' resolution (a range of 2 at 1e16),
  // v += step would never advance.
  const double count = std::floor((hi - first) / step + 1e-9) + 1.0;
  if (!(count >= 1.0 && count <= 1000.0)) return t;
  for (int i = 0; i < static_cast<int>(count); ++i) {
    const double v = first + i * step;
    t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return t;
}

/// Decimals needed to print ticks spaced by `step` without losing their differences.
inline int tick_decimals(const std::vector<double>& ticks) {
  if (ticks.size() < 2) return 2;
  const double step = std::abs(ticks[1] - ticks[0]);
  // Ticks below the values' resolution can be equal (step 0, -log10 = inf): clamped as a double
  // first, since converting inf to int is undefined (found by fuzz/convergence_csv).
  const double d = std::ceil(-std::log10(step) - 1e-9);
  if (std::isnan(d)) return 2;
  return static_cast<int>(std::clamp(d, 0.0, 6.0));
}

/// Range [lo, hi] of the finite values in v (lo > hi when there are none).
inline void finite_range(const std::vector<double>& v, double& lo, double& hi) {
  for (double x : v)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
}

/// Widens a degenerate or empty range so that it can be drawn.
inline void pad_range(double& lo, double& hi, double rel = 0.05) {
  if (lo > hi) {
    lo = 0;
    hi = 1;
    return;
  }
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    const double d = std::max(std::abs(hi) * 0.1, 1e-3);
    lo -= d;
    hi += d;
    return;
  }
  const double d = (hi - lo) * rel;
  lo -= d;
  hi += d;
}

/// A rectangular plot panel: data (x, y) -> pixels, with optional log10 y axis.
struct plot_panel {
  double left = 0, top = 0, width = 300, height = 200;  ///< px, the plotting area
  double xlo = 0, xhi = 1, ylo = 0, yhi = 1;            ///< data range (log: positive values)
  bool log_y = false;

  double X(double x) const { return left + (x - xlo) / (xhi - xlo) * width; }
  double Y(double y) const {
    if (log_y) {
      const double l = std::log10(std::max(y, 1e-300));
      return top + height - (l - std::log10(ylo)) / (std::log10(yhi) - std::log10(ylo)) * height;
    }
    return top + height - (y - ylo) / (yhi - ylo) * height;
  }

  /// Frame, grid, tick labels, axis labels and title.
  void draw_axes(std::ostream& os, std::string_view xlabel, std::string_view ylabel,
                 std::string_view title) const {
    os << "<g class=\"axes\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#333\">\n";
    os << "<rect x=\"" << fnum(left) << "\" y=\"" << fnum(top) << "\" width=\"" << fnum(width)
       << "\" height=\"" << fnum(height) << "\" fill=\"#fff\" stroke=\"#888\"/>\n";
    const auto xt = nice_ticks(xlo, xhi, 5);
    const int xd = tick_decimals(xt);
    for (double v : xt) {
      const double px = X(v);
      os << "<line x1=\"" << fnum(px) << "\" y1=\"" << fnum(top) << "\" x2=\"" << fnum(px)
         << "\" y2=\"" << fnum(top + height) << "\" stroke=\"#e4e4e4\"/>\n";
      os << "<text x=\"" << fnum(px) << "\" y=\"" << fnum(top + height + 14)
         << "\" text-anchor=\"middle\">" << fnum(v, xd) << "</text>\n";
    }
    std::vector<double> yt;
    if (log_y) {
      const int e0 = static_cast<int>(std::ceil(std::log10(ylo) - 1e-9));
      const int e1 = static_cast<int>(std::floor(std::log10(yhi) + 1e-9));
      const int stride = std::max(1, (e1 - e0 + 1) / 6 + 1);
      for (int e = e0; e <= e1; e += stride) yt.push_back(std::pow(10.0, e));
    } else {
      yt = nice_ticks(ylo, yhi, 5);
    }
    const int yd = tick_decimals(yt);
    for (double v : yt) {
      const double py = Y(v);
      os << "<line x1=\"" << fnum(left) << "\" y1=\"" << fnum(py) << "\" x2=\""
         << fnum(left + width) << "\" y2=\"" << fnum(py) << "\" stroke=\"#e4e4e4\"/>\n";
      std::string label;
      if (log_y) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        label = buf;
      } else {
        label = fnum(v, yd);
      }
      os << "<text x=\"" << fnum(left - 4) << "\" y=\"" << fnum(py + 4) << "\" text-anchor=\"end\">"
         << label << "</text>\n";
    }
    if (!xlabel.empty())
      os << "<text x=\"" << fnum(left + width / 2) << "\" y=\"" << fnum(top + height + 30)
         << "\" text-anchor=\"middle\">" << xml_escape(xlabel) << "</text>\n";
    if (!ylabel.empty())
      os << "<text transform=\"translate(" << fnum(left - 42) << " " << fnum(top + height / 2)
         << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(ylabel) << "</text>\n";
    if (!title.empty())
      os << "<text x=\"" << fnum(left + width / 2) << "\" y=\"" << fnum(top - 8)
         << "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" << xml_escape(title)
         << "</text>\n";
    os << "</g>\n";
  }

  /// A polyline through the finite points (x[i], y[i]); broken where a value is not finite.
  void draw_line(std::ostream& os, const std::vector<double>& x, const std::vector<double>& y,
                 std::string_view stroke, double stroke_width = 1.5,
                 std::string_view extra = "") const {
    std::string pts;
    auto flush = [&] {
      if (!pts.empty())
        os << "<polyline fill=\"none\" stroke=\"" << stroke << "\" stroke-width=\""
           << fnum(stroke_width) << "\" " << extra << " points=\"" << pts << "\"/>\n";
      pts.clear();
    };
    const std::size_t n = std::min(x.size(), y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || (log_y && !(y[i] > 0))) {
        flush();
        continue;
      }
      pts += fnum(X(x[i])) + "," + fnum(Y(y[i])) + " ";
    }
    flush();
  }
};

/// The opening <svg> element (with the SVG namespace, required for a standalone file).
inline void svg_open(std::ostream& os, double width, double height, std::string_view title) {
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << fnum(width)
     << "\" height=\"" << fnum(height) << "\" viewBox=\"0 0 " << fnum(width) << " " << fnum(height)
     << "\">\n";
  if (!title.empty()) os << "<title>" << xml_escape(title) << "</title>\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
}

inline void svg_close(std::ostream& os) {
  os << "</svg>\n";
}

/// A qualitative palette for curves (colour-blind friendly "Okabe-Ito" order).
inline const char* palette(std::size_t i) {
  static constexpr const char* colours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                            "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  return colours[i % 8];
}

/// Writes `text` to the file `path`; std::runtime_error naming the file if that fails.
inline void save_text(const std::string& path, const std::string& text, const char* who) {
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(std::string(who) + ": cannot open '" + path + "' for writing");
  f << text;
  f.close();
  if (!f) throw std::runtime_error(std::string(who) + ": failed writing '" + path + "'");
}

}  // namespace gaitsynth::viz_detail
