#pragma once
/// \file controllers/end_effector/null_space_damper.hpp
/// Ours, not the paper's: a spring and damper on the joint motions that move no frame, null(J).
///
/// Why. J^T f reaches rank J = 12 of the 17 joint DOFs of the Table 3 biped; the other 5 (the
/// pelvis rolling about the hip axis, whose COM sits on that axis, and each knee swiveling about
/// the hip-ankle line) get no torque from eq. 5 and would drift. The paper does not say what holds
/// them in PhysX. We ask for the joint accelerations
///
///   ddq_n = P (-kp q - kd v),   P = N N^T, N an orthonormal basis of null(J) (nj x (nj - rank J)),
///
/// (q, v the joint angles and rates; kp in 1/s^2, kd in 1/s) and produce them with the torque
///
///   tau_n = S ddq_n,   S = M_jj - M_jr M_rr^-1 M_rj,
///
/// S the joint-space inertia with the root free (the Schur complement of the root block of M, so
/// that (M^-1)_jj = S^-1 and tau_n alone accelerates the joints by exactly ddq_n). So tau_n moves
/// no frame relative to the upper body (dynamically consistent, Khatib 1987), leaving the frames
/// to eq. 5, and each null-space mode is a unit-mass spring-damper whatever its inertia: the
/// explicit step is stable while h kd < 2 (h the time between commands).
///
/// Why not the simpler designs (docs/reproductions/wu2010.md, "the ankle chatter"). (1) An earlier
/// version sent -kp q - kd v (N m/rad, N m s/rad) through appendix B's canceling QP with the knee
/// torque; its force bound saturates when the spring is stretched, and then the whole damper leaks
/// onto every joint: on the foot's roll (ankle_x, M^-1 entry ~630 / kg m^2) kd = 20 N m s/rad at
/// 2400 Hz gives h kd M^-1 = 5.3 > 2, and the explicit step reverses the foot's roll rate every
/// step, growing. (2) The torque P (-kp q - kd v) without S stays in null(J) but its ankle
/// components still spin a light swing foot: the swing ankle's roll and yaw diverged the same way.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/QR>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// Scratch for null_space_spring_damper, sized once (no allocation per tick).
struct null_space_workspace {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;  ///< of J^T (nj x K3)
  Eigen::MatrixXd Q;                               ///< nj x nj: [range(J^T) | null(J)]
  Eigen::LLT<Eigen::MatrixXd> root_llt;            ///< of M_rr (nr x nr)
  Eigen::MatrixXd Mrr, Mrj_solved, S;              ///< nr x nr, nr x nj (M_rr^-1 M_rj), nj x nj
  Eigen::VectorXd hh_work, accel, coords, tau;     ///< nj each
  Eigen::Index rank = 0;

  null_space_workspace() = default;
  /// For a J of K3 rows, nj joint DOFs and a root of nr velocity DOFs.
  null_space_workspace(Eigen::Index K3, Eigen::Index nj, Eigen::Index nr)
      : qr(nj, K3),
        Q(Eigen::MatrixXd::Identity(nj, nj)),
        root_llt(nr),
        Mrr(Eigen::MatrixXd::Identity(nr, nr)),
        Mrj_solved(Eigen::MatrixXd::Zero(nr, nj)),
        S(Eigen::MatrixXd::Zero(nj, nj)),
        hh_work(Eigen::VectorXd::Zero(nj)),
        accel(Eigen::VectorXd::Zero(nj)),
        coords(Eigen::VectorXd::Zero(nj)),
        tau(Eigen::VectorXd::Zero(nj)) {}
};

/// tau_n = S P (-kp q_j - kd v_j) (file comment) from J (K3 x nj), the joint-space inertia M
/// (nv x nv, the root's nr = nv - nj DOFs first), the joint angles q_j and rates v_j (nj each).
/// `rank_tolerance` is the relative pivot below which J^T's QR counts a column dependent
/// (force_qp_options::rank_tolerance). Returns a reference into ws (ws.tau); ws.accel holds ddq_n.
/// \throws std::invalid_argument for sizes that do not match the workspace.
inline const Eigen::VectorXd& null_space_spring_damper(const Eigen::Ref<const Eigen::MatrixXd>& J,
                                                       const Eigen::Ref<const Eigen::MatrixXd>& M,
                                                       const Eigen::Ref<const Eigen::VectorXd>& q_j,
                                                       const Eigen::Ref<const Eigen::VectorXd>& v_j,
                                                       double kp, double kd, double rank_tolerance,
                                                       null_space_workspace& ws) {
  const Eigen::Index nj = J.cols(), nr = ws.Mrr.rows();
  check_argument(ws.Q.rows() == nj && ws.qr.cols() == J.rows() && M.rows() == nr + nj &&
                     M.cols() == nr + nj && q_j.size() == nj && v_j.size() == nj,
                 "null_space_spring_damper: J is ", J.rows(), " x ", nj, ", M ", M.rows(), " x ",
                 M.cols(), ", q and v have ", q_j.size(), " and ", v_j.size(),
                 " entries; the workspace is for a ", ws.qr.cols(), " x ", ws.Q.rows(), " J and ",
                 nr, " root DOFs");
  ws.qr.setThreshold(rank_tolerance);
  ws.qr.compute(J.transpose());
  ws.rank = ws.qr.rank();
  ws.qr.householderQ().evalTo(ws.Q, ws.hh_work);
  const Eigen::Index n_null = nj - ws.rank;
  ws.accel = -kp * q_j - kd * v_j;
  auto N = ws.Q.rightCols(n_null);
  auto c = ws.coords.head(n_null);
  c.noalias() = N.transpose() * ws.accel;
  ws.accel.noalias() = N * c;
  // S = M_jj - M_jr M_rr^-1 M_rj
  ws.S = M.bottomRightCorner(nj, nj);
  if (nr > 0) {
    ws.Mrr = M.topLeftCorner(nr, nr);
    ws.root_llt.compute(ws.Mrr);
    ws.Mrj_solved = M.topRightCorner(nr, nj);
    ws.root_llt.solveInPlace(ws.Mrj_solved);
    ws.S.noalias() -= M.bottomLeftCorner(nj, nr) * ws.Mrj_solved;
  }
  ws.tau.noalias() = ws.S * ws.accel;
  return ws.tau;
}

}  // namespace gaitsynth
