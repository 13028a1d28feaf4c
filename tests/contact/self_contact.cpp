// contact/self_contact.hpp: the closest points of two segments against a brute-force search and
// hand-worked cases; the pair forces of wu2010_leg_collisions on crossed legs cancel (total force
// and total torque about any point zero: one line of action per pair) and push the capsules apart,
// more while they approach; a rollout with crossed legs separates the feet, and one whose legs
// never touch is bit for bit the rollout without pairs; bad pairs and gains throw naming them.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

double segment_distance(const vec3& p0, const vec3& p1, const vec3& q0, const vec3& q1) {
  const auto [s, t] = closest_segment_parameters(p0, p1, q0, q1);
  CHECK(s >= 0.0);
  CHECK(s <= 1.0);
  CHECK(t >= 0.0);
  CHECK(t <= 1.0);
  return ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).norm();
}

/// The smallest distance over a 401 x 401 grid of (s, t), refined around its best cell: an
/// upper bound within about 1e-7 of the true minimum for the segments below.
double brute_force_distance(const vec3& p0, const vec3& p1, const vec3& q0, const vec3& q1) {
  double best = 1e300, bs = 0, bt = 0;
  const auto at = [&](double s, double t) {
    return ((p0 + s * (p1 - p0)) - (q0 + t * (q1 - q0))).norm();
  };
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j <= 400; ++j)
      if (const double d = at(i / 400.0, j / 400.0); d < best)
        best = d, bs = i / 400.0, bt = j / 400.0;
  for (int i = -100; i <= 100; ++i)
    for (int j = -100; j <= 100; ++j) {
      const double s = std::clamp(bs + i * 2.5e-5, 0.0, 1.0),
                   t = std::clamp(bt + j * 2.5e-5, 0.0, 1.0);
      best = std::min(best, at(s, t));
    }
  return best;
}

/// The biped high above the ground with its left hip adducted so that its left foot and shank
/// overlap the right ones (its foot 5 cm left of the right foot, capsules 10 cm wide).
sim_state crossed_legs(const floating_model& m, double adduction = 0.14) {
  sim_state s = make_state(m);
  s.q[2] = 3.0;  // root z, m: nothing touches the ground
  s.q[floating_root::nq + m.dof_index("lhip_x")] = -adduction;
  return s;
}

/// The feet's lateral positions at the last observed step.
struct feet_y {
  double left = 0, right = 0;
  int lf = -1, rf = -1;
  template <class Ob>
  void observe(const Ob& ob) {
    left = ob.workspace().body_position[lf].y();
    right = ob.workspace().body_position[rf].y();
  }
};

}  // namespace

TEST_CASE("closest points of two segments: hand-worked cases", "[self_contact]") {
  // Perpendicular, crossing in projection, 0.3 apart in z.
  const auto [s, t] = closest_segment_parameters({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.3}, {0, 1, 0.3});
  CHECK(s == Approx(0.5));
  CHECK(t == Approx(0.5));
  CHECK(segment_distance({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.3}, {0, 1, 0.3}) == Approx(0.3));
  // Parallel and overlapping, 1 apart.
  CHECK(segment_distance({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0}) == Approx(1.0));
  // End point to end point.
  const auto [s2, t2] = closest_segment_parameters({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 5, 0});
  CHECK(s2 == 1.0);
  CHECK(t2 == 0.0);
  CHECK(segment_distance({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 5, 0}) == Approx(std::sqrt(2.0)));
  // Degenerate segments: two points, a point and a segment.
  CHECK(segment_distance({1, 2, 3}, {1, 2, 3}, {1, 2, 5}, {1, 2, 5}) == Approx(2.0));
  CHECK(segment_distance({0, 0, 1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}) == Approx(1.0));
  CHECK(segment_distance({-1, 0, 0}, {1, 0, 0}, {3, 0, 1}, {3, 0, 1}) == Approx(std::sqrt(5.0)));
}

TEST_CASE("closest points of two segments agree with a brute-force search", "[self_contact]") {
  std::mt19937_64 rng(2010);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto point = [&] { return vec3(u(rng), u(rng), u(rng)); };
  for (int k = 0; k < 40; ++k) {
    const vec3 p0 = point(), p1 = point(), q0 = point();
    // Every fourth pair nearly parallel.
    const vec3 q1 = k % 4 == 0 ? q0 + (p1 - p0) * 0.7 + 1e-9 * point() : point();
    const double d = segment_distance(p0, p1, q0, q1);
    const double brute = brute_force_distance(p0, p1, q0, q1);
    INFO("pair " << k);
    // The closest pair: nothing on the grid is closer (nearly parallel segments are taken as
    // parallel, whose closest points differ in distance by about their angle, 1e-9 rad, times a
    // length; the allowance 1e-8 m is ten times that), and the grid comes within its resolution.
    CHECK(d <= brute + (k % 4 == 0 ? 1e-8 : 1e-12));
    CHECK(d >= brute - 1e-6);
  }
}

TEST_CASE("inter-leg forces cancel, push apart and damp an approach", "[self_contact]") {
  const floating_model m = wu2010_biped();
  const self_contact_parameters p = wu2010_leg_collisions(m);
  REQUIRE(p.pairs.size() == 9);
  auto ws = make_workspace(m);
  const sim_state s = crossed_legs(m);
  forward_kinematics(m, ws, s.q, s.v);
  clear_external_wrenches(ws);
  const int touching = apply_self_contact_forces(m, ws, p);
  CHECK(touching >= 2);  // at least shanks and feet
  vec3 force = vec3::Zero(), torque = vec3::Zero();
  double largest = 0.0;
  for (int b = 0; b < m.num_bodies(); ++b) {
    const vec3 tb = ws.f_ext[b].head<3>(), fb = ws.f_ext[b].tail<3>();
    force += fb;
    torque += tb + ws.body_position[b].cross(fb);  // about the world origin
    largest = std::max(largest, fb.norm());
  }
  REQUIRE(largest > 100.0);
  CHECK(force.norm() <= 1e-9 * largest);
  CHECK(torque.norm() <= 1e-8 * largest);
  // The left foot is pushed to the left (+y), the right one to the right.
  const int lfoot = m.body_index("lfoot"), rfoot = m.body_index("rfoot");
  CHECK(ws.f_ext[lfoot].tail<3>().y() > 0.0);
  CHECK(ws.f_ext[rfoot].tail<3>().y() < 0.0);

  // Approaching (the left leg swinging right) the damping adds to the spring.
  sim_state moving = s;
  moving.v[floating_root::nv + m.dof_index("lhip_x")] = -2.0;  // adducting further, rad/s
  forward_kinematics(m, ws, moving.q, moving.v);
  clear_external_wrenches(ws);
  apply_self_contact_forces(m, ws, p);
  const double approaching = ws.f_ext[rfoot].tail<3>().norm();
  forward_kinematics(m, ws, s.q, s.v);
  clear_external_wrenches(ws);
  apply_self_contact_forces(m, ws, p);
  CHECK(approaching > ws.f_ext[rfoot].tail<3>().norm());
}

TEST_CASE("coincident capsule axes still give finite, balanced forces", "[self_contact]") {
  const floating_model m = wu2010_biped();
  auto ws = make_workspace(m);
  const sim_state s = make_state(m);
  forward_kinematics(m, ws, s.q, s.v);
  // Two spheres (zero-length capsules) at the hip's centre, one on each thigh (the hip joints
  // are at y = +-0.1 m): d = 0, no direction between them.
  self_contact_parameters p;
  p.pairs.push_back({{m.body_index("lthigh"), {0, -0.1, 0}, {0, -0.1, 0}, 0.05},
                     {m.body_index("rthigh"), {0, 0.1, 0}, {0, 0.1, 0}, 0.05}});
  // And two crossing segments: the thighs' axes moved to pass through the hip's centre.
  p.pairs.push_back({{m.body_index("lthigh"), {-0.1, -0.1, 0}, {0.1, -0.1, 0}, 0.05},
                     {m.body_index("rthigh"), {0, 0.0, 0}, {0, 0.2, 0}, 0.05}});
  validate(m, p);
  clear_external_wrenches(ws);
  CHECK(apply_self_contact_forces(m, ws, p) == 2);
  vec3 force = vec3::Zero();
  for (int b = 0; b < m.num_bodies(); ++b) {
    CHECK(ws.f_ext[b].allFinite());
    force += ws.f_ext[b].tail<3>();
  }
  CHECK(ws.f_ext[m.body_index("lthigh")].tail<3>().norm() > 0.0);
  CHECK(force.norm() <= 1e-9 * ws.f_ext[m.body_index("lthigh")].tail<3>().norm());
}

TEST_CASE("a rollout with crossed legs separates them; untouched legs change nothing",
          "[self_contact]") {
  const floating_model m = wu2010_biped();
  const pose_hold passive(m, {.output = command_kind::joint_torque});
  const std::vector<double> x(passive.num_parameters(), 0.0);
  auto scratch = make_rollout_scratch(m);
  rollout_options o;
  o.duration = 0.05;
  o.detect_falls = false;
  o.initial_state = crossed_legs(m);
  const auto run = [&](const rollout_options& opt) {
    feet_y f{.lf = m.body_index("lfoot"), .rf = m.body_index("rfoot")};
    rollout(m, torque_actuator{}, passive, distance_objective(), flat_terrain{},
            semi_implicit_euler{}, x, opt, scratch, f);
    return f.left - f.right;
  };
  const double without = run(o);
  o.self_contact = wu2010_leg_collisions(m);
  const double with = run(o);
  CHECK(with > without + 0.01);  // m: the feet pushed apart

  // Standing in the neutral pose the legs never touch: the same rollout bit for bit.
  rollout_options stand;
  stand.duration = 0.3;
  stand.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, stand.initial_state.q);
  const rollout_result a = rollout(m, torque_actuator{}, passive, distance_objective(),
                                   flat_terrain{}, semi_implicit_euler{}, x, stand, scratch);
  stand.self_contact = wu2010_leg_collisions(m);
  const rollout_result b = rollout(m, torque_actuator{}, passive, distance_objective(),
                                   flat_terrain{}, semi_implicit_euler{}, x, stand, scratch);
  CHECK(a.com_final == b.com_final);
  CHECK(a.time == b.time);
}

TEST_CASE("bad self-collision pairs and gains throw naming them", "[self_contact]") {
  const floating_model m = wu2010_biped();
  const self_contact_parameters good = wu2010_leg_collisions(m);
  auto bad = good;
  bad.pairs[0].a.body = 99;
  CHECK_THROWS_WITH(validate(m, bad), Catch::Contains("pair 0: body 99"));
  bad = good;
  bad.pairs[3].b.radius = 0.0;
  CHECK_THROWS_WITH(validate(m, bad),
                    Catch::Contains("pair 3: radius must be finite and > 0, got 0"));
  bad = good;
  bad.pairs[1].b.body = bad.pairs[1].a.body;
  CHECK_THROWS_WITH(validate(m, bad), Catch::Contains("pair 1: both capsules are on body"));
  bad = good;
  bad.pairs[2].a.p1.x() = std::nan("");
  CHECK_THROWS_WITH(validate(m, bad), Catch::Contains("pair 2: end points must be finite"));
  bad = good;
  bad.kp = -1.0;
  CHECK_THROWS_WITH(validate(m, bad), Catch::Contains("kp must be finite and >= 0, got -1"));
  bad = good;
  bad.kd = std::nan("");
  CHECK_THROWS_WITH(validate(m, bad), Catch::Contains("kd must be finite and >= 0, got nan"));
  // The rollout checks them before its first step.
  const pose_hold passive(m, {.output = command_kind::joint_torque});
  const std::vector<double> x(passive.num_parameters(), 0.0);
  rollout_options o;
  o.duration = 0.01;
  o.initial_state = make_state(m);
  o.self_contact = good;
  o.self_contact.pairs[0].a.radius = -1.0;
  auto scratch = make_rollout_scratch(m);
  CHECK_THROWS_WITH(rollout(m, torque_actuator{}, passive, distance_objective(), flat_terrain{},
                            semi_implicit_euler{}, x, o, scratch),
                    Catch::Contains("radius must be finite and > 0, got -1"));
}
