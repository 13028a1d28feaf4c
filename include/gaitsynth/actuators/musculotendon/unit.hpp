#pragma once
/// \file actuators/musculotendon/unit.hpp
/// One musculotendon unit as the actuator uses it: its name, its Hill parameters
/// (contraction.hpp) and the one or two joint DOFs it spans (path.hpp), with the MTU length and
/// the torques its force makes at a configuration.
#include <Eigen/Core>
#include <array>
#include <string>

#include "gaitsynth/actuators/musculotendon/contraction.hpp"
#include "gaitsynth/actuators/musculotendon/path.hpp"

namespace gaitsynth::musculotendon {

struct unit {
  std::string name;  ///< e.g. "lGAS"
  unit_parameters parameters;
  std::array<joint_crossing, 2> crossings{};
  int num_crossings = 1;  ///< 1 (uniarticular) or 2 (biarticular)

  /// l_MTU (m) at joint angles qj (the joint DOFs, model::dofs order).
  template <class Joints>
  double length(const Joints& qj) const {
    std::array<double, 2> arms{};
    return length_and_arms(qj, reference_sines(), arms);
  }
  /// Each crossing's joint_crossing::reference_sine() (0 for a missing second crossing).
  std::array<double, 2> reference_sines() const {
    return {crossings[0].reference_sine(),
            num_crossings == 2 ? crossings[1].reference_sine() : 0.0};
  }
  /// l_MTU with reference_sines() given (an actuator computes them once), and each crossing's
  /// moment arm r(phi) written to arms: what an actuator needs once per physics step.
  template <class Joints>
  double length_and_arms(const Joints& qj, const std::array<double, 2>& reference_sines,
                         std::array<double, 2>& arms) const {
    double l = parameters.optimal_fiber_length + parameters.tendon_slack_length;
    for (int c = 0; c < num_crossings; ++c) {
      const double q = qj[crossings[c].dof];
      l += crossings[c].length_change(q, reference_sines[c]);
      arms[c] = crossings[c].arm(q);
    }
    return l;
  }
  /// Adds the joint torques of MTU force F at joint angles qj to tau (joint DOFs).
  template <class Joints, class Torques>
  void add_torques(const Joints& qj, double force, Torques& tau) const {
    for (int c = 0; c < num_crossings; ++c)
      tau[crossings[c].dof] += crossings[c].torque(qj[crossings[c].dof], force);
  }
};

}  // namespace gaitsynth::musculotendon
