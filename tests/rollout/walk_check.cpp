// rollout/walk_check.hpp and rollout_options::stall: a body coasting at a known speed without
// gravity or contact advances exactly v t, so where the stall rule stops it is known in closed
// form.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/walk_check.hpp"

using namespace gaitsynth;

namespace {

/// A free box with one hinged flap, no gravity and no contact points: it coasts.
floating_model coasting_box() {
  model_builder<floating_root> b("coasting_box");
  b.set_gravity({0, 0, 0});
  b.add_body({.name = "box", .mass = 2.0, .inertia = Eigen::Matrix3d::Identity() * 0.1});
  b.add_body({.name = "flap",
              .parent = "box",
              .joint_offset = {0, 0, -0.1},
              .mass = 0.5,
              .com = {0, 0, -0.1},
              .inertia = Eigen::Matrix3d::Identity() * 0.01,
              .dofs = {{.name = "hinge"}}});
  return b.build();
}

/// The box coasting forward at vx m/s from 1 m up, for `seconds` with stall detection `stall`.
rollout_result coast(double vx, double seconds, stall_detection stall) {
  const floating_model m = coasting_box();
  rollout_options o;
  o.duration = seconds;
  o.detect_falls = false;
  o.stall = stall;
  o.initial_state.q = Eigen::VectorXd::Zero(m.nq());
  o.initial_state.q[2] = 1.0;
  o.initial_state.q[3] = 1.0;  // identity quaternion (w first)
  o.initial_state.v = Eigen::VectorXd::Zero(m.nv());
  o.initial_state.v[0] = vx;  // floating root: linear (world), then angular velocity
  auto scr = make_rollout_scratch(m);
  const std::vector<double> p{0.0};  // the hinge's target (gains 0: no torque)
  return rollout(m, torque_actuator{}, pose_hold(m, {.output = command_kind::joint_torque}),
                 distance_objective(), flat_terrain(), semi_implicit_euler(),
                 std::span<const double>(p), o, scr);
}

}  // namespace

TEST_CASE("stall detection: the COM must advance min_progress in every window",
          "[rollout][walk_check]") {
  const stall_detection five_s{.window = 5.0, .min_progress = 0.1};
  SECTION("off by default: a still body runs to the horizon") {
    const rollout_result r = coast(0.0, 12.0, {});
    CHECK(r.reason == stop_reason::horizon);
    CHECK(r.time == Approx(12.0));
  }
  SECTION("a still body stalls at the end of the first window") {
    const rollout_result r = coast(0.0, 12.0, five_s);
    CHECK(r.reason == stop_reason::stalled);
    CHECK(to_string(r.reason) == "stalled");
    CHECK(r.failed());
    CHECK(r.time == Approx(5.0));
  }
  SECTION("0.021 m/s covers 0.105 m per window and walks; 0.019 m/s covers 0.095 m and stalls") {
    const rollout_result fast = coast(0.021, 12.0, five_s);
    CHECK(fast.reason == stop_reason::horizon);
    CHECK(fast.com_final.x() - fast.com_initial.x() == Approx(0.021 * 12.0).epsilon(1e-6));
    const rollout_result slow = coast(0.019, 12.0, five_s);
    CHECK(slow.reason == stop_reason::stalled);
    CHECK(slow.time == Approx(5.0));
  }
  SECTION("backwards is no progress") {
    CHECK(coast(-0.5, 12.0, five_s).reason == stop_reason::stalled);
  }
  SECTION("bad settings name the field") {
    CHECK_THROWS_WITH(coast(0.0, 1.0, {.window = -1.0}),
                      Catch::Contains("stall.window") && Catch::Contains("-1"));
    CHECK_THROWS_WITH(coast(0.0, 1.0, {.window = 5.0, .min_progress = std::nan("")}),
                      Catch::Contains("stall.min_progress"));
  }
}

TEST_CASE("walked: to the horizon, no stall, and the minimum average speed",
          "[rollout][walk_check]") {
  const walk_criteria c{};  // 5 s windows, 0.1 m
  CHECK(c.stall.window == 5.0);
  CHECK(c.stall.min_progress == 0.1);
  const rollout_result moving = coast(0.5, 12.0, walk_options({}, c).stall);
  CHECK(walked(moving, c));
  CHECK(walked(moving, {.min_average_speed = 0.49}));
  CHECK_FALSE(walked(moving, {.min_average_speed = 0.51}));
  const walk_check w = judge_walk(moving, c);
  CHECK(w.walked);
  CHECK_FALSE(w.fell);
  CHECK_FALSE(w.stalled);
  CHECK(w.average_speed == Approx(0.5).epsilon(1e-6));
  CHECK(std::string(verdict(w)) == "walked");
  CHECK(std::string(verdict(judge_walk(moving, {.min_average_speed = 1.0}))) == "too slow");

  const rollout_result still = coast(0.0, 12.0, c.stall);
  const walk_check s = judge_walk(still, c);
  CHECK_FALSE(s.walked);
  CHECK(s.stalled);
  CHECK_FALSE(s.fell);
  CHECK(std::string(verdict(s)) == "stalled");
}
