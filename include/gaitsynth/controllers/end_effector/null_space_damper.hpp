#pragma once
/// \file controllers/end_effector/null_space_damper.hpp
/// Ours, not the paper's: a spring and damper on the joint motions that move no frame, null(J).
///
/// Why. J^T f reaches rank J = 12 of the 17 joint DOFs of the Table 3 biped; the other 5 (the
/// pelvis rolling about the hip axis, whose COM sits on that axis, and each knee swiveling about
/// the hip-ankle line) get no torque from eq. 5 and would drift. The paper does not say what holds
/// them in PhysX. We ask for the joint accelerations
///
///   ddq_n = P (-kp q - kd v),   P the orthogonal projector on null(J),
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
/// Why not the simpler designs (docs/reproductions/wu2010.md, "Why it does not walk"). (1) An
/// earlier version sent -kp q - kd v (N m/rad, N m s/rad) through appendix B's canceling QP with
/// the knee torque; its force bound saturates when the spring is stretched, and then the whole
/// damper leaks onto every joint: on the foot's roll (ankle_x, M^-1 entry ~630 / kg m^2) kd = 20 N
/// m s/rad at 2400 Hz gives h kd M^-1 = 5.3 > 2, and the explicit step reverses the foot's roll
/// rate every step, growing. (2) The torque P (-kp q - kd v) without S stays in null(J) but its
/// ankle components still spin a light swing foot: the swing ankle's roll and yaw diverged the same
/// way.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// Scratch for null_space_spring_damper, sized once (no allocation per tick).
struct null_space_workspace {
  Eigen::MatrixXd gram;                ///< n x n (top-left rank x rank used): V^T V
  Eigen::MatrixXd Mrr, Mrj_solved, S;  ///< nr x nr, nr x nj (M_rr^-1 M_rj), nj x nj
  Eigen::VectorXd accel, coords, tau;  ///< nj, n, nj

  null_space_workspace() = default;
  /// For nj joint DOFs, a root of nr velocity DOFs and a range basis of up to n columns.
  null_space_workspace(Eigen::Index nj, Eigen::Index nr, Eigen::Index n)
      : gram(Eigen::MatrixXd::Zero(n, n)),
        Mrr(Eigen::MatrixXd::Identity(nr, nr)),
        Mrj_solved(Eigen::MatrixXd::Zero(nr, nj)),
        S(Eigen::MatrixXd::Zero(nj, nj)),
        accel(Eigen::VectorXd::Zero(nj)),
        coords(Eigen::VectorXd::Zero(n)),
        tau(Eigen::VectorXd::Zero(nj)) {}
};

/// tau_n = S P (-kp q_j - kd v_j) (file comment). V (nj x rank) spans range(J^T), the joint
/// torques J^T f can make: force_qp_workspace's J^T U, its first `rank` columns (its QR of J
/// decides the rank, as for eq. 5), so P = I - V (V^T V)^-1 V^T. M is the joint-space inertia
/// (nv x nv, the root's nr = nv - nj DOFs first); q_j, v_j the joint angles and rates. Returns a
/// reference into ws (ws.tau); ws.accel holds the accelerations P (-kp q_j - kd v_j).
/// \throws std::invalid_argument for sizes that do not match the workspace.
inline const Eigen::VectorXd& null_space_spring_damper(const Eigen::Ref<const Eigen::MatrixXd>& V,
                                                       const Eigen::Ref<const Eigen::MatrixXd>& M,
                                                       const Eigen::Ref<const Eigen::VectorXd>& q_j,
                                                       const Eigen::Ref<const Eigen::VectorXd>& v_j,
                                                       double kp, double kd,
                                                       null_space_workspace& ws) {
  const Eigen::Index nj = ws.S.rows(), nr = ws.Mrr.rows(), r = V.cols();
  check_argument(V.rows() == nj && r <= ws.gram.rows() && M.rows() == nr + nj &&
                     M.cols() == nr + nj && q_j.size() == nj && v_j.size() == nj,
                 "null_space_spring_damper: V is ", V.rows(), " x ", r, ", M ", M.rows(), " x ",
                 M.cols(), ", q and v have ", q_j.size(), " and ", v_j.size(),
                 " entries; the workspace is for ", nj, " joint DOFs, ", nr,
                 " root DOFs and up to ", ws.gram.rows(), " columns");
  ws.accel = -kp * q_j - kd * v_j;
  if (r > 0) {  // accel -= V (V^T V)^-1 V^T accel, the Cholesky factor in place (no allocation)
    auto G = ws.gram.topLeftCorner(r, r);
    G.noalias() = V.transpose() * V;
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(G);
    auto c = ws.coords.head(r);
    c.noalias() = V.transpose() * ws.accel;
    llt.solveInPlace(c);
    ws.accel.noalias() -= V * c;
  }
  // S = M_jj - M_jr M_rr^-1 M_rj
  ws.S = M.bottomRightCorner(nj, nj);
  if (nr > 0) {
    ws.Mrr = M.topLeftCorner(nr, nr);
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> root(ws.Mrr);
    ws.Mrj_solved = M.topRightCorner(nr, nj);
    root.solveInPlace(ws.Mrj_solved);
    ws.S.noalias() -= M.bottomLeftCorner(nj, nr) * ws.Mrj_solved;
  }
  ws.tau.noalias() = ws.S * ws.accel;
  return ws.tau;
}

}  // namespace gaitsynth
