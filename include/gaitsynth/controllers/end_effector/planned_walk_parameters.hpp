#pragma once
/// \file controllers/end_effector/planned_walk_parameters.hpp
/// The optimized part of one half-cycle's planner parameters Omega (Wu & Popovic 2010, Table 1) as
/// a flat vector, and the left/right mirror image of Omega (for symmetric controllers, Table 1's
/// caption: "Each half-cycle in a controller has its own path planning parameters, except for
/// symmetric controllers").
///
/// The vector holds exactly Table 1's planner unknowns (25 values, planner_vector_names' order);
/// the components of planner_parameters that Table 1 does not list (the lateral l of the control
/// points, the upper-body control points' v, alpha_a) are not optimized and come from a base
/// planner_parameters. Lateral components are "left" (+y of psi_m's frame, planner_parameters.hpp).
#include <array>
#include <cstddef>
#include <span>
#include <utility>

#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

inline constexpr std::size_t planner_vector_size = 25;

/// Table 1's planner unknowns, in the flat vector's order ("along" and "left" are psi_m's local
/// axes; u, v the control points' distance along the chord and height).
inline constexpr std::array<const char*, planner_vector_size> planner_vector_names{
    "t_e",
    "k_sw_plus.along",
    "k_sw_plus.left",
    "k_sw_minus.along",
    "k_sw_minus.left",
    "c_sw.along",
    "c_sw.left",
    "k_ub.along",
    "k_ub.left",
    "c_ub.along",
    "c_ub.left",
    "z_ub",
    "theta_ub",
    "phi_ub",
    "psi_ub",
    "gamma1",
    "gamma2",
    "w_sw1.u",
    "w_sw1.v",
    "w_sw2.u",
    "w_sw2.v",
    "theta_sw1",
    "theta_sw2",
    "w_ub1.u",
    "w_ub2.u"};

/// Omega's Table 1 components as a flat vector (planner_vector_names' order).
inline std::array<double, planner_vector_size> to_planner_vector(const planner_parameters& p) {
  return {p.t_e,       p.k_sw_plus.x(), p.k_sw_plus.y(), p.k_sw_minus.x(), p.k_sw_minus.y(),
          p.c_sw.x(),  p.c_sw.y(),      p.k_ub.x(),      p.k_ub.y(),       p.c_ub.x(),
          p.c_ub.y(),  p.z_ub,          p.theta_ub,      p.phi_ub,         p.psi_ub,
          p.gamma1,    p.gamma2,        p.w_sw1.x(),     p.w_sw1.z(),      p.w_sw2.x(),
          p.w_sw2.z(), p.theta_sw1,     p.theta_sw2,     p.w_ub1.x(),      p.w_ub2.x()};
}

/// `base` with its Table 1 components replaced by v (planner_vector_names' order). No validation
/// (validate(planner_parameters) does it).
inline planner_parameters from_planner_vector(std::span<const double> v, planner_parameters base) {
  check_size(static_cast<std::ptrdiff_t>(v.size()),
             static_cast<std::ptrdiff_t>(planner_vector_size), "from_planner_vector");
  planner_parameters& p = base;
  p.t_e = v[0];
  p.k_sw_plus = vec2(v[1], v[2]);
  p.k_sw_minus = vec2(v[3], v[4]);
  p.c_sw = vec2(v[5], v[6]);
  p.k_ub = vec2(v[7], v[8]);
  p.c_ub = vec2(v[9], v[10]);
  p.z_ub = v[11];
  p.theta_ub = v[12];
  p.phi_ub = v[13];
  p.psi_ub = v[14];
  p.gamma1 = v[15];
  p.gamma2 = v[16];
  p.w_sw1.x() = v[17];
  p.w_sw1.z() = v[18];
  p.w_sw2.x() = v[19];
  p.w_sw2.z() = v[20];
  p.theta_sw1 = v[21];
  p.theta_sw2 = v[22];
  p.w_ub1.x() = v[23];
  p.w_ub2.x() = v[24];
  return p;
}

/// The mirror image of Omega across the sagittal plane of psi_m (left <-> right): the half-cycle
/// on the other stance foot of a symmetric walk. Lateral offsets (c_sw, c_ub, the control points'
/// l) change sign; the lateral K+ and K- entries swap (a deviation to the left becomes one to the
/// right, eq. 8's {.}+ and {.}- trade places); the upper body's roll phi_ub and yaw offset psi_ub
/// change sign (a mirror reverses rotations about the forward and vertical axes, keeps those about
/// the lateral one). Along-track components, K_ub (one gain per axis, sign-independent), heights,
/// pitches, timing and alpha_a are unchanged. (Stance-dependent geometry, d0 of Fig. 6, is the
/// planner's: neutral_midpoint_offset.) mirrored(mirrored(p)) == p.
inline planner_parameters mirrored(const planner_parameters& p) {
  planner_parameters m = p;
  m.k_sw_plus.y() = p.k_sw_minus.y();
  m.k_sw_minus.y() = p.k_sw_plus.y();
  m.c_sw.y() = -p.c_sw.y();
  m.c_ub.y() = -p.c_ub.y();
  m.phi_ub = -p.phi_ub;
  m.psi_ub = -p.psi_ub;
  m.w_sw1.y() = -p.w_sw1.y();
  m.w_sw2.y() = -p.w_sw2.y();
  m.w_ub1.y() = -p.w_ub1.y();
  m.w_ub2.y() = -p.w_ub2.y();
  return m;
}

}  // namespace gaitsynth
