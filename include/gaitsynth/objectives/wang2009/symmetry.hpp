#pragma once
/// \file objectives/wang2009/symmetry.hpp
/// E_sym of Wang, Fleet & Hertzmann 2009, eq. 8: left and right strides of equal duration,
///     E_sym = Q(dt_0 - dt_2; eps_t) + Q(dt_1 - dt_3; eps_t),
/// dt_i the average duration of controller phase i (step_view::controller_phase; Fig. 2).
///
/// A visit of a phase is measured only when it is complete: it began at a phase change and ended
/// at another one (the start state is mid-phase, and the visit in progress at the end is cut
/// off). Its duration is its step count times dt. A pair in which either phase has no complete
/// visit contributes 0 (there is no average to compare; a controller stuck in one phase is
/// charged by the other terms). Phases outside 0..3 (-1: no state machine) are not measured.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/thresholded_quadratic.hpp"

namespace gaitsynth::wang2009 {

struct symmetry_options {
  double eps_t = 0.025;  ///< s
};

class symmetry {
 public:
  using options = symmetry_options;
  struct accumulator_type {
    std::int64_t steps = 0;         ///< steps seen
    int phase = -1;                 ///< the current phase
    bool from_change = false;       ///< the current visit began at a phase change
    std::int64_t visit_steps = 0;   ///< steps of the current visit so far
    double dt = 0.0;                ///< s
    std::array<double, 4> total{};  ///< s, summed duration of complete visits per phase
    std::array<int, 4> visits{};    ///< complete visits per phase
  };

  explicit symmetry(options o = {}) : opt_(o) {
    check_argument(std::isfinite(opt_.eps_t) && opt_.eps_t >= 0.0,
                   "wang2009::symmetry: eps_t must be finite and >= 0, got ", opt_.eps_t);
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    const int p = v.controller_phase;
    a.dt = v.dt;
    if (a.steps++ == 0) {
      a.phase = p;
      a.visit_steps = 1;
      return;
    }
    if (p == a.phase) {
      ++a.visit_steps;
      return;
    }
    if (a.from_change && a.phase >= 0 && a.phase < 4) {
      a.total[a.phase] += static_cast<double>(a.visit_steps) * a.dt;
      ++a.visits[a.phase];
    }
    a.phase = p;
    a.from_change = true;
    a.visit_steps = 1;
  }
  /// Average duration of phase i's complete visits, s; negative when there is none.
  static double average_duration(const accumulator_type& a, int i) {
    return a.visits[i] > 0 ? a.total[i] / a.visits[i] : -1.0;
  }
  /// eq. 8.
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    double e = 0.0;
    for (int i = 0; i < 2; ++i)
      if (a.visits[i] > 0 && a.visits[i + 2] > 0)
        e += thresholded_quadratic(average_duration(a, i) - average_duration(a, i + 2), opt_.eps_t);
    return e;
  }

  static std::array<std::string_view, 1> term_names() { return {"E_sym"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, rollout_outcome{});
  }

 private:
  options opt_;
};

}  // namespace gaitsynth::wang2009
