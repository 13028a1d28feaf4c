#pragma once
/// \file objectives/wang2009/user_gait.hpp
/// E_user of Wang, Fleet & Hertzmann 2009, eq. 4: the user's optional targets for the average
/// forward speed v_x and the step length s,
///     E_user = Q(v_x - v_x_target; eps_vel) + Q(s - s_target; eps_step),
/// each term present only when its target is given (Q: eq. 3).
///
/// v_x: the average COM velocity along +x, (com_final.x - com_initial.x) / simulated time.
///
/// s (the paper does not define how it is measured): the mean of the x distances between
/// consecutive heel strikes of alternating feet. A foot (the foot body and its toes) touches when
/// either has a contact point touching (step_view::contact_count); a heel strike is a foot's
/// first touching step after it was airborne for at least min_airborne_time (so a bounce of the
/// landing foot is not a new strike; a foot touching at the start has not struck). Its position
/// is the x of the foot body's origin (the ankle). A strike of the other foot than the previous
/// strike's adds the signed distance x_strike - x_previous as one step; a strike of the same foot
/// (a shuffle) only moves the reference. With no step completed, s = 0: a character that never
/// steps has step length 0 (so a step target is penalized).
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"
#include "gaitsynth/objectives/wang2009/thresholded_quadratic.hpp"

namespace gaitsynth::wang2009 {

struct user_gait_options {
  std::optional<double> target_speed;        ///< v_x target, m/s (any finite value)
  std::optional<double> target_step_length;  ///< s target, m (finite, > 0)
  double eps_vel = 0.025;                    ///< m/s
  double eps_step = 0.025;                   ///< m
  double min_airborne_time = 0.05;           ///< s a foot must be off the ground before a strike
};

/// Heel strikes and step lengths, measured from the feet's contact counts (see the file comment).
struct step_counter {
  std::array<bool, 2> touching{};    ///< [left, right] at the last step
  std::array<double, 2> airborne{};  ///< s off the ground so far, [left, right]
  int last_foot = -1;                ///< 0 left, 1 right, -1 none yet
  double last_x = 0.0;               ///< m, the last strike's ankle x
  double step_sum = 0.0;             ///< m
  int steps = 0;                     ///< completed steps (strikes of alternating feet)
  int strikes = 0;

  template <class View>
  void add(const View& v, const foot_bodies& f, double min_airborne, bool first) {
    for (int side = 0; side < 2; ++side) {
      const bool left = side == 0;
      const bool now = v.contact_count[f.foot(left)] + v.contact_count[f.toes(left)] > 0;
      if (first) {
        touching[side] = now;
        airborne[side] = 0.0;
      } else if (now && !touching[side] && airborne[side] >= min_airborne) {
        const double x = v.body_position[f.foot(left)].x();
        if (last_foot >= 0 && last_foot != side) {
          step_sum += x - last_x;
          ++steps;
        }
        last_foot = side;
        last_x = x;
        ++strikes;
      }
      // Off the ground during [t, t + dt): dt more of airborne time; any contact resets it.
      airborne[side] = now ? 0.0 : airborne[side] + v.dt;
      touching[side] = now;
    }
  }
  /// Mean step length, m; 0 with no completed step.
  double mean() const { return steps > 0 ? step_sum / steps : 0.0; }
};

class user_gait {
 public:
  using options = user_gait_options;
  struct accumulator_type {
    rollout_track track;
    step_counter counter;
  };

  /// `m`: the simulated model. With a step-length target it must have the bodies lfoot, ltoes,
  /// rfoot and rtoes (\throws std::invalid_argument naming the missing one); without, the step
  /// length is measured (for the report) when they exist.
  template <root_joint Root>
  explicit user_gait(const model<Root>& m, options o = {}) : opt_(o) {
    check_argument(!opt_.target_speed || std::isfinite(*opt_.target_speed),
                   "wang2009::user_gait: target_speed is not finite (",
                   opt_.target_speed.value_or(0.0), ")");
    if (opt_.target_step_length)
      check_positive(*opt_.target_step_length, "wang2009::user_gait: target_step_length (m)");
    check_argument(std::isfinite(opt_.eps_vel) && opt_.eps_vel >= 0.0,
                   "wang2009::user_gait: eps_vel must be finite and >= 0, got ", opt_.eps_vel);
    check_argument(std::isfinite(opt_.eps_step) && opt_.eps_step >= 0.0,
                   "wang2009::user_gait: eps_step must be finite and >= 0, got ", opt_.eps_step);
    check_argument(std::isfinite(opt_.min_airborne_time) && opt_.min_airborne_time >= 0.0,
                   "wang2009::user_gait: min_airborne_time must be finite and >= 0, got ",
                   opt_.min_airborne_time);
    if (opt_.target_step_length)
      feet_ = foot_bodies::of(m);
    else
      feet_ = foot_bodies::find(m);
  }

  const options& opts() const { return opt_; }
  /// Whether the step length is measured (the model has the feet).
  bool measures_steps() const { return feet_.has_value(); }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    if (feet_) check_bodies(m, feet_->max_index(), "wang2009::user_gait");
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    if (feet_) a.counter.add(v, *feet_, opt_.min_airborne_time, a.track.steps == 0);
    a.track.add(v);
  }
  /// eq. 4.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    double e = 0.0;
    if (opt_.target_speed)
      e += thresholded_quadratic(average_com_velocity(out).x() - *opt_.target_speed, opt_.eps_vel);
    if (opt_.target_step_length)
      e += thresholded_quadratic(a.counter.mean() - *opt_.target_step_length, opt_.eps_step);
    return e;
  }

  /// Mean step length so far, m (0 with none completed).
  static double step_length(const accumulator_type& a) { return a.counter.mean(); }
  /// Steps completed so far (pairs of strikes of alternating feet).
  static int step_count(const accumulator_type& a) { return a.counter.steps; }

  /// Running values: E_user, the average forward speed (m/s) and the mean step length (m).
  static std::array<std::string_view, 3> term_names() {
    return {"E_user", "speed_m_s", "step_length_m"};
  }
  void terms(const accumulator_type& a, std::span<double> out) const {
    const rollout_outcome o = a.track.outcome();
    out[0] = finish(a, o);
    out[1] = average_com_velocity(o).x();
    out[2] = a.counter.mean();
  }

 private:
  options opt_;
  std::optional<foot_bodies> feet_;
};

}  // namespace gaitsynth::wang2009
