#pragma once
/// \file controllers/end_effector/planner_targets.hpp
/// The planner's targets, Wu & Popovic 2010 appendix A.2, in our frame (x forward, y left, z up;
/// the mapping from the paper's +y-forward frame is in planner_parameters.hpp):
///
///   swing foot   q_sw,es = q_st + q_sw,0 + q_sw,bal                                       (8)
///                q_sw,0  = R_z(psi_f') d0 + R_z(psi_m) r x + R_z(psi_f) d0   (Fig. 6; the text
///                          prints R_z(psi_f) for the first term, its own "where psi_f' is the
///                          previous facing angle" and Fig. 6 say psi_f')
///                q_sw,bal = R_z(psi_m) (K+ {dq}+ + K- {dq}- + c_sw)
///                yaw psi_sw,es = psi_f; pitch theta_sw,es from the terrain slope at the target
///   upper body   q_ub,eh = q_st + q_ub,0 + q_ub,bal                                       (9)
///                q_ub,0  = R_z(psi_f') d0 + 1/2 R_z(psi_m) r x          (point (a) of Fig. 6)
///                q_ub,bal = R_z(psi_m) (K_ub dq + c_ub)
///                z_ub,eh = min(stance foot z, swing target z) + z_ub
///                R_ub,eh = R_z(psi_f) R_x(phi_ub) R_y(-theta_ub) R_z(psi_ub)              (10)
///
/// x is our forward unit vector (the paper's y). d0 is the offset from the stance foot to midway
/// between the feet in the neutral pose facing +x: (0, -|d0|) from a left stance foot, (0, +|d0|)
/// from a right one. dq = dq'_ub,eh is the upper body's horizontal deviation from the previous
/// half-cycle's target at its end, expressed in the local frame of psi_m (component 0 along psi_m,
/// 1 to its left; the paper says "computed in the local coordinate system" without saying whose
/// psi_m: ours is this half-cycle's, which keeps the plan orientation invariant); {.}+ and {.}- are
/// componentwise max(., 0) and min(., 0), K+, K-, K_ub diagonal.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/motion/stance_side.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

inline mat3 rotation_z(double a) {
  return Eigen::AngleAxisd(a, vec3::UnitZ()).toRotationMatrix();
}
inline mat3 rotation_y(double a) {
  return Eigen::AngleAxisd(a, vec3::UnitY()).toRotationMatrix();
}
inline mat3 rotation_x(double a) {
  return Eigen::AngleAxisd(a, vec3::UnitX()).toRotationMatrix();
}

/// R_z(a) on the horizontal plane.
inline vec2 rotate2(double a, const vec2& q) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * q.x() - s * q.y(), s * q.x() + c * q.y()};
}

/// The heading of a horizontal direction: the unit vector R_z(a) x.
inline vec2 heading2(double a) {
  return {std::cos(a), std::sin(a)};
}

/// The angle a wrapped to (-pi, pi].
inline double wrap_angle(double a) {
  constexpr double pi = std::numbers::pi;
  a = std::remainder(a, 2.0 * pi);
  return a <= -pi ? a + 2.0 * pi : a;
}

/// Fig. 6's d0 for the stance foot `side`, facing +x.
inline vec2 neutral_midpoint_offset(stance_side side, double half_spacing) {
  return {0.0, side == stance_side::left ? -half_spacing : half_spacing};
}

/// Eq. 8's goal-based placement q_sw,0 (Fig. 6's three vectors).
inline vec2 swing_goal_offset(const task_goal& g, double previous_facing, const vec2& d0) {
  return rotate2(previous_facing, d0) + g.step_length * heading2(g.movement) +
         rotate2(g.facing, d0);
}

/// Eq. 8's piecewise-linear balance adjustment q_sw,bal; `deviation_world` is dq'_ub,eh in world
/// axes (rotated here into psi_m's local frame).
inline vec2 swing_balance_offset(const task_goal& g, const planner_parameters& p,
                                 const vec2& deviation_world) {
  const vec2 dq = rotate2(-g.movement, deviation_world);
  const vec2 plus = dq.cwiseMax(0.0), minus = dq.cwiseMin(0.0);
  const vec2 local = p.k_sw_plus.cwiseProduct(plus) + p.k_sw_minus.cwiseProduct(minus) + p.c_sw;
  return rotate2(g.movement, local);
}

/// Eq. 8: the swing foot's horizontal target at the end of the footstep.
inline vec2 swing_foot_horizontal_target(const vec2& q_stance, const task_goal& g,
                                         const planner_parameters& p, double previous_facing,
                                         const vec2& d0, const vec2& deviation_world) {
  return q_stance + swing_goal_offset(g, previous_facing, d0) +
         swing_balance_offset(g, p, deviation_world);
}

/// Eq. 9's q_ub,0: midway along the goal movement from the point between the feet (point (a)).
inline vec2 upper_body_goal_offset(const task_goal& g, double previous_facing, const vec2& d0) {
  return rotate2(previous_facing, d0) + 0.5 * g.step_length * heading2(g.movement);
}

/// Eq. 9's linear balance adjustment q_ub,bal.
inline vec2 upper_body_balance_offset(const task_goal& g, const planner_parameters& p,
                                      const vec2& deviation_world) {
  const vec2 dq = rotate2(-g.movement, deviation_world);
  return rotate2(g.movement, p.k_ub.cwiseProduct(dq) + p.c_ub);
}

/// Eq. 9: the upper body's horizontal target at the end of the half-cycle.
inline vec2 upper_body_horizontal_target(const vec2& q_stance, const task_goal& g,
                                         const planner_parameters& p, double previous_facing,
                                         const vec2& d0, const vec2& deviation_world) {
  return q_stance + upper_body_goal_offset(g, previous_facing, d0) +
         upper_body_balance_offset(g, p, deviation_world);
}

/// Eq. 9's vertical component: the lower of the two feet at the end of the footstep plus z_ub.
inline double upper_body_target_height(double stance_foot_z, double swing_target_z,
                                       const planner_parameters& p) {
  return std::min(stance_foot_z, swing_target_z) + p.z_ub;
}

/// Eq. 10 (mapped to our frame, planner_parameters.hpp).
inline mat3 upper_body_target_rotation(const task_goal& g, const planner_parameters& p) {
  return rotation_z(g.facing) * rotation_x(p.phi_ub) * rotation_y(-p.theta_ub) *
         rotation_z(p.psi_ub);
}

/// Eq. 11's foot rotation R_z(psi) R_x(theta) in our frame: R_z(psi) R_y(-theta), theta > 0
/// raising the toes.
inline mat3 foot_rotation(double psi, double theta) {
  return rotation_z(psi) * rotation_y(-theta);
}

/// The yaw and pitch of a foot rotation (the inverse of foot_rotation, the twist about the foot's
/// long axis dropped: A.3 fixes it to 0): the foot's x axis is (cos th cos ps, cos th sin ps, sin
/// th).
inline vec2 foot_yaw_pitch(const mat3& R) {
  const vec3 a = R.col(0);
  return {std::atan2(a.y(), a.x()), std::asin(std::clamp(a.z(), -1.0, 1.0))};
}

/// A.2's target pitch theta_sw,es from the terrain slope: the angle of the ground's tangent along
/// the facing direction psi at (x, y) (> 0 where the ground rises ahead).
template <class Terrain>
double terrain_pitch(const Terrain& t, const vec2& q, double psi) {
  const vec3 n = t.normal(q.x(), q.y());
  const double along = n.x() * std::cos(psi) + n.y() * std::sin(psi);
  return std::atan2(-along, n.z());
}

}  // namespace gaitsynth
