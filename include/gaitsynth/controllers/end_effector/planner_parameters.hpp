#pragma once
/// \file controllers/end_effector/planner_parameters.hpp
/// The inputs of Wu & Popovic 2010's end-effector path planner (Sec. 4, appendix A): the task goal
/// G = (psi_f, psi_m, r), the planner parameters Omega (appendix A's underlined unknowns, tuned
/// by the offline optimization, Table 1's bounds) and the planner's fixed setup (character
/// geometry and switches, not optimized).
///
/// Convention mapping (the paper's frame -> ours). The paper's forward axis is +y, z up, so its x
/// axis points right; ours (models/wu2010.hpp) is x forward, y left, z up: ours = R_z(-90 deg)
/// paper. Both measure yaw counterclockwise about +z, so an angle psi "from the paper's y axis"
/// is the same number as psi "from our +x axis" and R_z(psi) is unchanged; the paper's unit
/// vector y (forward) becomes our x. The paper's R_x(theta) (about its rightward axis) becomes
/// our R_y(-theta) and its R_y(phi) (about its forward axis) our R_x(phi). So here:
///   - psi_f, psi_m: facing and movement directions, radians from +x, counterclockwise (left);
///   - foot pitch theta_sw (eq. 11's x orientation): positive raises the toes;
///     R_sw = R_z(psi_sw) R_y(-theta_sw);
///   - eq. 10: R_ub = R_z(psi_f) R_x(phi_ub) R_y(-theta_ub) R_z(psi_ub): theta_ub > 0 leans the
///     upper body back, phi_ub > 0 leans it right (both as the paper's R_x, R_y);
///   - 2D vectors "in the local frame" of psi_m (gains K, biases c): component 0 along the
///     movement direction, component 1 to its left.
#include <Eigen/Core>
#include <cmath>

#include "gaitsynth/error.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

using vec2 = Eigen::Vector2d;

/// The task goal G of Sec. 4 for one half-cycle.
struct task_goal {
  double facing = 0.0;       ///< psi_f: desired facing at the end of the half-cycle, rad from +x
  double movement = 0.0;     ///< psi_m: desired movement direction, rad from +x
  double step_length = 0.0;  ///< r: desired step length, m (Sec. 8.3: 0.65 forward, 0 standing)
};

/// Omega: one half-cycle's planner parameters, appendix A's underlined unknowns with Table 1's
/// bounds. The defaults are ours (a neutral plan: no balance feedback, no bias, a 6 cm swing-foot
/// lift, straight upper-body path); the optimization sets them. Control points of the paths are
/// 3D (u, l, v): u the normalized distance along the path's horizontal chord (0 at the start, 1 at
/// the target), l a lateral offset to the chord's left in m, v the height in m. The paper gives the
/// 2D (u, v) case and says its implementation used 3D control points; l = 0 is the 2D case.
struct planner_parameters {
  double t_e = 0.1;  ///< footstep extension, s (A.1)                  Table 1: [0, 0.6] x t_h
  // Swing-foot target, eq. 8's balance feedback q_sw,bal.
  vec2 k_sw_plus = vec2::Zero();   ///< K+ diagonal (along, left)     [0, 3]
  vec2 k_sw_minus = vec2::Zero();  ///< K- diagonal (along, left)     [0, 3]
  vec2 c_sw = vec2::Zero();        ///< c_sw, m (along, left)         [-0.3, 0.3]
  // Upper-body target, eq. 9's q_ub,bal, the height z_ub and eq. 10's angles.
  vec2 k_ub = vec2::Zero();  ///< K_ub diagonal (along, left); Table 1 names only K+-'s bounds
  vec2 c_ub = vec2::Zero();  ///< c_ub, m (along, left)               [-0.3, 0.3]
  /// z_ub: upper-body reference point above the lower foot's reference point at the end of the
  /// footstep, m. Table 1: [-0.3, 0.3] + z_ub0 (the natural height). Ours: for models/wu2010.hpp
  /// the upper body's COM stands 1.45 m above the ankles with straight legs; 1.40 bends the knees.
  double z_ub = 1.40;
  double theta_ub = 0.0;  ///< eq. 10 pitch, rad (> 0 leans back)      [-15, 15] deg
  double phi_ub = 0.0;    ///< eq. 10 roll, rad (> 0 leans right)      [-15, 15] deg
  double psi_ub = 0.0;    ///< eq. 10 yaw offset, rad                  [-30, 30] deg
  // Swing-foot path (A.3): type III in (u, l, v) and its timing gamma1, gamma2.
  double gamma1 = 1.0 / 3.0;          ///< time warp (gamma1 = 1/3, gamma2 = 2/3 is none) [0, 1]
  double gamma2 = 2.0 / 3.0;          ///<                                                 [0, 1]
  vec3 w_sw1 = vec3(0.1, 0.0, 0.08);  ///< u [0, 0.8], v [0, 0.8] m (l: ours, 0 in 2D)
  vec3 w_sw2 = vec3(0.9, 0.0, 0.08);  ///< u [0.2, 1.0], v [0, 0.8] m
  double theta_sw1 = 0.0;             ///< eq. 11 pitch control points, rad; Table 1 prints
  double theta_sw2 = 0.0;             ///< [-180, 80] deg (likely [-80, 80])
  // Upper-body path (A.3): type II in (u, l, v).
  vec3 w_ub1 = vec3(1.0 / 3.0, 0.0, 0.0);  ///< u [0, 0.66] (Table 1 lists only u)
  vec3 w_ub2 = vec3(2.0 / 3.0, 0.0, 0.0);  ///< u [0.33, 1]
  /// Edge avoidance (A.2): the upper-body target moves by alpha_a dq_a when the swing target moves
  /// by dq_a. Not in Table 1; ours 0.5 (the upper-body target is midway along the step).
  double alpha_a = 0.5;
};

/// A box fixed to the foot link (its oriented bounding box, A.3): centre and half extents in the
/// foot's body frame, m.
struct foot_box {
  vec3 center = vec3::Zero();
  vec3 half_extents = vec3::Zero();
};

/// The OBB of models/wu2010.hpp's foot (heel box, toe box and the plate over them, origin at the
/// ankle): x in [-0.06, 0.19], y in [-0.05, 0.05], z in [-0.06, -0.01].
inline foot_box wu2010_foot_box() {
  return {vec3(0.065, 0.0, -0.035), vec3(0.125, 0.05, 0.025)};
}

/// What the planner needs of the character and how it runs; fixed, not optimized.
struct planner_setup {
  double t_h = 0.55;  ///< half-cycle duration, s (Sec. 8.3: 0.55 for every walk)
  /// |d0|: the lateral offset from a foot to midway between the feet in the neutral pose (Fig. 6).
  /// models/wu2010.hpp's hip joints are 0.1 m to either side of the pelvis.
  double foot_half_spacing = 0.1;
  foot_box foot = wu2010_foot_box();  ///< the foot's reference point is the foot link's origin
  /// The upper body's planned point, in its body frame (ours: the COM of models/wu2010.hpp's upper
  /// body, 0.4 m above the waist joint; the LA frame of Sec. 5 sits there too).
  vec3 upper_body_point = vec3(0.0, 0.0, 0.4);
  /// Sampling of the foot box for collision-free heights (foot_clearance.hpp): a lattice of
  /// along x across x 2 (bottom and top faces) points, corners included.
  int footprint_along = 9;
  int footprint_across = 3;
  bool terrain_awareness = true;       ///< false: a terrain-blind planner (issue 12, claim 3)
  bool edge_avoidance = false;         ///< A.2's search at vertical drops
  double edge_search_fraction = 0.75;  ///< d_s = this x foot length (A.2: 0.75)
};

namespace detail {
inline void check_finite_value(double v, const char* what) {
  check_argument(std::isfinite(v), what, " must be finite, got ", v);
}
inline void check_finite_vec(const auto& v, const char* what) {
  for (int i = 0; i < static_cast<int>(v.size()); ++i)
    check_argument(std::isfinite(v[i]), what, "[", i, "] must be finite, got ", v[i]);
}
}  // namespace detail

/// \throws std::invalid_argument naming the component unless every angle and length is finite.
inline void validate(const task_goal& g) {
  detail::check_finite_value(g.facing, "task_goal: facing (psi_f)");
  detail::check_finite_value(g.movement, "task_goal: movement (psi_m)");
  detail::check_finite_value(g.step_length, "task_goal: step_length (r)");
}

/// \throws std::invalid_argument naming the parameter and value unless every parameter is finite,
/// t_e >= 0, gamma1, gamma2 and the swing control points' u in [0, 1] (these keep the swing path's
/// u(s) nondecreasing, which the terrain sampling inverts; path_curves.hpp).
inline void validate(const planner_parameters& p) {
  using detail::check_finite_value, detail::check_finite_vec;
  check_argument(std::isfinite(p.t_e) && p.t_e >= 0.0,
                 "planner_parameters: t_e must be finite and >= 0, got ", p.t_e);
  check_finite_vec(p.k_sw_plus, "planner_parameters: k_sw_plus");
  check_finite_vec(p.k_sw_minus, "planner_parameters: k_sw_minus");
  check_finite_vec(p.c_sw, "planner_parameters: c_sw");
  check_finite_vec(p.k_ub, "planner_parameters: k_ub");
  check_finite_vec(p.c_ub, "planner_parameters: c_ub");
  check_finite_value(p.z_ub, "planner_parameters: z_ub");
  check_finite_value(p.theta_ub, "planner_parameters: theta_ub");
  check_finite_value(p.phi_ub, "planner_parameters: phi_ub");
  check_finite_value(p.psi_ub, "planner_parameters: psi_ub");
  check_finite_vec(p.w_sw1, "planner_parameters: w_sw1");
  check_finite_vec(p.w_sw2, "planner_parameters: w_sw2");
  check_finite_value(p.theta_sw1, "planner_parameters: theta_sw1");
  check_finite_value(p.theta_sw2, "planner_parameters: theta_sw2");
  check_finite_vec(p.w_ub1, "planner_parameters: w_ub1");
  check_finite_vec(p.w_ub2, "planner_parameters: w_ub2");
  check_finite_value(p.alpha_a, "planner_parameters: alpha_a");
  const auto unit = [](double v, const char* what) {
    check_argument(v >= 0.0 && v <= 1.0, "planner_parameters: ", what, " must be in [0, 1], got ",
                   v);
  };
  unit(p.gamma1, "gamma1");
  unit(p.gamma2, "gamma2");
  unit(p.w_sw1.x(), "w_sw1.u");
  unit(p.w_sw2.x(), "w_sw2.u");
}

/// \throws std::invalid_argument naming the value unless the setup is usable.
inline void validate(const planner_setup& s) {
  check_argument(std::isfinite(s.t_h) && s.t_h > 0.0,
                 "planner_setup: t_h must be finite and > 0, got ", s.t_h);
  check_argument(std::isfinite(s.foot_half_spacing) && s.foot_half_spacing >= 0.0,
                 "planner_setup: foot_half_spacing must be finite and >= 0, got ",
                 s.foot_half_spacing);
  detail::check_finite_vec(s.foot.center, "planner_setup: foot.center");
  for (int i = 0; i < 3; ++i)
    check_argument(std::isfinite(s.foot.half_extents[i]) && s.foot.half_extents[i] > 0.0,
                   "planner_setup: foot.half_extents[", i, "] must be finite and > 0, got ",
                   s.foot.half_extents[i]);
  detail::check_finite_vec(s.upper_body_point, "planner_setup: upper_body_point");
  check_argument(s.footprint_along >= 2 && s.footprint_along <= 64,
                 "planner_setup: footprint_along must be in [2, 64], got ", s.footprint_along);
  check_argument(s.footprint_across >= 2 && s.footprint_across <= 64,
                 "planner_setup: footprint_across must be in [2, 64], got ", s.footprint_across);
  check_argument(std::isfinite(s.edge_search_fraction) && s.edge_search_fraction >= 0.0,
                 "planner_setup: edge_search_fraction must be finite and >= 0, got ",
                 s.edge_search_fraction);
}

}  // namespace gaitsynth
