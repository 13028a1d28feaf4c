#pragma once
/// \file penalty_contact.hpp
/// Penalty (spring-damper) ground contact at the model's contact points, with Coulomb friction
/// through a tangential anchor spring (docs/contact.md has the equations and the reasons for the
/// parameter values).
///
/// For every contact point P (body b, world position p, world velocity v), with depth d and unit
/// outward normal n from terrain_penetration(terrain, p) and v_n = n.v (> 0: separating):
///
///   normal force      f_n = max(0, kp d - kd' v_n)                       (no pulling)
///   first touch       anchor a := p                                      (d crosses 0)
///   tangential force  f_t = -kt (p - a)_t - bt' v_t       (x_t: x minus its component along n)
///   Coulomb cone      if |f_t| > mu f_n: f_t := mu f_n f_t / |f_t|, and the anchor moves to
///                     a := p + f_t / kt, so the anchor spring alone sits on the cone (sliding)
///   force on body b   f = f_n n + f_t, applied at p (add_point_force into ws.f_ext)
///
/// Defaults: kp = 75000 N/m, kd = 2000 N s/m (Wang et al. 2009, sec. 6, who used ODE at 2400 Hz),
/// mu = 1 (configurable; Wang used 10, 0.8 and 0.3), kt = kp and bt = kd (see contact_parameters).
///
/// kd' and bt' are the damping coefficients after the implicit-damping correction (on by default):
/// ODE solves its spring-damper contact implicitly, but here the force is explicit, and
/// kd = 2000 N s/m per point on a light body (a 0.1-0.2 kg toe, whose effective mass at a corner is
/// a few tens of grams) makes kd dt / m >> 2 at 2400 Hz: the damper reverses the velocity each step
/// and the toe explodes. So each damper uses the force backward Euler would give for that point on
/// its body alone, shared by the n_b touching points of the body:
///
///   kd' = kd / (1 + n_b kd dt / m_eff(n)),   bt' = bt / (1 + n_b bt dt / m_eff(t)),
///   1 / m_eff(u) = 1 / m_b + (r x u)^T I_b^-1 (r x u),  r = p - com_b (world),
///
/// the effective mass of the free body at P along u. Joints only add inertia, so this is a lower
/// bound of the true effective mass, which keeps every damper stable; on heavy bodies kd' ~ kd.
/// The springs stay explicit (kp, kt with the lightest toe points keep dt * omega < 2 at 2400 Hz).
///
/// Contact counts (Wang et al. 2009's objective needs "3 or more points of contact" on the stance
/// foot or toe and "the top of the swing toe in contact"): a point touches while d > 0.
///
/// Broad phase (3D path): a body whose contact points all lie within its reach r_b of its origin
/// (the largest |point|, body frame) is skipped while its origin is more than r_b (plus 1 nm for
/// rounding) above terrain_max_height over the disc of radius r_b below it: none of its points can
/// touch, so the forces, anchors and counts are exactly those of the full pass. A skipped point's
/// depth is minus its body's vertical clearance bound (negative, not its own depth along the
/// normal), and its position and normal are not updated. The 43 body
/// points of the Wang 2009 humanoid never touch while it walks; this keeps them nearly free.
/// Terrains without a height bound (terrain_max_height = +infinity) skip nothing.
///
/// No allocation: contact_state is sized once by make_contact_state(model).
#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Contact model constants (SI units). One set for all points.
struct contact_parameters {
  double kp = 75000.0;  ///< normal stiffness per point, N/m (Wang et al. 2009)
  double kd = 2000.0;   ///< normal damping per point, N s/m (Wang et al. 2009)
  double mu = 1.0;      ///< Coulomb friction coefficient (>= 0)
  /// Tangential anchor stiffness per point, N/m. Equal to kp so that the sticking deflection is at
  /// most mu times the normal penetration (mu f_n / kt = mu d) -- about 1 mm for a standing
  /// 70 kg character with mu = 1 -- and the tangential modes are no stiffer, hence no less stable,
  /// than the normal ones at the papers' 2400 Hz.
  double kt = 75000.0;
  /// Tangential damping per point, N s/m. Equal to kd for the same reason: the anchor spring then
  /// has the normal direction's damping ratio, and sticking feet do not ring.
  double bt = 2000.0;
  /// Use the implicit-Euler damping coefficients kd', bt' (file comment). Off: plain kd and bt.
  bool implicit_damping = true;
};

/// Throws std::invalid_argument naming the first bad parameter.
inline void validate(const contact_parameters& p) {
  check_positive(p.kp, "contact_parameters.kp (N/m)");
  check_argument(std::isfinite(p.kd) && p.kd >= 0.0,
                 "contact_parameters.kd (N s/m) must be finite and >= 0, got ", p.kd);
  check_argument(std::isfinite(p.mu) && p.mu >= 0.0,
                 "contact_parameters.mu must be finite and >= 0, got ", p.mu);
  check_positive(p.kt, "contact_parameters.kt (N/m)");
  check_argument(std::isfinite(p.bt) && p.bt >= 0.0,
                 "contact_parameters.bt (N s/m) must be finite and >= 0, got ", p.bt);
}

/// Per-rollout contact state: friction anchors (they persist between steps), and this step's
/// forces and counts. Index k follows model.contact_points, b follows model.bodies.
struct contact_state {
  // ---- per contact point --------------------------------------------------------------------
  std::vector<vec3> anchor;           ///< friction anchor, world, m (meaningful while active)
  std::vector<std::uint8_t> active;   ///< 1 while the point is below the terrain (d > 0)
  std::vector<std::uint8_t> sliding;  ///< 1 if friction was on the cone this step
  // position and normal are this step's for the points the broad phase did not skip (file
  // comment); a skipped point keeps its last ones, and its depth is minus its body's clearance.
  std::vector<vec3> position;        ///< world position p of the point this step, m
  std::vector<double> depth;         ///< penetration d, m (<= 0: not touching)
  std::vector<vec3> normal;          ///< terrain normal n used this step (world)
  std::vector<double> normal_force;  ///< f_n >= 0, N
  std::vector<vec3> force;           ///< total contact force f = f_n n + f_t on the body, world, N
  // ---- per body -----------------------------------------------------------------------------
  std::vector<int> points_touching;            ///< number of its points with d > 0
  std::vector<std::uint8_t> toe_top_touching;  ///< 1 if one of its toe_top points touches
  // ---- totals -------------------------------------------------------------------------------
  int total_points_touching = 0;
  bool any_toe_top_touching = false;
  // ---- cached from the model by make_contact_state ------------------------------------------
  std::vector<double> inv_mass;   ///< per body, 1/kg
  std::vector<mat3> inv_inertia;  ///< per body, about its COM, body axes, 1/(kg m^2)
  /// per body, the largest distance of its contact points from its origin, m (-1: no points)
  std::vector<double> reach;
  /// scratch: per body, 1 if the broad phase found it near the terrain this step
  std::vector<std::uint8_t> near;
  /// scratch: per body, how far its lowest possible point is above the terrain bound, m
  std::vector<double> clearance;
  std::vector<mat3> inv_inertia_world;  ///< scratch: R I^-1 R^T of touching bodies this step
  std::vector<vec3> com_offset_world;   ///< scratch: R com of touching bodies this step, m

  int num_points() const { return static_cast<int>(anchor.size()); }
  int num_bodies() const { return static_cast<int>(points_touching.size()); }

  /// Forgets all anchors and forces (start of a new rollout).
  void reset() {
    std::fill(anchor.begin(), anchor.end(), vec3::Zero());
    std::fill(active.begin(), active.end(), std::uint8_t{0});
    std::fill(sliding.begin(), sliding.end(), std::uint8_t{0});
    std::fill(position.begin(), position.end(), vec3::Zero());
    std::fill(depth.begin(), depth.end(), 0.0);
    std::fill(normal.begin(), normal.end(), vec3::UnitZ());
    std::fill(normal_force.begin(), normal_force.end(), 0.0);
    std::fill(force.begin(), force.end(), vec3::Zero());
    std::fill(points_touching.begin(), points_touching.end(), 0);
    std::fill(toe_top_touching.begin(), toe_top_touching.end(), std::uint8_t{0});
    total_points_touching = 0;
    any_toe_top_touching = false;
  }
};

/// A contact state sized for `m` (the only allocation contact needs).
template <root_joint Root>
contact_state make_contact_state(const model<Root>& m) {
  contact_state s;
  const auto np = m.contact_points.size();
  const auto nb = static_cast<std::size_t>(m.num_bodies());
  s.anchor.assign(np, vec3::Zero());
  s.active.assign(np, 0);
  s.sliding.assign(np, 0);
  s.position.assign(np, vec3::Zero());
  s.depth.assign(np, 0.0);
  s.normal.assign(np, vec3::UnitZ());
  s.normal_force.assign(np, 0.0);
  s.force.assign(np, vec3::Zero());
  s.points_touching.assign(nb, 0);
  s.toe_top_touching.assign(nb, 0);
  s.inv_mass.resize(nb);
  s.inv_inertia.resize(nb);
  s.inv_inertia_world.assign(nb, mat3::Zero());
  s.com_offset_world.assign(nb, vec3::Zero());
  s.reach.assign(nb, -1.0);
  s.near.assign(nb, 1);
  s.clearance.assign(nb, 0.0);
  for (const contact_point& cp : m.contact_points) {
    double& r = s.reach[static_cast<std::size_t>(cp.body)];
    r = std::max(r, cp.position.norm());
  }
  for (std::size_t b = 0; b < nb; ++b) {
    s.inv_mass[b] = 1.0 / m.bodies[b].mass;
    s.inv_inertia[b] = m.bodies[b].inertia.inverse();  // positive definite (model_builder)
  }
  return s;
}

namespace detail {
/// |u|^2 / m_eff(u) for a (not necessarily unit) direction u: |u|^2 / m_b + (r x u)^T I_w^-1 (r x
/// u), the inverse effective mass of the free body at lever r (from its COM, world) along u, times
/// |u|^2.
#if defined(__GNUC__)
// Inlined into the per-point loop: called twice per touching point, a call costs more than it.
__attribute__((always_inline))
#endif
inline double
scaled_inverse_effective_mass(double inv_mass, const mat3& inv_inertia_world, const vec3& r,
                              const vec3& u) {
  const vec3 ru = r.cross(u);
  return inv_mass * u.squaredNorm() + ru.dot(inv_inertia_world * ru);
}

/// c / (1 + n c dt / m_eff): the backward-Euler damping coefficient (penalty_contact.hpp).
inline double implicit_damping(double c, int n, double dt, double inv_m_eff) {
  return c / (1.0 + n * c * dt * inv_m_eff);
}

/// Zeroes the per-body and total counts (start of pass 1).
inline void reset_counts(contact_state& s) {
  std::fill(s.points_touching.begin(), s.points_touching.end(), 0);
  std::fill(s.toe_top_touching.begin(), s.toe_top_touching.end(), std::uint8_t{0});
  s.total_points_touching = 0;
  s.any_toe_top_touching = false;
}

/// Pass 1 for point k at world position pw: depth and normal against terrain t, and the counts.
template <terrain T>
inline void record_point(const contact_point& cp, int k, const vec3& pw, const T& t,
                         contact_state& s) {
  s.position[k] = pw;
  const surface_contact c = terrain_penetration(t, pw);
  s.depth[k] = c.depth;
  s.normal[k] = c.normal;
  if (c.depth > 0.0) {
    ++s.points_touching[cp.body];
    ++s.total_points_touching;
    if (cp.role == contact_point::kind::toe_top) {
      s.toe_top_touching[cp.body] = 1;
      s.any_toe_top_touching = true;
    }
  }
}

/// A point that does not touch: no force, and its anchor is forgotten.
inline void release_point(contact_state& s, int k) {
  s.active[k] = 0;
  s.sliding[k] = 0;
  s.normal_force[k] = 0.0;
  s.force[k].setZero();
}

/// The force of touching point k (depth d > 0) from its kinematics and damping coefficients:
/// normal force, friction anchor and Coulomb cone (file comment); stores it in `s` and adds it to
/// the body's external wrench `f_ext` (the lever rb is from the body origin). Shared by the
/// general and the planar path, so both round alike.
#if defined(__GNUC__)
__attribute__((always_inline))  // once per touching point: a call costs more than it
#endif
inline void
apply_point_force(const contact_parameters& p, contact_state& s, vec6& f_ext, int k, const vec3& pw,
                  const vec3& rb, const vec3& n, double d, double vn, const vec3& vt, double kd,
                  double bt) {
  const double fn = std::max(0.0, p.kp * d - kd * vn);

  if (!s.active[k]) s.anchor[k] = pw;  // first touch
  s.active[k] = 1;
  const vec3 disp = pw - s.anchor[k];
  const vec3 disp_t = disp - n.dot(disp) * n;
  vec3 ft = -p.kt * disp_t - bt * vt;
  const double limit = p.mu * fn;
  // |ft| > limit compared squared (limit >= 0): the square root stays off the sticking path.
  const double ft2 = ft.squaredNorm();
  s.sliding[k] = 0;
  if (ft2 > limit * limit) {
    // Sliding: kinetic friction mu f_n against the would-be sticking force; the anchor follows so
    // that its spring alone is on the cone (and sticking resumes once the pull drops inside).
    const double ft_norm = std::sqrt(ft2);
    ft = ft_norm > 0.0 ? vec3(ft * (limit / ft_norm)) : vec3::Zero();
    s.anchor[k] = pw + ft / p.kt;
    s.sliding[k] = 1;
  }
  const vec3 f = fn * n + ft;
  s.normal_force[k] = fn;
  s.force[k] = f;
  f_ext.template head<3>() += rb.cross(f);
  f_ext.template tail<3>() += f;
}

/// |u|^2 / m_eff(u) for the planar path: with r, u in the x-z plane (r_y = u_y = 0), r x u is
/// (0, r_z u_x - r_x u_z, 0), so only the y-y entry of the world inverse inertia matters, and
/// under a rotation about y that entry is the body-frame I^-1_yy. Every term dropped here is an
/// exact zero in scaled_inverse_effective_mass, so both give the same double.
inline double scaled_inverse_effective_mass_planar(double inv_mass, double inv_inertia_yy,
                                                   const vec3& r, const vec3& u) {
  const double ru = r.z() * u.x() - r.x() * u.z();
  return inv_mass * u.squaredNorm() + ru * (inv_inertia_yy * ru);
}

/// apply_contact_forces for models on the planar fast path (every body frame a rotation about y,
/// R = [c 0 s; 0 1 0; -s 0 c]): the 3x3 products of the general path are written out on the
/// entries that are not structurally zero, and the effective masses use the y-y inverse inertia.
/// The structural zeros enter the general path only as exact zero terms, so this path returns the
/// same doubles (tests/contact/planar_contact.cpp compares them); a point whose lever or normal
/// leaves the x-z plane (a height field sloping across y) takes the general formula.
template <terrain T>
void apply_contact_forces_planar(const model<planar_root>& m, workspace<planar_root>& ws,
                                 const T& t, const contact_parameters& p, contact_state& s,
                                 double dt) {
  const int np = static_cast<int>(m.contact_points.size());
  // R p for a body-frame vector p, from R's four in-plane entries.
  auto rotate = [&](int b, const vec3& x) {
    const mat3& R = ws.body_rotation[b];
    return vec3(R(0, 0) * x.x() + R(0, 2) * x.z(), x.y(), R(2, 0) * x.x() + R(2, 2) * x.z());
  };
  reset_counts(s);
  for (int k = 0; k < np; ++k) {
    const contact_point& cp = m.contact_points[k];
    record_point(cp, k, vec3(ws.body_position[cp.body] + rotate(cp.body, cp.position)), t, s);
  }
  for (int b = 0; b < s.num_bodies(); ++b)
    if (s.points_touching[b] > 0) s.com_offset_world[b] = rotate(b, m.bodies[b].com);

  for (int k = 0; k < np; ++k) {
    const contact_point& cp = m.contact_points[k];
    const double d = s.depth[k];
    if (!(d > 0.0)) {
      release_point(s, k);
      continue;
    }
    const int b = cp.body;
    const vec3& pw = s.position[k];
    const vec3 rb = pw - ws.body_position[b];
    const vec3 vw = ws.body_linear_velocity[b] + ws.body_angular_velocity[b].cross(rb);
    const vec3& n = s.normal[k];
    const double vn = n.dot(vw);
    const vec3 vt = vw - vn * n;
    const int nb = s.points_touching[b];
    const vec3 r = rb - s.com_offset_world[b];

    double kd = p.kd, bt = p.bt;
    if (p.implicit_damping) {
      const double vt2 = vt.squaredNorm();
      double inv_n = 0.0, inv_t = 0.0;
      if (r.y() == 0.0 && n.y() == 0.0 && vt.y() == 0.0) {
        const double Iyy = s.inv_inertia[b](1, 1);
        inv_n = scaled_inverse_effective_mass_planar(s.inv_mass[b], Iyy, r, n);
        if (vt2 > 0.0) inv_t = scaled_inverse_effective_mass_planar(s.inv_mass[b], Iyy, r, vt);
      } else {
        const mat3& R = ws.body_rotation[b];
        const mat3 Iinv = R * s.inv_inertia[b] * R.transpose();
        inv_n = scaled_inverse_effective_mass(s.inv_mass[b], Iinv, r, n);
        if (vt2 > 0.0) inv_t = scaled_inverse_effective_mass(s.inv_mass[b], Iinv, r, vt);
      }
      kd = implicit_damping(p.kd, nb, dt, inv_n);
      if (vt2 > 0.0) bt = p.bt * vt2 / (vt2 + nb * p.bt * dt * inv_t);
    }
    apply_point_force(p, s, ws.f_ext[b], k, pw, rb, n, d, vn, vt, kd, bt);
  }
}
}  // namespace detail

/// Computes the penalty contact force at every contact point of `m` against terrain `t`, adds them
/// to ws.f_ext (accumulates: clear_external_wrenches first), updates anchors, forces and counts in
/// `s`. Needs forward_kinematics(m, ws, q, v) for the current state. Call it once per time step
/// (it moves the friction anchors); multi-stage integrators hold its forces over the step.
/// \param dt  the time step, s (finite, > 0; used by the implicit damping)
/// \throws std::invalid_argument if `s` was not made for a model like `m` or dt is bad.
template <root_joint Root, terrain T>
void apply_contact_forces(const model<Root>& m, workspace<Root>& ws, const T& t,
                          const contact_parameters& p, contact_state& s, double dt) {
  const int np = static_cast<int>(m.contact_points.size());
  check_argument(s.num_points() == np && s.num_bodies() == m.num_bodies() &&
                     static_cast<int>(s.reach.size()) == m.num_bodies(),
                 "contact_state has ", s.num_points(), " points and ", s.num_bodies(),
                 " bodies, but model '", m.name, "' has ", np, " and ", m.num_bodies(),
                 " (use make_contact_state(model))");
  check_positive(dt, "dt (time step, s)");
  if constexpr (std::is_same_v<Root, planar_root>) {
    if (ws.scratch.planar.enabled) {
      detail::apply_contact_forces_planar(m, ws, t, p, s, dt);
      return;
    }
  }

  // Broad phase (file comment): which bodies might touch.
  constexpr double rounding_margin = 1e-9;  // m, far above the rounding of a point's position
  for (int b = 0; b < s.num_bodies(); ++b) {
    const double r = s.reach[b];
    if (r < 0.0) continue;
    const vec3& o = ws.body_position[b];
    s.clearance[b] = o.z() - r - rounding_margin - terrain_max_height(t, o.x(), o.y(), r);
    s.near[b] = !(s.clearance[b] > 0.0);  // NaN: near, so the full pass sees it
  }

  // Pass 1: depths, normals and counts (the implicit damping shares each body among its touching
  // points, so counts come first).
  detail::reset_counts(s);
  for (int k = 0; k < np; ++k) {
    const contact_point& cp = m.contact_points[k];
    if (!s.near[cp.body]) {
      s.depth[k] = -s.clearance[cp.body];
      continue;
    }
    detail::record_point(cp, k, point_position(m, ws, cp.body, cp.position), t, s);
  }

  for (int b = 0; b < s.num_bodies(); ++b)
    if (s.points_touching[b] > 0) {
      const mat3& R = ws.body_rotation[b];
      s.com_offset_world[b].noalias() = R * m.bodies[b].com;
      if (p.implicit_damping)
        s.inv_inertia_world[b].noalias() = R * s.inv_inertia[b] * R.transpose();
    }

  // Pass 2: forces.
  for (int k = 0; k < np; ++k) {
    const contact_point& cp = m.contact_points[k];
    const double d = s.depth[k];
    if (!(d > 0.0)) {
      detail::release_point(s, k);
      continue;
    }
    const int b = cp.body;
    const vec3& pw = s.position[k];
    const vec3 rb = pw - ws.body_position[b];  // from the body origin
    const vec3 vw = ws.body_linear_velocity[b] + ws.body_angular_velocity[b].cross(rb);
    const vec3& n = s.normal[k];
    const double vn = n.dot(vw);
    const vec3 vt = vw - vn * n;
    const int nb = s.points_touching[b];
    const vec3 r = rb - s.com_offset_world[b];  // from the body's COM

    double kd = p.kd, bt = p.bt;
    if (p.implicit_damping) {
      const mat3& Iinv = s.inv_inertia_world[b];
      kd = detail::implicit_damping(
          p.kd, nb, dt, detail::scaled_inverse_effective_mass(s.inv_mass[b], Iinv, r, n));
      // bt / (1 + n bt dt X / |vt|^2) with X = |vt|^2 / m_eff(vt), as one division.
      const double vt2 = vt.squaredNorm();
      if (vt2 > 0.0)
        bt = p.bt * vt2 /
             (vt2 +
              nb * p.bt * dt * detail::scaled_inverse_effective_mass(s.inv_mass[b], Iinv, r, vt));
    }
    detail::apply_point_force(p, s, ws.f_ext[b], k, pw, rb, n, d, vn, vt, kd, bt);
  }
}

}  // namespace gaitsynth
