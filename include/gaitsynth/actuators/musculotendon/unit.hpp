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
    double l = parameters.optimal_fiber_length + parameters.tendon_slack_length;
    for (int c = 0; c < num_crossings; ++c) l += crossings[c].length_change(qj[crossings[c].dof]);
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
