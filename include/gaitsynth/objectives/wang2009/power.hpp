#pragma once
/// \file objectives/wang2009/power.hpp
/// E_power of Wang, Fleet & Hertzmann 2009, eq. 12: an efficient gait, nearly passive swing,
///     E_power = 1/T sum_t sum_j tau_tj^2      ((N m)^2),
/// tau_tj the actuator torque of joint DOF j (step_view::joint_torques(): the passive joint-limit
/// springs are not the controller's effort), averaged over the steps simulated (a rate of the
/// motion that happened; a fall is charged by E_fail).
///
/// Cost of transport (options::cost_of_transport; the paper uses it when no target speed is
/// given): E_power / v_x, v_x the average forward COM speed (m/s). Below min_speed (standing,
/// walking backward) E_power / v continues as its tangent at min_speed,
///     E_power / min_speed * (2 - v_x / min_speed),
/// a finite penalty that keeps growing as v_x decreases (never inf or NaN, and still pointing
/// towards walking forward).
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"

namespace gaitsynth::wang2009 {

struct power_options {
  bool cost_of_transport = false;  ///< E_power / v_x instead of E_power
  double min_speed = 0.1;          ///< m/s (> 0), see the file comment
};

class power {
 public:
  using options = power_options;
  struct accumulator_type {
    rollout_track track;
    double sum = 0.0;   ///< sum over steps of sum_j tau_j^2, (N m)^2
    double last = 0.0;  ///< the last step's sum_j tau_j^2
  };

  explicit power(options o = {}) : opt_(o) {
    check_positive(opt_.min_speed, "wang2009::power: min_speed (m/s)");
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
    a.last = v.joint_torques().squaredNorm();
    a.sum += a.last;
  }
  /// E_power of eq. 12, (N m)^2 (the mean; 0 with no step).
  static double mean_squared_torque(const accumulator_type& a) {
    return a.track.steps > 0 ? a.sum / static_cast<double>(a.track.steps) : 0.0;
  }
  /// E_power / v_x with the guard of the file comment, (N m)^2 s/m.
  double cost_of_transport(double e_power, double vx) const {
    if (vx >= opt_.min_speed) return e_power / vx;
    return e_power / opt_.min_speed * (2.0 - vx / opt_.min_speed);
  }
  /// eq. 12, or the cost of transport.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const double e = mean_squared_torque(a);
    return opt_.cost_of_transport ? cost_of_transport(e, average_com_velocity(out).x()) : e;
  }

  /// Running values: the term (E_power or the cost of transport) and this step's sum tau^2.
  static std::array<std::string_view, 2> term_names() { return {"E_power", "tau_squared"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
    out[1] = a.last;
  }

 private:
  options opt_;
};

}  // namespace gaitsynth::wang2009
