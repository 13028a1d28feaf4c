#pragma once
/// \file objectives/distance.hpp
/// Two simple objectives (lower is better):
///   - distance_travelled: cost = -(COM displacement along a unit direction) (m), so minimizing
///     it walks as far as possible in that direction (+x by default, the walking direction);
///   - time_to_fall: cost = (requested duration - time of the fall) (s) when the character fell,
///     0 when it stayed up: minimizing it first keeps the character up longer (the "survive
///     first" term of Wang et al. 2009's objective, Sec. 4, which terminates falling rollouts).
/// Combine them with weighted_sum (objectives/weighted_sum.hpp), e.g. distance_objective() below.
#include <algorithm>
#include <array>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"

namespace gaitsynth {

class distance_travelled {
 public:
  struct accumulator_type {
    bool started = false;
    vec3 com_start = vec3::Zero();
    vec3 com_last = vec3::Zero();
  };

  /// `direction`: any non-zero finite vector (normalized here); +x by default.
  explicit distance_travelled(const vec3& direction = vec3::UnitX()) {
    check_argument(direction.allFinite() && direction.norm() > 1e-12,
                   "distance_travelled: direction must be finite and non-zero, got (",
                   direction.transpose(), ")");
    dir_ = direction.normalized();
  }
  const vec3& direction() const { return dir_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void accumulate(accumulator_type& a, const step_view<Root>& v) const {
    if (!a.started) {
      a.started = true;
      a.com_start = v.com;
    }
    a.com_last = v.com;
  }
  /// -(com_final - com_initial) . direction, m.
  double finish(const accumulator_type&, const rollout_outcome& out) const {
    return -(out.com_final - out.com_initial).dot(dir_);
  }

  static std::array<std::string_view, 1> term_names() { return {"distance_m"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.started ? (a.com_last - a.com_start).dot(dir_) : 0.0;
  }

 private:
  vec3 dir_ = vec3::UnitX();
};

class time_to_fall {
 public:
  struct accumulator_type {};

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void accumulate(accumulator_type&, const step_view<Root>&) const {}
  /// Remaining time when the character fell (s); 0 otherwise.
  double finish(const accumulator_type&, const rollout_outcome& out) const {
    if (out.reason != stop_reason::fell) return 0.0;
    return std::max(out.duration - out.time, 0.0);
  }
};

/// cost = -w_distance * distance along +x + w_fall * (time lost to a fall). With the defaults, a
/// second of standing is worth 10 m of walking: an optimizer learns not to fall first.
inline weighted_sum<distance_travelled, time_to_fall> distance_objective(
    double w_distance = 1.0, double w_fall = 10.0, const vec3& direction = vec3::UnitX()) {
  return weighted_sum<distance_travelled, time_to_fall>(
      {w_distance, w_fall}, distance_travelled(direction), time_to_fall{});
}

}  // namespace gaitsynth
