#pragma once
/// \file aba_by_joint.hpp
/// ABA passes 1-3 with each body's DOFs taken together as one joint of 1 to 3 DOFs (Featherstone
/// 2008, Table 7.1, a joint with a 6 x k motion subspace S): a hip's three DOFs cost one rank-3
/// update of the articulated inertia and one 3 x 3 inverse instead of three rank-1 updates and
/// three divisions in a row through two massless intermediate bodies (aba.hpp, aba_passes). The
/// same recursion in the same frame (world axes about the root origin), so the accelerations
/// agree with the single-DOF passes to rounding (tests/dynamics/aba.cpp).
#include <array>

#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth::detail {

/// The inverse of a k x k symmetric positive definite matrix (k <= 3; row-major, by cofactors).
template <int K>
inline std::array<double, 9> inverse_spd_small(const double (&D)[K][K]) {
  std::array<double, 9> X{};
  if constexpr (K == 1) {
    X[0] = 1.0 / D[0][0];
  } else if constexpr (K == 2) {
    const double r = 1.0 / (D[0][0] * D[1][1] - D[0][1] * D[0][1]);
    X[0] = D[1][1] * r;
    X[1] = X[2] = -D[0][1] * r;
    X[3] = D[0][0] * r;
  } else {
    const double a = D[0][0], b = D[0][1], c = D[0][2], d = D[1][1], e = D[1][2], f = D[2][2];
    const double A00 = d * f - e * e, A01 = c * e - b * f, A02 = b * e - c * d;
    const double r = 1.0 / (a * A00 + b * A01 + c * A02);
    X[0] = A00 * r;
    X[1] = X[3] = A01 * r;
    X[2] = X[6] = A02 * r;
    X[4] = (a * f - c * c) * r;
    X[5] = X[7] = (b * c - a * e) * r;
    X[8] = (a * d - b * b) * r;
  }
  return X;
}

/// Pass 2 for body b, whose K DOFs are first, ..., first + K - 1 (nodes first + 1 ... first + K;
/// its inertia and its children's sit at node first + K): U = IA S, D = S^T IA S (+ armature),
/// u = tau - S^T pA, then Ia = IA - U D^-1 U^T and pa = pA + IA c + U D^-1 (u - U^T c) into the
/// parent, c the joint's velocity-product acceleration (the sum of its nodes').
template <int K, root_joint Root>
inline void aba_joint_backward(workspace<Root>& ws, int b, int first,
                               const Eigen::Ref<const Eigen::VectorXd>& tau,
                               const double* armature) {
  auto& s = ws.scratch;
  auto& J = s.joints;
  constexpr int nvr = Root::nv;
  const int n = first + K;
  const int p = s.node_parent[first + 1];
  const smat& IA = s.IA[n];
  const svec& pA = s.pA[n];
  svec c = s.C[first + 1];
  for (int k = 1; k < K; ++k) c += s.C[first + 1 + k];
  std::array<svec, 3>& U = J.U[b];
  double D[K][K];
  double w[K];
  for (int k = 0; k < K; ++k) U[k] = op_times(IA, s.S[first + 1 + k]);
  for (int i = 0; i < K; ++i) {
    const svec& Si = s.S[first + 1 + i];
    for (int k = 0; k <= i; ++k) D[i][k] = D[k][i] = sdot(Si, U[k]);
    if (armature != nullptr) D[i][i] += armature[first + i];
    J.u[b][i] = tau[nvr + first + i] - sdot(Si, pA);
    w[i] = J.u[b][i] - sdot(U[i], c);
  }
  const std::array<double, 9> Di = inverse_spd_small<K>(D);
  J.Dinv[b] = Di;
  J.c[b] = c;
  // U D^-1, column by column.
  std::array<svec, K> UD;
  for (int k = 0; k < K; ++k) {
    UD[k] = U[0] * Di[k];
    for (int i = 1; i < K; ++i) UD[k] += U[i] * Di[i * K + k];
  }
  svec dp = pA + op_times(IA, c);
  for (int k = 0; k < K; ++k) dp += UD[k] * w[k];
  s.pA[p] += dp;
  smat& IAp = s.IA[p];
  for (int col = 0; col < 6; ++col) {
    svec x = IA[col] - UD[0] * U[0][col];
    for (int k = 1; k < K; ++k) x -= UD[k] * U[k][col];
    IAp[col] += x;
  }
}

/// Pass 3 for body b: a' = a_parent + c, qdd = D^-1 (u - U^T a'), a = a' + S qdd.
template <int K, root_joint Root>
inline void aba_joint_forward(workspace<Root>& ws, int b, int first) {
  auto& s = ws.scratch;
  const auto& J = s.joints;
  constexpr int nvr = Root::nv;
  const svec a = s.A[s.node_parent[first + 1]] + J.c[b];
  double r[K];
  for (int i = 0; i < K; ++i) r[i] = J.u[b][i] - sdot(J.U[b][i], a);
  svec an = a;
  for (int i = 0; i < K; ++i) {
    double qdd = 0.0;
    for (int k = 0; k < K; ++k) qdd += J.Dinv[b][i * K + k] * r[k];
    ws.ddq[nvr + first + i] = qdd;
    an += s.S[first + 1 + i] * qdd;
  }
  s.A[first + K] = an;
}

}  // namespace gaitsynth::detail
