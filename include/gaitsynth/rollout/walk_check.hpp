#pragma once
/// \file rollout/walk_check.hpp
/// The library's one definition of "walked", used by every claim test and example: a rollout walked
/// when it ran to its horizon with stall detection on (it neither fell, diverged nor stopped
/// advancing: rollout_options::stall) and its average forward speed reached the criteria's minimum.
///
///   rollout_options o = walk_options(base, walk_criteria{});   // stall detection on
///   const rollout_result r = rollout(..., o, ...);
///   if (walked(r, walk_criteria{})) ...
///   const walk_check w = check_walk(problem, x, 100.0);         // the same through a problem
#include <Eigen/Core>
#include <cmath>

#include "gaitsynth/error.hpp"
#include "gaitsynth/rollout/options.hpp"
#include "gaitsynth/rollout/result.hpp"
#include "gaitsynth/rollout/termination.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// What counts as walking. The default stall rule: less than 0.1 m of forward COM progress in a
/// 5 s window (issue 15's figure; a walker at 0.3 m/s covers 1.5 m in one).
struct walk_criteria {
  stall_detection stall{.window = 5.0, .min_progress = 0.1};
  double min_average_speed = 0.0;  ///< m/s along +x over the whole rollout
};

/// o with c's stall detection turned on.
inline rollout_options walk_options(rollout_options o, const walk_criteria& c = {}) {
  o.stall = c.stall;
  return o;
}

/// Whether r (a rollout run with walk_options(..., c)) walked by criteria c.
/// \throws std::invalid_argument for a non-finite c.min_average_speed (nothing would walk).
inline bool walked(const rollout_result& r, const walk_criteria& c = {}) {
  check_argument(std::isfinite(c.min_average_speed),
                 "walk_criteria::min_average_speed must be finite, got ", c.min_average_speed);
  if (r.reason != stop_reason::horizon || !(r.time > 0.0)) return false;
  return (r.com_final.x() - r.com_initial.x()) / r.time >= c.min_average_speed;
}

/// How a controller fares in a long test rollout.
struct walk_check {
  double seconds = 0.0;        ///< simulated time before the end, a fall or a stall, s
  bool fell = false;           ///< stopped by a fall or a divergence
  bool stalled = false;        ///< stopped by the stall rule (upright, not advancing)
  bool walked = false;         ///< the library's verdict (walked() above)
  double distance = 0.0;       ///< COM displacement along x, m
  double average_speed = 0.0;  ///< distance / seconds, m/s
  double cost = 0.0;           ///< objective value of the whole rollout
  rollout_result result;
};

/// r judged by criteria c.
inline walk_check judge_walk(const rollout_result& r, const walk_criteria& c = {}) {
  walk_check w;
  w.result = r;
  w.seconds = r.time;
  w.fell = r.reason == stop_reason::fell || r.reason == stop_reason::non_finite;
  w.stalled = r.reason == stop_reason::stalled;
  w.walked = walked(r, c);
  w.distance = r.com_final.x() - r.com_initial.x();
  w.average_speed = w.seconds > 0 ? w.distance / w.seconds : 0.0;
  w.cost = r.cost;
  return w;
}

/// "walked", "fell", "diverged", "stalled" or "too slow": the verdict in a word, for reports.
inline const char* verdict(const walk_check& w) {
  if (w.walked) return "walked";
  if (w.stalled) return "stalled";
  if (w.result.reason == stop_reason::non_finite) return "diverged";
  if (w.fell) return "fell";
  return w.result.reason == stop_reason::horizon ? "too slow" : "stopped by the objective";
}

/// Parameters x of problem prob (rollout/problem.hpp; with variants, its main problem) walked for
/// `seconds` with c's stall detection, recorded into `record` when given.
template <class Problem>
walk_check check_walk(const Problem& prob, const Eigen::VectorXd& x, double seconds = 70.0,
                      trajectory* record = nullptr, int record_every = 40,
                      const walk_criteria& c = {}) {
  check_argument(std::isfinite(seconds) && seconds >= 0.0,
                 "check_walk: seconds must be finite and >= 0 s, got ", seconds);
  check_argument(std::isfinite(c.min_average_speed),
                 "walk_criteria::min_average_speed must be finite, got ", c.min_average_speed);
  if constexpr (requires { prob.main(); }) {
    // A problem with variants (rollout/problem_with_variants.hpp): the walk is the main problem's.
    return check_walk(prob.main(), x, seconds, record, record_every, c);
  } else {
    auto ctx = prob.make_context();
    ctx.options.stall = c.stall;
    return judge_walk(prob.evaluate(x, seconds, ctx, record, record_every), c);
  }
}

}  // namespace gaitsynth
