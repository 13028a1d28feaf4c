#pragma once
/// \file termination.hpp
/// Why a rollout stopped, and the fall test. A failed rollout is a *result* (a reason and a cost),
/// never an exception: optimizers evaluate thousands of candidate parameter vectors and many of
/// them fall or diverge; that is information, not an error.
#include <cmath>
#include <cstdint>
#include <string_view>

namespace gaitsynth {

/// Why rollout() returned.
enum class stop_reason : std::uint8_t {
  horizon,  ///< simulated the whole requested duration
  fell,     ///< the COM dropped below the fall height above the terrain (paper convention: a fall)
  non_finite,  ///< diverged: q or v not finite, or the COM faster than divergence_com_speed
  objective,   ///< the objective asked to stop early (its done() returned true)
  stalled      ///< the COM advanced less than a stall window's distance (rollout_options::stall)
};

constexpr std::string_view to_string(stop_reason r) {
  switch (r) {
    case stop_reason::horizon:
      return "horizon";
    case stop_reason::fell:
      return "fell";
    case stop_reason::non_finite:
      return "non_finite";
    case stop_reason::objective:
      return "objective";
    case stop_reason::stalled:
      return "stalled";
  }
  return "unknown";
}

/// True when the reason means the rollout did not run to the horizon because something went wrong
/// with the motion (fell, diverged, stalled). An objective's own early stop is not a failure.
constexpr bool is_failure(stop_reason r) {
  return r == stop_reason::fell || r == stop_reason::non_finite || r == stop_reason::stalled;
}

/// The fall test of the rollout loop: the COM height above the terrain directly below it is under
/// `threshold` (m). Written as a free function so that tests and controllers use the same rule.
inline bool has_fallen(double com_height_above_terrain, double threshold) {
  return com_height_above_terrain < threshold;
}

}  // namespace gaitsynth
