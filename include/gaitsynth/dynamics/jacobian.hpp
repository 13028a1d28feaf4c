#pragma once
/// \file jacobian.hpp
/// Point and orientation Jacobians in the world frame (Featherstone 2008, sec. 4.1, eq. 4.17 for
/// the body Jacobian; here only the ancestors' columns are non-zero).
#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

namespace detail {
/// Column of a motion axis S about the reference point: the velocity of the point r is
/// S.lin + S.ang x r.
inline vec3 point_velocity_column(const svec& S, const vec3& r) {
  return lin(S) + ang(S).cross(r);
}
}  // namespace detail

/// J (3 x nv): world velocity of the point p_body (body frame) of `body` is J v. Computes the poses
/// for q (cached when forward_kinematics already ran for the same q).
/// \throws std::invalid_argument on wrong sizes or a bad body index.
template <root_joint Root>
void point_jacobian(const model<Root>& m, workspace<Root>& ws,
                    const Eigen::Ref<const Eigen::VectorXd>& q, int body, const vec3& p_body,
                    Eigen::Ref<Eigen::MatrixXd> J) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  check_argument(body >= 0 && body < m.num_bodies(), "body index ", body, " out of range [0, ",
                 m.num_bodies(), ")");
  check_argument(J.rows() == 3 && J.cols() == m.nv(), "J: wrong size, expected 3 x ", m.nv(),
                 ", got ", J.rows(), " x ", J.cols());
  detail::ensure_poses(m, ws, q);
  const auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const vec3 r = s.body_rel[body] + ws.body_rotation[body] * p_body;  // relative to the reference
  J.setZero();
  for (int n = s.body_node[body]; n > 0; n = s.node_parent[n])
    J.col(nvr + n - 1) = detail::point_velocity_column(s.S[n], r);
  if constexpr (nvr > 0) {
    for (int i = 0; i < nvr; ++i) {
      const auto Si = s.S0.col(i);
      J.col(i) = Si.template tail<3>() + vec3(Si.template head<3>()).cross(r);
    }
  }
}

/// J (3 x nj, the joint columns): the world velocity of the point p_body of `body` relative to the
/// point of `reference` that coincides with it, J_body(p) - J_reference(p) without the root's
/// columns (they cancel). One walk up each chain instead of two full point Jacobians; the columns
/// of the joints both bodies hang from come out exactly zero (the same column added and
/// subtracted). Wu & Popovic 2010's J (controllers/end_effector/generalized_forces.hpp).
template <root_joint Root>
void relative_point_jacobian(const model<Root>& m, workspace<Root>& ws,
                             const Eigen::Ref<const Eigen::VectorXd>& q, int body,
                             const vec3& p_body, int reference, Eigen::Ref<Eigen::MatrixXd> J) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  check_argument(body >= 0 && body < m.num_bodies() && reference >= 0 && reference < m.num_bodies(),
                 "relative_point_jacobian: body ", body, " or reference ", reference,
                 " out of range [0, ", m.num_bodies(), ")");
  check_argument(J.rows() == 3 && J.cols() == m.num_joint_dofs(),
                 "relative_point_jacobian: J must be 3 x ", m.num_joint_dofs(), ", got ", J.rows(),
                 " x ", J.cols());
  detail::ensure_poses(m, ws, q);
  const auto& s = ws.scratch;
  const vec3 r = s.body_rel[body] + ws.body_rotation[body] * p_body;
  J.setZero();
  for (int n = s.body_node[body]; n > 0; n = s.node_parent[n])
    J.col(n - 1) += detail::point_velocity_column(s.S[n], r);
  for (int n = s.body_node[reference]; n > 0; n = s.node_parent[n])
    J.col(n - 1) -= detail::point_velocity_column(s.S[n], r);
}

/// J (3 x nv): world angular velocity of `body` is J v.
template <root_joint Root>
void body_orientation_jacobian(const model<Root>& m, workspace<Root>& ws,
                               const Eigen::Ref<const Eigen::VectorXd>& q, int body,
                               Eigen::Ref<Eigen::MatrixXd> J) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  check_argument(body >= 0 && body < m.num_bodies(), "body index ", body, " out of range [0, ",
                 m.num_bodies(), ")");
  check_argument(J.rows() == 3 && J.cols() == m.nv(), "J: wrong size, expected 3 x ", m.nv(),
                 ", got ", J.rows(), " x ", J.cols());
  detail::ensure_poses(m, ws, q);
  const auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  J.setZero();
  for (int n = s.body_node[body]; n > 0; n = s.node_parent[n])
    J.col(nvr + n - 1) = detail::ang(s.S[n]);
  if constexpr (nvr > 0) J.template leftCols<nvr>() = s.S0.template topRows<3>();
}

}  // namespace gaitsynth
