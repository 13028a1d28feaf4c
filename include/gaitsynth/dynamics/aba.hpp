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
inline svec external_force_at_ref(const workspace<Root>& ws, int b) {
  const vec6& fe = ws.f_ext[b];
  const vec3 f = fe.template tail<3>();
  return make_svec(fe.template head<3>() + ws.scratch.body_rel[b].cross(f), f);
}

/// Gravity as an upward acceleration of the world (Featherstone sec. 5.3): a_base = [0; -g].
template <root_joint Root>
inline svec base_acceleration(const model<Root>& m) {
  return make_svec(vec3::Zero(), -m.gravity);
}

/// ABA passes 2 and 3 (kinematics must be current). Writes ws.ddq.
template <root_joint Root>
void aba_passes(const model<Root>& m, workspace<Root>& ws,
                const Eigen::Ref<const Eigen::VectorXd>& tau) {
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const int nn = s.nj + 1;
  // Pass 1 (the kinematic part, body inertias and v x* I v are in update_poses /
  // update_velocities): initial articulated inertias and bias forces, p = v x* I v - f_ext.
  for (int n = 0; n < nn; ++n) {
    const int b = s.node_body[n];
    if (b >= 0) {
      s.IA[n] = s.body_I[b];
      s.pA[n] = s.body_bias[b] - external_force_at_ref(ws, b);
      if (n > 0) {
        s.Uacc[n] = op_times(s.body_I[b], s.S[n]);
        s.Dacc[n] = sdot(s.S[n], s.Uacc[n]);
      }
    } else {
      set_zero(s.IA[n]);
      s.pA[n].setZero();
      s.Uacc[n].setZero();
      s.Dacc[n] = 0.0;
    }
  }
  // Pass 2 (backward): project each articulated inertia through its 1-DOF joint into the parent.
  // No coordinate transform is needed: all quantities share world axes and the reference point.
  // The pass is latency bound along the tree, so the parent's U_p = IA_p S_p and D_p = S_p^T U_p
  // are assembled ahead from each child's contribution (IA_c S_p - U_c Dinv_c (U_c^T S_p) and
  // S_p^T IA_c S_p - Dinv_c (U_c^T S_p)^2): only one scalar FMA separates a node's division from
  // its parent's.
  for (int n = nn - 1; n >= 1; --n) {
    const svec& S = s.S[n];
    const smat& IA = s.IA[n];
    const svec& c = s.C[n];
    const svec U = s.Uacc[n];  // == IA * S
    const double Dinv = 1.0 / s.Dacc[n];  // == 1 / (S^T IA S)
    const double u = tau[nvr + n - 1] - sdot(S, s.pA[n]);
    s.U[n] = U;
    s.Dinv[n] = Dinv;
    s.u[n] = u;
    const int p = s.node_parent[n];
    // Ia = IA - U D^-1 U^T;  pa = pA + Ia c + U D^-1 u = pA + IA c + U D^-1 (u - U^T c).
    s.pA[p] += s.pA[n] + op_times(IA, c) + U * (Dinv * (u - sdot(U, c)));
    if (p > 0) {
      const svec& Sp = s.S[p];
      const svec X = op_times(IA, Sp);
      const double Y = sdot(U, Sp);
      s.Uacc[p] += X - U * (Dinv * Y);
      s.Dacc[p] += sdot(Sp, X) - Dinv * (Y * Y);
    }
    const svec DU = Dinv * U;
    smat& IAp = s.IA[p];
    for (int k = 0; k < 6; ++k) IAp[k] += IA[k] - U * DU[k];
  }
  // Root and pass 3 (forward).
  const svec a_base = base_acceleration(m);
  if constexpr (nvr > 0) {
    // Root: a0 = a_base + c0 + S0 ddq_r and S0^T (IA0 a0 + pA0) = tau_r, so
    // (S0^T IA0 S0) ddq_r = tau_r - S0^T (pA0 + IA0 (a_base + c0)).
    using S0_t = typename detail::dynamics_scratch<Root>::root_subspace;
    const S0_t& S0 = s.S0;
    const svec a_pre = a_base + s.C[0];
    const mat6 IA0 = to_mat6(s.IA[0]);
    const Eigen::Matrix<double, 6, nvr> IS = IA0 * S0;
    const Eigen::Matrix<double, nvr, nvr> D = S0.transpose() * IS;
    const vec6 f0 = to_vec6(s.pA[0] + op_times(s.IA[0], a_pre));
    const Eigen::Matrix<double, nvr, 1> rhs = tau.template head<nvr>() - S0.transpose() * f0;
    const Eigen::Matrix<double, nvr, 1> ddq_r = D.llt().solve(rhs);
    ws.ddq.template head<nvr>() = ddq_r;
    const vec6 Sq = S0 * ddq_r;
    s.A[0] = a_pre;
    s.A[0].template head<6>() += Sq;
  } else {
    s.A[0] = a_base;
  }
  for (int n = 1; n < nn; ++n) {
    const svec a = s.A[s.node_parent[n]] + s.C[n];
    const double qdd = s.Dinv[n] * (s.u[n] - sdot(s.U[n], a));
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
