#pragma once
/// \file controllers/end_effector/planner_timing.hpp
/// The planner's timing, Wu & Popovic 2010 appendix A.1 (Fig. 5): a half-cycle lasts t_h; the
/// swing phase (which includes the time the foot touches the ground but is not yet stationary)
/// lasts the footstep duration t_h + t_e, reaching t_e into the next half-cycle, where that
/// half-cycle's stance foot is still finishing this swing. Normalized times, t the time since the
/// half-cycle began:
///
///   s_h(t) = t / t_h               half-cycle time (upper-body paths)
///   s_s(t) = t / (t_h + t_e)       footstep time (swing-foot paths)
///
/// The paper optimizes t_e in [0, 0.6] t_h (Table 1) and fixes t_h = 0.55 s for every walk (Sec.
/// 8.3).
#include <algorithm>
#include <cmath>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct half_cycle_timing {
  double t_h = 0.55;  ///< half-cycle duration, s (> 0)
  double t_e = 0.0;   ///< footstep extension, s (>= 0)

  double footstep_duration() const { return t_h + t_e; }
  /// s_h(t) = t / t_h (A.1), not clamped.
  double s_h(double t) const { return t / t_h; }
  /// s_s(t) = t / (t_h + t_e) (A.1), not clamped.
  double s_s(double t) const { return t / (t_h + t_e); }
  /// ds_h/dt and ds_s/dt: the factors that turn d/ds into d/dt.
  double ds_h_dt() const { return 1.0 / t_h; }
  double ds_s_dt() const { return 1.0 / (t_h + t_e); }
};

/// \throws std::invalid_argument naming the value unless t_h is finite and > 0 and t_e finite and
/// >= 0.
inline half_cycle_timing make_half_cycle_timing(double t_h, double t_e) {
  check_argument(std::isfinite(t_h) && t_h > 0.0,
                 "half_cycle_timing: t_h (half-cycle duration) must be finite and > 0, got ", t_h);
  check_argument(std::isfinite(t_e) && t_e >= 0.0,
                 "half_cycle_timing: t_e (footstep extension) must be finite and >= 0, got ", t_e);
  return {t_h, t_e};
}

/// Clamps a normalized time to [0, 1] (paths hold their end points before and after); a NaN
/// stays NaN.
inline double clamp_unit(double s) {
  return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
}

}  // namespace gaitsynth
