#pragma once
/// \file analysis/cycle_window.hpp
/// A gait curve's mean, minimum and maximum over a window of the cycle: the numbers Wang et al.
/// 2012 Sec. 6.2 compare walkers by ("minimum knee flexion angle [in stance] of 2 deg ... the same
/// angle for nwalk is 9 deg", "excessive knee flexion", "too much knee flexion during the swing
/// phase", "too much dorsiflexion before heel-strike"). The windows are fixed fractions of the
/// heel-strike-to-heel-strike cycle, the same for every walker, so walkers compare on one rule:
///
///   const gait_cycle_data g = gait_cycles(m, tr, {.channels = human_sagittal_channels("l")});
///   const cycle_window_stats k = cycle_window(g.percent, g.mean[1], gait_windows::mid_stance);
///
/// mid_stance 15-50 % (mid and terminal stance: after the loading response, before pre-swing),
/// swing 62-100 % and terminal_swing 90-100 % (a normal walk's phases, Perry & Burnfield 2010).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct cycle_window_range {
  double from = 0.0;  ///< % of the cycle
  double to = 100.0;  ///< % of the cycle
};

namespace gait_windows {
inline constexpr cycle_window_range mid_stance{15.0, 50.0};
inline constexpr cycle_window_range swing{62.0, 100.0};
inline constexpr cycle_window_range terminal_swing{90.0, 100.0};
}  // namespace gait_windows

struct cycle_window_stats {
  double mean = 0.0, min = 0.0, max = 0.0;
  int samples = 0;  ///< curve points inside the window
};

/// Statistics of the samples y[i] whose percent[i] lies in [w.from, w.to]. Throws
/// std::invalid_argument for curves of different or zero length, a non-finite value, or a window
/// that is empty, reversed or holds no sample.
inline cycle_window_stats cycle_window(std::span<const double> percent, std::span<const double> y,
                                       cycle_window_range w) {
  check_argument(!percent.empty() && percent.size() == y.size(),
                 "cycle_window: percent and y must have the same, non-zero length, got ",
                 percent.size(), " and ", y.size());
  check_argument(std::isfinite(w.from) && std::isfinite(w.to) && w.from <= w.to,
                 "cycle_window: the window must be finite with from <= to, got [", w.from, ", ",
                 w.to, "]");
  cycle_window_stats s;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -s.min;
  double sum = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (percent[i] < w.from || percent[i] > w.to) continue;
    check_argument(std::isfinite(y[i]), "cycle_window: y at ", percent[i], " % is ", y[i]);
    sum += y[i];
    s.min = std::min(s.min, y[i]);
    s.max = std::max(s.max, y[i]);
    ++s.samples;
  }
  check_argument(s.samples > 0, "cycle_window: no sample in [", w.from, ", ", w.to, "] %");
  s.mean = sum / s.samples;
  return s;
}

}  // namespace gaitsynth
