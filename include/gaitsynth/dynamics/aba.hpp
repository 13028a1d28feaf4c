#pragma once
/// \file aba.hpp
/// Forward dynamics by the articulated-body algorithm (Featherstone 2008, sec. 7.3, Table 7.1), in
/// world axes about the root origin (see workspace.hpp), with external body wrenches (ws.f_ext) and
/// gravity as a fictitious base acceleration (sec. 5.3).
#include <Eigen/Cholesky>
#include <cmath>

#include "gaitsynth/dynamics/aba_by_joint.hpp"
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

/// Solves A x = b for a small symmetric positive definite A (the root's articulated inertia
/// S0^T IA0 S0) by an LDL^T factorization with compile-time bounds: fully unrolled, it is several
/// times cheaper than Eigen's general LLT for a 6x6 and as accurate (no pivoting is needed for
/// SPD).
template <int N>
Eigen::Matrix<double, N, 1> solve_spd(const Eigen::Matrix<double, N, N>& A,
                                      const Eigen::Matrix<double, N, 1>& b) {
  double L[N][N] = {};
  double d[N] = {}, dinv[N] = {};
  for (int j = 0; j < N; ++j) {
    double djj = A(j, j);
    for (int k = 0; k < j; ++k) djj -= L[j][k] * L[j][k] * d[k];
    d[j] = djj;
    dinv[j] = 1.0 / djj;
    for (int i = j + 1; i < N; ++i) {
      double lij = A(i, j);
      for (int k = 0; k < j; ++k) lij -= L[i][k] * L[j][k] * d[k];
      L[i][j] = lij * dinv[j];
    }
  }
  Eigen::Matrix<double, N, 1> x;
  for (int i = 0; i < N; ++i) {  // L y = b
    double yi = b[i];
    for (int k = 0; k < i; ++k) yi -= L[i][k] * x[k];
    x[i] = yi;
  }
  for (int i = 0; i < N; ++i) x[i] *= dinv[i];  // D z = y
  for (int i = N - 1; i >= 0; --i) {            // L^T x = z
    double xi = x[i];
    for (int k = i + 1; k < N; ++k) xi -= L[k][i] * x[k];
    x[i] = xi;
  }
  return x;
}

/// The root's acceleration from its articulated inertia IA[0] and bias pA[0] (ABA's pass 2 done):
/// writes the root's ddq and s.A[0].
template <root_joint Root>
void aba_root(const model<Root>& m, workspace<Root>& ws,
              const Eigen::Ref<const Eigen::VectorXd>& tau) {
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const svec a_base = base_acceleration(m);
  if constexpr (std::is_same_v<Root, floating_root>) {
    // By joints (and only there: the node passes keep their rounding, workspace.hpp says why): a
    // free root's S0 = [0 R; 1 0] is orthogonal (S0^-T = S0), so the equation below,
    // (S0^T IA0 S0) ddq_r = tau_r - S0^T f0, is IA0 z = S0 tau_r - f0 with ddq_r = S0^T z, and
    // the root's acceleration is a_pre + S0 ddq_r = a_pre + z: one 6 x 6 solve in world axes,
    // without forming S0^T IA0 S0.
    if (s.joints.enabled) {
      const svec a_pre = a_base + s.C[0];
      const vec6 f0 = to_vec6(s.pA[0] + op_times(s.IA[0], a_pre));
      const vec6 z = solve_spd<6>(to_mat6(s.IA[0]), s.S0 * tau.template head<6>() - f0);
      ws.ddq.template head<6>() = s.S0.transpose() * z;
      s.A[0] = a_pre;
      s.A[0].template head<6>() += z;
      return;
    }
  }
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
    const Eigen::Matrix<double, nvr, 1> ddq_r = solve_spd<nvr>(D, rhs);
    ws.ddq.template head<nvr>() = ddq_r;
    const vec6 Sq = S0 * ddq_r;
    s.A[0] = a_pre;
    s.A[0].template head<6>() += Sq;
  } else {
    s.A[0] = a_base;
  }
}

/// ABA passes 1-3 by joints (aba_by_joint.hpp; s.joints.enabled). Writes ws.ddq.
template <root_joint Root>
void aba_passes_by_joint(const model<Root>& m, workspace<Root>& ws,
                         const Eigen::Ref<const Eigen::VectorXd>& tau, const double* armature) {
  auto& s = ws.scratch;
  const int nb = s.nb;
  // Pass 1: each body's inertia and bias force p = v x* I v - f_ext at its joint's node.
  for (int b = 0; b < nb; ++b) {
    const int n = s.body_node[b];
    s.IA[n] = s.body_I[b];
    s.pA[n] = s.body_bias[b] - external_force_at_ref(ws, b);
  }
  // Pass 2 (backward, children before parents).
  for (int b = nb - 1; b >= 1; --b) {
    const body& bd = m.bodies[b];
    switch (bd.num_dofs) {
      case 1:
        aba_joint_backward<1>(ws, b, bd.first_dof, tau, armature);
        break;
      case 2:
        aba_joint_backward<2>(ws, b, bd.first_dof, tau, armature);
        break;
      default:
        aba_joint_backward<3>(ws, b, bd.first_dof, tau, armature);
        break;
    }
  }
  aba_root(m, ws, tau);
  // Pass 3 (forward).
  for (int b = 1; b < nb; ++b) {
    const body& bd = m.bodies[b];
    switch (bd.num_dofs) {
      case 1:
        aba_joint_forward<1>(ws, b, bd.first_dof);
        break;
      case 2:
        aba_joint_forward<2>(ws, b, bd.first_dof);
        break;
      default:
        aba_joint_forward<3>(ws, b, bd.first_dof);
        break;
    }
  }
}

/// ABA passes 2 and 3 (kinematics must be current). Writes ws.ddq. With `armature` (num_joint_dofs
/// values >= 0, or nullptr for none) it solves (M + diag(armature)) ddq = tau - C instead: each
/// DOF's D = S^T IA S gets its armature added (Featherstone 2008, sec. 7.3; Pinocchio's
/// model.armature), which is how the rollout takes joint dampers implicitly (rollout_options::
/// implicit_joint_damping). nullptr leaves every operation as it was.
template <root_joint Root>
void aba_passes(const model<Root>& m, workspace<Root>& ws,
                const Eigen::Ref<const Eigen::VectorXd>& tau, const double* armature = nullptr) {
  auto& s = ws.scratch;
  if (s.joints.enabled) {
    aba_passes_by_joint(m, ws, tau, armature);
    return;
  }
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
    if (armature != nullptr && n > 0) s.Dacc[n] += armature[n - 1];
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
    const svec U = s.Uacc[n];             // == IA * S
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
  aba_root(m, ws, tau);  // and pass 3 (forward)
  for (int n = 1; n < nn; ++n) {
    const svec a = s.A[s.node_parent[n]] + s.C[n];
    const double qdd = s.Dinv[n] * (s.u[n] - sdot(s.U[n], a));
    ws.ddq[nvr + n - 1] = qdd;
    s.A[n] = a + s.S[n] * qdd;
  }
}

/// Planar fast path of ABA passes 1-3 (workspace.hpp, planar_scratch): the same recursion as
/// aba_passes on 3-vectors and symmetric 3x3 inertias, with the same look-ahead assembly of the
/// parent's U = IA S and D = S^T IA S in pass 2. Writes ws.ddq.
inline void aba_passes_planar(const model<planar_root>& m, workspace<planar_root>& ws,
                              const Eigen::Ref<const Eigen::VectorXd>& tau) {
  auto& s = ws.scratch;
  auto& P = s.planar;
  constexpr int nvr = planar_root::nv;
  const int nn = s.nj + 1;
  // Pass 1: IA = I, pA = v x* I v - f_ext (f_ext shifted from the body origin to the reference:
  // n_y + (rel x f)_y), and the node's own U = I S, D = S^T I S.
  for (int n = 0; n < nn; ++n) {
    const int b = s.node_body[n];
    if (b >= 0) {
      const psym& I = P.body_I[b];
      P.IA[n] = I;
      const vec6& fe = ws.f_ext[b];
      const vec3& r = s.body_rel[b];
      P.pA[n] = P.body_bias[b] - pvec(fe[1] + r.z() * fe[3] - r.x() * fe[5], fe[3], fe[5]);
      const pvec U = sym_mul(I, P.S[n]);
      P.U[n] = U;
      P.D[n] = P.S[n].dot(U);
    } else {
      P.IA[n] = psym{};
      P.pA[n].setZero();
      P.U[n].setZero();
      P.D[n] = 0.0;
    }
  }
  // Pass 2 (backward): Ia = IA - U D^-1 U^T, pa = pA + Ia c + U D^-1 u into the parent; the
  // parent's U and D get Ia S_p = X - U D^-1 Y and S_p^T Ia S_p = S_p^T X - D^-1 Y^2
  // (X = IA S_p, Y = U^T S_p) now, so only a multiply-add separates a division from the next.
  // Along a chain (parent n - 1, the next node visited) the parent's sums stay in registers
  // instead of a store and a reload on the critical path; the additions are the same, in the
  // same order, as accumulating in memory.
  for (int n = nn - 1; n >= 1; --n) {
    psym IA = P.IA[n];
    pvec pA = P.pA[n], U = P.U[n];
    double D = P.D[n];
    for (;; --n) {
      const pvec& S = P.S[n];
      const double Dinv = 1.0 / D;
      const double u = tau[nvr + n - 1] - S.dot(pA);
      P.U[n] = U;
      P.Dinv[n] = Dinv;
      P.u[n] = u;
      const int p = s.node_parent[n];
      const pvec DU = Dinv * U;
      psym Ia;
      Ia.a = IA.a - DU[0] * U[0];
      Ia.b = IA.b - DU[0] * U[1];
      Ia.c = IA.c - DU[0] * U[2];
      Ia.d = IA.d - DU[1] * U[1];
      Ia.e = IA.e - DU[1] * U[2];
      Ia.f = IA.f - DU[2] * U[2];
      const pvec dpA = pA + sym_mul(Ia, P.C[n]) + DU * u;
      if (p == 0) {
        P.pA[0] += dpA;
        P.IA[0] += Ia;
        break;
      }
      const pvec& Sp = P.S[p];
      const pvec X = sym_mul(IA, Sp);
      const double Y = U.dot(Sp);
      const pvec dU = X - DU * Y;
      const double dD = Sp.dot(X) - Dinv * (Y * Y);
      if (p != n - 1) {  // the chain ends: the parent is visited later, from memory
        P.pA[p] += dpA;
        P.U[p] += dU;
        P.D[p] += dD;
        P.IA[p] += Ia;
        break;
      }
      pA = P.pA[p] + dpA;
      U = P.U[p] + dU;
      D = P.D[p] + dD;
      psym IAp = P.IA[p];
      IAp += Ia;
      IA = IAp;
    }
  }
  // Root: S0 maps (x, z, pitch) to the planar components (1, 2, 0), so S0^T IA0 S0 is IA0 with
  // rows and columns permuted; solve it (3x3, symmetric positive definite) by LDL^T.
  const pvec a_pre = pvec(0.0, -m.gravity.x(), -m.gravity.z()) + P.C[0];
  const psym& I0 = P.IA[0];
  const pvec f0 = P.pA[0] + sym_mul(I0, a_pre);
  const double D00 = I0.d, D10 = I0.e, D11 = I0.f, D20 = I0.b, D21 = I0.c, D22 = I0.a;
  const double r0 = tau[0] - f0[1], r1 = tau[1] - f0[2], r2 = tau[2] - f0[0];
  const double d0 = D00;
  const double l10 = D10 / d0, l20 = D20 / d0;
  const double d1 = D11 - l10 * D10;
  const double l21 = (D21 - l20 * D10) / d1;
  const double d2 = D22 - l20 * D20 - l21 * l21 * d1;
  const double y1 = r1 - l10 * r0, y2 = r2 - l20 * r0 - l21 * y1;
  const double x2 = y2 / d2;
  const double x1 = y1 / d1 - l21 * x2;
  const double x0 = r0 / d0 - l10 * x1 - l20 * x2;
  ws.ddq[0] = x0;
  ws.ddq[1] = x1;
  ws.ddq[2] = x2;
  P.A[0] = a_pre + pvec(x2, x0, x1);
  // Pass 3 (forward).
  // Along a chain the parent's acceleration stays in a register.
  pvec A_prev = P.A[0];
  for (int n = 1; n < nn; ++n) {
    const int p = s.node_parent[n];
    pvec a;
    if (p == n - 1)
      a = A_prev + P.C[n];
    else
      a = P.A[p] + P.C[n];
    const double qdd = P.Dinv[n] * (P.u[n] - P.U[n].dot(a));
    ws.ddq[nvr + n - 1] = qdd;
    A_prev = a + P.S[n] * qdd;
    P.A[n] = A_prev;
  }
}

/// ABA for the (q, v) the workspace's kinematics are current for (the caller guarantees it: the
/// rollout loop, which just ran forward_kinematics on the state it integrates). \returns ws.ddq
template <root_joint Root>
const Eigen::VectorXd& aba_with_current_kinematics(const model<Root>& m, workspace<Root>& ws,
                                                   const Eigen::Ref<const Eigen::VectorXd>& tau) {
  if constexpr (std::is_same_v<Root, planar_root>) {
    if (ws.scratch.planar.enabled) {
      aba_passes_planar(m, ws, tau);
      return ws.ddq;
    }
  }
  aba_passes(m, ws, tau);
  return ws.ddq;
}

/// The same with an armature per joint DOF (aba_passes), on the general path only: the caller
/// makes sure the workspace does not run the planar fast path (disable_planar_path).
template <root_joint Root>
const Eigen::VectorXd& aba_with_current_kinematics(const model<Root>& m, workspace<Root>& ws,
                                                   const Eigen::Ref<const Eigen::VectorXd>& tau,
                                                   const double* armature) {
  aba_passes(m, ws, tau, armature);
  return ws.ddq;
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
  detail::ensure_kinematics_fast(m, ws, q, v);
  if constexpr (std::is_same_v<Root, planar_root>) {
    if (ws.scratch.planar.enabled) {
      detail::aba_passes_planar(m, ws, tau);
      return ws.ddq;
    }
  }
  detail::aba_passes(m, ws, tau);
  return ws.ddq;
}

/// Forward dynamics with an armature a (num_joint_dofs values >= 0, kg m^2 for a hinge): solves
/// (M(q) + diag(0_root, a)) ddq = tau - C(q, v) (gravity, external wrenches), M the joint-space
/// inertia. With a_j = dt kd_j, that is one step of a joint damper kd taken implicitly
/// (backward Euler: the damper's torque -kd (v + dt ddq)), stable for any kd, in any
/// configuration. The general path only: \throws std::invalid_argument if ws runs the planar fast
/// path (disable_planar_path(ws) first), a size is wrong or an armature entry is negative or not
/// finite. \returns ws.ddq
template <root_joint Root>
const Eigen::VectorXd& aba(const model<Root>& m, workspace<Root>& ws,
                           const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v,
                           const Eigen::Ref<const Eigen::VectorXd>& tau,
                           const Eigen::Ref<const Eigen::VectorXd>& armature) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::check_v(m, tau, "tau (generalized forces)");
  check_size(armature.size(), m.num_joint_dofs(), "armature (one value per joint DOF)");
  for (Eigen::Index j = 0; j < armature.size(); ++j)
    check_argument(std::isfinite(armature[j]) && armature[j] >= 0.0, "armature of DOF ", j,
                   " must be finite and >= 0, got ", armature[j]);
  check_argument(!detail::planar_path(ws),
                 "aba with an armature runs the general path: call disable_planar_path(ws) first");
  detail::ensure_kinematics_fast(m, ws, q, v);
  detail::aba_passes(m, ws, tau, armature.data());
  return ws.ddq;
}

}  // namespace gaitsynth
