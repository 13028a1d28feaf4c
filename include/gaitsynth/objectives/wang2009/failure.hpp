#pragma once
/// \file objectives/wang2009/failure.hpp
/// E_fail of Wang, Fleet & Hertzmann 2009, eq. 7: the fraction of the horizon spent fallen,
///     E_fail = 1/T sum_t failed_t,
/// failed_t = 1 when the COM is below fail_height (0.7 m; 0.4 m for the "long arm" character)
/// above ground_height (the step view does not give the terrain height under the COM: a constant
/// ground height, 0 for the flat terrain).
///
/// T is the step count of the requested horizon. The paper's sum runs over all T steps; a rollout
/// here stops at a fall (stop_reason::fell) or when the objective says so (stop_reason::objective),
/// and the steps it did not simulate count as failed:
///     E_fail = (failed steps + (T - steps simulated)) / T.
/// That is what makes a fall cost: without it, stopping early would shorten the sum.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"

namespace gaitsynth::wang2009 {

struct failure_options {
  double fail_height = 0.7;    ///< m of COM height above the ground below which a step failed
  double ground_height = 0.0;  ///< m, world z of the ground
};

class failure {
 public:
  using options = failure_options;
  struct accumulator_type {
    rollout_track track;
    std::int64_t failed = 0;  ///< simulated steps with the COM below the fail height
  };

  explicit failure(options o = {}) : opt_(o) {
    check_positive(opt_.fail_height, "wang2009::failure: fail_height (m)");
    check_argument(std::isfinite(opt_.ground_height),
                   "wang2009::failure: ground_height is not finite (", opt_.ground_height, ")");
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
    a.failed += v.com.z() - opt_.ground_height < opt_.fail_height ? 1 : 0;
  }
  /// eq. 7 with the unsimulated tail of an early stop counted as failed. A rollout that stopped
  /// before its first step (a start state already fallen) is entirely failed.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const bool early = out.reason == stop_reason::fell || out.reason == stop_reason::objective;
    if (a.track.steps == 0) return early && out.duration > 0.0 ? 1.0 : 0.0;
    const std::int64_t T = horizon_steps(out, a.track.dt, a.track.steps);
    const std::int64_t tail = early ? T - a.track.steps : 0;
    return static_cast<double>(a.failed + tail) / static_cast<double>(T);
  }

  static std::array<std::string_view, 1> term_names() { return {"E_fail"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
  }

 private:
  options opt_;
};

}  // namespace gaitsynth::wang2009
