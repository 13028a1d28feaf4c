#pragma once
/// \file objectives/wang2009/power_ratio.hpp
/// E_ratio of Wang, Fleet & Hertzmann 2009, eqs. 13-15: an ankle-powered gait with a nearly
/// passive knee, as in human walking (Novacheck 1998),
///     P_DOF  = 1/T sum_t sum_{j in DOF} tau_tj^2                       (14)
///     r      = [P_hips, P_knees, P_ankles] / (P_hips + P_knees + P_ankles)   (13)
///     E_ratio = ||r - r_walk||_2,  r_walk = [0.43, 0.04, 0.53]           (15)
/// hips: lhip_x/y/z and rhip_x/y/z; knees: lknee, rknee; ankles: lankle_x/y, rankle_x/y (the toe
/// hinges are not counted). tau: actuator torques (step_view::joint_torques()), T the steps
/// simulated (it cancels in r). With no torque at all r is undefined: r = 0 then (E_ratio =
/// ||r_walk||), never NaN.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"

namespace gaitsynth::wang2009 {

struct power_ratio_options {
  std::array<double, 3> target{0.43, 0.04, 0.53};  ///< r_walk: hip, knee, ankle
};

class power_ratio {
 public:
  using options = power_ratio_options;
  struct accumulator_type {
    rollout_track track;
    std::array<double, 3> sum{};  ///< sum over steps of tau^2 per group (hips, knees, ankles)
  };

  /// `m` must have the hip, knee and ankle DOFs named in the file comment (\throws
  /// std::invalid_argument naming a missing one).
  template <root_joint Root>
  explicit power_ratio(const model<Root>& m, options o = {})
      : opt_(o),
        hips_{m.dof_index("lhip_x"), m.dof_index("lhip_y"), m.dof_index("lhip_z"),
              m.dof_index("rhip_x"), m.dof_index("rhip_y"), m.dof_index("rhip_z")},
        knees_{m.dof_index("lknee"), m.dof_index("rknee")},
        ankles_{m.dof_index("lankle_x"), m.dof_index("lankle_y"), m.dof_index("rankle_x"),
                m.dof_index("rankle_y")} {
    for (int i = 0; i < 3; ++i)
      check_argument(std::isfinite(opt_.target[i]) && opt_.target[i] >= 0.0,
                     "wang2009::power_ratio: target[", i, "] must be finite and >= 0, got ",
                     opt_.target[i]);
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    int top = 0;
    for (int j : hips_) top = std::max(top, j);
    for (int j : knees_) top = std::max(top, j);
    for (int j : ankles_) top = std::max(top, j);
    check_argument(top < m.num_joint_dofs(), "wang2009::power_ratio: model '", m.name, "' has ",
                   m.num_joint_dofs(), " joint DOFs, the term reads DOF ", top);
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
    const auto tau = v.joint_torques();
    for (int j : hips_) a.sum[0] += tau[j] * tau[j];
    for (int j : knees_) a.sum[1] += tau[j] * tau[j];
    for (int j : ankles_) a.sum[2] += tau[j] * tau[j];
  }
  /// [P_hips, P_knees, P_ankles] of eq. 14, (N m)^2.
  static std::array<double, 3> powers(const accumulator_type& a) {
    std::array<double, 3> p{};
    if (a.track.steps > 0)
      for (int i = 0; i < 3; ++i) p[i] = a.sum[i] / static_cast<double>(a.track.steps);
    return p;
  }
  /// r of eq. 13 (sums to 1; all 0 with no torque).
  static std::array<double, 3> ratio(const accumulator_type& a) {
    const double total = a.sum[0] + a.sum[1] + a.sum[2];
    std::array<double, 3> r{};
    if (total > 0.0)
      for (int i = 0; i < 3; ++i) r[i] = a.sum[i] / total;
    return r;
  }
  /// eq. 15.
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    const std::array<double, 3> r = ratio(a);
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += (r[i] - opt_.target[i]) * (r[i] - opt_.target[i]);
    return std::sqrt(s);
  }

  /// How far r lies outside the box |r_i - target_i| <= tolerance: the largest excess, 0 inside
  /// (ours: the ratio as a constraint, rollout/problem_with_constraint.hpp, where eq. 15's penalty
  /// gives way to other terms). \throws std::invalid_argument for a tolerance not finite and >= 0.
  double violation(const accumulator_type& a, double tolerance) const {
    check_argument(std::isfinite(tolerance) && tolerance >= 0.0,
                   "wang2009::power_ratio: tolerance must be finite and >= 0, got ", tolerance);
    const std::array<double, 3> r = ratio(a);
    double v = 0.0;
    for (int i = 0; i < 3; ++i) v = std::max(v, std::abs(r[i] - opt_.target[i]) - tolerance);
    return v;
  }

  /// Running values: E_ratio and r (hip, knee, ankle).
  static std::array<std::string_view, 4> term_names() {
    return {"E_ratio", "r_hip", "r_knee", "r_ankle"};
  }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, rollout_outcome{});
    const std::array<double, 3> r = ratio(a);
    for (int i = 0; i < 3; ++i) out[1 + i] = r[i];
  }

 private:
  options opt_;
  std::array<int, 6> hips_;
  std::array<int, 2> knees_;
  std::array<int, 4> ankles_;
};

}  // namespace gaitsynth::wang2009
