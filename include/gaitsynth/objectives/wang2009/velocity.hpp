#pragma once
/// \file objectives/wang2009/velocity.hpp
/// E_vel of Wang, Fleet & Hertzmann 2009, eq. 5: walk along +x, not sideways or up/down, and
/// start at the speed the walk keeps:
///     E_vel = Q(v_y; eps_vel) + lambda_vel [Q(v_0x - v_x; eps_vel) + Q(v_z; 2 eps_vel)],
/// v_x, v_y, v_z: the average COM velocity over the rollout (COM displacement / simulated time);
/// v_0x: the start state's COM x velocity (the first step's view.com_velocity.x). Footnote 2:
/// v_x is replaced by the target speed when one is given (options::target_speed).
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"
#include "gaitsynth/objectives/wang2009/thresholded_quadratic.hpp"

namespace gaitsynth::wang2009 {

struct velocity_options {
  double eps_vel = 0.025;              ///< m/s
  double lambda_vel = 0.01;            ///< weight of the start-speed and vertical terms
  std::optional<double> target_speed;  ///< m/s: replaces v_x in Q(v_0x - v_x) (footnote 2)
};

class velocity {
 public:
  using options = velocity_options;
  struct accumulator_type {
    rollout_track track;
  };

  explicit velocity(options o = {}) : opt_(o) {
    check_argument(std::isfinite(opt_.eps_vel) && opt_.eps_vel >= 0.0,
                   "wang2009::velocity: eps_vel must be finite and >= 0, got ", opt_.eps_vel);
    check_argument(std::isfinite(opt_.lambda_vel) && opt_.lambda_vel >= 0.0,
                   "wang2009::velocity: lambda_vel must be finite and >= 0, got ", opt_.lambda_vel);
    check_argument(!opt_.target_speed || std::isfinite(*opt_.target_speed),
                   "wang2009::velocity: target_speed is not finite (",
                   opt_.target_speed.value_or(0.0), ")");
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
  }
  /// eq. 5.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const vec3 avg = average_com_velocity(out);
    const double vx = opt_.target_speed.value_or(avg.x());
    const double v0x = a.track.com_velocity_first.x();
    return thresholded_quadratic(avg.y(), opt_.eps_vel) +
           opt_.lambda_vel * (thresholded_quadratic(v0x - vx, opt_.eps_vel) +
                              thresholded_quadratic(avg.z(), 2.0 * opt_.eps_vel));
  }

  static std::array<std::string_view, 1> term_names() { return {"E_vel"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
  }

 private:
  options opt_;
};

}  // namespace gaitsynth::wang2009
