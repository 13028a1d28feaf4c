#pragma once
/// \file objectives/wang2012/metabolic_energy.hpp
/// J_M of Wang et al. 2012 Sec. 5.1, the average rate of metabolic energy of the body, W:
///
///   J_M = B_dot + 1/T sum_t sum_m E_dot_{m,t},    B_dot = 1.51 W/kg x body mass (Anderson 1999)
///
/// E_dot_{m,t} the rate of MTU m at step t (metabolic_rate.hpp) from the musculotendon actuator's
/// state at t (activation, fiber length and velocity, MTU and contractile forces) and the
/// excitation the command holds over [t, t + dt). T counts the steps simulated, so a fall is
/// charged elsewhere (the task terms), as for E_power of Wang et al. 2009. Needs a rollout whose
/// actuator state is a musculotendon_state (musculotendon_actuator).
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_rate.hpp"

namespace gaitsynth::wang2012 {

class metabolic_energy {
 public:
  struct accumulator_type {
    std::int64_t steps = 0;
    double body_mass = 0.0;  ///< kg, of the model
    metabolic_rates sum;     ///< per rate, summed over steps and muscles, W
    metabolic_rates last;    ///< this step's, summed over muscles, W
  };

  /// units: the actuator's MTUs, in its order (musculotendon_actuator::units()).
  explicit metabolic_energy(const std::vector<musculotendon::unit>& units,
                            metabolic_constants c = {}, double basal_rate_per_kg = 1.51)
      : constants_(c), basal_per_kg_(basal_rate_per_kg) {
    check_argument(c.slow_twitch_ratio >= 0.0 && c.slow_twitch_ratio <= 1.0,
                   "wang2012::metabolic_energy: slow_twitch_ratio must be in [0, 1], got ",
                   c.slow_twitch_ratio);
    check_positive(c.specific_tension, "wang2012::metabolic_energy: specific_tension (Pa)");
    check_positive(c.muscle_density, "wang2012::metabolic_energy: muscle_density (kg/m^3)");
    check_argument(std::isfinite(basal_rate_per_kg) && basal_rate_per_kg >= 0.0,
                   "wang2012::metabolic_energy: basal_rate_per_kg must be finite and >= 0, got ",
                   basal_rate_per_kg);
    for (const auto& u : units) {
      mass_.push_back(muscle_mass(u.parameters, c));
      optimal_length_.push_back(u.parameters.optimal_fiber_length);
    }
  }

  /// kg per MTU, in the actuator's order.
  const std::vector<double>& muscle_masses() const { return mass_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    accumulator_type a;
    a.body_mass = m.total_mass();
    return a;
  }
  template <class View>
  void accumulate(accumulator_type& acc, const View& v) const {
    const musculotendon_state& st = v.actuator_state();
    const Eigen::VectorXd& u = v.command();
    acc.last = {};
    for (std::size_t i = 0; i < mass_.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      const metabolic_rates r = muscle_metabolic_rates(
          mass_[i], u[k], st.activation[k], st.fiber_length[k] / optimal_length_[i],
          st.fiber_velocity[k], st.force[k], st.active_force[k], constants_);
      acc.last.activation += r.activation;
      acc.last.maintenance += r.maintenance;
      acc.last.shortening += r.shortening;
      acc.last.work += r.work;
    }
    acc.sum.activation += acc.last.activation;
    acc.sum.maintenance += acc.last.maintenance;
    acc.sum.shortening += acc.last.shortening;
    acc.sum.work += acc.last.work;
    ++acc.steps;
  }
  double basal_rate(const accumulator_type& a) const { return basal_per_kg_ * a.body_mass; }
  /// The muscles' average rate (W), 0 before the first step.
  static double average_muscle_rate(const accumulator_type& a) {
    return a.steps > 0 ? a.sum.total() / static_cast<double>(a.steps) : 0.0;
  }
  /// J_M, W.
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    return basal_rate(a) + average_muscle_rate(a);
  }

  static std::array<std::string_view, 6> term_names() {
    return {"J_M", "E_dot", "A_dot", "M_dot", "S_dot", "W_dot"};
  }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, {});
    out[1] = a.last.total();
    out[2] = a.last.activation;
    out[3] = a.last.maintenance;
    out[4] = a.last.shortening;
    out[5] = a.last.work;
  }

 private:
  metabolic_constants constants_;
  double basal_per_kg_;
  std::vector<double> mass_, optimal_length_;
};

}  // namespace gaitsynth::wang2012
