#pragma once
/// \file configuration.hpp
/// Operations on generalized positions that respect the root's geometry (Pinocchio's
/// joint-configuration.hpp): the floating root's orientation is a unit quaternion (w, x, y, z)
/// whose velocity is the body-frame angular velocity, so q is not simply q + dt v.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "gaitsynth/detail/standard_normal.hpp"
#include "gaitsynth/detail/uniform01.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

namespace detail {
/// exp of a rotation vector as a unit quaternion (Taylor series near 0 keeps it exact to rounding).
inline quat quat_exp(const vec3& theta) {
  const double a = theta.norm();
  const double half = 0.5 * a;
  double k;  // sin(a/2) / a
  if (a < 1e-6)
    k = 0.5 - a * a / 48.0;
  else
    k = std::sin(half) / a;
  return quat(std::cos(half), k * theta.x(), k * theta.y(), k * theta.z());
}
/// log of a unit quaternion as a rotation vector (angle in [0, pi]).
inline vec3 quat_log(const quat& q0) {
  quat q = q0.w() < 0 ? quat(-q0.w(), -q0.x(), -q0.y(), -q0.z()) : q0;
  const vec3 xyz(q.x(), q.y(), q.z());
  const double s = xyz.norm();
  const double a = 2.0 * std::atan2(s, q.w());
  if (s < 1e-12) return 2.0 * xyz / q.w();
  return (a / s) * xyz;
}
}  // namespace detail

/// q_out = q "+" v dt: joints and translations move by v dt; the floating root's quaternion is
/// multiplied on the right by exp(omega_body dt / 2) (body-frame angular velocity) and
/// renormalized. q_out may be the same vector as q. \throws std::invalid_argument on wrong sizes.
template <root_joint Root>
void integrate_configuration(const model<Root>& m, const Eigen::Ref<const Eigen::VectorXd>& q,
                             const Eigen::Ref<const Eigen::VectorXd>& v, double dt,
                             Eigen::Ref<Eigen::VectorXd> q_out) {
  check_size(q.size(), m.nq(), "q (generalized positions)");
  check_size(v.size(), m.nv(), "v (generalized velocities)");
  check_size(q_out.size(), m.nq(), "q_out (generalized positions)");
  constexpr int nqr = Root::nq, nvr = Root::nv;
  if constexpr (std::is_same_v<Root, floating_root>) {
    const quat q0(q[3], q[4], q[5], q[6]);
    const quat q1 = (q0 * detail::quat_exp(dt * v.template segment<3>(3))).normalized();
    q_out.template head<3>() = q.template head<3>() + dt * v.template head<3>();
    q_out[3] = q1.w();
    q_out[4] = q1.x();
    q_out[5] = q1.y();
    q_out[6] = q1.z();
  } else if constexpr (nqr > 0) {
    q_out.template head<nqr>() = q.template head<nqr>() + dt * v.template head<nvr>();
  }
  const int nj = m.num_joint_dofs();
  q_out.segment(nqr, nj) = q.segment(nqr, nj) + dt * v.segment(nvr, nj);
}

/// v_out such that integrate_configuration(m, q0, v_out, 1) == q1 (the inverse of integrate; for
/// the quaternion, the body-frame rotation vector of q0^-1 q1 with angle in [0, pi]).
template <root_joint Root>
void difference_configuration(const model<Root>& m, const Eigen::Ref<const Eigen::VectorXd>& q0,
                              const Eigen::Ref<const Eigen::VectorXd>& q1,
                              Eigen::Ref<Eigen::VectorXd> v_out) {
  check_size(q0.size(), m.nq(), "q0 (generalized positions)");
  check_size(q1.size(), m.nq(), "q1 (generalized positions)");
  check_size(v_out.size(), m.nv(), "v_out (generalized velocities)");
  constexpr int nqr = Root::nq, nvr = Root::nv;
  if constexpr (std::is_same_v<Root, floating_root>) {
    const quat a = quat(q0[3], q0[4], q0[5], q0[6]).normalized();
    const quat b = quat(q1[3], q1[4], q1[5], q1[6]).normalized();
    v_out.template head<3>() = q1.template head<3>() - q0.template head<3>();
    v_out.template segment<3>(3) = detail::quat_log(a.conjugate() * b);
  } else if constexpr (nqr > 0) {
    v_out.template head<nvr>() = q1.template head<nqr>() - q0.template head<nqr>();
  }
  const int nj = m.num_joint_dofs();
  v_out.segment(nvr, nj) = q1.segment(nqr, nj) - q0.segment(nqr, nj);
}

/// Renormalizes the floating root's quaternion in place (no-op for other roots).
/// \throws std::invalid_argument on a wrong size or a zero / non-finite quaternion.
template <root_joint Root>
void normalize_configuration(const model<Root>& m, Eigen::Ref<Eigen::VectorXd> q) {
  check_size(q.size(), m.nq(), "q (generalized positions)");
  if constexpr (std::is_same_v<Root, floating_root>) {
    const double n = q.template segment<4>(3).norm();
    check_argument(std::isfinite(n) && n > 0.0, "q: root quaternion has norm ", n,
                   " and cannot be normalized");
    q.template segment<4>(3) /= n;
  }
}

/// A random configuration drawn from `rng` with the library's portable variates (the same numbers
/// for the same seed on every standard library; optimizers/random.hpp says why not the std::
/// distributions, so the engine is std::mt19937_64, as everywhere in gaitsynth). With u =
/// detail::uniform01(rng) = (rng() >> 11) * 2^-53 in [0, 1), in this order: planar root x, z
/// uniform in [-1, 1) m (-1 + 2u) and pitch in [-pi, pi) (pi (-1 + 2u)); floating root translation
/// uniform in [-1, 1) m per coordinate, then a quaternion uniform on SO(3) (four standard normals
/// from detail::fill_standard_normal, normalized; redrawn in the practically impossible case of
/// norm < 1e-6); then each joint angle lo + (hi - lo) u, where [lo, hi] is its limit intersected
/// with [-pi, pi] (lo itself when that is empty).
template <root_joint Root>
Eigen::VectorXd random_configuration(const model<Root>& m, std::mt19937_64& rng) {
  constexpr double pi = std::numbers::pi;
  auto uniform_symmetric = [&rng] { return -1.0 + 2.0 * detail::uniform01(rng); };
  Eigen::VectorXd q(m.nq());
  if constexpr (std::is_same_v<Root, planar_root>) {
    q[0] = uniform_symmetric();
    q[1] = uniform_symmetric();
    q[2] = pi * uniform_symmetric();
  } else if constexpr (std::is_same_v<Root, floating_root>) {
    for (int i = 0; i < 3; ++i) q[i] = uniform_symmetric();
    Eigen::Vector4d gauss;
    do {
      detail::fill_standard_normal(rng, gauss);
    } while (gauss.norm() < 1e-6);
    q.template segment<4>(3) = gauss.normalized();
  }
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const double lo = std::max(m.dofs[j].limit.lower, -pi);
    const double hi = std::max(lo, std::min(m.dofs[j].limit.upper, pi));
    // lo + (hi - lo) u can round up past hi; the draw must stay within the limit.
    q[Root::nq + j] = std::min(hi, lo + (hi - lo) * detail::uniform01(rng));
  }
  return q;
}

}  // namespace gaitsynth
