#pragma once
/// \file joint_limits.hpp
/// Passive soft joint-limit torques (model.hpp, limit_model): a stiff spring-damper past the bound
/// (Wang et al. 2009, ODE style) or an exponential spring (Sharon & van de Panne 2005, Sec. 4:
/// "joint angle limits ... using exponential springs").
#include <cmath>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

/// Torque of one soft limit at angle x (rad) and rate xd (rad/s); 0 inside [lower, upper].
///   spring_damper: past upper, -k (x - upper) - d xd; past lower, -k (x - lower) - d xd.
///   exponential:   past upper, -k (exp(s (x - upper)) - 1) - d xd;
///                  past lower,  k (exp(s (lower - x)) - 1) - d xd.
inline double joint_limit_torque(const joint_limit& L, double x, double xd) {
  switch (L.model) {
    case limit_model::none:
      return 0.0;
    case limit_model::spring_damper:
      if (x > L.upper) return -L.stiffness * (x - L.upper) - L.damping * xd;
      if (x < L.lower) return -L.stiffness * (x - L.lower) - L.damping * xd;
      return 0.0;
    case limit_model::exponential:
      if (x > L.upper)
        return -L.stiffness * std::expm1(L.sharpness * (x - L.upper)) - L.damping * xd;
      if (x < L.lower)
        return L.stiffness * std::expm1(L.sharpness * (L.lower - x)) - L.damping * xd;
      return 0.0;
  }
  return 0.0;
}

/// -d joint_limit_torque / d xd at angle x: the limit's damping past a bound, 0 inside (or for
/// limit_model::none). The rollout takes this damper implicitly with
/// rollout_options::implicit_joint_damping.
inline double joint_limit_damping(const joint_limit& L, double x) {
  if (L.model == limit_model::none) return 0.0;
  return (x > L.upper || x < L.lower) ? L.damping : 0.0;
}

/// Adds the soft-limit torques of every joint DOF to tau_out (size nv; root entries untouched).
/// \throws std::invalid_argument on wrong sizes.
template <root_joint Root>
void joint_limit_torques(const model<Root>& m, const Eigen::Ref<const Eigen::VectorXd>& q,
                         const Eigen::Ref<const Eigen::VectorXd>& v,
                         Eigen::Ref<Eigen::VectorXd> tau_out) {
  check_size(q.size(), m.nq(), "q (generalized positions)");
  check_size(v.size(), m.nv(), "v (generalized velocities)");
  check_size(tau_out.size(), m.nv(), "tau_out (generalized forces)");
  const int nj = m.num_joint_dofs();
  for (int j = 0; j < nj; ++j) {
    const joint_limit& L = m.dofs[j].limit;
    if (L.model == limit_model::none) continue;
    tau_out[Root::nv + j] += joint_limit_torque(L, q[Root::nq + j], v[Root::nv + j]);
  }
}

}  // namespace gaitsynth
