#pragma once
/// \file state.hpp
/// The simulation state: generalized positions q (nq), velocities v (nv) and time t (s). It is a
/// copyable value; policies' own evolving state (controller phase, muscle activations, contact
/// anchors) lives beside it in the rollout, not here.
#include <Eigen/Core>

#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

struct sim_state {
  Eigen::VectorXd q;
  Eigen::VectorXd v;
  double t = 0.0;
};

/// The neutral configuration: all joint angles zero, root at the origin, identity orientation.
template <root_joint Root>
Eigen::VectorXd neutral_configuration(const model<Root>& m) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq());
  if constexpr (Root::nq == 7) q[3] = 1.0;  // quaternion w
  return q;
}

/// A state at rest in the neutral configuration.
template <root_joint Root>
sim_state make_state(const model<Root>& m) {
  return sim_state{neutral_configuration(m), Eigen::VectorXd::Zero(m.nv()), 0.0};
}

}  // namespace gaitsynth
