#pragma once
/// \file analysis/ankle_push_off.hpp
/// Ankle push-off in a recorded walk: the ankle's mechanical power over each stance phase of one
/// foot, and where in stance its positive peak falls. Human walking generates most of its ankle
/// work in late stance, a burst of plantarflexion power before toe-off (Winter's A2; Novacheck
/// 1998); Wang et al. 2009 ask their optimized walkers for it.
///
/// A stance is a maximal run of recorded frames in which a sole or toe contact point of the foot
/// or its toes touches and, when the frames record contact forces, carries force (at lift-off a
/// point still below the ground while its damper cancels its spring carries nothing); only stances
/// with a swing frame on both sides count (complete ones).
///
/// The power is the plantarflexors': tau * qdot of the sagittal ankle DOF while tau > 0, and 0
/// while the moment dorsiflexes (plantarflexion is positive in the models here). Push-off is
/// plantarflexor generation (tau > 0, qdot > 0). A dorsiflexing moment with a dorsiflexing
/// velocity also makes positive tau * qdot: the swing's ankle target snapping the foot up in the
/// last frame of contact, when the next state has begun, gives kilowatts for one frame, and with
/// the plain product that snap, not push-off, would decide where the power peaks.
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

namespace detail {
/// The tenth (0 .. 9) of stance that phase (0 .. 1, 1 in the last) falls in.
inline std::size_t stance_tenth(double phase) {
  return static_cast<std::size_t>(std::min(9, static_cast<int>(10.0 * phase)));
}
/// Centre (0.05 .. 0.95) of the tenth where a power curve by tenths is largest.
inline double curve_peak_fraction(const std::array<double, 10>& power_by_tenth) {
  const auto top = std::max_element(power_by_tenth.begin(), power_by_tenth.end());
  return 0.1 * static_cast<double>(top - power_by_tenth.begin()) + 0.05;
}
}  // namespace detail

struct ankle_stance {
  double t_begin = 0.0, t_end = 0.0;  ///< s: first and last frame of contact
  double peak_power = 0.0;            ///< W, the largest ankle power in the stance
  double peak_fraction = 0.0;         ///< where it falls, 0 (touch-down) .. 1 (lift-off)
  double positive_work = 0.0;         ///< J, the integral of the positive part of the power
  /// W, the mean power in each tenth of the stance (frames by their fraction of stance).
  std::array<double, 10> power_by_tenth{};
};

struct ankle_push_off_report {
  std::vector<ankle_stance> stances;  ///< complete stances, in time order
  /// Stances whose peak is generation (> 0 W) and lies in late stance (peak_fraction >=
  /// late_stance), as a fraction of all complete stances (0 when there are none).
  double late_peak_fraction = 0.0;
  double mean_peak_power = 0.0;     ///< W, over the complete stances
  double mean_peak_fraction = 0.0;  ///< over the complete stances
  /// W, power_by_tenth averaged over the stances: the stance's power curve, robust to the
  /// single-frame spikes of contact that can decide a stance's own peak.
  std::array<double, 10> mean_power_by_tenth{};
  /// Centre (0.05 .. 0.95) of the tenth of stance where mean_power_by_tenth is largest.
  double mean_curve_peak_fraction = 0.0;
};

/// The push-off of ankle DOF `ankle` (name) with foot bodies `foot` and `toes` (names; toes may be
/// empty) in trajectory tr of model m. Late stance begins at `late_stance` (fraction of stance).
/// Throws std::invalid_argument naming an unknown DOF or body, or a trajectory of another model.
template <root_joint Root>
ankle_push_off_report ankle_push_off(const model<Root>& m, const trajectory& tr,
                                     const std::string& ankle, const std::string& foot,
                                     const std::string& toes = "", double late_stance = 0.5) {
  const int vj = Root::nv + m.dof_index(ankle);
  const int foot_body = m.body_index(foot);
  const int toe_body = toes.empty() ? -1 : m.body_index(toes);
  check_argument(late_stance >= 0.0 && late_stance <= 1.0,
                 "ankle_push_off: late_stance must be in [0, 1], got ", late_stance);
  std::vector<int> points;
  for (int i = 0; i < static_cast<int>(m.contact_points.size()); ++i) {
    const contact_point& cp = m.contact_points[static_cast<std::size_t>(i)];
    const bool foot_point =
        cp.role == contact_point::kind::sole || cp.role == contact_point::kind::toe;
    if (foot_point && (cp.body == foot_body || cp.body == toe_body)) points.push_back(i);
  }
  check_argument(!points.empty(), "ankle_push_off: body '", foot, "' has no sole or toe points");
  const auto n = tr.frames.size();
  std::vector<unsigned char> down(n, 0);
  for (std::size_t f = 0; f < n; ++f) {
    const trajectory_frame& fr = tr.frames[f];
    check_argument(fr.v.size() == m.nv() && fr.tau.size() == m.nv() &&
                       fr.contact_active.size() == m.contact_points.size(),
                   "ankle_push_off: frame ", f, " does not fit model '", m.name, "'");
    const bool forces = fr.contact_force.size() == m.contact_points.size();
    for (const int i : points) {
      const auto k = static_cast<std::size_t>(i);
      down[f] |= fr.contact_active[k] && (!forces || fr.contact_force[k].squaredNorm() > 0.0);
    }
  }
  ankle_push_off_report out;
  std::size_t f = 0;
  while (f < n && down[f]) ++f;  // a stance under way at the start is not complete
  while (f < n) {
    while (f < n && !down[f]) ++f;
    const std::size_t b = f;
    while (f < n && down[f]) ++f;
    if (f >= n || b >= n || f - b < 2) continue;  // runs to the end, or a single-frame touch
    ankle_stance s;
    s.t_begin = tr.frames[b].t;
    s.t_end = tr.frames[f - 1].t;
    s.peak_power = -1e300;
    std::array<int, 10> in_tenth{};
    for (std::size_t k = b; k < f; ++k) {
      const double tau = tr.frames[k].tau[vj];
      const double p = tau > 0.0 ? tau * tr.frames[k].v[vj] : 0.0;
      const double phase = (tr.frames[k].t - s.t_begin) / (s.t_end - s.t_begin);
      const std::size_t tenth = detail::stance_tenth(phase);
      s.power_by_tenth[tenth] += p;
      ++in_tenth[tenth];
      if (p > s.peak_power) {
        s.peak_power = p;
        s.peak_fraction = (tr.frames[k].t - s.t_begin) / (s.t_end - s.t_begin);
      }
      if (k + 1 < f) s.positive_work += std::max(p, 0.0) * (tr.frames[k + 1].t - tr.frames[k].t);
    }
    for (std::size_t i = 0; i < 10; ++i)
      if (in_tenth[i] > 0) s.power_by_tenth[i] /= in_tenth[i];
    out.stances.push_back(s);
  }
  if (out.stances.empty()) return out;
  int late = 0;
  for (const ankle_stance& s : out.stances) {
    late += s.peak_power > 0.0 && s.peak_fraction >= late_stance;
    out.mean_peak_power += s.peak_power;
    out.mean_peak_fraction += s.peak_fraction;
    for (std::size_t i = 0; i < 10; ++i) out.mean_power_by_tenth[i] += s.power_by_tenth[i];
  }
  const double count = static_cast<double>(out.stances.size());
  out.late_peak_fraction = late / count;
  out.mean_peak_power /= count;
  out.mean_peak_fraction /= count;
  for (double& p : out.mean_power_by_tenth) p /= count;
  out.mean_curve_peak_fraction = detail::curve_peak_fraction(out.mean_power_by_tenth);
  return out;
}

}  // namespace gaitsynth
