#pragma once
/// \file muscle_hold.hpp
/// A test controller for musculotendon_actuator: every MTU at one constant excitation, and every
/// joint DOF servoed to q = 0 by the mixed block with fixed gains (standing_pd's by default).
/// Until the reflex controller of Wang et al. 2012 exists it is what drives the muscle actuator
/// in the actuator, rollout and allocation tests.
#include <Eigen/Core>
#include <span>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth::test_support {

struct muscle_hold {
  struct state_type {};
  int num_units = 16;
  double excitation = 0.05;
  Eigen::VectorXd kp, kd;  ///< per joint DOF; the mixed block servos every DOF to 0

  template <root_joint Root>
  static muscle_hold standing(const model<Root>& m, int num_units, double excitation, double dt,
                              double gain_scale = 1.0) {
    const pd_actuator g = standing_pd(m, dt, gain_scale);
    return {num_units, excitation, g.kp, g.kd};
  }

  std::size_t num_parameters() const { return 1; }
  /// p[0]: the excitation of every MTU.
  void bind(std::span<const double> p) {
    check_parameters(p, 1, "muscle_hold");
    excitation = p[0];
  }
  double period() const { return 0.0; }
  static constexpr command_kind output_kind() { return command_kind::excitation; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void command(const sensors<Root>&, state_type&, Eigen::Ref<Eigen::VectorXd> out) const {
    const Eigen::Index nj = kp.size();
    out.head(num_units).setConstant(excitation);
    out.segment(num_units, nj).setZero();  // targets
    out.segment(num_units + nj, nj) = kp;
    out.segment(num_units + 2 * nj, nj) = kd;
    out.segment(num_units + 3 * nj, nj).setZero();
  }
};

}  // namespace gaitsynth::test_support
