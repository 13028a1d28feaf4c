#pragma once
/// \file objectives/wu2010/helper_penalty.hpp
/// The helper force's exact nonsmooth penalty of Wu & Popovic 2010, Sec. 8.2, eq. 7:
///     w_h L {h_max}+,   w_h = 5e-3 (Sec. 8.3), L the number of timesteps,
/// accumulated as w_h {h_max}+ dt / timestep per physics step (common.hpp: L counts eq. 6's
/// timesteps, 1/64 s, the paper's; timestep = 0: physics steps), h_max read from planned_walk's
/// report (0 without the helper force), so over T seconds it totals w_h (T / timestep) {h_max}+.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wu2010/common.hpp"

namespace gaitsynth::wu2010 {

struct helper_penalty_options {
  double w_h = 5e-3;                 ///< 1/N per timestep (>= 0)
  double timestep = paper_timestep;  ///< s, eq. 6's j (common.hpp); 0: per physics step
};

class helper_penalty {
 public:
  using options = helper_penalty_options;
  struct accumulator_type {
    double sum = 0.0;  ///< w_h sum_j {h_max}+ so far
  };

  explicit helper_penalty(const planned_walk_report_layout& layout, options o = {})
      : layout_(layout), opt_(o) {
    check_argument(std::isfinite(opt_.w_h) && opt_.w_h >= 0.0,
                   "wu2010::helper_penalty: w_h must be finite and >= 0, got ", opt_.w_h);
    check_timestep(opt_.timestep, "wu2010::helper_penalty");
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
    const auto r = checked_report(v.controller_report, layout_, "wu2010::helper_penalty");
    a.sum += timestep_weight(v.dt, opt_.timestep) * opt_.w_h * std::max(r[layout_.h_max], 0.0);
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.sum; }

  static std::array<std::string_view, 1> term_names() { return {"E_helper"}; }
  void terms(const accumulator_type& a, std::span<double> out) const { out[0] = a.sum; }

 private:
  planned_walk_report_layout layout_;
  options opt_;
};

}  // namespace gaitsynth::wu2010
