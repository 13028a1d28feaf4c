#pragma once
/// \file controllers/end_effector/force_qp.hpp
/// The per-tick QP of Wu & Popovic 2010, eq. 5, with Sec. 6.3's pinned frames, and the canceling
/// QP of appendix B's eq. 12:
///
///   min_f ||A f - b||_W^2   s.t.  -f_max <= f <= f_max (5b),  -tau_max <= J^T f <= tau_max (5c),
///                                 Z^T f = 0 (5d: Z's columns span null(J^T))
///
/// with the rows of every pinned action frame removed from A and b (Sec. 6.3).
///
/// Formulation solved (equivalent, cheaper). (5d) says f lies in range(J). A column-pivoted QR of
/// J (3K x nj) gives an orthonormal basis U (3K x r, r = rank J) of range(J) and Z (the other
/// 3K - r columns of Q) of null(J^T). Writing f = U c, (5d) holds by construction and ||f|| =
/// ||c||, so eq. 5 becomes a QP in c with r unknowns and no equality rows instead of 3K unknowns
/// and 3K - r equality rows (for the Table 3 biped r = 12 of 24: the feet have 12 DOF relative
/// to the upper body, and 5 of the 17 joint DOFs (pelvis roll about the hip axis, each knee's
/// swivel) move no frame). c is padded to n = min(3K, nj) unknowns so that the sizes never change
/// with the rank; the padded unknowns have zero columns and are held at 0 by the term below.
/// tests/controllers/end_effector_qp.cpp solves the original eq. 5 and compares.
///
/// Regularization. The Hessian U^T A^T W A U is singular whenever rows are removed: with both
/// feet pinned only the upper body's 6 rows remain for r = 12 unknowns, and how the legs share the
/// upper body's force is left open. We add lambda ||f||^2 (= lambda ||c||^2) with lambda =
/// `regularization` x max(largest diagonal entry of the Hessian, 1): among the forces that
/// reproduce the ideal wrenches equally well it picks the smallest (the least-norm least-squares
/// answer, as a pseudo-inverse would), and when the Hessian is regular it moves the answer by a
/// relative amount of order lambda / its smallest eigenvalue. The default 1e-6 keeps the Cholesky
/// factor of qp/goldfarb_idnani.hpp well above its pivot floor (n eps times the largest diagonal
/// entry, ~4e-15 relative).
#include <Eigen/Core>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <vector>

#include "gaitsynth/controllers/end_effector/generalized_forces.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/qp/goldfarb_idnani.hpp"

namespace gaitsynth {

struct force_qp_options {
  double f_max = 2000.0;          ///< eq. 5b, per entry of f (N)
  double regularization = 1e-6;   ///< relative lambda (file comment)
  double rank_tolerance = 1e-10;  ///< relative pivot below which J's QR counts a column dependent
};

/// Scratch and results, sized once for a layout and a model (no allocation per tick).
struct force_qp_workspace {
  Eigen::Index K3 = 0, nj = 0, n = 0, rows_full = 0;
  Eigen::MatrixXd A;   ///< eq. 4's A (rows_full x 3K), all rows
  Eigen::VectorXd b;   ///< rows_full
  Eigen::VectorXd w;   ///< W's diagonal, all rows
  Eigen::MatrixXd Ar;  ///< A without the pinned frames' rows (the first `rows` rows are used)
  Eigen::VectorXd br, wr;
  Eigen::Index rows = 0;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  Eigen::MatrixXd Q;        ///< 3K x 3K: [U | Z]
  Eigen::VectorXd hh_work;  ///< Householder scratch
  Eigen::Index rank = 0;
  Eigen::MatrixXd U;    ///< 3K x n: range(J)'s basis, zero past column rank
  Eigen::MatrixXd JtU;  ///< nj x n: J^T U
  Eigen::MatrixXd AU;   ///< rows_full x n (top `rows` rows used), W^1/2 Ar U
  dense_qp qp;          ///< eq. 5 in c
  qp_workspace qp_ws;
  dense_qp cancel;  ///< appendix B's canceling program in c
  qp_workspace cancel_ws;
  Eigen::VectorXd f;          ///< 3K: the generalized forces
  Eigen::VectorXd tau;        ///< nj: J^T f
  Eigen::VectorXd f_theta;    ///< 3K: appendix B's f_theta
  Eigen::VectorXd tau_extra;  ///< nj: tau_theta + J^T f_theta
  qp_status status = qp_status::optimal;
  qp_status cancel_status = qp_status::optimal;

  force_qp_workspace() = default;
  /// For K pairs, N action frames and nj joint DOFs.
  force_qp_workspace(int K, int N, int nj_)
      : K3(3 * K), nj(nj_), n(std::min<Eigen::Index>(3 * K, nj_)), rows_full(3 * N + 6) {
    check_argument(K >= 1 && N >= 1 && nj_ >= 1, "force_qp_workspace: need K, N, nj >= 1, got ", K,
                   ", ", N, ", ", nj_);
    A.setZero(rows_full, K3);
    b.setZero(rows_full);
    w.setOnes(rows_full);
    Ar.setZero(rows_full, K3);
    br.setZero(rows_full);
    wr.setZero(rows_full);
    qr = Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(K3, nj);
    Q.setIdentity(K3, K3);
    hh_work.setZero(K3);
    U.setZero(K3, n);
    JtU.setZero(nj, n);
    AU.setZero(rows_full, n);
    qp = make_dense_qp(n, 0, K3 + nj);
    qp_ws = qp_workspace(n, 0, K3 + nj);
    cancel = make_dense_qp(n, 0, K3);
    cancel_ws = qp_workspace(n, 0, K3);
    f.setZero(K3);
    tau.setZero(nj);
    f_theta.setZero(K3);
    tau_extra.setZero(nj);
  }
};

/// U, Z (ws.Q) and J^T U from J (3K x nj).
inline void factor_pair_jacobian(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                 const force_qp_options& opt, force_qp_workspace& ws) {
  check_argument(J.rows() == ws.K3 && J.cols() == ws.nj, "factor_pair_jacobian: J must be ", ws.K3,
                 " x ", ws.nj, ", got ", J.rows(), " x ", J.cols());
  ws.qr.setThreshold(opt.rank_tolerance);
  ws.qr.compute(J);
  ws.rank = std::min<Eigen::Index>(ws.qr.rank(), ws.n);
  ws.qr.householderQ().evalTo(ws.Q, ws.hh_work);
  ws.U.setZero();
  ws.U.leftCols(ws.rank) = ws.Q.leftCols(ws.rank);
  ws.JtU.noalias() = J.transpose() * ws.U;
}

/// Adds the file comment's lambda = regularization x max(largest diagonal entry, 1) to H's diagonal
/// (both QPs here use the one rule).
inline void add_regularization(Eigen::MatrixXd& H, const force_qp_options& opt) {
  H.diagonal().array() += opt.regularization * std::max(H.diagonal().maxCoeff(), 1.0);
}

/// Eq. 5 after factor_pair_jacobian. A and b are ws.A and ws.b (assemble_eq4), W's diagonal is
/// ws.w; pinned[j] != 0 removes action frame j's rows (Sec. 6.3); tau_max has nj entries (> 0).
/// Writes ws.f and ws.tau = J^T f; returns the status (on failure f and tau are zero).
inline qp_status solve_force_qp(std::span<const unsigned char> pinned,
                                const Eigen::Ref<const Eigen::VectorXd>& tau_max,
                                const force_qp_options& opt, force_qp_workspace& ws) {
  const Eigen::Index N = (ws.rows_full - 6) / 3;
  check_size(static_cast<std::ptrdiff_t>(pinned.size()), N, "solve_force_qp: pinned flags");
  check_size(tau_max.size(), ws.nj, "solve_force_qp: tau_max");
  // Sec. 6.3: keep the upper body's rows and the rows of every frame that is not pinned.
  Eigen::Index r = 0;
  auto keep = [&](Eigen::Index row) {
    ws.Ar.row(r) = ws.A.row(row);
    ws.br[r] = ws.b[row];
    ws.wr[r] = ws.w[row];
    ++r;
  };
  for (Eigen::Index i = 0; i < 3; ++i) keep(i);
  for (Eigen::Index j = 0; j < N; ++j)
    if (!pinned[static_cast<std::size_t>(j)])
      for (Eigen::Index i = 0; i < 3; ++i) keep(action_row(static_cast<int>(j)) + i);
  for (Eigen::Index i = ws.rows_full - 3; i < ws.rows_full; ++i) keep(i);
  ws.rows = r;

  // ||A U c - b||_W^2 = c' (AU)' W (AU) c - 2 b' W (AU) c + const: H = (W^1/2 AU)' (W^1/2 AU),
  // g = -(W^1/2 AU)' W^1/2 b (the factor 2 dropped).
  auto AU = ws.AU.topRows(r);
  AU.noalias() = ws.Ar.topRows(r) * ws.U;
  for (Eigen::Index i = 0; i < r; ++i) {
    const double s = std::sqrt(ws.wr[i]);
    AU.row(i) *= s;
    ws.br[i] *= s;
  }
  dense_qp& qp = ws.qp;
  qp.H.noalias() = AU.transpose() * AU;
  qp.g.noalias() = -AU.transpose() * ws.br.head(r);
  add_regularization(qp.H, opt);
  qp.C.topRows(ws.K3) = ws.U;
  qp.C.bottomRows(ws.nj) = ws.JtU;
  qp.c_lower.head(ws.K3).setConstant(-opt.f_max);
  qp.c_upper.head(ws.K3).setConstant(opt.f_max);
  qp.c_lower.tail(ws.nj) = -tau_max;
  qp.c_upper.tail(ws.nj) = tau_max;
  const qp_result& res = solve_qp(qp, ws.qp_ws);
  ws.status = res.status;
  if (res.status != qp_status::optimal) {
    ws.f.setZero();
    ws.tau.setZero();
    return ws.status;
  }
  ws.f.noalias() = ws.U * res.x;
  ws.tau.noalias() = ws.JtU * res.x;
  return ws.status;
}

/// Appendix B's canceling QP after factor_pair_jacobian: f_theta minimizing
/// ||tau_theta + J^T f_theta||^2 with -f_max <= f_theta <= f_max and f_theta in range(J) (as f),
/// regularized as eq. 5. Writes ws.f_theta and ws.tau_extra = tau_theta + J^T f_theta (eq. 12's
/// bracket): the part of tau_theta that the frames' forces cannot cancel, near the singular knee
/// only what the force bound leaves. A zero tau_theta skips the solve.
inline qp_status solve_canceling_qp(const Eigen::Ref<const Eigen::VectorXd>& tau_theta,
                                    const force_qp_options& opt, force_qp_workspace& ws) {
  check_size(tau_theta.size(), ws.nj, "solve_canceling_qp: tau_theta");
  if (tau_theta.isZero(0.0)) {
    ws.f_theta.setZero();
    ws.tau_extra.setZero();
    return ws.cancel_status = qp_status::optimal;
  }
  dense_qp& qp = ws.cancel;
  qp.H.noalias() = ws.JtU.transpose() * ws.JtU;
  qp.g.noalias() = ws.JtU.transpose() * tau_theta;
  add_regularization(qp.H, opt);
  qp.C = ws.U;
  qp.c_lower.setConstant(-opt.f_max);
  qp.c_upper.setConstant(opt.f_max);
  const qp_result& res = solve_qp(qp, ws.cancel_ws);
  ws.cancel_status = res.status;
  if (res.status != qp_status::optimal) {
    ws.f_theta.setZero();
    ws.tau_extra.setZero();
    return ws.cancel_status;
  }
  ws.f_theta.noalias() = ws.U * res.x;
  ws.tau_extra = tau_theta;
  ws.tau_extra.noalias() += ws.JtU * res.x;
  return ws.cancel_status;
}

}  // namespace gaitsynth
