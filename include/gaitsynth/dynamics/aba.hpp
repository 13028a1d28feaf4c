#pragma once
/// \file aba.hpp
/// Forward dynamics by the articulated-body algorithm (Featherstone 2008, sec. 7.3, Table 7.1), in
/// world axes about the root origin (see workspace.hpp), with external body wrenches (ws.f_ext) and
/// gravity as a fictitious base acceleration (sec. 5.3).
#include <Eigen/Cholesky>

#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

namespace detail {

/// External wrench of body b as a spatial force about the reference point (world axes).
template <root_joint Root>
inline vec6 external_force_at_ref(const workspace<Root>& ws, int b) {
  const vec6& fe = ws.f_ext[b];
  vec6 f;
  f.template head<3>() = fe.template head<3>() + ws.scratch.body_rel[b].cross(fe.template tail<3>());
  f.template tail<3>() = fe.template tail<3>();
  return f;
}

/// Gravity as an upward acceleration of the world (Featherstone sec. 5.3): a_base = [0; -g].
template <root_joint Root>
inline vec6 base_acceleration(const model<Root>& m) {
  vec6 a;
  a << 0.0, 0.0, 0.0, -m.gravity;
  return a;
}

/// ABA passes 2 and 3 (kinematics must be current). Writes ws.ddq.
template <root_joint Root>
void aba_passes(const model<Root>& m, workspace<Root>& ws,
                const Eigen::Ref<const Eigen::VectorXd>& tau) {
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const int nn = s.nj + 1;
  // Pass 1 (the kinematic part is in update_poses / update_velocities): initial articulated
  // inertias and bias forces, p = v x* I v - f_ext (eq. 7.38 in world axes).
  for (int n = 0; n < nn; ++n) {
    const int b = s.node_body[n];
    if (b >= 0) {
      const spatial::rigid_inertia& I = s.body_inertia[b];
      s.IA[n] = I.matrix();
      s.pA[n] = spatial::cross_force(s.V[n], I.momentum(s.V[n])) - external_force_at_ref(ws, b);
    } else {
      s.IA[n].setZero();
      s.pA[n].setZero();
    }
  }
  // Pass 2 (backward): project each articulated inertia through its 1-DOF joint into the parent.
  // No coordinate transform is needed: all quantities share world axes and the reference point.
  for (int n = nn - 1; n >= 1; --n) {
    const vec6& S = s.S[n];
    const mat6& IA = s.IA[n];
    const vec6 U = IA * S;
    const double Dinv = 1.0 / S.dot(U);
    const double u = tau[nvr + n - 1] - S.dot(s.pA[n]);
    s.U[n] = U;
    s.Dinv[n] = Dinv;
    s.u[n] = u;
    const int p = s.node_parent[n];
    const vec6& c = s.C[n];
    // Ia = IA - U D^-1 U^T;  pa = pA + Ia c + U D^-1 u = pA + IA c + U D^-1 (u - U^T c).
    s.pA[p] += s.pA[n] + IA * c + U * (Dinv * (u - U.dot(c)));
    s.IA[p].noalias() += IA - (Dinv * U) * U.transpose();
  }
  // Root and pass 3 (forward).
  const vec6 a_base = base_acceleration(m);
  if constexpr (nvr > 0) {
    // Root: a0 = a_base + c0 + S0 ddq_r and S0^T (IA0 a0 + pA0) = tau_r, so
    // (S0^T IA0 S0) ddq_r = tau_r - S0^T (pA0 + IA0 (a_base + c0)).
    using S0_t = typename detail::dynamics_scratch<Root>::root_subspace;
    const S0_t& S0 = s.S0;
    const vec6 a_pre = a_base + s.C[0];
    const Eigen::Matrix<double, 6, nvr> IS = s.IA[0] * S0;
    const Eigen::Matrix<double, nvr, nvr> D = S0.transpose() * IS;
    const Eigen::Matrix<double, nvr, 1> rhs =
        tau.template head<nvr>() - S0.transpose() * (s.pA[0] + s.IA[0] * a_pre);
    const Eigen::Matrix<double, nvr, 1> ddq_r = D.llt().solve(rhs);
    ws.ddq.template head<nvr>() = ddq_r;
    s.A[0] = a_pre + S0 * ddq_r;
  } else {
    s.A[0] = a_base;
  }
  for (int n = 1; n < nn; ++n) {
    const vec6 a = s.A[s.node_parent[n]] + s.C[n];
    const double qdd = s.Dinv[n] * (s.u[n] - s.U[n].dot(a));
    ws.ddq[nvr + n - 1] = qdd;
    s.A[n] = a + s.S[n] * qdd;
  }
}

}  // namespace detail

/// Forward dynamics: the generalized accelerations ddq (size nv) for positions q (nq), velocities v
/// (nv) and generalized forces tau (nv; the root entries are generalized forces on the root joint,
/// usually 0), including gravity and the external body wrenches in ws.f_ext.
/// \returns ws.ddq
/// \throws std::invalid_argument if a vector or the workspace has the wrong size.
template <root_joint Root>
const Eigen::VectorXd& aba(const model<Root>& m, workspace<Root>& ws,
                           const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v,
                           const Eigen::Ref<const Eigen::VectorXd>& tau) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::check_v(m, tau, "tau (generalized forces)");
  detail::ensure_kinematics(m, ws, q, v);
  detail::aba_passes(m, ws, tau);
  return ws.ddq;
}

}  // namespace gaitsynth
