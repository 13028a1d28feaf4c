#pragma once
/// \file analysis/human_ankle_push_off.hpp
/// The human reference for analysis/ankle_push_off.hpp: a person's plantarflexor power over
/// stance, by tenths, computed from normative joint angles and moments (data/normative_gait/), so
/// that a walker's push-off can be set beside a human's by the same measure.
///
/// Stance runs from heel strike (0 % of the cycle, where the tables begin) to toe-off, taken as
/// the first sample after the largest plantarflexor moment at which that moment has fallen below
/// 5 % of it (the tables give no contact events; the plantarflexor moment vanishes as the foot
/// unloads). The power is the same as the simulated walker's: tau * qdot with plantarflexion
/// positive, while the moment plantarflexes (tau > 0), else 0; the angle's rate by central
/// differences over the cycle, which lasts `stride_time` seconds.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "gaitsynth/analysis/ankle_push_off.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/io/normative_gait.hpp"

namespace gaitsynth {

struct human_ankle_push_off_report {
  double toe_off_percent = 0.0;  ///< % of the gait cycle where stance ends
  /// W, the mean plantarflexor power in each tenth of stance (samples by their fraction of stance)
  std::array<double, 10> power_by_tenth{};
  double curve_peak_fraction = 0.0;  ///< centre (0.05 .. 0.95) of the tenth with the most power
  double peak_power = 0.0;           ///< W, the largest sample in stance
  double peak_fraction = 0.0;        ///< where it falls, 0 (heel strike) .. 1 (toe-off)
};

/// The plantarflexor power of the normative curves `angle` (deg, dorsiflexion positive) and
/// `moment` (N m, dorsiflexor positive) of h, over a cycle of stride_time seconds.
/// \throws std::out_of_range for a missing variable, std::invalid_argument naming a bad
/// stride_time, curves of different samples, or units other than deg and N*m.
inline human_ankle_push_off_report human_ankle_push_off(
    const normative_gait& h, double stride_time,
    std::string_view angle = "ankle_dorsiflexion_angle",
    std::string_view moment = "ankle_dorsiflexion_moment") {
  check_argument(std::isfinite(stride_time) && stride_time > 0.0,
                 "human_ankle_push_off: stride_time must be > 0 s, got ", stride_time);
  const normative_curve& a = h.curve(angle);
  const normative_curve& m = h.curve(moment);
  check_argument(a.unit == "deg" && m.unit == "N*m", "human_ankle_push_off: units '", a.unit,
                 "' and '", m.unit, "', want 'deg' and 'N*m'");
  check_argument(a.percent == m.percent && a.percent.size() >= 3, "human_ankle_push_off: '", angle,
                 "' and '", moment, "' need the same samples (at least 3)");
  const std::size_t n = a.percent.size();
  // Plantarflexion positive: the negated dorsiflexion angle and moment.
  const auto tau = [&](std::size_t k) { return -m.mean[k]; };
  const auto qdot = [&](std::size_t k) {
    const std::size_t lo = k == 0 ? 0 : k - 1, hi = std::min(k + 1, n - 1);
    const double dt = (a.percent[hi] - a.percent[lo]) / 100.0 * stride_time;
    return -(a.mean[hi] - a.mean[lo]) * std::numbers::pi / 180.0 / dt;
  };
  std::size_t k_peak = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (tau(k) > tau(k_peak)) k_peak = k;
  check_argument(tau(k_peak) > 0.0, "human_ankle_push_off: '", moment,
                 "' never plantarflexes (largest plantarflexor moment ", tau(k_peak), " N m)");
  std::size_t k_off = k_peak;
  while (k_off + 1 < n && tau(k_off) >= 0.05 * tau(k_peak)) ++k_off;
  human_ankle_push_off_report out;
  out.toe_off_percent = a.percent[k_off];
  std::array<int, 10> in_tenth{};
  out.peak_power = -1e300;
  for (std::size_t k = 0; k <= k_off; ++k) {
    const double p = tau(k) > 0.0 ? tau(k) * qdot(k) : 0.0;
    const double phase = a.percent[k] / out.toe_off_percent;
    const std::size_t tenth = detail::stance_tenth(phase);
    out.power_by_tenth[tenth] += p;
    ++in_tenth[tenth];
    if (p > out.peak_power) {
      out.peak_power = p;
      out.peak_fraction = phase;
    }
  }
  for (std::size_t i = 0; i < 10; ++i)
    if (in_tenth[i] > 0) out.power_by_tenth[i] /= in_tenth[i];
  out.curve_peak_fraction = detail::curve_peak_fraction(out.power_by_tenth);
  return out;
}

}  // namespace gaitsynth
