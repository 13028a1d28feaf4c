// Wu & Popovic 2010's end-effector path planner (Sec. 4, appendix A; controllers/end_effector/
// path_curves.hpp ... half_cycle_plan.hpp): the curves of A.3 and their derivatives, A.1's timing,
// A.2's targets (eqs. 8-10, the piecewise-linear feedback, edge avoidance), the upper convex hull
// of Fig. 8, the swing-foot path over flat ground and a 0.1 m step, the upper-body path, the whole
// half-cycle plan's orientation invariance and stance-foot hand-over, and bad input refused with
// the value named.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/controllers/end_effector/half_cycle_plan.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

namespace {

constexpr double pi = std::numbers::pi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Central difference of f at s.
template <class F>
auto central(F f, double s, double h = 1e-6) {
  return decltype(f(s))((f(s + h) - f(s - h)) / (2.0 * h));
}

/// The angular velocity that maps R(s - h) to R(s + h), per unit s (world axes).
template <class F>
vec3 angular_rate(F R_of, double s, double h = 1e-6) {
  const Eigen::AngleAxisd aa(mat3(R_of(s + h) * R_of(s - h).transpose()));
  return aa.angle() * aa.axis() / (2.0 * h);
}

/// Smallest height of the foot box above the terrain, on a lattice finer than the planner's
/// (17 x 5 points on 3 layers: bottom, middle, top), for the foot link at `pose`.
template <class T>
double box_clearance(const T& t, const foot_box& b, const link_target& pose) {
  double lo = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 17; ++i)
      for (int j = 0; j < 5; ++j) {
        const vec3 p =
            b.center + vec3(b.half_extents.x() * (i / 8.0 - 1.0),
                            b.half_extents.y() * (j / 2.0 - 1.0), b.half_extents.z() * (k - 1.0));
        const vec3 w = pose.position + pose.rotation * p;
        lo = std::min(lo, w.z() - t.height(w.x(), w.y()));
      }
  return lo;
}

/// A forward step: left stance foot at (0, 0.1), right swing foot 0.3 m behind at (-0.3, -0.1),
/// both resting on z = 0 (ankle 0.06 above the ground), the upper body's COM over the middle.
planner_input forward_input() {
  planner_input in;
  in.stance = stance_side::left;
  in.stance_foot.position = vec3(0.0, 0.1, 0.06);
  in.swing_foot.position = vec3(-0.3, -0.1, 0.06);
  in.upper_body.position = vec3(-0.15, 0.0, 1.45);
  return in;
}

task_goal forward_goal() {
  return {0.0, 0.0, 0.65};
}

/// Rotates a whole input about the world z axis by a (positions about the origin).
planner_input rotated(const planner_input& in, double a) {
  planner_input r = in;
  const mat3 Rz = rotation_z(a);
  for (end_effector_pose* p : {&r.upper_body, &r.stance_foot, &r.swing_foot}) {
    p->position = Rz * p->position;
    p->rotation = Rz * p->rotation;
  }
  r.previous_facing += a;
  r.upper_body_deviation = rotate2(a, in.upper_body_deviation);
  return r;
}

void require_rotated(const link_target& a, const link_target& b, double angle) {
  const mat3 Rz = rotation_z(angle);
  CHECK((Rz * a.position - b.position).norm() < 1e-9);
  CHECK((Rz * a.velocity - b.velocity).norm() < 1e-9);
  CHECK((Rz * a.rotation - b.rotation).norm() < 1e-9);
  CHECK((Rz * a.angular_velocity - b.angular_velocity).norm() < 1e-9);
}

}  // namespace

TEST_CASE("path curves: types I, II, III and their derivatives (A.3)", "[end_effector][planner]") {
  // Type I: ends, zero end slopes, point symmetry about s = 1/2, the midpoint.
  CHECK(slow_in_out(0.0, 2.0, 5.0) == Approx(2.0));
  CHECK(slow_in_out(1.0, 2.0, 5.0) == Approx(5.0));
  CHECK(slow_in_out(0.5, 2.0, 5.0) == Approx(3.5));
  CHECK(slow_in_out_derivative(0.0, 2.0, 5.0) == Approx(0.0).margin(1e-15));
  CHECK(slow_in_out_derivative(1.0, 2.0, 5.0) == Approx(0.0).margin(1e-14));
  CHECK(slow_in_out_derivative(0.5, 2.0, 5.0) == Approx(1.5 * pi));
  for (double s : {0.1, 0.27, 0.4})
    CHECK(slow_in_out(1.0 - s, 2.0, 5.0) - 2.0 == Approx(5.0 - slow_in_out(s, 2.0, 5.0)));

  // Bernstein: partition of unity; B at the ends and its end tangents 3 (a1 - a0), 3 (a3 - a2).
  for (double s : {0.0, 0.3, 0.8, 1.0}) {
    const auto b = bernstein3(s);
    CHECK(b[0] + b[1] + b[2] + b[3] == Approx(1.0));
  }
  const double a0 = 1.0, a1 = 2.0, a2 = -1.0, a3 = 0.5;
  CHECK(bezier(0.0, a0, a1, a2, a3) == Approx(a0));
  CHECK(bezier(1.0, a0, a1, a2, a3) == Approx(a3));
  CHECK(bezier(0.5, a0, a1, a2, a3) == Approx((a0 + 3 * a1 + 3 * a2 + a3) / 8.0));
  CHECK(bezier_derivative(0.0, a0, a1, a2, a3) == Approx(3.0 * (a1 - a0)));
  CHECK(bezier_derivative(1.0, a0, a1, a2, a3) == Approx(3.0 * (a3 - a2)));

  // Type III with the identity warp (1/3, 2/3) is B; a warp keeps the ends.
  for (double s : {0.0, 0.2, 0.55, 0.9, 1.0}) {
    CHECK(bezier_time_warp(s, 1.0 / 3.0, 2.0 / 3.0) == Approx(s).margin(1e-15));
    CHECK(warped_bezier(s, a0, a1, a2, a3, 1.0 / 3.0, 2.0 / 3.0) ==
          Approx(bezier(s, a0, a1, a2, a3)));
    CHECK(warped_bezier_derivative(s, a0, a1, a2, a3, 1.0 / 3.0, 2.0 / 3.0) ==
          Approx(bezier_derivative(s, a0, a1, a2, a3)));
  }
  CHECK(warped_bezier(0.0, a0, a1, a2, a3, 0.9, 0.1) == Approx(a0));
  CHECK(warped_bezier(1.0, a0, a1, a2, a3, 0.9, 0.1) == Approx(a3));

  // Derivatives against central differences, scalar and vector, including s outside [0, 1].
  const vec3 p0(0, 0, 0), p1(0.2, 0.1, 0.3), p2(0.7, -0.2, 0.4), p3(1, 0, 0);
  for (double s : {-0.1, 0.05, 0.33, 0.61, 0.97, 1.2}) {
    CHECK(slow_in_out_derivative(s, -1.0, 3.0) ==
          Approx(central([&](double x) { return slow_in_out(x, -1.0, 3.0); }, s)).epsilon(1e-7));
    CHECK(bezier_derivative(s, a0, a1, a2, a3) ==
          Approx(central([&](double x) { return bezier(x, a0, a1, a2, a3); }, s)).epsilon(1e-7));
    CHECK(warped_bezier_derivative(s, a0, a1, a2, a3, 0.8, 0.3) ==
          Approx(central([&](double x) { return warped_bezier(x, a0, a1, a2, a3, 0.8, 0.3); }, s))
              .epsilon(1e-7));
    const vec3 dv = warped_bezier_derivative(s, p0, p1, p2, p3, 0.1, 0.9);
    const vec3 fd =
        central([&](double x) { return warped_bezier(x, p0, p1, p2, p3, 0.1, 0.9); }, s);
    CHECK((dv - fd).norm() < 1e-7);
    const vec3 dc = slow_in_out_derivative(s, p1, p2);
    CHECK((dc - central([&](double x) { return slow_in_out(x, p1, p2); }, s)).norm() < 1e-7);
  }

  // The warp is nondecreasing for any gamma in [0, 1] (what the terrain sampling relies on).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double g1 = U(rng), g2 = U(rng);
    for (int i = 0; i <= 50; ++i) CHECK(bezier_time_warp_derivative(i / 50.0, g1, g2) >= -1e-12);
  }
}

TEST_CASE("planner timing (A.1)", "[end_effector][planner]") {
  const half_cycle_timing t = make_half_cycle_timing(0.55, 0.11);
  CHECK(t.footstep_duration() == Approx(0.66));
  CHECK(t.s_h(0.275) == Approx(0.5));
  CHECK(t.s_s(0.33) == Approx(0.5));
  CHECK(t.s_s(0.55) == Approx(0.55 / 0.66));
  CHECK(t.ds_h_dt() == Approx(1.0 / 0.55));
  CHECK(t.ds_s_dt() == Approx(1.0 / 0.66));
  CHECK_THROWS_WITH(make_half_cycle_timing(-0.5, 0.1), Contains("t_h") && Contains("-0.5"));
  CHECK_THROWS_WITH(make_half_cycle_timing(0.55, -0.01), Contains("t_e") && Contains("-0.01"));
  CHECK_THROWS_WITH(make_half_cycle_timing(kNaN, 0.1), Contains("t_h") && Contains("nan"));
}

TEST_CASE("upper convex hull of heights (Fig. 8)", "[end_effector][planner]") {
  constexpr int n = 64;
  std::array<double, n> u{}, h{};
  for (int i = 0; i < n; ++i) u[i] = i / 63.0;

  SECTION("flat ground: zero offset everywhere") {
    const auto hull = upper_convex_hull(u, h);
    CHECK(hull.size == 2);
    for (double x : {0.0, 0.3, 1.0}) CHECK(hull(x) == 0.0);
  }
  SECTION("a step up at u = 0.5: a ramp from the start to the step's first sample, then flat") {
    for (int i = 0; i < n; ++i) h[i] = u[i] >= 0.5 ? 0.1 : 0.0;
    const auto hull = upper_convex_hull(u, h);
    REQUIRE(hull.size == 3);
    CHECK(hull.u[1] == Approx(32 / 63.0));
    CHECK(hull(16 / 63.0) == Approx(0.05));
    CHECK(hull(0.8) == Approx(0.1));
    CHECK(hull.value_and_slope(0.2).second == Approx(0.1 / (32 / 63.0)));
  }
  SECTION("a single bump: a tent") {
    h[31] = 0.2;
    const auto hull = upper_convex_hull(u, h);
    REQUIRE(hull.size == 3);
    CHECK(hull(u[31]) == Approx(0.2));
    CHECK(hull(u[31] / 2) == Approx(0.1));
    CHECK(hull(1.0) == Approx(0.0).margin(1e-15));
  }
  SECTION("random heights: above every sample, concave, through both ends") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0.0, 0.2);
    for (int trial = 0; trial < 20; ++trial) {
      for (double& x : h) x = U(rng);
      const auto hull = upper_convex_hull(u, h);
      CHECK(hull(0.0) == h[0]);
      CHECK(hull(1.0) == h[n - 1]);
      for (int i = 0; i < n; ++i) CHECK(hull(u[i]) >= h[i] - 1e-12);
      for (int k = 2; k < hull.size; ++k) {
        const double s0 = (hull.h[k - 1] - hull.h[k - 2]) / (hull.u[k - 1] - hull.u[k - 2]);
        const double s1 = (hull.h[k] - hull.h[k - 1]) / (hull.u[k] - hull.u[k - 1]);
        CHECK(s1 < s0);
      }
    }
  }
}

TEST_CASE("targets: eqs. 8-10 and the piecewise-linear feedback (A.2)", "[end_effector][planner]") {
  planner_parameters p;
  const vec2 d0_left = neutral_midpoint_offset(stance_side::left, 0.1);
  CHECK(d0_left.isApprox(vec2(0.0, -0.1)));
  CHECK(neutral_midpoint_offset(stance_side::right, 0.1).isApprox(vec2(0.0, 0.1)));

  // Eq. 8, straight: from the left foot at (0, 0.1) the right foot lands at (0.65, -0.1).
  const vec2 q_st(0.0, 0.1);
  const task_goal fwd{0.0, 0.0, 0.65};
  CHECK(swing_foot_horizontal_target(q_st, fwd, p, 0.0, d0_left, vec2::Zero())
            .isApprox(vec2(0.65, -0.1)));
  // Turning left 90 deg while moving forward: Fig. 6's third vector R_z(pi/2) d0 = (0.1, 0), and
  // the first uses the previous facing (0): (0, -0.1) + (0.65, 0) + (0.1, 0).
  const task_goal turn{pi / 2, 0.0, 0.65};
  CHECK(swing_goal_offset(turn, 0.0, d0_left).isApprox(vec2(0.75, -0.1)));
  // ... and with psi_f' = pi / 2 as well, the first vector turns too: (0.1, 0) + (0.65, 0) + (0.1,
  // 0).
  CHECK(swing_goal_offset(turn, pi / 2, d0_left).isApprox(vec2(0.85, 0.0)));
  // Sideways (psi_m = pi / 2, facing +x), r = 0.5.
  CHECK(swing_goal_offset({0.0, pi / 2, 0.5}, 0.0, d0_left).isApprox(vec2(0.0, 0.3)));

  // The feedback: K+ on positive deviation components, K- on negative ones, in psi_m's frame.
  p.k_sw_plus = vec2(1.0, 2.0);
  p.k_sw_minus = vec2(0.5, 0.25);
  p.c_sw = vec2(0.01, -0.02);
  CHECK(swing_balance_offset(fwd, p, vec2(0.1, 0.2)).isApprox(vec2(0.1 + 0.01, 0.4 - 0.02)));
  CHECK(swing_balance_offset(fwd, p, vec2(-0.1, -0.2)).isApprox(vec2(-0.05 + 0.01, -0.05 - 0.02)));
  CHECK(swing_balance_offset(fwd, p, vec2(0.1, -0.2)).isApprox(vec2(0.1 + 0.01, -0.05 - 0.02)));
  // Moving along +y (psi_m = pi/2): a world deviation along +y is "ahead" (local +x, K+ = 1), one
  // along +x is to the right (local -y, K- = 0.25); the result is rotated back.
  const task_goal side{0.0, pi / 2, 0.5};
  CHECK(swing_balance_offset(side, p, vec2(0.0, 0.1)).isApprox(rotate2(pi / 2, vec2(0.11, -0.02))));
  CHECK(swing_balance_offset(side, p, vec2(0.1, 0.0))
            .isApprox(rotate2(pi / 2, vec2(0.01, -0.025 - 0.02))));

  // Eq. 9: midway along the step from the point between the feet, plus the linear feedback.
  p.k_ub = vec2(0.5, 1.0);
  p.c_ub = vec2(0.0, 0.03);
  CHECK(upper_body_horizontal_target(q_st, fwd, p, 0.0, d0_left, vec2::Zero())
            .isApprox(vec2(0.325, 0.03)));
  CHECK(upper_body_horizontal_target(q_st, fwd, p, 0.0, d0_left, vec2(-0.1, 0.1))
            .isApprox(vec2(0.325 - 0.05, 0.03 + 0.1)));
  CHECK(upper_body_target_height(0.06, 0.16, p) == Approx(0.06 + p.z_ub));
  CHECK(upper_body_target_height(0.26, 0.16, p) == Approx(0.16 + p.z_ub));

  // Eq. 10 in our frame: theta leans back, phi leans right, psi_f turns the whole.
  p.theta_ub = 0.2;
  const mat3 Rb = upper_body_target_rotation({0.0, 0.0, 0.0}, p);
  CHECK(Rb.col(2).x() == Approx(-std::sin(0.2)));  // the trunk's axis tilts backward
  p.theta_ub = 0.0;
  p.phi_ub = 0.2;
  CHECK(upper_body_target_rotation({0.0, 0.0, 0.0}, p).col(2).y() == Approx(-std::sin(0.2)));
  CHECK(upper_body_target_rotation({0.7, 0.0, 0.0}, p)
            .isApprox(rotation_z(0.7) * upper_body_target_rotation({0.0, 0.0, 0.0}, p)));

  // Foot pitch: theta > 0 raises the toes; foot_yaw_pitch inverts foot_rotation.
  CHECK(foot_rotation(0.0, 0.3).col(0).z() == Approx(std::sin(0.3)));
  CHECK(foot_yaw_pitch(foot_rotation(2.5, -0.4)).isApprox(vec2(2.5, -0.4)));
  // Target pitch from the slope: +0.2 rad rising along +x gives 0.2 facing +x, -0.2 facing -x,
  // 0 facing across.
  const slope_terrain slope(0.2);
  CHECK(terrain_pitch(slope, vec2(1.0, 0.0), 0.0) == Approx(0.2));
  CHECK(terrain_pitch(slope, vec2(1.0, 0.0), pi) == Approx(-0.2));
  CHECK(terrain_pitch(slope, vec2(1.0, 0.0), pi / 2) == Approx(0.0).margin(1e-12));
}

TEST_CASE("foot clearance and edge avoidance", "[end_effector][planner]") {
  const foot_box b = wu2010_foot_box();
  const flat_terrain ground(0.0);
  // Level: the ankle rests 0.06 above the ground; over a plane at 0.3, 0.36.
  CHECK(plane_clearance(b, mat3::Identity()).height == Approx(0.06));
  CHECK(lowest_collision_free_height(ground, b, mat3::Identity(), vec2(1, 2), 9, 3) ==
        Approx(0.06));
  CHECK(lowest_collision_free_height(flat_terrain(0.3), b, mat3::Identity(), vec2(1, 2), 9, 3) ==
        Approx(0.36));
  // Toes up by 0.3 rad: the heel's bottom corner (-0.06, ., -0.06) is lowest.
  const mat3 R = foot_rotation(0.4, 0.3);
  const vec3 heel(-0.06, 0.05, -0.06);
  CHECK(plane_clearance(b, R).height == Approx(-(R * heel).z()));
  CHECK(lowest_collision_free_height(ground, b, R, vec2(0, 0), 9, 3) ==
        Approx(plane_clearance(b, R).height));

  // A step up at x = 0.1 (0.1 m): the level foot at the origin reaches x = 0.19 over it.
  const steps_terrain step({{0.1, 0.1}}, 0.0);
  CHECK(lowest_collision_free_height(step, b, mat3::Identity(), vec2(0, 0), 9, 3) == Approx(0.16));
  CHECK(lowest_collision_free_height(step, b, mat3::Identity(), vec2(-0.2, 0), 9, 3) ==
        Approx(0.06));

  // Edge avoidance: a target whose foot straddles the edge moves by d_s = 0.75 x 0.25 along psi_m
  // to whichever side is level; a level target stays.
  const double ds = 0.75 * 0.25;
  CHECK(
      edge_avoidance_shift(step, b, vec2(0.05, 0.0), 0.0, 0.0, 0.75, 9, 3).isApprox(vec2(ds, 0.0)));
  CHECK(edge_avoidance_shift(step, b, vec2(0.6, 0.0), 0.0, 0.0, 0.75, 9, 3).isZero());
  // At x = 0.0 the level foot spans [-0.06, 0.19]: +d_s lands on the tread, -d_s before the edge.
  CHECK(landing_rotation(step, b, vec2(0.0, 0.0), 0.0, 9, 3) > 0.3);
  CHECK(landing_rotation(step, b, vec2(0.0 + ds, 0.0), 0.0, 9, 3) == 0.0);
}

TEST_CASE("swing-foot path (A.3): flat ground, derivatives, a 0.1 m step",
          "[end_effector][planner]") {
  planner_setup setup;
  planner_parameters p;
  p.theta_sw1 = 0.3;  // toes up mid-swing, so the plane clearance varies along the path
  p.theta_sw2 = -0.2;
  p.gamma1 = 0.7;
  p.gamma2 = 0.2;
  p.w_sw1 = vec3(0.2, 0.03, 0.1);
  p.w_sw2 = vec3(0.7, -0.02, 0.05);
  swing_path_ends e;
  e.start = vec3(-0.3, -0.1, 0.06);
  e.target = vec2(0.65, -0.1);
  const double duration = 0.66;

  SECTION("flat ground z = 0: the unadjusted path, from the start to the target") {
    const swing_foot_path path = make_swing_foot_path(e, p, duration, setup, flat_terrain(0.0));
    for (double g : path.sample_offset) CHECK(g == Approx(0.0).margin(1e-12));
    for (int i = 0; i <= 40; ++i) {
      const double s = i / 40.0;
      CHECK((path.at_s(s, 1.0).position - path.unadjusted_position(s)).norm() < 1e-12);
    }
    CHECK((path.at_s(0.0, 1.0).position - e.start).norm() < 1e-12);
    CHECK((path.at_s(1.0, 1.0).position - vec3(0.65, -0.1, 0.06)).norm() < 1e-12);
    // The samples sit at uniform u.
    for (int i = 0; i < swing_terrain_samples; ++i) {
      vec3 c, dc;
      path.chord_point(path.sample_s[i], c, dc);
      CHECK(c.x() == Approx(i / 63.0).margin(1e-12));
    }
    // Velocities: d/dt = d/ds / duration, against central differences in t (flat: no hull kink).
    for (double t : {0.05, 0.2, 0.33, 0.5, 0.61}) {
      const link_target a = path.at(t);
      const vec3 fd = central([&](double x) { return path.at(x).position; }, t);
      CHECK((a.velocity - fd).norm() < 1e-6);
      const vec3 w = angular_rate([&](double x) { return path.at(x).rotation; }, t);
      CHECK((a.angular_velocity - w).norm() < 1e-6);
    }
    // Outside the footstep it holds its ends, still.
    CHECK(path.at(0.7).velocity.isZero());
    CHECK((path.at(0.7).position - path.at_s(1.0, 1.0).position).norm() < 1e-15);
    // Yaw: C from 0 to psi_es; pitch V through theta_sw1, theta_sw2 (ends 0 here).
    CHECK(foot_yaw_pitch(path.at_s(1.0, 1.0).rotation).isApprox(vec2(0.0, 0.0)));
  }

  SECTION("over a 0.1 m step the foot box clears the terrain at every sample") {
    const steps_terrain step({{0.3, 0.1}}, 0.0);
    const swing_foot_path path = make_swing_foot_path(e, p, duration, setup, step);
    // It lands on the tread; the hull lies above the samples.
    CHECK(path.at_s(1.0, 1.0).position.z() == Approx(0.16));
    for (int i = 0; i < swing_terrain_samples; ++i) {
      CHECK(path.hull(path.sample_u[i]) >= path.sample_offset[i] - 1e-12);
      const link_target pose = path.at_s(path.sample_s[i], 1.0);
      CHECK(box_clearance(step, setup.foot, pose) >= -1e-9);
    }
    // Between samples too (every 1/2000 of the footstep; the hull's ramp is conservative for a
    // step), while without the hull the box would run 0.1 m into the riser.
    double worst = 1e9, worst_unadjusted = 1e9;
    for (int i = 0; i <= 2000; ++i) {
      const double s = i / 2000.0;
      worst = std::min(worst, box_clearance(step, setup.foot, path.at_s(s, 1.0)));
      link_target flat = path.at_s(s, 1.0);
      flat.position = path.unadjusted_position(s);
      worst_unadjusted = std::min(worst_unadjusted, box_clearance(step, setup.foot, flat));
    }
    CHECK(worst > -1e-9);
    CHECK(worst_unadjusted < -0.05);
  }
}

TEST_CASE("upper-body path (A.3): ends, slope, slerp, derivatives", "[end_effector][planner]") {
  planner_parameters p;
  p.w_ub1 = vec3(0.2, 0.02, 0.03);
  p.w_ub2 = vec3(0.9, -0.01, -0.02);
  const mat3 R0 = rotation_z(0.1) * rotation_x(0.05), R1 = rotation_z(0.6) * rotation_y(-0.1);
  const upper_body_path path =
      make_upper_body_path(vec3(0, 0, 1.45), R0, vec3(0.4, 0.1, 1.55), R1, p, 0.55, 0.0);
  CHECK((path.at(0.0).position - vec3(0, 0, 1.45)).norm() < 1e-12);
  CHECK((path.at(0.55).position - vec3(0.4, 0.1, 1.55)).norm() < 1e-12);
  CHECK((path.at(0.0).rotation - R0).norm() < 1e-12);
  CHECK((path.at(0.55).rotation - R1).norm() < 1e-12);
  // With straight control points (v = l = 0) the height is the linear slope in u.
  planner_parameters straight;
  const upper_body_path line =
      make_upper_body_path(vec3(0, 0, 1.45), R0, vec3(0.4, 0, 1.55), R0, straight, 0.55, 0.0);
  for (double t : {0.1, 0.3}) {
    const vec3 q = line.at(t).position;
    CHECK(q.z() == Approx(1.45 + 0.1 * q.x() / 0.4));
    CHECK(q.y() == Approx(0.0).margin(1e-15));
  }
  for (double t : {0.03, 0.2, 0.41, 0.52}) {
    const link_target a = path.at(t);
    CHECK((a.velocity - central([&](double x) { return path.at(x).position; }, t)).norm() < 1e-6);
    const vec3 w = angular_rate([&](double x) { return path.at(x).rotation; }, t);
    CHECK((a.angular_velocity - w).norm() < 1e-6);
  }
  CHECK(path.at(0.6).velocity.isZero());
  CHECK(path.at(0.6).angular_velocity.isZero());
}

TEST_CASE("half-cycle plan: targets, orientation invariance, stance hand-over",
          "[end_effector][planner]") {
  planner_setup setup;
  planner_parameters p;
  p.t_e = 0.1;
  p.k_sw_plus = vec2(0.3, 0.5);
  p.k_sw_minus = vec2(0.6, 0.2);
  p.c_sw = vec2(0.02, -0.01);
  p.k_ub = vec2(0.2, 0.4);
  p.c_ub = vec2(0.01, 0.02);
  p.theta_sw1 = 0.2;
  p.psi_ub = 0.1;
  p.w_ub1 = vec3(0.3, 0.01, 0.02);
  planner_input in = forward_input();
  in.upper_body_deviation = vec2(0.03, -0.02);
  in.swing_foot.rotation = rotation_z(-0.1);
  const task_goal goal{0.2, 0.1, 0.65};
  const flat_terrain ground(0.0);

  const half_cycle_plan plan = plan_half_cycle(goal, p, setup, in, ground);
  // Eq. 8 from the stance foot as it stands.
  const vec2 d0 = neutral_midpoint_offset(stance_side::left, 0.1);
  CHECK(plan.swing_target.isApprox(
      swing_foot_horizontal_target(vec2(0.0, 0.1), goal, p, 0.0, d0, in.upper_body_deviation)));
  const end_effector_targets start = plan.at(0.0), end = plan.at(0.65);
  CHECK((start.swing_foot.position - in.swing_foot.position).norm() < 1e-12);
  CHECK((start.swing_foot.rotation - in.swing_foot.rotation).norm() < 1e-12);
  CHECK((end.swing_foot.position.head<2>() - plan.swing_target).norm() < 1e-12);
  CHECK(end.swing_foot.position.z() == Approx(0.06));
  CHECK(foot_yaw_pitch(end.swing_foot.rotation).x() == Approx(0.2));
  // The upper body: link origin = planned point - R r; its point starts where it is.
  const vec3 r = start.upper_body.rotation * setup.upper_body_point;
  CHECK((start.upper_body.position + r - in.upper_body.position).norm() < 1e-12);
  const end_effector_targets half = plan.at(0.55);
  CHECK((half.upper_body.position + half.upper_body.rotation * setup.upper_body_point -
         plan.upper_body_target)
            .norm() < 1e-12);
  CHECK(plan.upper_body_target.z() == Approx(0.06 + p.z_ub));
  // The stance foot stands still.
  CHECK((plan.at(0.3).stance_foot.position - in.stance_foot.position).norm() == 0.0);
  CHECK(plan.at(0.3).stance_foot.velocity.isZero());
  // The link origin's velocity is consistent with its position.
  for (double t : {0.1, 0.4}) {
    const auto pos = [&](double x) { return plan.at(x).upper_body.position; };
    CHECK((plan.at(t).upper_body.velocity - central(pos, t)).norm() < 1e-6);
  }
  // Lower-level order: upper body, left foot (stance here), right foot (swing).
  std::array<link_target, 3> links;
  plan.link_targets(0.2, links);
  CHECK((links[1].position - plan.at(0.2).stance_foot.position).norm() == 0.0);
  CHECK((links[2].position - plan.at(0.2).swing_foot.position).norm() == 0.0);

  SECTION("orientation invariance: goal and biped turned by dpsi turn the whole plan") {
    for (double dpsi : {0.7, -2.0, pi}) {
      const task_goal g2{goal.facing + dpsi, goal.movement + dpsi, goal.step_length};
      const half_cycle_plan turned = plan_half_cycle(g2, p, setup, rotated(in, dpsi), ground);
      for (double t : {0.0, 0.13, 0.3, 0.5, 0.6}) {
        const end_effector_targets a = plan.at(t), b = turned.at(t);
        require_rotated(a.upper_body, b.upper_body, dpsi);
        require_rotated(a.swing_foot, b.swing_foot, dpsi);
        require_rotated(a.stance_foot, b.stance_foot, dpsi);
      }
    }
  }

  SECTION("the next half-cycle: the stance foot finishes the previous swing, then stays") {
    planner_input next;
    next.stance = stance_side::right;
    const end_effector_targets at_end = plan.at(0.55);
    next.stance_foot.position = at_end.swing_foot.position;
    next.stance_foot.rotation = at_end.swing_foot.rotation;
    next.swing_foot.position = in.stance_foot.position;
    next.upper_body.position = at_end.upper_body.position +
                               at_end.upper_body.rotation * setup.upper_body_point +
                               vec3(0.02, 0, 0);
    next.upper_body.rotation = at_end.upper_body.rotation;
    next.upper_body_deviation = upper_body_deviation(plan, next.upper_body.position);
    CHECK(next.upper_body_deviation.isApprox(vec2(0.02, 0.0)));
    const half_cycle_plan second = plan_half_cycle(goal, p, setup, next, ground, &plan);
    CHECK(second.has_tail);
    for (double t : {0.0, 0.05, 0.09})
      CHECK((second.at(t).stance_foot.position - plan.at(0.55 + t).swing_foot.position).norm() <
            1e-12);
    CHECK((second.at(0.1).stance_foot.position - plan.at(0.65).swing_foot.position).norm() < 1e-12);
    CHECK(second.at(0.3).stance_foot.velocity.isZero());
    // q_st is where the previous swing lands; psi_f' is the previous goal's facing.
    const vec2 d0r = neutral_midpoint_offset(stance_side::right, 0.1);
    CHECK(second.swing_target.isApprox(swing_foot_horizontal_target(
        plan.swing_target, goal, p, goal.facing, d0r, next.upper_body_deviation)));
  }
}

TEST_CASE("half-cycle plan on terrain: landing height, pitch, blind planning, edge avoidance",
          "[end_effector][planner]") {
  planner_setup setup;
  planner_parameters p;
  const planner_input in = forward_input();
  const task_goal goal = forward_goal();

  // Up a 0.1 m step at x = 0.3: the foot lands on the tread, the upper body's height keeps to the
  // lower (stance) foot.
  const steps_terrain step({{0.3, 0.1}}, 0.0);
  const half_cycle_plan up = plan_half_cycle(goal, p, setup, in, step);
  CHECK(up.at(0.65).swing_foot.position.z() == Approx(0.16));
  CHECK(up.upper_body_target.z() == Approx(0.06 + p.z_ub));
  // Blind: the step is not seen; the foot plans to land at the stance foot's level.
  setup.terrain_awareness = false;
  const half_cycle_plan blind = plan_half_cycle(goal, p, setup, in, step);
  CHECK(blind.at(0.65).swing_foot.position.z() == Approx(0.06));
  setup.terrain_awareness = true;

  // On a +0.2 rad slope rising ahead the foot lands pitched toes-up by 0.2.
  const slope_terrain slope(0.2);
  const half_cycle_plan on_slope = plan_half_cycle(goal, p, setup, in, slope);
  CHECK(foot_yaw_pitch(on_slope.at(0.65).swing_foot.rotation).y() == Approx(0.2));
  const link_target land = on_slope.at(0.65).swing_foot;
  CHECK(box_clearance(slope, setup.foot, land) == Approx(0.0).margin(1e-9));

  // Edge avoidance: a step edge under the planned landing (x = 0.65) moves the target forward
  // by d_s, and the upper-body target by alpha_a d_s.
  const steps_terrain edge({{0.7, 0.1}}, 0.0);
  setup.edge_avoidance = true;
  const half_cycle_plan avoid = plan_half_cycle(goal, p, setup, in, edge);
  const double ds = 0.75 * 0.25;
  CHECK(avoid.edge_shift.isApprox(vec2(ds, 0.0)));
  CHECK(avoid.swing_target.isApprox(vec2(0.65 + ds, -0.1)));
  CHECK(avoid.upper_body_target.x() == Approx(0.325 + p.alpha_a * ds));
}

TEST_CASE("touchdown stance target: where the foot landed, resting on the ground",
          "[end_effector][planner]") {
  planner_setup setup;
  const half_cycle_plan plan =
      plan_half_cycle(forward_goal(), planner_parameters{}, setup, forward_input(), flat_terrain{});
  // A foot that landed 0.3 m off its planned spot, yawed 0.4 rad, pitched and rolled, 2 cm high.
  end_effector_pose foot;
  foot.position = vec3(0.95, -0.25, 0.08);
  foot.rotation = rotation_z(0.4) * rotation_y(-0.2) * rotation_x(0.1);
  // Flat ground: level with the foot's yaw, the box's lowest corner on z = 0.
  const link_target flat = touchdown_stance_target(setup, foot, plan, flat_terrain{});
  CHECK(flat.rotation.isApprox(rotation_z(0.4), 1e-12));
  CHECK(flat.position.head<2>().isApprox(foot.position.head<2>(), 1e-12));
  CHECK(box_clearance(flat_terrain{}, setup.foot, flat) == Approx(0.0).margin(1e-9));
  CHECK(flat.velocity.isZero());
  CHECK(flat.angular_velocity.isZero());
  // A 0.2 rad slope rising along +x: the ground's tangent along yaw 0.4 rises atan(tan 0.2 cos
  // 0.4); the foot keeps its yaw, takes that pitch, and rests on the slope.
  const slope_terrain slope(0.2);
  const link_target on_slope = touchdown_stance_target(setup, foot, plan, slope);
  const vec2 yp = foot_yaw_pitch(on_slope.rotation);
  CHECK(yp.x() == Approx(0.4));
  CHECK(yp.y() == Approx(std::atan(std::tan(0.2) * std::cos(0.4))));
  CHECK(box_clearance(slope, setup.foot, on_slope) == Approx(0.0).margin(1e-9));
  // Blind: level on the plane of the plan's stance foot (z = 0 here), whatever the terrain.
  setup.terrain_awareness = false;
  const link_target blind = touchdown_stance_target(setup, foot, plan, slope);
  CHECK(blind.rotation.isApprox(rotation_z(0.4), 1e-12));
  CHECK(box_clearance(flat_terrain{}, setup.foot, blind) == Approx(0.0).margin(1e-9));
  // A NaN pose is refused, named.
  foot.position.x() = kNaN;
  CHECK_THROWS_WITH(
      touchdown_stance_target(setup, foot, plan, flat_terrain{}),
      Catch::Contains("touchdown_stance_target") && Catch::Contains("foot.position[0]"));
}

TEST_CASE("planner: bad input throws naming the value", "[end_effector][planner]") {
  const planner_setup setup;
  const planner_parameters p;
  const planner_input in = forward_input();
  const flat_terrain ground(0.0);
  CHECK_THROWS_WITH(plan_half_cycle({kNaN, 0.0, 0.65}, p, setup, in, ground),
                    Contains("facing") && Contains("nan"));
  CHECK_THROWS_WITH(plan_half_cycle({0.0, 0.0, INFINITY}, p, setup, in, ground),
                    Contains("step_length") && Contains("inf"));
  planner_setup bad_setup;
  bad_setup.t_h = -0.55;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), p, bad_setup, in, ground),
                    Contains("t_h") && Contains("-0.55"));
  planner_parameters bad = p;
  bad.t_e = -0.1;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), bad, setup, in, ground),
                    Contains("t_e") && Contains("-0.1"));
  bad = p;
  bad.k_sw_minus.y() = kNaN;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), bad, setup, in, ground),
                    Contains("k_sw_minus[1]") && Contains("nan"));
  bad = p;
  bad.z_ub = INFINITY;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), bad, setup, in, ground),
                    Contains("z_ub") && Contains("inf"));
  bad = p;
  bad.gamma2 = 1.5;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), bad, setup, in, ground),
                    Contains("gamma2") && Contains("1.5"));
  bad = p;
  bad.w_sw1.x() = -0.2;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), bad, setup, in, ground),
                    Contains("w_sw1.u") && Contains("-0.2"));
  planner_input bad_in = in;
  bad_in.swing_foot.position.z() = kNaN;
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), p, setup, bad_in, ground),
                    Contains("swing_foot.position[2]") && Contains("nan"));
  bad_in = in;
  bad_in.stance = stance_side::none;  // the keyframes' "not given", shared type
  CHECK_THROWS_WITH(plan_half_cycle(forward_goal(), p, setup, bad_in, ground),
                    Contains("stance") && Contains("none"));
}
