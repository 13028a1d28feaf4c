#pragma once
/// \file workspace.hpp
/// Per-thread scratch and results of the dynamics algorithms (Pinocchio's "Data"). Sized once by
/// make_workspace(model); no algorithm allocates afterwards.
///
/// Internally every algorithm works in *world axes about a moving reference point*: the root body's
/// origin at the current configuration (docs/dynamics.md, "Spatial frames"). Using world axes
/// removes the per-body 6x6 coordinate transforms of the body-frame ABA (Featherstone 2008,
/// sec. 7.3 vs. the world-convention variant used by Pinocchio 3), and putting the origin at the
/// root keeps lever arms short however far the character walks. The public fields below are
/// converted to plain world quantities.
///
/// A body with k revolute DOFs is treated as a chain of k DOF "nodes" at the body origin, of which
/// only the last carries the body's inertia (Featherstone sec. 4.4: a multi-DOF joint as a chain of
/// single-DOF joints with massless intermediate bodies). Node 0 is the root joint (Root::nv DOFs),
/// node n >= 1 is joint DOF n - 1.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/spatial.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

namespace detail {

/// Padded spatial vector [angular (3); linear (3); 0; 0]. Eight doubles are one AVX-512 register
/// (two AVX2 ones), so the 6D operations of the passes below compile to a few full-width
/// instructions instead of 4 + 2 split packets; the padding is kept at zero.
using svec = Eigen::Matrix<double, 8, 1>;
/// Padded spatial 6x6 operator stored by columns: IA[k] is column k as a padded spatial vector.
/// (An array of full vectors, not an 8x6 matrix: Eigen then uses full-width packets for every
/// column operation.)
using smat = std::array<svec, 6>;

inline auto ang(svec& x) {
  return x.template head<3>();
}
inline auto ang(const svec& x) {
  return x.template head<3>();
}
inline auto lin(svec& x) {
  return x.template segment<3>(3);
}
inline auto lin(const svec& x) {
  return x.template segment<3>(3);
}
/// [a; l; 0; 0], assembled in registers and stored at full vector width: eight scalar stores
/// followed by the full-width loads of the next operation defeat store-to-load forwarding (a wide
/// load spanning several narrower stores waits for them). About 2 % of a 3D rollout with
/// AVX-512, nothing measurable with SSE2; the values are the same either way.
inline svec make_svec(const vec3& a, const vec3& l) {
  svec x;
#if defined(__AVX512F__)
  _mm512_storeu_pd(x.data(), _mm512_set_pd(0.0, 0.0, l[2], l[1], l[0], a[2], a[1], a[0]));
#elif defined(__AVX__)
  _mm256_storeu_pd(x.data(), _mm256_setr_pd(a[0], a[1], a[2], l[0]));
  _mm256_storeu_pd(x.data() + 4, _mm256_setr_pd(l[1], l[2], 0.0, 0.0));
#elif defined(__SSE2__)
  _mm_storeu_pd(x.data(), _mm_setr_pd(a[0], a[1]));
  _mm_storeu_pd(x.data() + 2, _mm_setr_pd(a[2], l[0]));
  _mm_storeu_pd(x.data() + 4, _mm_setr_pd(l[1], l[2]));
  _mm_storeu_pd(x.data() + 6, _mm_setzero_pd());
#else
  x << a, l, 0.0, 0.0;
#endif
  return x;
}
inline vec6 to_vec6(const svec& x) {
  return x.template head<6>();
}

/// a . b over the six spatial components (written out: a pairwise sum vectorizes well and avoids
/// GCC 12's false -Wmaybe-uninitialized inside Eigen's AVX-512 horizontal reduction).
inline double sdot(const svec& a, const svec& b) {
  const svec p = a.cwiseProduct(b);
  return ((p[0] + p[1]) + (p[2] + p[3])) + (p[4] + p[5]);
}

/// v x m (Featherstone eq. 2.31) on padded vectors.
inline svec cross_motion(const svec& v, const svec& m) {
  const vec3 w = ang(v), vo = lin(v), mw = ang(m), mv = lin(m);
  return make_svec(w.cross(mw), w.cross(mv) + vo.cross(mw));
}
/// v x* f (eq. 2.32) on padded vectors.
inline svec cross_force(const svec& v, const svec& f) {
  const vec3 w = ang(v), vo = lin(v), n = ang(f), fl = lin(f);
  return make_svec(w.cross(n) + vo.cross(fl), w.cross(fl));
}
/// The padded 6x6 matrix of a compact rigid inertia (Featherstone eq. 2.63):
/// [Ic + m (|c|^2 1 - c c^T), m [c]x; m [c]x^T, m 1].
inline void inertia_matrix(const spatial::rigid_inertia& I, smat& out) {
  const double m = I.mass;
  const vec3 c = I.com;
  const vec3 mc = m * c;
  const mat3 A = I.inertia_com + m * (c.squaredNorm() * mat3::Identity() - c * c.transpose());
  // Columns 0-2: [A e_k; m [c]x^T e_k] with m [c]x^T e_k = m (e_k x c)... written out:
  out[0] = make_svec(A.col(0), vec3(0.0, -mc.z(), mc.y()));
  out[1] = make_svec(A.col(1), vec3(mc.z(), 0.0, -mc.x()));
  out[2] = make_svec(A.col(2), vec3(-mc.y(), mc.x(), 0.0));
  // Columns 3-5: [m [c]x e_k; m e_k].
  out[3] = make_svec(vec3(0.0, mc.z(), -mc.y()), vec3(m, 0.0, 0.0));
  out[4] = make_svec(vec3(-mc.z(), 0.0, mc.x()), vec3(0.0, m, 0.0));
  out[5] = make_svec(vec3(mc.y(), -mc.x(), 0.0), vec3(0.0, 0.0, m));
}
inline void set_zero(smat& A) {
  for (auto& c : A) c.setZero();
}
/// y = A x for a padded operator (one full-width FMA per column).
inline svec op_times(const smat& A, const svec& x) {
  // Pairwise sums: the ABA passes are latency bound along the tree, so a short dependency chain
  // (mul, fma, add, add) beats six chained FMAs.
  const svec y01 = A[0] * x[0] + A[1] * x[1];
  const svec y23 = A[2] * x[2] + A[3] * x[3];
  const svec y45 = A[4] * x[4] + A[5] * x[5];
  return (y01 + y23) + y45;
}
/// The unpadded 6x6 matrix.
inline mat6 to_mat6(const smat& A) {
  mat6 M;
  for (int k = 0; k < 6; ++k) M.col(k) = A[k].template head<6>();
  return M;
}

/// Planar fast path (models with a planar_root whose joint axes are all +-y): every motion is in
/// the world x-z plane, so spatial vectors reduce to 3-vectors [omega_y; v_x; v_z] (motion) and
/// [n_y; f_x; f_z] (force), and spatial inertias to 3x3 matrices: the rows and columns 1, 3, 5 of
/// the 6D quantities about the same reference point (Featherstone 2008, sec. 2.16, planar
/// vectors). The out-of-plane components never feed back: for a planar v, the planar part of
/// v x* f depends only on the planar part of f, and the joint axes only see planar parts; so the
/// planar articulated-body algorithm gives the 6D one's ddq up to rounding (tests/dynamics/
/// planar.cpp checks both against each other).
using pvec = Eigen::Vector3d;
/// Symmetric planar operator [a b c; b d e; c e f] (inertias), as scalars: the planar passes are
/// latency bound, and plain scalars keep every value in registers or in simple store-load pairs.
struct psym {
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0, e = 0.0, f = 0.0;
  psym& operator+=(const psym& o) {
    a += o.a;
    b += o.b;
    c += o.c;
    d += o.d;
    e += o.e;
    f += o.f;
    return *this;
  }
};
inline pvec sym_mul(const psym& I, const pvec& x) {
  return pvec(I.a * x[0] + I.b * x[1] + I.c * x[2], I.b * x[0] + I.d * x[1] + I.e * x[2],
              I.c * x[0] + I.e * x[1] + I.f * x[2]);
}

struct planar_scratch {
  bool enabled = false;  ///< the model qualifies (set once by make_workspace)
  int level = 0;         ///< 0: nothing valid, 1: poses for q_cache, 2: and velocities for v_cache
  std::vector<double> cos_q, sin_q;  ///< per DOF of q after x, z: root pitch, then the joints
  std::vector<double> cos_b, sin_b;  ///< per body: its world pitch, R = Ry(pitch)
  std::vector<vec3> body_com;        ///< per body: COM relative to the reference point, world
  std::vector<double> body_mass;     ///< per body
  std::vector<psym> body_I;          ///< per body: planar inertia about the reference point
  std::vector<pvec> body_bias;       ///< per body: v x* I v
  std::vector<pvec> S, V, C;         ///< per node (S[0] unused): axis, velocity, Sdot qdot
  std::vector<psym> IA;              ///< per node: articulated inertia
  std::vector<pvec> pA, U, A;        ///< per node: bias force, IA S (assembled ahead), accel.
  std::vector<double> D, Dinv, u;    ///< per node: S^T IA S (assembled ahead), its inverse, u
};

/// v x m for planar motion vectors (the planar rows of eq. 2.31).
inline pvec planar_cross_motion(const pvec& v, const pvec& m) {
  return pvec(0.0, v[0] * m[2] - v[2] * m[0], v[1] * m[0] - v[0] * m[1]);
}
/// v x* f for a planar motion v and planar force f (the planar rows of eq. 2.32).
inline pvec planar_cross_force(const pvec& v, const pvec& f) {
  return pvec(v[2] * f[1] - v[1] * f[2], v[0] * f[2], -v[0] * f[1]);
}

/// Everything the algorithms keep between passes. Internal: names and layout may change.
template <root_joint Root>
struct dynamics_scratch {
  static constexpr int nvr = Root::nv;
  using root_subspace = Eigen::Matrix<double, 6, (nvr > 0 ? nvr : 1)>;

  // ---- constants derived from the model at make_workspace --------------------------------------
  const void* model_id = nullptr;  ///< the model the cached kinematics belong to
  int nb = 0, nj = 0;              ///< bodies, joint DOFs
  std::vector<int> node_parent;    ///< per node (nj + 1): parent node, -1 for node 0
  std::vector<int> node_body;      ///< per node: body whose inertia the node carries, -1 if none
  std::vector<int> body_node;      ///< per body: node its inertia is attached to (its last DOF)
  /// per joint DOF: 0, 1, 2 if the axis is +-x, +-y, +-z of the body frame (a rotation then mixes
  /// two columns only), 3 for a general axis; dof_axis_sign is the sign of a coordinate axis.
  std::vector<int> dof_axis_kind;
  std::vector<double> dof_axis_sign;
  std::vector<unsigned char> body_inertia_principal;  ///< per body: inertia diagonal in its frame

  // ---- kinematics (forward_kinematics) ----------------------------------------------------------
  vec3 ref = vec3::Zero();                           ///< reference point (root body origin), world
  std::vector<vec3> body_rel;                        ///< body origin relative to ref, world axes
  std::vector<double> sin_q, cos_q;                  ///< per joint DOF: sin and cos of its angle
  std::vector<spatial::rigid_inertia> body_inertia;  ///< per body, world axes, about ref
  std::vector<smat> body_I;         ///< per body: 6x6 spatial inertia (world axes, about ref)
  std::vector<svec> body_bias;      ///< per body: v x* I v (velocity-product force)
  std::vector<svec> body_momentum;  ///< per body: I v (spatial momentum about ref)
  std::vector<svec> S;              ///< per node (index 0 unused): joint motion axis, about ref
  root_subspace S0 = root_subspace::Zero();  ///< root joint motion subspace (6 x Root::nv)
  std::vector<svec> V;                       ///< per node: spatial velocity
  std::vector<svec> C;  ///< per node: velocity-product acceleration (Sdot qdot)

  // ---- articulated-body / recursive Newton-Euler passes -----------------------------------------
  std::vector<smat> IA;      ///< per node: articulated inertia (ABA) / composite inertia (CRBA)
  std::vector<svec> pA;      ///< per node: bias force (ABA) / body force (RNEA)
  std::vector<svec> U;       ///< per node: IA * S
  std::vector<svec> Uacc;    ///< per node: IA S assembled ahead from the children (ABA look-ahead)
  std::vector<double> Dacc;  ///< per node: S^T IA S assembled ahead from the children
  std::vector<double> Dinv;  ///< per node: 1 / (S^T IA S)
  std::vector<double> u;     ///< per node: tau - S^T pA
  std::vector<svec> A;       ///< per node: spatial acceleration (gravity included as base accel.)

  /// ABA by joints (aba.hpp, aba_passes_by_joint): each body's 1-3 DOFs as one joint with a 6 x k
  /// motion subspace (Featherstone 2008, Table 7.1) instead of a chain of single-DOF nodes with
  /// massless bodies between them. Opt-in (enable_aba_by_joint); sized by make_workspace when
  /// every non-root body has 1 to 3 DOFs (available); per body, the values pass 3 needs.
  struct joint_blocks {
    bool available = false;
    bool enabled = false;
    std::vector<std::array<svec, 3>> U;       ///< per body: IA S, one column per DOF
    std::vector<std::array<double, 9>> Dinv;  ///< per body: (S^T IA S)^-1, k x k, row-major
    std::vector<std::array<double, 3>> u;     ///< per body: tau - S^T pA
    std::vector<svec> c;                      ///< per body: the sum of its nodes' C
  } joints;

  // ---- cache of the configuration the kinematics were computed for ------------------------------
  Eigen::VectorXd q_cache, v_cache;
  /// Validity of the 6D scratch above: 0: nothing valid, 1: poses for q_cache, 2: poses and
  /// velocities. (planar.level says the same of the planar scratch; the public outputs of the
  /// workspace are current when either is.)
  int level = 0;

  planar_scratch planar;  ///< planar fast path (empty unless planar.enabled)
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

  Eigen::VectorXd ddq;   ///< aba output, nv
  Eigen::VectorXd tau;   ///< rnea output, nv
  Eigen::VectorXd bias;  ///< nonlinear_effects output (C v + g), nv
  Eigen::MatrixXd M;     ///< crba output, nv x nv

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
  s.dof_axis_kind.assign(nj, 3);
  s.dof_axis_sign.assign(nj, 1.0);
  for (int j = 0; j < nj; ++j) {
    const vec3& a = m.dofs[j].axis;
    for (int k = 0; k < 3; ++k)
      if (std::abs(a[k]) == 1.0 && a[(k + 1) % 3] == 0.0 && a[(k + 2) % 3] == 0.0) {
        s.dof_axis_kind[j] = k;
        s.dof_axis_sign[j] = a[k];
      }
  }
  s.body_inertia_principal.assign(nb, 0);
  for (int b = 0; b < nb; ++b) {
    const mat3& I = m.bodies[b].inertia;
    s.body_inertia_principal[b] = I == mat3(I.diagonal().asDiagonal()) ? 1 : 0;
  }
  s.body_rel.assign(nb, vec3::Zero());
  s.sin_q.assign(nj, 0.0);
  s.cos_q.assign(nj, 1.0);
  s.body_inertia.assign(nb, spatial::rigid_inertia{});
  s.S.assign(nn, detail::svec::Zero());
  s.V.assign(nn, detail::svec::Zero());
  s.C.assign(nn, detail::svec::Zero());
  detail::smat zero6;
  detail::set_zero(zero6);
  s.IA.assign(nn, zero6);
  s.pA.assign(nn, detail::svec::Zero());
  s.U.assign(nn, detail::svec::Zero());
  s.Uacc.assign(nn, detail::svec::Zero());
  s.Dacc.assign(nn, 0.0);
  s.body_I.assign(nb, zero6);
  s.body_bias.assign(nb, detail::svec::Zero());
  s.body_momentum.assign(nb, detail::svec::Zero());
  s.Dinv.assign(nn, 0.0);
  s.u.assign(nn, 0.0);
  s.A.assign(nn, detail::svec::Zero());
  bool by_joint = nb > 1;
  for (int b = 1; b < nb; ++b)
    by_joint = by_joint && m.bodies[b].num_dofs >= 1 && m.bodies[b].num_dofs <= 3;
  s.joints.available = by_joint;
  s.joints.enabled = false;
  if (by_joint) {
    std::array<detail::svec, 3> zero_columns;  // Eigen leaves a default-constructed svec unset
    zero_columns.fill(detail::svec::Zero());
    s.joints.U.assign(nb, zero_columns);
    s.joints.Dinv.assign(nb, {});
    s.joints.u.assign(nb, {});
    s.joints.c.assign(nb, detail::svec::Zero());
  }
  s.q_cache = Eigen::VectorXd::Constant(m.nq(), std::numeric_limits<double>::quiet_NaN());
  s.v_cache = Eigen::VectorXd::Constant(nv, std::numeric_limits<double>::quiet_NaN());
  s.level = 0;
  if constexpr (std::is_same_v<Root, planar_root>) {
    bool planar = true;
    for (int j = 0; j < nj; ++j) planar = planar && s.dof_axis_kind[j] == 1;
    auto& P = s.planar;
    P.enabled = planar;
    if (planar) {
      P.cos_q.assign(nj + 1, 1.0);
      P.sin_q.assign(nj + 1, 0.0);
      P.cos_b.assign(nb, 1.0);
      P.sin_b.assign(nb, 0.0);
      P.body_com.assign(nb, vec3::Zero());
      P.body_mass.assign(nb, 0.0);
      for (int b = 0; b < nb; ++b) P.body_mass[b] = m.bodies[b].mass;
      P.body_I.assign(nb, detail::psym{});
      P.body_bias.assign(nb, detail::pvec::Zero());
      for (auto* x : {&P.S, &P.V, &P.C, &P.pA, &P.U, &P.A}) x->assign(nn, detail::pvec::Zero());
      P.IA.assign(nn, detail::psym{});
      P.D.assign(nn, 0.0);
      P.Dinv.assign(nn, 0.0);
      P.u.assign(nn, 0.0);
    }
  }
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

/// Runs aba on this workspace by joints (dynamics/aba_by_joint.hpp: each body's 1-3 DOFs as one
/// joint), or again by single-DOF nodes (on = false, the default of make_workspace). Both solve
/// the same equations; by joints is about 9 % faster on the 3D humanoids but rounds differently,
/// and every saved walker under data/ was made and is checked with the node passes (their Table 1
/// forces move by 5-10 N with the rounding: docs/performance.md, "ABA by joints"), so it is not
/// the default. \returns whether it is now on (false for a model with a body of more than three
/// DOFs, which always runs by nodes).
template <root_joint Root>
bool enable_aba_by_joint(workspace<Root>& ws, bool on = true) {
  ws.scratch.joints.enabled = on && ws.scratch.joints.available;
  return ws.scratch.joints.enabled;
}

/// Turns the planar fast path off for this workspace, so every algorithm runs the general 6D code
/// (tests compare the two; the results agree to rounding). A no-op for other roots.
template <root_joint Root>
void disable_planar_path(workspace<Root>& ws) {
  ws.scratch.planar.enabled = false;
  ws.scratch.planar.level = 0;
  ws.scratch.level = 0;
}

/// Forgets the cached kinematics, so the next algorithm recomputes them (benchmarks; never needed
/// for correctness). The readers (center_of_mass, kinetic_energy, ...) then throw until
/// forward_kinematics runs again.
template <root_joint Root>
void invalidate_kinematics(workspace<Root>& ws) {
  ws.scratch.level = 0;
  ws.scratch.planar.level = 0;
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
