#pragma once
/// \file crba.hpp
/// The joint-space inertia matrix by the composite-rigid-body algorithm (Featherstone 2008,
/// sec. 6.2, Table 6.2), in world axes about the root origin.
#include "gaitsynth/dynamics/kinematics.hpp"

namespace gaitsynth {

/// The joint-space inertia matrix M(q) (nv x nv, symmetric, both triangles filled).
/// \returns ws.M
/// \throws std::invalid_argument if q or the workspace has the wrong size.
template <root_joint Root>
const Eigen::MatrixXd& crba(const model<Root>& m, workspace<Root>& ws,
                            const Eigen::Ref<const Eigen::VectorXd>& q) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::ensure_poses(m, ws, q);
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  const int nn = s.nj + 1;
  // Composite inertias (eq. 6.20): no transforms, everything shares world axes and the reference.
  for (int n = 0; n < nn; ++n) {
    const int b = s.node_body[n];
    if (b >= 0)
      s.IA[n] = s.body_I[b];
    else
      detail::set_zero(s.IA[n]);
  }
  for (int n = nn - 1; n >= 1; --n)
    for (int k = 0; k < 6; ++k) s.IA[s.node_parent[n]][k] += s.IA[n][k];
  Eigen::MatrixXd& M = ws.M;
  M.setZero();
  for (int n = 1; n < nn; ++n) {
    const int i = nvr + n - 1;
    const detail::svec F = detail::op_times(s.IA[n], s.S[n]);
    M(i, i) = detail::sdot(s.S[n], F);
    for (int k = s.node_parent[n]; k > 0; k = s.node_parent[k]) {
      const int jk = nvr + k - 1;
      M(jk, i) = M(i, jk) = detail::sdot(s.S[k], F);
    }
    if constexpr (nvr > 0) {
      const Eigen::Matrix<double, nvr, 1> col = s.S0.transpose() * detail::to_vec6(F);
      M.col(i).template head<nvr>() = col;
      M.row(i).template head<nvr>() = col.transpose();
    }
  }
  if constexpr (nvr > 0) {
    const mat6 IA0 = detail::to_mat6(s.IA[0]);
    const Eigen::Matrix<double, nvr, nvr> M0 = s.S0.transpose() * IA0 * s.S0;
    M.template topLeftCorner<nvr, nvr>() = 0.5 * (M0 + M0.transpose());  // exactly symmetric
  }
  return M;
}

}  // namespace gaitsynth
