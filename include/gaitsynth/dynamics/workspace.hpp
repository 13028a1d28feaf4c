#pragma once
/// \file workspace.hpp
/// Per-thread scratch and results of the dynamics algorithms (Pinocchio's "Data"). Sized once by
/// make_workspace(model); no algorithm allocates afterwards.
///
/// Internally every algorithm works in *world axes about a moving reference point*: the root body's
/// origin at the current configuration (docs/dynamics.md, "Spatial frames"). Using world axes removes
/// the per-body 6x6 coordinate transforms of the body-frame ABA (Featherstone 2008, sec. 7.3 vs. the
/// world-convention variant used by Pinocchio 3), and putting the origin at the root keeps lever arms
/// short however far the character walks. The public fields below are converted to plain world
/// quantities.
///
/// A body with k revolute DOFs is treated as a chain of k DOF "nodes" at the body origin, of which
/// only the last carries the body's inertia (Featherstone sec. 4.4: a multi-DOF joint as a chain of
/// single-DOF joints with massless intermediate bodies). Node 0 is the root joint (Root::nv DOFs),
/// node n >= 1 is joint DOF n - 1.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/spatial.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

namespace detail {

/// Everything the algorithms keep between passes. Internal: names and layout may change.
template <root_joint Root>
struct dynamics_scratch {
  static constexpr int nvr = Root::nv;
  using root_subspace = Eigen::Matrix<double, 6, (nvr > 0 ? nvr : 1)>;

  // ---- constants derived from the model at make_workspace --------------------------------------
  const void* model_id = nullptr;   ///< the model this workspace was made for (identity check)
  int nb = 0, nj = 0;               ///< bodies, joint DOFs
  std::vector<int> node_parent;     ///< per node (nj + 1): parent node, -1 for node 0
  std::vector<int> node_body;       ///< per node: body whose inertia the node carries, -1 if none
  std::vector<int> body_node;       ///< per body: node its inertia is attached to (its last DOF)

  // ---- kinematics (forward_kinematics) ----------------------------------------------------------
  vec3 ref = vec3::Zero();          ///< reference point (root body origin), world
  std::vector<vec3> body_rel;       ///< body origin relative to ref, world axes
  std::vector<spatial::rigid_inertia> body_inertia;  ///< per body, world axes, about ref
  std::vector<vec6> S;              ///< per node (index 0 unused): joint motion axis, about ref
  root_subspace S0 = root_subspace::Zero();  ///< root joint motion subspace (6 x Root::nv)
  std::vector<vec6> V;              ///< per node: spatial velocity
  std::vector<vec6> C;              ///< per node: velocity-product acceleration (Sdot qdot)

  // ---- articulated-body / recursive Newton-Euler passes -----------------------------------------
  std::vector<mat6> IA;     ///< per node: articulated inertia (ABA) / composite inertia (CRBA)
  std::vector<vec6> pA;     ///< per node: bias force (ABA) / body force (RNEA)
  std::vector<vec6> U;      ///< per node: IA * S
  std::vector<double> Dinv; ///< per node: 1 / (S^T IA S)
  std::vector<double> u;    ///< per node: tau - S^T pA
  std::vector<vec6> A;      ///< per node: spatial acceleration (gravity included as base accel.)

  // ---- cache of the configuration the kinematics were computed for ------------------------------
  Eigen::VectorXd q_cache, v_cache;
  int level = 0;  ///< 0: nothing valid, 1: poses for q_cache, 2: poses and velocities
};

}  // namespace detail

/// Results and scratch of the dynamics algorithms for one model<Root> (one per thread).
template <root_joint Root>
struct workspace {
  // Filled by forward_kinematics (all world frame).
  std::vector<mat3> body_rotation;          ///< R_world_body, per body
  std::vector<vec3> body_position;          ///< body origin, world, m
  std::vector<vec3> body_angular_velocity;  ///< world axes, rad/s
  std::vector<vec3> body_linear_velocity;   ///< velocity of the body origin, world, m/s
  /// External wrench per body: [torque about the body ORIGIN (world axes), N m; force (world), N].
  /// Read by aba (and rnea_with_external); zero it with clear_external_wrenches.
  std::vector<vec6> f_ext;

  Eigen::VectorXd ddq;  ///< aba output, nv
  Eigen::VectorXd tau;  ///< rnea output, nv
  Eigen::VectorXd bias; ///< nonlinear_effects output (C v + g), nv
  Eigen::MatrixXd M;    ///< crba output, nv x nv

  detail::dynamics_scratch<Root> scratch;  ///< internal
};

/// Creates a workspace sized for `m`. This is the only allocation the algorithms need.
template <root_joint Root>
workspace<Root> make_workspace(const model<Root>& m) {
  workspace<Root> ws;
  const int nb = m.num_bodies(), nj = m.num_joint_dofs(), nv = m.nv();
  ws.body_rotation.assign(nb, mat3::Identity());
  ws.body_position.assign(nb, vec3::Zero());
  ws.body_angular_velocity.assign(nb, vec3::Zero());
  ws.body_linear_velocity.assign(nb, vec3::Zero());
  ws.f_ext.assign(nb, vec6::Zero());
  ws.ddq = Eigen::VectorXd::Zero(nv);
  ws.tau = Eigen::VectorXd::Zero(nv);
  ws.bias = Eigen::VectorXd::Zero(nv);
  ws.M = Eigen::MatrixXd::Zero(nv, nv);

  auto& s = ws.scratch;
  s.model_id = &m;
  s.nb = nb;
  s.nj = nj;
  const int nn = nj + 1;
  s.node_parent.assign(nn, -1);
  s.node_body.assign(nn, -1);
  s.body_node.assign(nb, 0);
  s.node_body[0] = 0;
  for (int b = 1; b < nb; ++b) {
    const body& bd = m.bodies[b];
    int parent_node = s.body_node[bd.parent];
    for (int k = 0; k < bd.num_dofs; ++k) {
      const int j = bd.first_dof + k;
      s.node_parent[j + 1] = parent_node;
      parent_node = j + 1;
    }
    s.body_node[b] = parent_node;
    s.node_body[parent_node] = b;
  }
  s.body_rel.assign(nb, vec3::Zero());
  s.body_inertia.assign(nb, spatial::rigid_inertia{});
  s.S.assign(nn, vec6::Zero());
  s.V.assign(nn, vec6::Zero());
  s.C.assign(nn, vec6::Zero());
  s.IA.assign(nn, mat6::Zero());
  s.pA.assign(nn, vec6::Zero());
  s.U.assign(nn, vec6::Zero());
  s.Dinv.assign(nn, 0.0);
  s.u.assign(nn, 0.0);
  s.A.assign(nn, vec6::Zero());
  s.q_cache = Eigen::VectorXd::Constant(m.nq(), std::numeric_limits<double>::quiet_NaN());
  s.v_cache = Eigen::VectorXd::Constant(nv, std::numeric_limits<double>::quiet_NaN());
  s.level = 0;
  return ws;
}

/// Zeroes every body's external wrench (call once per step before adding contact and push forces).
template <root_joint Root>
void clear_external_wrenches(workspace<Root>& ws) {
  for (auto& f : ws.f_ext) f.setZero();
}

/// Accumulates a force `world_force` (N, world) applied at `world_point` (m, world) on `body` into
/// ws.f_ext[body] (as a torque about the body origin plus the force). Needs the body's pose, i.e.
/// forward_kinematics for the current q.
template <root_joint Root>
void add_point_force(const model<Root>& m, workspace<Root>& ws, int body, const vec3& world_point,
                     const vec3& world_force) {
  (void)m;
  ws.f_ext[body].template head<3>() += (world_point - ws.body_position[body]).cross(world_force);
  ws.f_ext[body].template tail<3>() += world_force;
}

/// Accumulates a pure wrench [torque (world, N m); force (world, N)] acting on `body`, with the
/// torque about the body origin.
template <root_joint Root>
void add_body_wrench(workspace<Root>& ws, int body, const vec6& wrench) {
  ws.f_ext[body] += wrench;
}

/// Forgets the cached kinematics, so the next algorithm recomputes them (benchmarks; never needed
/// for correctness).
template <root_joint Root>
void invalidate_kinematics(workspace<Root>& ws) {
  ws.scratch.level = 0;
}

namespace detail {
/// Throws std::invalid_argument unless `ws` was made for a model with the sizes of `m`.
template <root_joint Root>
void check_workspace(const model<Root>& m, const workspace<Root>& ws) {
  check_argument(ws.scratch.nb == m.num_bodies() && ws.scratch.nj == m.num_joint_dofs(),
                 "workspace was made for a model with ", ws.scratch.nb, " bodies and ",
                 ws.scratch.nj, " joint DOFs, but model '", m.name, "' has ", m.num_bodies(),
                 " and ", m.num_joint_dofs());
}
}  // namespace detail

}  // namespace gaitsynth
