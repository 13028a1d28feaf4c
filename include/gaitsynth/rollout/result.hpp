#pragma once
/// \file result.hpp
/// What rollout() returns, and the failed-rollout cost convention.
///
/// Cost convention (every optimizer in optimizers/ relies on it):
///   - a rollout that runs to the horizon, falls, or is stopped by its objective gets the cost the
///     objective computes (objective::finish); falling is expressed by the objective (for example
///     time_to_fall), not by the loop;
///   - a rollout whose state stops being finite (divergence) gets cost = +infinity
///     (failed_rollout_cost) and reason stop_reason::non_finite; finish() is not called (unless
///     rollout_options::score_divergence: then finish() scores it like an early stop, and a
///     non-finite value is +infinity);
///   - a finish() that returns NaN is reported as +infinity as well (objective_value keeps the
///   NaN).
/// So the cost is never NaN; optimizers rank +infinity (and, defensively, any non-finite value)
/// worst, and a failed rollout is never an exception.
#include <cmath>
#include <cstdint>
#include <limits>

#include "gaitsynth/rollout/termination.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

inline constexpr double failed_rollout_cost = std::numeric_limits<double>::infinity();

struct rollout_result {
  double cost =
      failed_rollout_cost;  ///< objective cost; +infinity for a failed (non-finite) rollout
  double time = 0.0;        ///< simulated time, s (from the initial state's t)
  stop_reason reason = stop_reason::horizon;
  std::int64_t steps = 0;             ///< physics steps taken
  std::int64_t controller_calls = 0;  ///< times controller::command ran
  double objective_value = std::numeric_limits<double>::quiet_NaN();  ///< finish() as returned
  vec3 com_initial = vec3::Zero();                                    ///< world, m
  vec3 com_final = vec3::Zero();  ///< world, m, at the last finite state
  double fall_height = 0.0;       ///< the COM height threshold used, m above the terrain

  bool failed() const { return is_failure(reason); }
  bool diverged() const { return reason == stop_reason::non_finite; }
};

}  // namespace gaitsynth
