#pragma once
/// \file objectives/wang2009/landing.hpp
/// E_land of Wang, Fleet & Hertzmann 2009, eq. 6: no push-off before the stance foot is planted,
/// no stubbed swing toe,
///     E_land = 1/T sum_t (stance_t + stubbed_t).
/// With the controller phase p of Fig. 2 (step_view::controller_phase; phases 0, 1: right foot
/// stance, left swing; 2, 3: left stance, right swing):
///   stance_t  = 1 in phase 1 or 3 (toe-off) when neither the stance foot body nor the stance toe
///               body has 3 or more contact points touching;
///   stubbed_t = 1 when a toe-top point of the swing toe touches.
/// A controller without phases (p = -1, or any p outside 0..3, or options::read_phase = false for
/// a controller whose discrete state is not Wang's state machine): stance_t = 0 and stubbed_t =
/// 1 when the top of either toe touches.
///
/// T is the step count of the requested horizon, not of the steps simulated, as in eq. 7: every
/// step then weighs 1/T whenever the rollout stops, so cutting a rollout short changes nothing of
/// what its simulated steps cost (the unsimulated tail is charged by E_fail, which dominates:
/// w_fail / T per step against at most 2 w_land / T here). Dividing by the steps simulated would
/// instead make the same events weigh more in a rollout that falls sooner.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"

namespace gaitsynth::wang2009 {

struct landing_options {
  int planted_points = 3;  ///< a body with this many points touching is planted
  bool read_phase = true;  ///< false: treat every step as phase -1 (see the file comment)
};

class landing {
 public:
  using options = landing_options;
  struct accumulator_type {
    rollout_track track;
    std::int64_t stance = 0;   ///< steps with stance_t = 1
    std::int64_t stubbed = 0;  ///< steps with stubbed_t = 1
  };

  /// `m` must have the bodies lfoot, ltoes, rfoot, rtoes (\throws std::invalid_argument naming a
  /// missing one).
  template <root_joint Root>
  explicit landing(const model<Root>& m, options o = {}) : opt_(o), feet_(foot_bodies::of(m)) {
    check_argument(opt_.planted_points >= 1, "wang2009::landing: planted_points must be >= 1, got ",
                   opt_.planted_points);
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    check_bodies(m, feet_.max_index(), "wang2009::landing");
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
    const int p = opt_.read_phase ? v.controller_phase : -1;
    const int side = stance_side(p);
    if (side < 0) {
      a.stubbed += v.toe_top_contact ? 1 : 0;
      return;
    }
    const bool stance_left = side == 1;
    if (p == 1 || p == 3) {
      const bool planted = v.contact_count[feet_.foot(stance_left)] >= opt_.planted_points ||
                           v.contact_count[feet_.toes(stance_left)] >= opt_.planted_points;
      a.stance += planted ? 0 : 1;
    }
    a.stubbed += v.toe_top_touching[feet_.toes(!stance_left)] != 0 ? 1 : 0;
  }
  /// eq. 6, T the horizon's steps; 0 when nothing was simulated.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const std::int64_t T = horizon_steps(out, a.track.dt, a.track.steps);
    if (T <= 0) return 0.0;
    return static_cast<double>(a.stance + a.stubbed) / static_cast<double>(T);
  }

  static std::array<std::string_view, 1> term_names() { return {"E_land"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
  }

 private:
  options opt_;
  foot_bodies feet_;
};

}  // namespace gaitsynth::wang2009
