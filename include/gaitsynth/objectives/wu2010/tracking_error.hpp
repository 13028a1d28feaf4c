#pragma once
/// \file objectives/wu2010/tracking_error.hpp
/// The frame-tracking error of Wu & Popovic 2010, Sec. 8.1 (eq. 6's first term):
///     E_track = sum_j sum_i e_track,i,   e_track,i = {||f_i||^2 - eps_track}+ (+ {||tau_i||^2 -
///     eps_track}+ for the LA frame),
/// j the timestep, f_i and tau_i eqs. 1-3 with sqrt(tracking weights) as coefficients and no bias,
/// whose squared norms planned_walk reports (planned_walk_report.hpp). Tolerance eps_track =
/// 2.5e-3 (m^2 with Sec. 8.3's unit weights). A sum over eq. 6's timesteps: each physics step
/// counts dt / timestep (common.hpp; 1/64 s, the paper's), 1 with timestep = 0.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wu2010/common.hpp"

namespace gaitsynth::wu2010 {

struct tracking_error_options {
  double eps_track = 2.5e-3;         ///< Sec. 8.1's tolerance (>= 0)
  double timestep = paper_timestep;  ///< s, eq. 6's j (common.hpp); 0: per physics step
};

class tracking_error {
 public:
  using options = tracking_error_options;
  struct accumulator_type {
    double sum = 0.0;   ///< E_track so far
    double last = 0.0;  ///< this step's sum_i e_track,i (unweighted)
  };

  explicit tracking_error(const planned_walk_report_layout& layout, options o = {})
      : layout_(layout), opt_(o) {
    check_argument(std::isfinite(opt_.eps_track) && opt_.eps_track >= 0.0,
                   "wu2010::tracking_error: eps_track must be finite and >= 0, got ",
                   opt_.eps_track);
    check_timestep(opt_.timestep, "wu2010::tracking_error");
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void reset_accumulator(const model<Root>&, accumulator_type& a) const {
    a = {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    const auto r = checked_report(v.controller_report, layout_, "wu2010::tracking_error");
    double e = 0.0;
    for (std::size_t i = 0; i < layout_.tracking_count; ++i)
      e += std::max(r[layout_.tracking_begin + i] - opt_.eps_track, 0.0);
    a.last = e;
    a.sum += timestep_weight(v.dt, opt_.timestep) * e;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.sum; }

  static std::array<std::string_view, 2> term_names() { return {"E_track", "e_track"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.sum;
    out[1] = a.last;
  }

 private:
  planned_walk_report_layout layout_;
  options opt_;
};

}  // namespace gaitsynth::wu2010
