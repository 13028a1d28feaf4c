#pragma once
/// \file rnea.hpp
/// Inverse dynamics by the recursive Newton-Euler algorithm (Featherstone 2008, sec. 5.3,
/// Table 5.1) in world axes about the root origin, with gravity as a fictitious base acceleration.
#include "gaitsynth/dynamics/aba.hpp"

namespace gaitsynth {

namespace detail {

/// tau = M(q) a + C(q, v) v + g(q) [- J^T f_ext]; `a == nullptr` means a = 0, and
/// `with_velocity == false` means v = 0: the velocity terms (C, v x* I v) are then neither read
/// nor written, so gravity_forces leaves the velocities of v_cache to the readers. Poses current,
/// and velocities when with_velocity.
template <root_joint Root>
void rnea_passes(const model<Root>& m, workspace<Root>& ws, const double* a, bool with_velocity,
                 bool with_external, Eigen::VectorXd& out) {
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const int nn = s.nj + 1;
  const svec a_base = base_acceleration(m);
  if constexpr (nvr > 0) {
    s.A[0] = a_base;
    if (with_velocity) s.A[0] += s.C[0];
    if (a) s.A[0].template head<6>() += s.S0 * Eigen::Map<const Eigen::Matrix<double, nvr, 1>>(a);
  } else {
    s.A[0] = a_base;
  }
  for (int n = 1; n < nn; ++n) {
    s.A[n] = s.A[s.node_parent[n]];
    if (with_velocity) s.A[n] += s.C[n];
    if (a) s.A[n] += s.S[n] * a[nvr + n - 1];
  }
  // Body forces f = I a + v x* I v (eq. 5.9 in world axes), minus external wrenches.
  for (int n = 0; n < nn; ++n) {
    const int b = s.node_body[n];
    if (b >= 0) {
      s.pA[n] = op_times(s.body_I[b], s.A[n]);
      if (with_velocity) s.pA[n] += s.body_bias[b];
      if (with_external) s.pA[n] -= external_force_at_ref(ws, b);
    } else {
      s.pA[n].setZero();
    }
  }
  for (int n = nn - 1; n >= 1; --n) {
    out[nvr + n - 1] = sdot(s.S[n], s.pA[n]);
    s.pA[s.node_parent[n]] += s.pA[n];
  }
  if constexpr (nvr > 0) out.template head<nvr>() = s.S0.transpose() * to_vec6(s.pA[0]);
}

}  // namespace detail

/// Inverse dynamics: the generalized forces tau = M(q) a + C(q, v) v + g(q) (size nv) that produce
/// accelerations a. Ignores ws.f_ext (see rnea_with_external).
/// \returns ws.tau
/// \throws std::invalid_argument if a vector or the workspace has the wrong size.
template <root_joint Root>
const Eigen::VectorXd& rnea(const model<Root>& m, workspace<Root>& ws,
                            const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v,
                            const Eigen::Ref<const Eigen::VectorXd>& a) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::check_v(m, a, "a (generalized accelerations)");
  detail::ensure_kinematics(m, ws, q, v);
  detail::rnea_passes(m, ws, a.data(), true, false, ws.tau);
  return ws.tau;
}

/// Like rnea, but the external body wrenches in ws.f_ext act too: tau = M a + C v + g - J^T f_ext,
/// so rnea_with_external(q, v, aba(q, v, tau)) == tau.
template <root_joint Root>
const Eigen::VectorXd& rnea_with_external(const model<Root>& m, workspace<Root>& ws,
                                          const Eigen::Ref<const Eigen::VectorXd>& q,
                                          const Eigen::Ref<const Eigen::VectorXd>& v,
                                          const Eigen::Ref<const Eigen::VectorXd>& a) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::check_v(m, a, "a (generalized accelerations)");
  detail::ensure_kinematics(m, ws, q, v);
  detail::rnea_passes(m, ws, a.data(), true, true, ws.tau);
  return ws.tau;
}

/// The bias forces C(q, v) v + g(q) (RNEA with a = 0, no external wrenches).
/// \returns ws.bias
template <root_joint Root>
const Eigen::VectorXd& nonlinear_effects(const model<Root>& m, workspace<Root>& ws,
                                         const Eigen::Ref<const Eigen::VectorXd>& q,
                                         const Eigen::Ref<const Eigen::VectorXd>& v) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::ensure_kinematics(m, ws, q, v);
  detail::rnea_passes(m, ws, nullptr, true, false, ws.bias);
  return ws.bias;
}

/// The gravity forces g(q) alone (RNEA with v = 0, a = 0). Leaves the cached velocities alone:
/// after forward_kinematics(q, v) the velocity readers still see v. \returns ws.bias
template <root_joint Root>
const Eigen::VectorXd& gravity_forces(const model<Root>& m, workspace<Root>& ws,
                                      const Eigen::Ref<const Eigen::VectorXd>& q) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::ensure_poses(m, ws, q);
  detail::rnea_passes(m, ws, nullptr, false, false, ws.bias);
  return ws.bias;
}

}  // namespace gaitsynth
