#pragma once
/// \file gait_plot_svg.hpp
/// Gait-cycle plot as SVG: one panel per channel (by default sagittal hip, knee and ankle angles)
/// against percent of the gait cycle, the mean over cycles as a solid curve inside a band of
/// +- one standard deviation, and optionally each cycle as a thin curve: the layout of
/// Wang et al. 2009, Figure 6. The analysis is gait_cycles() (gait_cycles.hpp). Reference curves
/// (human data, io/normative_gait.hpp) can be drawn over a panel, dashed in their own band, as
/// Fig. 6 overlays motion capture. docs/viewer.md.
#include <cmath>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "gaitsynth/viz/gait_cycles.hpp"
#include "gaitsynth/viz/svg.hpp"

namespace gaitsynth {

/// A reference curve over one panel: dashed, inside its own band of +- sd.
struct gait_reference {
  std::size_t channel = 0;  ///< the panel: an index into cycles.channels
  std::string label;        ///< named in the plot's note
  std::vector<double> percent, mean;
  std::vector<double> sd;  ///< empty: no band
};

struct gait_plot_options {
  gait_cycle_options cycles;  ///< channels, side, foot, cycle starts
  bool show_cycles = true;    ///< every cycle as a thin grey curve under the mean
  std::string title;          ///< empty: "<model>: gait cycles"
  double panel_width = 300;   ///< px
  double panel_height = 220;  ///< px
  std::vector<gait_reference> references;
};

/// Draws an already computed gait_cycle_data (lets callers reuse or inspect the numbers).
inline void write_gait_plot_svg(const gait_cycle_data& d, std::ostream& os,
                                const gait_plot_options& opt, const std::string& model_name) {
  using namespace viz_detail;
  check_positive(opt.panel_width, "write_gait_plot_svg: panel_width");
  check_positive(opt.panel_height, "write_gait_plot_svg: panel_height");
  const std::size_t nch = d.channels.size();
  for (std::size_t r = 0; r < opt.references.size(); ++r) {
    const gait_reference& ref = opt.references[r];
    check_argument(ref.channel < nch, "write_gait_plot_svg: reference ", r, " ('", ref.label,
                   "') is for panel ", ref.channel, " of ", nch);
    check_argument(ref.mean.size() == ref.percent.size() && ref.percent.size() >= 2 &&
                       (ref.sd.empty() || ref.sd.size() == ref.percent.size()),
                   "write_gait_plot_svg: reference '", ref.label, "' has ", ref.percent.size(),
                   " percentages, ", ref.mean.size(), " means and ", ref.sd.size(),
                   " s.d.s (want at least 2, equal sizes, s.d. optional)");
    for (std::size_t s = 0; s < ref.percent.size(); ++s)
      check_argument(std::isfinite(ref.percent[s]) && std::isfinite(ref.mean[s]) &&
                         (ref.sd.empty() || std::isfinite(ref.sd[s])),
                     "write_gait_plot_svg: reference '", ref.label, "' sample ", s,
                     " is not finite");
  }
  const double ml = 64, mr = 16, mt = 56, mb = 70, gap = 70;
  const double W = ml + mr + nch * opt.panel_width + (nch > 0 ? (nch - 1) * gap : 0);
  const double H = mt + opt.panel_height + mb;
  const std::string title = opt.title.empty() ? model_name + ": gait cycles" : opt.title;
  svg_open(os, W, H, title);
  os << "<text x=\"" << fnum(W / 2)
     << "\" y=\"20\" text-anchor=\"middle\" font-family=\"sans-serif\""
     << " font-size=\"15\" font-weight=\"bold\">" << xml_escape(title) << "</text>\n";
  const int n = d.num_cycles();
  for (std::size_t c = 0; c < nch; ++c) {
    plot_panel P;
    P.left = ml + c * (opt.panel_width + gap);
    P.top = mt;
    P.width = opt.panel_width;
    P.height = opt.panel_height;
    P.xlo = 0;
    P.xhi = 100;
    double lo = 1e300, hi = -1e300;
    for (const auto& cv : d.curves[c]) finite_range(cv, lo, hi);
    for (std::size_t s = 0; s < d.percent.size() && n > 0; ++s) {
      lo = std::min(lo, d.mean[c][s] - d.stddev[c][s]);
      hi = std::max(hi, d.mean[c][s] + d.stddev[c][s]);
    }
    for (const gait_reference& ref : opt.references)
      if (ref.channel == c)
        for (std::size_t s = 0; s < ref.percent.size(); ++s) {
          const double e = ref.sd.empty() ? 0.0 : ref.sd[s];
          lo = std::min(lo, ref.mean[s] - e);
          hi = std::max(hi, ref.mean[s] + e);
        }
    pad_range(lo, hi);
    P.ylo = lo;
    P.yhi = hi;
    const gait_channel& ch = d.channels[c];
    os << "<g class=\"panel\" id=\"panel-" << c << "\">\n";
    P.draw_axes(os, "% gait cycle", ch.unit.empty() ? ch.label : ch.label + " (" + ch.unit + ")",
                ch.label);
    for (const gait_reference& ref : opt.references) {
      if (ref.channel != c) continue;
      if (!ref.sd.empty()) {
        std::string band;
        auto add = [&](std::size_t s, double sign) {  // appended piecewise: GCC 12's -Wrestrict
          band += fnum(P.X(ref.percent[s]));
          band += ',';
          band += fnum(P.Y(ref.mean[s] + sign * ref.sd[s]));
          band += ' ';
        };
        for (std::size_t s = 0; s < ref.percent.size(); ++s) add(s, 1.0);
        for (std::size_t s = ref.percent.size(); s-- > 0;) add(s, -1.0);
        os << "<polygon class=\"reference-band\" fill=\"#2ca02c\" fill-opacity=\"0.18\" "
              "stroke=\"none\" points=\""
           << band << "\"/>\n";
      }
      P.draw_line(os, ref.percent, ref.mean, "#2ca02c", 1.8,
                  "class=\"reference\" stroke-dasharray=\"6 4\"");
    }
    if (n == 0) {
      os << "<text x=\"" << fnum(P.left + P.width / 2) << "\" y=\"" << fnum(P.top + P.height / 2)
         << "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"12\" fill=\"#a00\">"
         << "no complete gait cycle</text>\n";
    } else {
      // Band of +- one standard deviation: upper edge forward, lower edge back.
      std::string band;
      for (std::size_t s = 0; s < d.percent.size(); ++s)
        band += fnum(P.X(d.percent[s])) + "," + fnum(P.Y(d.mean[c][s] + d.stddev[c][s])) + " ";
      for (std::size_t s = d.percent.size(); s-- > 0;)
        band += fnum(P.X(d.percent[s])) + "," + fnum(P.Y(d.mean[c][s] - d.stddev[c][s])) + " ";
      os << "<polygon class=\"band\" fill=\"#f4a460\" fill-opacity=\"0.45\" stroke=\"none\" "
            "points=\""
         << band << "\"/>\n";
      if (opt.show_cycles)
        for (const auto& cv : d.curves[c])
          P.draw_line(os, d.percent, cv, "#8a8a8a", 0.7, "class=\"cycle\" stroke-opacity=\"0.7\"");
      P.draw_line(os, d.percent, d.mean[c], "#1f3a93", 2.2, "class=\"mean\"");
    }
    os << "</g>\n";
  }
  std::string note;
  if (n > 0) {
    note = "mean (solid) and +-1 s.d. (band) over " + std::to_string(n) + " cycle" +
           (n == 1 ? "" : "s") +
           (d.foot.empty() ? " (given starts)" : " between heel strikes of " + d.foot);
  } else {
    note = "fewer than two heel strikes" + (d.foot.empty() ? std::string() : " of " + d.foot) +
           " found (" + std::to_string(d.cycle_starts.size()) + ")";
  }
  for (const gait_reference& ref : opt.references)
    note += "; dashed green: " + ref.label + " (" + d.channels[ref.channel].label + ")";
  os << "<text x=\"" << fnum(ml) << "\" y=\"" << fnum(H - 12)
     << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#555\">" << xml_escape(note)
     << "</text>\n";
  svg_close(os);
}

/// Gait-cycle plot of a trajectory (see the file comment). Throws std::invalid_argument for bad
/// options or names (gait_cycles()).
template <root_joint Root>
void write_gait_plot_svg(const model<Root>& m, const trajectory& traj, std::ostream& os,
                         const gait_plot_options& opt = {}) {
  const gait_cycle_data d = gait_cycles(m, traj, opt.cycles);
  write_gait_plot_svg(d, os, opt, m.name);
}

/// Writes the gait-cycle plot to `path` (nothing when the arguments are invalid);
/// std::runtime_error if the file cannot be written.
template <root_joint Root>
void save_gait_plot_svg(const model<Root>& m, const trajectory& traj, const std::string& path,
                        const gait_plot_options& opt = {}) {
  std::ostringstream s;
  write_gait_plot_svg(m, traj, s, opt);
  viz_detail::save_text(path, s.str(), "save_gait_plot_svg");
}

}  // namespace gaitsynth
