#pragma once
/// \file controllers/end_effector/half_cycle_plan.hpp
/// One half-cycle of Wu & Popovic 2010's end-effector path planner (Sec. 4, appendix A): planned
/// once at the start of the half-cycle by plan_half_cycle() from the task goal G, the parameters
/// Omega, the current end-effector poses, the previous half-cycle's upper-body deviation and the
/// terrain; then queried every tick, at the time t since the half-cycle began, for the desired
/// pose and twist of the upper body, the swing foot and the stance foot (the lower level's link
/// targets, frames.hpp). Planning allocates nothing (fixed-size arrays); queries are arithmetic.
///
/// Steps (appendix A): targets (planner_targets.hpp: eq. 8 for the swing foot, then A.2's edge
/// avoidance if enabled, eq. 9 and 10 for the upper body; the upper body's height uses the swing
/// foot's landing height, known once its path is built), then paths (swing_foot_path.hpp with the
/// terrain hull over t_h + t_e, upper_body_path.hpp over t_h). The stance foot (Fig. 5): it is
/// still finishing the previous half-cycle's swing for the first t_e' of this one, then
/// stationary at that swing's end; without a previous plan it is stationary where it stands. The
/// swing target is placed from that stationary position q_st.
///
/// Terrain-blind planning (setup.terrain_awareness = false, issue 12's claim 3): the swing path
/// samples a plane at the stance foot's ground level (its reference height minus its box's
/// plane clearance) instead of the terrain, and the target pitch is 0.
#include <Eigen/Core>
#include <cmath>
#include <span>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/controllers/end_effector/foot_clearance.hpp"
#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/planner_parameters.hpp"
#include "gaitsynth/controllers/end_effector/planner_targets.hpp"
#include "gaitsynth/controllers/end_effector/planner_timing.hpp"
#include "gaitsynth/controllers/end_effector/swing_foot_path.hpp"
#include "gaitsynth/controllers/end_effector/upper_body_path.hpp"

namespace gaitsynth {

/// A position and rotation (world).
struct end_effector_pose {
  vec3 position = vec3::Zero();
  mat3 rotation = mat3::Identity();
};

/// What the planner reads at the start of a half-cycle.
struct planner_input {
  /// The upper body: its planned point (setup.upper_body_point, world) and rotation.
  end_effector_pose upper_body;
  end_effector_pose stance_foot;  ///< foot link origin (ankle) and rotation
  end_effector_pose swing_foot;
  stance_side stance = stance_side::left;
  double previous_facing = 0.0;  ///< psi_f' (replaced by the previous plan's psi_f if given)
  /// dq'_ub,eh: the upper body's horizontal deviation from the previous half-cycle's target at its
  /// end, world axes (upper_body_deviation() computes it); zero for the first half-cycle.
  vec2 upper_body_deviation = vec2::Zero();
};

/// Desired pose and twist of each end-effector *link* (body origins, as the lower level's
/// link_target wants).
struct end_effector_targets {
  link_target upper_body, stance_foot, swing_foot;
};

struct half_cycle_plan {
  task_goal goal;
  half_cycle_timing timing;
  stance_side stance = stance_side::left;
  vec3 upper_body_point = vec3::Zero();   ///< the planned point in the upper body's frame
  vec2 swing_target = vec2::Zero();       ///< q_sw,es after edge avoidance
  vec2 edge_shift = vec2::Zero();         ///< dq_a (zero without edge avoidance)
  vec3 upper_body_target = vec3::Zero();  ///< p_ub,eh (planned point)
  mat3 upper_body_target_rotation = mat3::Identity();
  upper_body_path upper_body;
  swing_foot_path swing;
  link_target stance_rest;   ///< the stance foot once stationary
  bool has_tail = false;     ///< the stance foot finishes the previous swing first
  swing_foot_path tail;      ///< that swing (its own time origin: t + tail_offset)
  double tail_offset = 0.0;  ///< the previous half-cycle's t_h
  double tail_end = 0.0;     ///< t_e': the tail runs for t < t_e'

  /// The targets at time t since the half-cycle began (t > t_h keeps the upper body at its end;
  /// the swing foot runs to t_h + t_e). No allocation.
  end_effector_targets at(double t) const {
    end_effector_targets out;
    const link_target ub = upper_body.at(t);
    const vec3 r = ub.rotation * upper_body_point;
    out.upper_body = ub;
    out.upper_body.position = ub.position - r;
    out.upper_body.velocity = ub.velocity - ub.angular_velocity.cross(r);
    out.swing_foot = swing.at(t);
    out.stance_foot = (has_tail && t < tail_end) ? tail.at(t + tail_offset) : stance_rest;
    return out;
  }

  /// The same as the lower level's link order of biped_end_effector_layout (upper body, left foot,
  /// right foot): writes targets[0..2].
  void link_targets(double t, std::span<link_target> targets) const {
    check_size(static_cast<std::ptrdiff_t>(targets.size()), 3, "half_cycle_plan::link_targets");
    const end_effector_targets e = at(t);
    targets[0] = e.upper_body;
    targets[stance == stance_side::left ? 1 : 2] = e.stance_foot;
    targets[stance == stance_side::left ? 2 : 1] = e.swing_foot;
  }
};

/// dq'_ub,eh for the next half-cycle: where the upper body's planned point is (world) at the end of
/// `previous`, minus that plan's target, horizontal.
inline vec2 upper_body_deviation(const half_cycle_plan& previous, const vec3& upper_body_point) {
  return (upper_body_point - previous.upper_body_target).head<2>();
}

namespace detail {
inline void check_pose(const end_effector_pose& p, const char* what,
                       const char* where = "plan_half_cycle") {
  for (int i = 0; i < 3; ++i)
    check_argument(std::isfinite(p.position[i]), where, ": ", what, ".position[", i,
                   "] must be finite, got ", p.position[i]);
  for (int i = 0; i < 9; ++i)
    check_argument(std::isfinite(p.rotation.data()[i]), where, ": ", what, ".rotation entry ", i,
                   " must be finite, got ", p.rotation.data()[i]);
}
}  // namespace detail

/// Plans one half-cycle (appendix A). `previous` (may be null) is the plan of the half-cycle
/// that just ended: its swing becomes this plan's stance-foot tail, its psi_f is psi_f'.
/// \throws std::invalid_argument naming the value for a non-finite goal, parameter, setup value or
/// pose, t_h <= 0, t_e < 0, gamma / control-point u outside [0, 1], or stance_side::none.
template <terrain T>
half_cycle_plan plan_half_cycle(const task_goal& goal, const planner_parameters& omega,
                                const planner_setup& setup, const planner_input& in,
                                const T& terrain, const half_cycle_plan* previous = nullptr) {
  validate(goal);
  validate(omega);
  validate(setup);
  check_argument(in.stance != stance_side::none,
                 "plan_half_cycle: the stance foot must be left or right, got none");
  detail::check_pose(in.upper_body, "upper_body");
  detail::check_pose(in.stance_foot, "stance_foot");
  detail::check_pose(in.swing_foot, "swing_foot");
  detail::check_finite_value(in.previous_facing, "plan_half_cycle: previous_facing");
  detail::check_finite_vec(in.upper_body_deviation, "plan_half_cycle: upper_body_deviation");

  half_cycle_plan plan;
  plan.goal = goal;
  plan.timing = make_half_cycle_timing(setup.t_h, omega.t_e);
  plan.stance = in.stance;
  plan.upper_body_point = setup.upper_body_point;

  // The stance foot: stationary where the previous swing ends, or where it stands (Fig. 5).
  if (previous != nullptr) {
    plan.has_tail = previous->timing.t_e > 0.0;
    plan.tail = previous->swing;
    plan.tail_offset = previous->timing.t_h;
    plan.tail_end = previous->timing.t_e;
    plan.stance_rest = previous->swing.at_s(1.0, 0.0);
  } else {
    plan.stance_rest.position = in.stance_foot.position;
    plan.stance_rest.rotation = in.stance_foot.rotation;
  }
  const double psi_prev = previous != nullptr ? previous->goal.facing : in.previous_facing;
  const vec2 q_st = plan.stance_rest.position.head<2>();
  const vec2 d0 = neutral_midpoint_offset(in.stance, setup.foot_half_spacing);

  // Eq. 8 and A.2's edge avoidance.
  vec2 q_sw =
      swing_foot_horizontal_target(q_st, goal, omega, psi_prev, d0, in.upper_body_deviation);
  if (setup.edge_avoidance && setup.terrain_awareness) {
    plan.edge_shift = edge_avoidance_shift(terrain, setup.foot, q_sw, goal.facing, goal.movement,
                                           setup.edge_search_fraction, setup.footprint_along,
                                           setup.footprint_across);
    q_sw += plan.edge_shift;
  }
  plan.swing_target = q_sw;

  // The swing-foot path (A.3) with its terrain hull.
  swing_path_ends ends;
  ends.start = in.swing_foot.position;
  const vec2 yp = foot_yaw_pitch(in.swing_foot.rotation);
  ends.psi_start = yp.x();
  ends.theta_start = yp.y();
  ends.target = q_sw;
  ends.psi_end = goal.facing;
  const double footstep = plan.timing.footstep_duration();
  if (setup.terrain_awareness) {
    ends.theta_end = terrain_pitch(terrain, q_sw, goal.facing);
    plan.swing = make_swing_foot_path(ends, omega, footstep, setup, terrain);
  } else {
    const mat3& Rst = plan.stance_rest.rotation;
    const double ground = plan.stance_rest.position.z() - plane_clearance(setup.foot, Rst).height;
    ends.theta_end = 0.0;
    plan.swing = make_swing_foot_path(ends, omega, footstep, setup, flat_terrain(ground));
  }
  const double swing_landing_z = plan.swing.at_s(1.0, 0.0).position.z();

  // Eqs. 9 and 10 and the upper-body path.
  const vec2 q_ub =
      upper_body_horizontal_target(q_st, goal, omega, psi_prev, d0, in.upper_body_deviation) +
      omega.alpha_a * plan.edge_shift;
  plan.upper_body_target =
      vec3(q_ub.x(), q_ub.y(),
           upper_body_target_height(plan.stance_rest.position.z(), swing_landing_z, omega));
  plan.upper_body_target_rotation = upper_body_target_rotation(goal, omega);
  plan.upper_body =
      make_upper_body_path(in.upper_body.position, in.upper_body.rotation, plan.upper_body_target,
                           plan.upper_body_target_rotation, omega, setup.t_h, goal.movement);
  return plan;
}

/// Ours (planned_walk_options::stance_target = touchdown; the paper keeps Fig. 5's planned end):
/// the stance foot's stationary target taken where the foot touched down, `foot` its sensed pose.
/// The foot keeps its sensed yaw and horizontal position; its pitch and height are those of a foot
/// resting on the ground there (the terrain's slope along the yaw and the box's lowest
/// collision-free height, as a swing target's), or, planning blind, level on the plane the plan's
/// stance foot rests on. So the frames of a foot that landed off its planned spot are pinned (Sec.
/// 6.3) instead of being dragged toward it.
template <terrain T>
link_target touchdown_stance_target(const planner_setup& setup, const end_effector_pose& foot,
                                    const half_cycle_plan& plan, const T& terrain) {
  detail::check_pose(foot, "foot", "touchdown_stance_target");
  const vec2 q = foot.position.head<2>();
  const double yaw = foot_yaw_pitch(foot.rotation).x();
  link_target target;
  if (setup.terrain_awareness) {
    target.rotation = foot_rotation(yaw, terrain_pitch(terrain, q, yaw));
    target.position << q,
        lowest_collision_free_height(terrain, setup.foot, target.rotation, q, setup.footprint_along,
                                     setup.footprint_across);
  } else {
    const mat3& Rst = plan.stance_rest.rotation;
    const double ground = plan.stance_rest.position.z() - plane_clearance(setup.foot, Rst).height;
    target.rotation = foot_rotation(yaw, 0.0);
    target.position << q, ground + plane_clearance(setup.foot, target.rotation).height;
  }
  return target;
}

}  // namespace gaitsynth
