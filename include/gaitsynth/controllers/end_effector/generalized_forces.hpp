#pragma once
/// \file controllers/end_effector/generalized_forces.hpp
/// Wu & Popovic 2010, Sec. 6.1 and eq. 4: the generalized state x = (p_ij) of the K frame pairs,
/// its Jacobian J = dx/dtheta over the joint angles (not the root), tau = J^T f, and the matrix A
/// and vector b of eq. 4 (A f = b: the pair forces reproduce the ideal wrenches).
///
/// The paper's root is the upper body, and "we do not compute the Jacobian with respect to
/// p_root or theta_root": J is dx/dtheta with the upper body held still, which is the velocity of
/// the action frame's origin relative to the upper body. Our model's root is the hip link, so
/// row block k is J_b(p_j) - J_ub(p_j) (joint columns): the point Jacobian of the action frame on
/// its link minus that of the upper body's point that coincides with p_j. Both share the root's
/// columns, which cancel, so the result does not depend on which body is the root. Pair k applies
/// f_k at p_j on the action link and -f_k on the upper body (at p_i with the moment
/// (p_j - p_i) x -f_k, Sec. 6.2: the same as -f_k at p_j); the pair is in equilibrium, so its
/// generalized forces on the root vanish and those on the joints are J^T f
/// (tests/controllers/end_effector_jacobian.cpp checks both through RNEA with external wrenches).
#include <Eigen/Core>

#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/pd_forces.hpp"
#include "gaitsynth/dynamics/jacobian.hpp"

namespace gaitsynth {

/// J (3K x nj) at configuration q: row block k is relative_point_jacobian of action frame k's
/// point on its link with respect to the upper body (dynamics/jacobian.hpp). Poses in `ws` are
/// reused when current for q.
template <root_joint Root>
void pair_jacobian(const model<Root>& m, workspace<Root>& ws,
                   const Eigen::Ref<const Eigen::VectorXd>& q, const end_effector_layout& L,
                   Eigen::Ref<Eigen::MatrixXd> J) {
  const int nj = m.num_joint_dofs(), K = L.num_pairs();
  check_argument(J.rows() == 3 * K && J.cols() == nj, "pair_jacobian: J must be ", 3 * K, " x ", nj,
                 ", got ", J.rows(), " x ", J.cols());
  const int ub = L.link_body[0];
  forward_kinematics(m, ws, q);
  for (int k = 0; k < K; ++k) {
    const action_frame& a = L.action[k];
    relative_point_jacobian(m, ws, q, L.link_body[a.link], a.point, ub, J.middleRows(3 * k, 3));
  }
}

/// Rows of eq. 4: [f_0 (3) | f_1 .. f_N (3 each) | tau_0 (3)], one reaction frame (M = 1).
inline Eigen::Index wrench_rows(const end_effector_layout& L) {
  return 3 * L.num_action() + 6;
}
/// Row of action frame j's first force entry in A and b.
inline Eigen::Index action_row(int j) {
  return 3 + 3 * static_cast<Eigen::Index>(j);
}

/// Eq. 4's A ((3N + 6) x 3K) and b. Pair k (reaction frame 0, action frame k): -f_k on the
/// reaction force rows, +f_k on frame k's rows, (p_k - p_0) x -f_k on the reaction torque rows.
inline void assemble_eq4(const end_effector_layout& L, const frame_states& s,
                         const ideal_wrenches& w, Eigen::Ref<Eigen::MatrixXd> A,
                         Eigen::Ref<Eigen::VectorXd> b) {
  const int N = L.num_action(), K = L.num_pairs();
  const Eigen::Index rows = wrench_rows(L), tr = rows - 3;
  check_argument(A.rows() == rows && A.cols() == 3 * K && b.size() == rows,
                 "assemble_eq4: A must be ", rows, " x ", 3 * K, " and b ", rows, ", got ",
                 A.rows(), " x ", A.cols(), " and ", b.size());
  A.setZero();
  for (int k = 0; k < K; ++k) {
    const Eigen::Index c = 3 * k;
    A.block<3, 3>(0, c) = -mat3::Identity();
    A.block<3, 3>(action_row(k), c) = mat3::Identity();
    const vec3 d = s.position[k] - s.reaction_position;
    // (d x -f) = -[d]x f
    A.block<3, 3>(tr, c) << 0.0, d.z(), -d.y(), -d.z(), 0.0, d.x(), d.y(), -d.x(), 0.0;
  }
  b.head<3>() = w.reaction_force;
  for (int j = 0; j < N; ++j) b.segment<3>(action_row(j)) = w.action_force[j];
  b.tail<3>() = w.reaction_torque;
}

}  // namespace gaitsynth
