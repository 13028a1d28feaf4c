#pragma once
/// \file objectives/wu2010/com_deviation.hpp
/// The per-footstep COM deviation of Wu & Popovic 2010, Sec. 8.1 (eq. 6's second term):
///     E_com = sum_k ||c^_k - c_k||^2_{W_c},   W_c = 100 I (Sec. 8.3),
/// c^_k the horizontal COM at the end of half-cycle k and c_k = c^_{k-1} + R_z(psi_m)(r x) its
/// planned target, which planned_walk reports from the command that starts half-cycle k. The end
/// of half-cycle k is the step whose report first shows k + 1: that step's view holds the COM the
/// controller planned k + 1 from, c^_k. A half-cycle the rollout did not finish is not charged
/// (the paper penalizes "at the end of the k-th half-cycle"). Vertical deviations are free.
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wu2010/common.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth::wu2010 {

struct com_deviation_options {
  double weight = 100.0;  ///< W_c = weight I, 1/m^2 (>= 0)
};

class com_deviation {
 public:
  using options = com_deviation_options;
  struct accumulator_type {
    double sum = 0.0;                       ///< E_com so far
    double last = 0.0;                      ///< the last charged ||dc_k||^2_{W_c}
    std::int64_t charged = 0;               ///< half-cycles charged
    double k = -1.0;                        ///< the previous step's half-cycle (-1: none yet)
    double target_x = 0.0, target_y = 0.0;  ///< its c_k, world, m
  };

  explicit com_deviation(const planned_walk_report_layout& layout, options o = {})
      : layout_(layout), opt_(o) {
    check_argument(std::isfinite(opt_.weight) && opt_.weight >= 0.0,
                   "wu2010::com_deviation: weight must be finite and >= 0, got ", opt_.weight);
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
    const auto r = checked_report(v.controller_report, layout_, "wu2010::com_deviation");
    const double k = r[layout_.half_cycle];
    if (a.k >= 0.0 && k != a.k) {  // half-cycle a.k just ended: v.com is c^_k
      const double dx = v.com.x() - a.target_x, dy = v.com.y() - a.target_y;
      a.last = opt_.weight * (dx * dx + dy * dy);
      a.sum += a.last;
      ++a.charged;
    }
    a.k = k;
    a.target_x = r[layout_.com_target];
    a.target_y = r[layout_.com_target + 1];
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.sum; }

  static std::array<std::string_view, 2> term_names() { return {"E_com", "com_dev_last"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.sum;
    out[1] = a.last;
  }

 private:
  planned_walk_report_layout layout_;
  options opt_;
};

}  // namespace gaitsynth::wu2010
