#pragma once
/// \file kinematics.hpp
/// Forward kinematics: body poses (and velocities) in the world frame, plus the per-DOF motion axes
/// and world-axes body inertias the other algorithms reuse (Featherstone 2008, sec. 4.1 and 5.3).
///
/// The workspace remembers the (q, v) its kinematics were computed for. Calling an algorithm with
/// the same q (and v) again skips the recomputation, so the usual step
///   forward_kinematics(m, ws, q, v); apply_contact_forces(...); aba(m, ws, q, v, tau);
/// pays for the kinematics once. The cache compares values, not addresses, so it is always safe.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/spatial/sincos.hpp"

namespace gaitsynth {

namespace detail {

/// Rotation by angle t about the unit axis a (Rodrigues): c I + s [a]x + (1 - c) a a^T.
/// Returns R * rot(a, t) without forming rot(a, t), given Ra = R * a, s = sin t, c = cos t.
inline mat3 rotate_intrinsic(const mat3& R, const vec3& a, const vec3& Ra, double s, double c) {
  mat3 out;
  // R [a]x: column i is R (a x e_i).
  out.col(0) = a.z() * R.col(1) - a.y() * R.col(2);
  out.col(1) = a.x() * R.col(2) - a.z() * R.col(0);
  out.col(2) = a.y() * R.col(0) - a.x() * R.col(1);
  const vec3 k = (1.0 - c) * Ra;
  for (int i = 0; i < 3; ++i) out.col(i) = c * R.col(i) + s * out.col(i) + a[i] * k;
  return out;
}

template <root_joint Root, class Q>
void root_pose(const model<Root>& m, const Q& q, mat3& R0, vec3& p0) {
  const vec3& off = m.bodies[0].joint_offset;
  if constexpr (std::is_same_v<Root, planar_root>) {
    const double s = std::sin(q[2]), c = std::cos(q[2]);
    R0 << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
    p0 = off + vec3(q[0], 0.0, q[1]);
  } else if constexpr (std::is_same_v<Root, floating_root>) {
    // Unit quaternion (w, x, y, z); normalized here so slightly drifted inputs stay rotations.
    R0 = quat(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
    p0 = off + vec3(q[0], q[1], q[2]);
  } else {
    R0.setIdentity();
    p0 = off;
  }
}

/// Poses, motion axes and world inertias for configuration q (no size checks).
template <root_joint Root, class Q>
void update_poses(const model<Root>& m, workspace<Root>& ws, const Q& q) {
  auto& s = ws.scratch;
  constexpr int nqr = Root::nq;
  mat3 R0;
  vec3 p0;
  root_pose(m, q, R0, p0);
  s.ref = p0;
  if constexpr (std::is_same_v<Root, planar_root>) {
    s.S0.setZero();
    s.S0(3, 0) = 1.0;  // x slide
    s.S0(5, 1) = 1.0;  // z slide
    s.S0(1, 2) = 1.0;  // pitch hinge about +y through the root origin (= the reference point)
  } else if constexpr (std::is_same_v<Root, floating_root>) {
    // v_root = [v_world of the root origin; omega in the root body frame]:
    // spatial velocity about the root origin = [R omega_b; v_world].
    s.S0.setZero();
    s.S0.template topRightCorner<3, 3>() = R0;
    s.S0.template bottomLeftCorner<3, 3>() = mat3::Identity();
  }
  ws.body_rotation[0] = R0;
  ws.body_position[0] = p0;
  s.body_rel[0].setZero();
  {
    const body& b0 = m.bodies[0];
    s.body_inertia[0] = {b0.mass, R0 * b0.com, R0 * b0.inertia * R0.transpose()};
    inertia_matrix(s.body_inertia[0], s.body_I[0]);
  }
  // All sines and cosines first, batched and vectorized (spatial/sincos.hpp), off the rotation
  // chain.
  spatial::sincos_batch(q.data() + nqr, s.sin_q.data(), s.cos_q.data(), s.nj);
  const int nb = m.num_bodies();
  for (int b = 1; b < nb; ++b) {
    const body& bd = m.bodies[b];
    const mat3& Rp = ws.body_rotation[bd.parent];
    const vec3 rel = s.body_rel[bd.parent] + Rp * bd.joint_offset;
    mat3 R = Rp;
    for (int k = 0; k < bd.num_dofs; ++k) {
      const int j = bd.first_dof + k;
      const double c = s.cos_q[j];
      const int kind = s.dof_axis_kind[j];
      vec3 w;  // world axis; invariant under its own rotation
      if (kind < 3) {
        // Rotation about a coordinate axis e_k: only the other two columns of R mix. The columns
        // are named at compile time (a switch, not (k + 1) % 3), so R stays in registers.
        const double sg = s.dof_axis_sign[j], sn = sg * s.sin_q[j];
        auto turn = [&]<int K, int K1, int K2>() {
          w = sg * R.col(K);
          const vec3 r1 = R.col(K1), r2 = R.col(K2);
          R.col(K1) = c * r1 + sn * r2;
          R.col(K2) = c * r2 - sn * r1;
        };
        if (kind == 0)
          turn.template operator()<0, 1, 2>();
        else if (kind == 1)
          turn.template operator()<1, 2, 0>();
        else
          turn.template operator()<2, 0, 1>();
      } else {
        const vec3& a = m.dofs[j].axis;
        w = R * a;
        R = rotate_intrinsic(R, a, w, s.sin_q[j], c);
      }
      s.S[j + 1] = make_svec(w, rel.cross(w));
    }
    ws.body_rotation[b] = R;
    s.body_rel[b] = rel;
    ws.body_position[b] = p0 + rel;
    // Principal axes (every box of the humanoids): R diag(I) R^T, a third fewer products.
    if (s.body_inertia_principal[b])
      s.body_inertia[b] = {bd.mass, rel + R * bd.com,
                           R * bd.inertia.diagonal().asDiagonal() * R.transpose()};
    else
      s.body_inertia[b] = {bd.mass, rel + R * bd.com, R * bd.inertia * R.transpose()};
    // The 6x6 inertia is independent work that fills the gaps of the latency-bound rotation chain.
    inertia_matrix(s.body_inertia[b], s.body_I[b]);
  }
}

/// Velocities and velocity-product accelerations for v (poses must be current).
template <root_joint Root, class Vv>
void update_velocities(const model<Root>& m, workspace<Root>& ws, const Vv& v) {
  auto& s = ws.scratch;
  constexpr int nvr = Root::nv;
  if constexpr (nvr > 0) {
    const vec6 V0 = s.S0 * v.template head<nvr>();
    const vec3 w = V0.template head<3>(), vo = V0.template segment<3>(3);
    s.V[0] = make_svec(w, vo);
    // Sdot v of the root about the (instantaneously fixed) reference point: [0; -omega x v_ref].
    s.C[0] = make_svec(vec3::Zero(), -w.cross(vo));
  } else {
    s.V[0].setZero();
    s.C[0].setZero();
  }
  const int nn = s.nj + 1;
  for (int n = 1; n < nn; ++n) {
    const svec vj = s.S[n] * v[nvr + n - 1];
    const svec& vp = s.V[s.node_parent[n]];
    s.V[n] = vp + vj;
    s.C[n] = cross_motion(vp, vj);  // Featherstone eq. 7.35 (c = v x S qdot)
  }
  const int nb = m.num_bodies();
  for (int b = 0; b < nb; ++b) {
    const svec& Vb = s.V[s.body_node[b]];
    ws.body_angular_velocity[b] = ang(Vb);
    ws.body_linear_velocity[b] = lin(Vb) + ang(Vb).cross(s.body_rel[b]);
    const svec h = op_times(s.body_I[b], Vb);  // kept: com_velocity sums the linear parts
    s.body_momentum[b] = h;
    s.body_bias[b] = cross_force(Vb, h);  // v x* I v (eq. 7.38)
  }
}

/// True when `ws` runs the planar fast path (workspace.hpp, planar_scratch).
template <root_joint Root>
constexpr bool planar_path(const workspace<Root>& ws) {
  if constexpr (std::is_same_v<Root, planar_root>)
    return ws.scratch.planar.enabled;
  else
    return false;
}

/// Planar fast path of update_poses: poses, joint axes and planar inertias about the reference
/// point (the root origin), and the public pose outputs. Every body frame is Ry(pitch_b), pitch_b
/// composed along the chain as (cos, sin) pairs.
template <class Q>
void update_poses_planar(const model<planar_root>& m, workspace<planar_root>& ws, const Q& q) {
  auto& s = ws.scratch;
  auto& P = s.planar;
  // q = [x, z, pitch, joints...]: the pitch and the joint angles are contiguous, one batch.
  spatial::sincos_batch(q.data() + 2, P.sin_q.data(), P.cos_q.data(), s.nj + 1);
  const double c0 = P.cos_q[0], s0 = P.sin_q[0];
  const vec3 p0 = m.bodies[0].joint_offset + vec3(q[0], 0.0, q[1]);
  s.ref = p0;
  const int nb = m.num_bodies();
  for (int b = 0; b < nb; ++b) {
    const body& bd = m.bodies[b];
    double c = c0, sn = s0;
    vec3 rel = vec3::Zero();
    if (b > 0) {
      const int p = bd.parent;
      const double cp = P.cos_b[p], sp = P.sin_b[p];
      const vec3& o = bd.joint_offset;
      rel = s.body_rel[p] + vec3(cp * o.x() + sp * o.z(), o.y(), cp * o.z() - sp * o.x());
      c = cp;
      sn = sp;
      for (int k = 0; k < bd.num_dofs; ++k) {
        const int j = bd.first_dof + k;
        const double sg = s.dof_axis_sign[j];
        // Axis sg e_y through the body origin, about the reference: [sg e_y; rel x sg e_y].
        P.S[j + 1] = pvec(sg, -sg * rel.z(), sg * rel.x());
        const double cq = P.cos_q[j + 1], sq = sg * P.sin_q[j + 1];
        const double cn = c * cq - sn * sq;
        sn = sn * cq + c * sq;
        c = cn;
      }
    }
    P.cos_b[b] = c;
    P.sin_b[b] = sn;
    // R = Ry(pitch) = [c 0 s; 0 1 0; -s 0 c]. The five constant entries are set by
    // make_workspace and never change (the 6D path writes the same values), so only the four
    // in-plane entries are stored per step.
    mat3& R = ws.body_rotation[b];
    R(0, 0) = c;
    R(0, 2) = sn;
    R(2, 0) = -sn;
    R(2, 2) = c;
    s.body_rel[b] = rel;
    ws.body_position[b] = p0 + rel;
    const vec3& cb = bd.com;
    const vec3 cw = rel + vec3(c * cb.x() + sn * cb.z(), cb.y(), c * cb.z() - sn * cb.x());
    P.body_com[b] = cw;
    // Rows/columns (1, 3, 5) of eq. 2.63 about the reference; Ry leaves I_yy unchanged.
    const double mb = bd.mass, mx = mb * cw.x(), mz = mb * cw.z();
    P.body_I[b] = {bd.inertia(1, 1) + mx * cw.x() + mz * cw.z(), mz, -mx, mb, 0.0, mb};
  }
}

/// Planar fast path of update_velocities (poses must be current).
template <class Vv>
void update_velocities_planar(const model<planar_root>& m, workspace<planar_root>& ws,
                              const Vv& v) {
  auto& s = ws.scratch;
  auto& P = s.planar;
  constexpr int nvr = planar_root::nv;
  // v_root = [xdot, zdot, pitchdot]; about the root origin: [omega_y; v_x; v_z].
  const pvec V0(v[2], v[0], v[1]);
  P.V[0] = V0;
  P.C[0] = pvec(0.0, -V0[0] * V0[2], V0[0] * V0[1]);  // [0; -omega x v_ref], as the 6D root
  const int nn = s.nj + 1;
  for (int n = 1; n < nn; ++n) {
    const pvec vj = P.S[n] * v[nvr + n - 1];
    const pvec& vp = P.V[s.node_parent[n]];
    P.V[n] = vp + vj;
    P.C[n] = planar_cross_motion(vp, vj);  // eq. 7.35
  }
  const int nb = m.num_bodies();
  for (int b = 0; b < nb; ++b) {
    const pvec& Vb = P.V[s.body_node[b]];
    const vec3& r = s.body_rel[b];
    ws.body_angular_velocity[b] = vec3(0.0, Vb[0], 0.0);
    ws.body_linear_velocity[b] = vec3(Vb[1] + Vb[0] * r.z(), 0.0, Vb[2] - Vb[0] * r.x());
    P.body_bias[b] = planar_cross_force(Vb, sym_mul(P.body_I[b], Vb));  // eq. 7.38
  }
}

/// The throwing half of require_kinematics (cold, out of line: the check sits on the rollout's
/// per-step readers, where it must cost a compare and a never-taken branch).
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] inline void throw_no_kinematics(const char* reader,
                                                                             int needed) {
  if (needed >= 2)
    throw std::logic_error(
        concat(reader,
               ": the workspace holds no velocities for its current configuration (none since "
               "make_workspace or invalidate_kinematics, or an algorithm taking only q moved it to "
               "another q since): call forward_kinematics(m, ws, q, v) first"));
  throw std::logic_error(concat(reader,
                                ": the workspace holds no kinematics (a new workspace, or after "
                                "invalidate_kinematics): call forward_kinematics(m, ws, q) first"));
}

/// Throws std::logic_error unless `level` (a scratch level: 1 poses, 2 poses and velocities of
/// q_cache and v_cache) is at least `needed`. The readers (center_of_mass, com_velocity,
/// centroidal_momentum, the energies, point_velocity) check the level of the scratch set they
/// read, so they return the kinematics of the last (q, v) or throw, never stale or zeroed values.
inline void require_kinematics(int level, int needed, const char* reader) {
  if (level < needed) [[unlikely]]
    throw_no_kinematics(reader, needed);
}

template <root_joint Root, class Q>
void check_q(const model<Root>& m, const Q& q) {
  check_size(q.size(), m.nq(), "q (generalized positions)");
}
template <root_joint Root, class Vv>
void check_v(const model<Root>& m, const Vv& v, const char* what) {
  check_size(v.size(), m.nv(), what);
}

/// True when q_cache holds q for this model in either representation (6D or planar).
template <root_joint Root>
bool same_q(const model<Root>& m, const workspace<Root>& ws,
            const Eigen::Ref<const Eigen::VectorXd>& q) {
  const auto& s = ws.scratch;
  return s.model_id == &m && (s.level >= 1 || s.planar.level >= 1) && q == s.q_cache;
}
/// True when v_cache holds v for the cached q in either representation (after same_q).
template <root_joint Root>
bool same_v(const workspace<Root>& ws, const Eigen::Ref<const Eigen::VectorXd>& v) {
  const auto& s = ws.scratch;
  return (s.level >= 2 || s.planar.level >= 2) && v == s.v_cache;
}

/// Makes the 6D scratch's poses current for q (recomputing only when q or the model differ from
/// the cached ones). The algorithms that need the 6D scratch (rnea, crba, Jacobians) use this.
template <root_joint Root>
void ensure_poses(const model<Root>& m, workspace<Root>& ws,
                  const Eigen::Ref<const Eigen::VectorXd>& q) {
  auto& s = ws.scratch;
  const bool sq = same_q(m, ws, q);
  if (sq && s.level >= 1) return;
  if (!sq) s.planar.level = 0;
  update_poses(m, ws, q);
  s.q_cache = q;
  s.model_id = &m;
  s.level = 1;
}

/// Makes the 6D scratch's poses and velocities current for (q, v).
template <root_joint Root>
void ensure_kinematics(const model<Root>& m, workspace<Root>& ws,
                       const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& v) {
  auto& s = ws.scratch;
  const bool sq = same_q(m, ws, q);
  if (sq && s.level >= 2 && v == s.v_cache) return;
  if (!sq)
    s.planar.level = 0;
  else if (!same_v(ws, v))
    s.planar.level = std::min(s.planar.level, 1);
  if (!(sq && s.level >= 1)) {
    update_poses(m, ws, q);
    s.q_cache = q;
    s.model_id = &m;
  }
  update_velocities(m, ws, v);
  s.v_cache = v;
  s.level = 2;
}

/// Makes the public poses current for q, through the planar fast path when the model has one
/// (forward_kinematics, aba and everything the rollout calls per step use this).
template <root_joint Root>
void ensure_poses_fast(const model<Root>& m, workspace<Root>& ws,
                       const Eigen::Ref<const Eigen::VectorXd>& q) {
  if constexpr (std::is_same_v<Root, planar_root>) {
    auto& s = ws.scratch;
    if (s.planar.enabled) {
      if (same_q(m, ws, q)) return;  // the public poses are current in either representation
      s.level = 0;
      update_poses_planar(m, ws, q);
      s.q_cache = q;
      s.model_id = &m;
      s.planar.level = 1;
      return;
    }
  }
  ensure_poses(m, ws, q);
}

/// Makes the public poses and velocities current for (q, v), with the planar scratch when the
/// model has the planar fast path (what aba needs).
template <root_joint Root>
void ensure_kinematics_fast(const model<Root>& m, workspace<Root>& ws,
                            const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v) {
  if constexpr (std::is_same_v<Root, planar_root>) {
    auto& s = ws.scratch;
    auto& P = s.planar;
    if (P.enabled) {
      const bool sq = same_q(m, ws, q);
      if (sq && P.level >= 2 && v == s.v_cache) return;
      if (!sq)
        s.level = 0;
      else if (!same_v(ws, v))
        s.level = std::min(s.level, 1);
      if (!(sq && P.level >= 1)) {
        update_poses_planar(m, ws, q);
        s.q_cache = q;
        s.model_id = &m;
      }
      update_velocities_planar(m, ws, v);
      s.v_cache = v;
      P.level = 2;
      return;
    }
  }
  ensure_kinematics(m, ws, q, v);
}

}  // namespace detail

/// Body poses (ws.body_rotation, ws.body_position) for configuration q (size nq).
/// \throws std::invalid_argument if q or the workspace has the wrong size.
template <root_joint Root>
void forward_kinematics(const model<Root>& m, workspace<Root>& ws,
                        const Eigen::Ref<const Eigen::VectorXd>& q) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::ensure_poses_fast(m, ws, q);
}

/// Body poses and velocities (also ws.body_angular_velocity, ws.body_linear_velocity) for (q, v).
/// \throws std::invalid_argument if q, v or the workspace has the wrong size.
template <root_joint Root>
void forward_kinematics(const model<Root>& m, workspace<Root>& ws,
                        const Eigen::Ref<const Eigen::VectorXd>& q,
                        const Eigen::Ref<const Eigen::VectorXd>& v) {
  detail::check_workspace(m, ws);
  detail::check_q(m, q);
  detail::check_v(m, v, "v (generalized velocities)");
  detail::ensure_kinematics_fast(m, ws, q, v);
}

/// World position of the point p_body (body frame) of `body` (after forward_kinematics).
template <root_joint Root>
vec3 point_position(const model<Root>& m, const workspace<Root>& ws, int body, const vec3& p_body) {
  (void)m;
  return ws.body_position[body] + ws.body_rotation[body] * p_body;
}

/// World velocity of the point p_body (body frame) of `body` (after forward_kinematics with v).
/// \throws std::logic_error if the workspace holds no velocities for its current configuration.
template <root_joint Root>
vec3 point_velocity(const model<Root>& m, const workspace<Root>& ws, int body, const vec3& p_body) {
  (void)m;
  // Either scratch set's velocities are current: both write the public ones.
  detail::require_kinematics(std::max(ws.scratch.level, ws.scratch.planar.level), 2,
                             "point_velocity");
  return ws.body_linear_velocity[body] +
         ws.body_angular_velocity[body].cross(ws.body_rotation[body] * p_body);
}

}  // namespace gaitsynth
