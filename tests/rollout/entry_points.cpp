// Bad numbers at the public entry points (issue 15, "a bad-input corpus ... the same for every
// public entry point that takes numbers from a user"): each defect is refused with a
// std::invalid_argument whose message names the field and the bad value, before anything runs
// (no crash, hang or silent garbage). One CHECK_THROWS_WITH per entry point and defect; the
// checks that existed before this file are here too, so that it lists the whole surface
// (docs/architecture.md, "Bad input"). What is accepted on purpose is checked as accepted: a
// terrain query outside a height field reads the clamped edge, it does not throw.
//
// The loaders' corpus (files) is tests/bad_inputs/ with tests/io/bad_inputs.cpp; this file needs
// no files. Nothing here simulates more than a few steps.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/continuation.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/optimizers/restarts.hpp"
#include "gaitsynth/optimizers/sds.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

using namespace gaitsynth;
using Catch::Contains;

namespace {

constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_ = std::numeric_limits<double>::infinity();

/// The cheap set-up every rollout check starts from: the 7-link planar human holding its neutral
/// pose for 4 physics steps.
struct planar_setup {
  planar_model m = sharon2005_human7();
  pd_actuator act = pd_actuator::uniform(m, 300.0, 30.0);
  Eigen::VectorXd params = Eigen::VectorXd::Zero(m.num_joint_dofs());
  rollout_options good;
  rollout_scratch<planar_root> scratch = make_rollout_scratch(m);
  planar_setup() {
    good.dt = 1.0 / 2400.0;
    good.duration = 4.0 / 2400.0;
  }
  rollout_result run(const rollout_options& o, const Eigen::VectorXd& p,
                     const pose_hold_options& po = {}) {
    return rollout(m, act, pose_hold(m, po), distance_objective(), flat_terrain(),
                   semi_implicit_euler(), p, o, scratch);
  }
  rollout_result run(const rollout_options& o) { return run(o, params); }
};

std::string got(std::ptrdiff_t expected, std::ptrdiff_t actual) {
  return "expected " + std::to_string(expected) + ", got " + std::to_string(actual);
}

}  // namespace

TEST_CASE("entry points: rollout() options", "[rollout][bad_input][entry_points]") {
  planar_setup s;
  const int nq = s.m.nq(), nv = s.m.nv();
  REQUIRE(s.run(s.good).reason == stop_reason::horizon);
  auto with = [&](auto change) {
    rollout_options o = s.good;
    change(o);
    return o;
  };
  // Timestep and horizon.
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.dt = -0.001; })),
                    Contains("dt") && Contains("-0.001"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.dt = 0.0; })), Contains("dt") && Contains("got 0"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.dt = nan_; })), Contains("dt") && Contains("nan"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.dt = inf_; })), Contains("dt") && Contains("inf"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.duration = -1.0; })),
                    Contains("duration") && Contains("-1"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.duration = inf_; })),
                    Contains("duration") && Contains("inf"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.duration = nan_; })),
                    Contains("duration") && Contains("nan"));
  // New: a horizon of more steps than the loop can count (was an int64 overflow).
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.duration = 1e10;
    o.dt = 1e-9;
  })),
                    Contains("duration / dt") && Contains("10000000000 s") && Contains("e-09 s"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.dt = 4.9406564584124654e-324; })),
                    Contains("duration / dt") && Contains("4.9406564584124654e-324 s"));
  // Fall and stall detection.
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.fall_fraction = -1.0; })),
                    Contains("fall_fraction") && Contains("-1"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.fall_height = nan_; })),
                    Contains("fall_height") && Contains("nan"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.stall.window = -5.0; })),
                    Contains("stall.window") && Contains("-5"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.stall.min_progress = nan_; })),
                    Contains("stall.min_progress") && Contains("nan"));
  // Start state and its velocity offset: sizes and values.
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.initial_state.q = Eigen::VectorXd::Zero(5); })),
                    Contains("initial_state.q") && Contains(got(nq, 5)));
  // A velocity or time without q would be dropped (the neutral pose starts at rest at t = 0).
  CHECK_THROWS_WITH(
      s.run(with([&](auto& o) { o.initial_state.v = Eigen::VectorXd::Ones(nv); })),
      Contains("initial_state") && Contains("without q") && Contains("size " + std::to_string(nv)));
  CHECK_THROWS_WITH(s.run(with([&](auto& o) { o.initial_state.t = 2.5; })),
                    Contains("initial_state") && Contains("without q") && Contains("2.5"));
  CHECK_THROWS_WITH(s.run(with([&](auto& o) {
    o.initial_state = make_state(s.m);
    o.initial_state.v.resize(2);
  })),
                    Contains("initial_state.v") && Contains(got(nv, 2)));
  CHECK_THROWS_WITH(s.run(with([&](auto& o) {
    o.initial_state = make_state(s.m);
    o.initial_state.q[4] = nan_;
  })),
                    Contains("initial_state.q") && Contains("element 4") && Contains("nan"));
  CHECK_THROWS_WITH(s.run(with([&](auto& o) {
    o.initial_state = make_state(s.m);
    o.initial_state.v[1] = -inf_;
  })),
                    Contains("initial_state.v") && Contains("element 1") && Contains("-inf"));
  CHECK_THROWS_WITH(s.run(with([&](auto& o) {
    o.initial_state = make_state(s.m);
    o.initial_state.t = inf_;
  })),
                    Contains("initial_state.t") && Contains("inf"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.initial_velocity_offset = Eigen::VectorXd(3); })),
                    Contains("initial_velocity_offset") && Contains(got(nv, 3)));
  CHECK_THROWS_WITH(
      s.run(with([&](auto& o) {
        o.initial_velocity_offset = Eigen::VectorXd::Zero(nv);
        o.initial_velocity_offset[2] = nan_;
      })),
      Contains("initial_velocity_offset") && Contains("element 2") && Contains("nan"));
  // Recording.
  trajectory tr;
  CHECK_THROWS_WITH(s.run(with([&](auto& o) {
    o.record = &tr;
    o.record_every = 0;
  })),
                    Contains("record_every") && Contains("got 0"));
  // Pushes: body index, force, start, duration.
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.pushes = {push{99, vec3(1, 0, 0), 0.0, 1.0}};
  })),
                    Contains("push 0") && Contains("body 99"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.pushes = {push{-1, vec3(1, 0, 0), 0.0, 1.0}};
  })),
                    Contains("push 0") && Contains("body -1"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.pushes = {push{0, vec3(1, 0, 0), 0.0, 1.0}, push{0, vec3(nan_, 0, 0), 0.0, 1.0}};
  })),
                    Contains("push 1") && Contains("force") && Contains("nan"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.pushes = {push{0, vec3(1, 0, 0), 0.0, -0.5}};
  })),
                    Contains("push 0") && Contains("duration") && Contains("-0.5"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) {
    o.pushes = {push{0, vec3(1, 0, 0), inf_, 1.0}};
  })),
                    Contains("push 0") && Contains("start") && Contains("inf"));
  CHECK_THROWS_WITH(periodic_pushes(0, vec3(1, 0, 0), 0.0, -4.0, 0.4, 3),
                    Contains("period") && Contains("-4"));
  CHECK_THROWS_WITH(periodic_pushes(0, vec3(1, 0, 0), 0.0, 4.0, 0.4, -3),
                    Contains("count") && Contains("-3"));
  // Contact parameters.
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.contact.kp = -1.0; })),
                    Contains("kp") && Contains("-1"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.contact.kd = nan_; })),
                    Contains("kd") && Contains("nan"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.contact.mu = -0.5; })),
                    Contains("mu") && Contains("-0.5"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.contact.kt = 0.0; })),
                    Contains("kt") && Contains("got 0"));
  CHECK_THROWS_WITH(s.run(with([](auto& o) { o.contact.bt = -inf_; })),
                    Contains("bt") && Contains("-inf"));
  // And the same scratch still runs a good rollout.
  CHECK(s.run(s.good).reason == stop_reason::horizon);
}

TEST_CASE("entry points: rollout() parameters and the controller",
          "[rollout][bad_input][entry_points]") {
  planar_setup s;
  const int nj = s.m.num_joint_dofs();
  CHECK_THROWS_WITH(s.run(s.good, Eigen::VectorXd::Zero(nj - 1)),
                    Contains("pose_hold parameters") && Contains(got(nj, nj - 1)));
  CHECK_THROWS_WITH(s.run(s.good, Eigen::VectorXd::Zero(nj + 3)),
                    Contains("pose_hold parameters") && Contains(got(nj, nj + 3)));
  Eigen::VectorXd p = s.params;
  p[2] = nan_;
  CHECK_THROWS_WITH(s.run(s.good, p), Contains("parameter 2") && Contains("nan"));
  p[2] = -inf_;
  CHECK_THROWS_WITH(s.run(s.good, p), Contains("parameter 2") && Contains("-inf"));
  // The controller's own numbers: its period and gains.
  CHECK_THROWS_WITH(s.run(s.good, s.params, {.period = -0.25}),
                    Contains("period") && Contains("-0.25"));
  CHECK_THROWS_WITH(s.run(s.good, s.params, {.period = nan_}),
                    Contains("period") && Contains("nan"));
  CHECK_THROWS_WITH(pose_hold(s.m, {.kp = Eigen::VectorXd::Zero(2)}),
                    Contains("gains") && Contains(got(nj, 2)));
  CHECK_THROWS_WITH(pose_hold(s.m, {.output = command_kind::excitation, .excitation = 1.5}),
                    Contains("excitation") && Contains("1.5"));
  CHECK_THROWS_WITH(pose_hold(-2), Contains("num_joint_dofs") && Contains("-2"));
  // A controller built for a timestep: Wang 2009's computes its gain caps for dt.
  const floating_model h = wang2009_humanoid();
  CHECK_THROWS_WITH(wang2009_controller(h, -1.0 / 2400.0), Contains("dt") && Contains("-0.0004"));
  CHECK_THROWS_WITH(wang2009_controller(h, 0.0), Contains("dt") && Contains("got 0"));
  // Placing a start state on the terrain (set-up helper).
  Eigen::VectorXd q = Eigen::VectorXd::Zero(s.m.nq());
  q[3] = nan_;
  CHECK_THROWS_WITH(place_on_terrain(s.m, flat_terrain(), q),
                    Contains("place_on_terrain") && Contains("element 3") && Contains("nan"));
  Eigen::VectorXd q_short = Eigen::VectorXd::Zero(4);
  CHECK_THROWS_WITH(place_on_terrain(s.m, flat_terrain(), q_short),
                    Contains("place_on_terrain") && Contains(got(s.m.nq(), 4)));
}

TEST_CASE("entry points: rollout_problem, problem_cost, check_walk",
          "[rollout][bad_input][entry_points]") {
  planar_setup s;
  const int nj = s.m.num_joint_dofs();
  rollout_problem prob{
      s.m,   s.act, pose_hold(s.m), distance_objective(), flat_terrain(), semi_implicit_euler(),
      s.good};
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(nj);
  const double horizon = 4.0 / 2400.0;
  CHECK(std::isfinite(prob.cost(x, horizon)));
  CHECK_THROWS_WITH(prob.cost(Eigen::VectorXd::Zero(2), horizon),
                    Contains("parameter vector") && Contains(got(nj, 2)));
  Eigen::VectorXd bad = x;
  bad[1] = nan_;
  CHECK_THROWS_WITH(prob.cost(bad, horizon), Contains("parameter 1 'p1'") && Contains("nan"));
  // New: the horizon is named as the caller passed it (was "rollout_options::duration").
  CHECK_THROWS_WITH(prob.cost(x, -1.0), Contains("horizon") && Contains("-1"));
  CHECK_THROWS_WITH(prob.cost(x, nan_), Contains("horizon") && Contains("nan"));
  CHECK_THROWS_WITH(prob.evaluate(x, inf_), Contains("horizon") && Contains("inf"));
  // A start state of the wrong size.
  auto prob_starts = prob;
  prob_starts.starts = {sim_state{Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(s.m.nv()), 0.0}};
  CHECK_THROWS_WITH(prob_starts.cost(x, horizon),
                    Contains("initial_state.q") && Contains(got(s.m.nq(), 3)));
  // problem_cost and its contexts.
  CHECK_THROWS_WITH(problem_contexts(prob, 0), Contains("worker") && Contains("got 0"));
  problem_contexts ctx(prob, 1);
  CHECK_THROWS_WITH(ctx[5], Contains("worker 5"));
  CHECK_THROWS_WITH(problem_cost(prob, 0.0, ctx), Contains("horizon") && Contains("got 0"));
  CHECK_THROWS_WITH(problem_cost(prob, -2.0, ctx), Contains("horizon") && Contains("-2"));
  CHECK_THROWS_WITH(problem_cost(prob, nan_, ctx), Contains("horizon") && Contains("nan"));
  // walk_check (new: seconds and min_average_speed; the stall rule is checked by the rollout).
  CHECK_THROWS_WITH(check_walk(prob, x, -1.0), Contains("seconds") && Contains("-1"));
  CHECK_THROWS_WITH(check_walk(prob, x, nan_), Contains("seconds") && Contains("nan"));
  CHECK_THROWS_WITH(
      check_walk(prob, x, horizon, nullptr, 1, walk_criteria{.min_average_speed = nan_}),
      Contains("min_average_speed") && Contains("nan"));
  CHECK_THROWS_WITH(walked(rollout_result{}, walk_criteria{.min_average_speed = -inf_}),
                    Contains("min_average_speed") && Contains("-inf"));
  CHECK_THROWS_WITH(
      check_walk(prob, x, horizon, nullptr, 1, walk_criteria{.stall = {.window = -5.0}}),
      Contains("stall.window") && Contains("-5"));
  trajectory tr;
  CHECK_THROWS_WITH(check_walk(prob, x, horizon, &tr, 0),
                    Contains("record_every") && Contains("got 0"));
  // Perturbed starts.
  CHECK_THROWS_WITH(joint_velocity_perturbations(s.m, -1, 0.05, 7),
                    Contains("count") && Contains("-1"));
  CHECK_THROWS_WITH(joint_velocity_perturbations(s.m, 2, nan_, 7),
                    Contains("sigma") && Contains("nan"));
  CHECK_THROWS_WITH(joint_velocity_perturbations(s.m, 2, -0.25, 7),
                    Contains("sigma") && Contains("-0.25"));
}

TEST_CASE("entry points: the push protocol", "[rollout][bad_input][entry_points]") {
  planar_setup s;
  const std::span<const double> p(s.params.data(), static_cast<std::size_t>(s.params.size()));
  auto trial = [&](const push_protocol& proto, int body = 0, vec3 force = vec3(10, 0, 0)) {
    return push_trial_run(s.m, s.act, pose_hold(s.m), flat_terrain(), semi_implicit_euler(), p,
                          s.good, body, force, proto);
  };
  auto scan = [&](const push_protocol& proto, vec3 direction = vec3(1, 0, 0)) {
    return max_push_force(s.m, s.act, pose_hold(s.m), flat_terrain(), semi_implicit_euler(), p,
                          s.good, 0, direction, proto);
  };
  CHECK_THROWS_WITH(trial({.duration = -40.0}), Contains("duration") && Contains("-40"));
  CHECK_THROWS_WITH(trial({.period = 0.0}), Contains("period") && Contains("got 0"));
  // New: each of these was a push validated later under another name, a pass never possible, an
  // int overflow, or a scan that would not end.
  CHECK_THROWS_WITH(trial({.period = 1e-12}),
                    Contains("duration / period") && Contains("40 s") && Contains("e-13 s"));
  CHECK_THROWS_WITH(trial({.push_duration = -0.5}), Contains("push_duration") && Contains("-0.5"));
  CHECK_THROWS_WITH(trial({.push_duration = nan_}), Contains("push_duration") && Contains("nan"));
  CHECK_THROWS_WITH(trial({.min_forward_speed = nan_}),
                    Contains("min_forward_speed") && Contains("nan"));
  CHECK_THROWS_WITH(trial({}, 99), Contains("body 99"));
  CHECK_THROWS_WITH(trial({}, 0, vec3(inf_, 0, 0)), Contains("force") && Contains("inf"));
  CHECK_THROWS_WITH(scan({.resolution = -5.0}), Contains("resolution") && Contains("-5"));
  CHECK_THROWS_WITH(scan({.max_force = nan_}), Contains("max_force") && Contains("nan"));
  CHECK_THROWS_WITH(scan({.max_force = -500.0}), Contains("max_force") && Contains("-500"));
  CHECK_THROWS_WITH(scan({.resolution = 1e-300}),
                    Contains("max_force / resolution") && Contains("e-300 N"));
  CHECK_THROWS_WITH(scan({}, vec3(0, nan_, 0)), Contains("direction") && Contains("nan"));
}

TEST_CASE("entry points: terrains", "[contact][bad_input][entry_points]") {
  CHECK_THROWS_WITH(flat_terrain(nan_), Contains("height") && Contains("nan"));
  // Slope.
  CHECK_THROWS_WITH(slope_terrain(2.0), Contains("angle") && Contains("got 2"));
  CHECK_THROWS_WITH(slope_terrain(nan_), Contains("angle") && Contains("nan"));
  CHECK_THROWS_WITH(slope_terrain(0.1, inf_), Contains("height_at_origin") && Contains("inf"));
  CHECK_THROWS_WITH(slope_terrain(0.1, 0.0, Eigen::Vector2d::Zero()),
                    Contains("direction") && Contains("(0 0)"));
  CHECK_THROWS_WITH(slope_terrain(0.1, 0.0, Eigen::Vector2d::UnitX(), Eigen::Vector2d(nan_, 0)),
                    Contains("origin") && Contains("nan"));
  // Height field: construction.
  const Eigen::Vector2d o(0, 0);
  Eigen::MatrixXd h(3, 2);
  h << 0.0, 0.5, 0.25, 0.75, 1.0, 1.25;
  CHECK_THROWS_WITH(height_field_terrain(o, -1.0, h), Contains("spacing.x") && Contains("-1"));
  CHECK_THROWS_WITH(height_field_terrain(o, Eigen::Vector2d(1.0, 0.0), h),
                    Contains("spacing.y") && Contains("got 0"));
  CHECK_THROWS_WITH(height_field_terrain(o, nan_, h), Contains("spacing.x") && Contains("nan"));
  CHECK_THROWS_WITH(height_field_terrain(Eigen::Vector2d(inf_, 0), 1.0, h),
                    Contains("origin") && Contains("inf"));
  Eigen::MatrixXd h_nan = h;
  h_nan(1, 0) = nan_;
  CHECK_THROWS_WITH(height_field_terrain(o, 1.0, h_nan),
                    Contains("node (1, 0)") && Contains("nan"));
  CHECK_THROWS_WITH(height_field_terrain(o, 1.0, Eigen::MatrixXd(0, 2)),
                    Contains("grid is empty") && Contains("0 x 2"));
  CHECK_THROWS_WITH(
      height_field_terrain(o, Eigen::Vector2d(1, 1), 3, 2, std::vector<double>(5, 0.0)),
      Contains("values") && Contains(got(6, 5)));
  CHECK_THROWS_WITH(height_field_terrain(o, Eigen::Vector2d(1, 1), 0, 2, std::vector<double>{}),
                    Contains("nx >= 1") && Contains("0 x 2"));
  CHECK_THROWS_WITH(random_height_field({.min_height = 1.0, .max_height = 0.0}, 1),
                    Contains("min_height") && Contains("[1, 0]"));
  CHECK_THROWS_WITH(random_height_field({.nx = -3}, 1), Contains("nx >= 1") && Contains("-3"));
  // Height field: a query outside the grid is clamped to the edge (documented; no exception on
  // the hot path), and so is an infinite one; NaN reads the first node.
  const height_field_terrain f(o, 1.0, h);  // x nodes 0, 1, 2; y nodes 0, 1
  CHECK(f.height(-100.0, 0.0) == 0.0);
  CHECK(f.height(100.0, 0.0) == 1.0);
  CHECK(f.height(100.0, 100.0) == 1.25);
  CHECK(f.height(-inf_, inf_) == 0.5);
  CHECK(f.height(0.5, -inf_) == 0.125);
  CHECK(f.height(nan_, 0.0) == 0.0);
  CHECK(f.gradient(-100.0, 0.5).x() == 0.0);
  CHECK(f.gradient(100.0, 0.5).x() == 0.0);
  CHECK(f.normal(-100.0, -100.0) == vec3::UnitZ());
  // Steps.
  CHECK_THROWS_WITH(steps_terrain(std::vector<steps_terrain::step>{}), Contains("empty"));
  CHECK_THROWS_WITH(steps_terrain({{0.0, 0.1}, {nan_, 0.2}}),
                    Contains("step 1") && Contains("x_start") && Contains("nan"));
  CHECK_THROWS_WITH(steps_terrain({{0.0, 0.1}, {1.0, inf_}}),
                    Contains("step 1 height") && Contains("inf"));
  CHECK_THROWS_WITH(steps_terrain({{1.0, 0.1}, {0.5, 0.2}}),
                    Contains("strictly increasing") && Contains("x_edges[1] = 0.5"));
  CHECK_THROWS_WITH(steps_terrain({{0.0, 0.1}}, nan_), Contains("base_height") && Contains("nan"));
  CHECK_THROWS_WITH(steps_terrain::stairs(0.0, -0.25, 0.1, 3),
                    Contains("run") && Contains("-0.25"));
  CHECK_THROWS_WITH(steps_terrain::stairs(0.0, 0.25, nan_, 3), Contains("rise") && Contains("nan"));
  CHECK_THROWS_WITH(steps_terrain::stairs(0.0, 0.25, 0.1, 0),
                    Contains("count") && Contains("got 0"));
  CHECK_THROWS_WITH(steps_terrain::stairs(inf_, 0.25, 0.1, 3),
                    Contains("x_start") && Contains("inf"));
  CHECK_THROWS_WITH(
      steps_terrain::boxes(o, Eigen::Vector2d(1.0, -2.0), Eigen::MatrixXd::Zero(2, 2)),
      Contains("size.y") && Contains("-2"));
  CHECK_THROWS_WITH(steps_terrain({0.0, 1.0}, {-inf_, inf_}, Eigen::MatrixXd::Zero(2, 1)),
                    Contains("heights rows") && Contains(got(1, 2)));
  CHECK_THROWS_WITH(random_boxes({.min_height = nan_}, 1),
                    Contains("min_height") && Contains("nan"));
  // The bumpy profile of Sharon 2005's Fig. 8 (new).
  using sharon_scenarios::bumpy_terrain;
  CHECK_THROWS_WITH(bumpy_terrain(90.0), Contains("max_slope_deg") && Contains("got 90"));
  CHECK_THROWS_WITH(bumpy_terrain(-1.0), Contains("max_slope_deg") && Contains("-1"));
  CHECK_THROWS_WITH(bumpy_terrain(nan_), Contains("max_slope_deg") && Contains("nan"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 0.0),
                    Contains("min_wavelength") && Contains("got 0 and 2"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 3.0, 2.0),
                    Contains("max_wavelength") && Contains("got 3 and 2"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 0.5, 2.0, -1.0), Contains("length") && Contains("-1"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 0.5, 2.0, inf_), Contains("length") && Contains("inf"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 0.5, 2.0, 10.0, nan_),
                    Contains("flat_until") && Contains("nan"));
  CHECK_THROWS_WITH(bumpy_terrain(11.0, 1, 0.5, 2.0, 10.0, 100.0),
                    Contains("flat over its whole length") && Contains("flat_until = 100"));
}

TEST_CASE("entry points: integrators, actuators, models", "[bad_input][entry_points]") {
  const planar_model m = sharon2005_human7();
  const int nj = m.num_joint_dofs();
  sim_state st = make_state(m);
  const auto still = [](const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                        Eigen::VectorXd& ddq) { ddq.setZero(); };
  semi_implicit_euler euler;
  euler.prepare(m);
  CHECK_THROWS_WITH(euler.step(m, st, -0.001, still), Contains("dt") && Contains("-0.001"));
  CHECK_THROWS_WITH(euler.step(m, st, nan_, still), Contains("dt") && Contains("nan"));
  odeint_rk4 rk4;
  rk4.prepare(m);
  CHECK_THROWS_WITH(rk4.step(m, st, 0.0, still), Contains("dt") && Contains("got 0"));
  sim_state short_state = st;
  short_state.q.resize(2);
  CHECK_THROWS_WITH(euler.step(m, short_state, 0.001, still),
                    Contains("state.q") && Contains(got(m.nq(), 2)));
  CHECK_THROWS_WITH(rk4.step(m, short_state, 0.001, still),
                    Contains("state.q") && Contains(got(m.nq(), 2)));
  // PD actuators (new: uniform names its gain at construction, not at the first rollout).
  CHECK_THROWS_WITH(pd_actuator::uniform(m, -300.0, 30.0),
                    Contains("uniform: kp") && Contains("-300"));
  CHECK_THROWS_WITH(pd_actuator::uniform(m, 300.0, nan_),
                    Contains("uniform: kd") && Contains("nan"));
  pd_actuator pd = pd_actuator::uniform(m, 300.0, 30.0);
  pd.kp[2] = -1.0;
  CHECK_THROWS_WITH(pd.make_state(m), Contains("kp of DOF 2") && Contains("-1"));
  pd.kp.resize(3);
  CHECK_THROWS_WITH(pd.make_state(m), Contains("kp") && Contains(got(nj, 3)));
  const Eigen::VectorXd g = Eigen::VectorXd::Constant(nj, 300.0);
  CHECK_THROWS_WITH(pd_actuator::capped(m, g, g, -0.5), Contains("dt") && Contains("-0.5"));
  CHECK_THROWS_WITH(pd_actuator::capped(m, g, g, 0.001, nan_),
                    Contains("margin") && Contains("nan"));
  CHECK_THROWS_WITH(pd_actuator::capped(m, g.head(2), g, 0.001),
                    Contains("kp") && Contains(got(nj, 2)));
  CHECK_THROWS_WITH(standing_pd(m, 0.001, -2.0), Contains("scale") && Contains("-2"));
  // Model builders: sizes, masses and scale factors.
  sharon2005_human7_parameters p7;
  p7.torso_mass = -40.0;
  CHECK_THROWS_WITH(sharon2005_human7(p7), Contains("torso_mass") && Contains("-40"));
  p7 = {};
  p7.shin_length = nan_;
  CHECK_THROWS_WITH(sharon2005_human7(p7), Contains("shin_length") && Contains("nan"));
  p7 = {};
  p7.heel_behind_ankle = 1.5;
  CHECK_THROWS_WITH(sharon2005_human7(p7), Contains("heel_behind_ankle") && Contains("1.5"));
  CHECK_THROWS_WITH(sharon2005_human16({.height = 0.0}), Contains("height") && Contains("got 0"));
  CHECK_THROWS_WITH(sharon2005_human16({.mass = inf_}), Contains("mass") && Contains("inf"));
  wang2009_body b;
  b.arm_mass_scale = 0.0;
  CHECK_THROWS_WITH(wang2009_humanoid(b), Contains("arm_mass_scale") && Contains("got 0"));
  b = {};
  b.arm_length_scale = nan_;
  CHECK_THROWS_WITH(wang2009_humanoid(b), Contains("arm_length_scale") && Contains("nan"));
  b = {};
  b.trunk_mass_scale = -1.3;
  CHECK_THROWS_WITH(wang2009_humanoid(b), Contains("trunk_mass_scale") && Contains("-1.3"));
  CHECK_THROWS_WITH(wang2009_humanoid(wang2009_preset("tall").scaled_to(-1.96, 79.0)),
                    Contains("height") && Contains("-1.96"));
  CHECK_THROWS_WITH(wang2009_preset("giant"), Contains("'giant'"));
}

TEST_CASE("entry points: CMA-ES, SDS and their driver", "[optimizers][bad_input][entry_points]") {
  const parameter_space space =
      parameter_space::box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(0.5, 0.5));
  auto cma = [&](cmaes_options o) { return cmaes(space, std::move(o)); };
  CHECK_THROWS_WITH(cma({.sigma0 = -0.25}), Contains("sigma0") && Contains("-0.25"));
  CHECK_THROWS_WITH(cma({.sigma0 = nan_}), Contains("sigma0") && Contains("nan"));
  CHECK_THROWS_WITH(cma({.population_size = 1}), Contains("population_size") && Contains("got 1"));
  CHECK_THROWS_WITH(cma({.population_size = 2000000000}),
                    Contains("population_size 2000000000") && Contains("96 GB"));
  CHECK_THROWS_WITH(cma({.x0 = Eigen::Vector3d(0.5, 0.5, 0.5)}),
                    Contains("x0") && Contains(got(2, 3)));
  CHECK_THROWS_WITH(cma({.x0 = Eigen::Vector2d(0.5, nan_)}),
                    Contains("parameter 'x1'") && Contains("initial value") && Contains("nan"));
  CHECK_THROWS_WITH(cma({.x0 = Eigen::Vector2d(0.5, 2.0)}),
                    Contains("parameter 'x1'") && Contains("initial value 2"));
  CHECK_THROWS_WITH(cma({.max_resamples = -1}), Contains("max_resamples") && Contains("-1"));
  CHECK_THROWS_WITH(cma({.penalty_weight = inf_}), Contains("penalty_weight") && Contains("inf"));
  CHECK_THROWS_WITH(cma({.eigen_gap = nan_}), Contains("eigen_gap") && Contains("nan"));
  CHECK_THROWS_WITH(cma({.stop = {.max_evaluations = -10}}),
                    Contains("max_evaluations") && Contains("-10"));
  CHECK_THROWS_WITH(cma({.stop = {.target_value = nan_}}),
                    Contains("target_value") && Contains("NaN"));
  CHECK_THROWS_WITH(cma({.tol_fun = -0.5}), Contains("tol_fun") && Contains("-0.5"));
  CHECK_THROWS_WITH(cmaes(parameter_space(), {}), Contains("empty"));
  CHECK_THROWS_WITH(cmaes_restarts(space, {}, {.population_factor = 0.5}),
                    Contains("population_factor") && Contains("0.5"));
  CHECK_THROWS_WITH(cmaes_restarts(space, {}, {.max_restarts = -1}),
                    Contains("max_restarts") && Contains("-1"));
  // Bounds.
  CHECK_THROWS_WITH(
      parameter_space::box(Eigen::Vector2d(0, 2), Eigen::Vector2d(1, 1), Eigen::Vector2d(0.5, 1)),
      Contains("parameter 'x1'") && Contains("lower bound (2)") && Contains("upper bound (1)"));
  CHECK_THROWS_WITH(parameter_space::box(Eigen::Vector2d(0, nan_), Eigen::Vector2d(1, 1),
                                         Eigen::Vector2d(0.5, 0.5)),
                    Contains("parameter 'x1'") && Contains("NaN") && Contains("nan"));
  CHECK_THROWS_WITH(parameter_space::box(Eigen::Vector2d(0, 0), Eigen::Vector3d(1, 1, 1),
                                         Eigen::Vector2d(0.5, 0.5)),
                    Contains("box upper") && Contains(got(2, 3)));
  // New: a range upper - lower that overflows (the scale was inf, the normalized mean NaN).
  CHECK_THROWS_WITH(
      parameter_space::box(Eigen::Vector2d(-1e308, 0), Eigen::Vector2d(1e308, 1),
                           Eigen::Vector2d(0, 0.5)),
      Contains("parameter 'x0'") && Contains("overflows") && Contains("-1e+308, 1e+308"));
  CHECK_THROWS_WITH(parameter_space::unbounded(Eigen::Vector2d(0, inf_)),
                    Contains("unbounded initial") && Contains("inf"));
  CHECK_THROWS_WITH(parameter_space::unbounded(Eigen::Vector2d(0, 0), -1.0),
                    Contains("scale") && Contains("-1"));
  CHECK_THROWS_WITH(
      parameter_space({{.name = "k", .lower = 1.0, .upper = 2.0, .initial = 1.5, .scale = nan_}}),
      Contains("parameter 'k'") && Contains("scale") && Contains("nan"));
  // SDS.
  auto sd = [&](sds_options o) { return sds(space, std::move(o)); };
  CHECK_THROWS_WITH(sd({.initial_step = 0.0}), Contains("initial_step") && Contains("got 0"));
  CHECK_THROWS_WITH(sd({.shrink = 1.0}), Contains("shrink") && Contains("got 1"));
  CHECK_THROWS_WITH(sd({.min_step = nan_}), Contains("min_step") && Contains("nan"));
  CHECK_THROWS_WITH(sd({.deltas = Eigen::Vector2d(1.0, nan_)}),
                    Contains("deltas") && Contains("element 1") && Contains("nan"));
  CHECK_THROWS_WITH(sd({.deltas = Eigen::Vector3d(1, 1, 1)}),
                    Contains("deltas") && Contains(got(2, 3)));
  CHECK_THROWS_WITH(sd({.x0 = Eigen::VectorXd::Zero(1)}), Contains("x0") && Contains(got(2, 1)));
  // The driver (new: run_options' numbers).
  const auto sphere = [](const Eigen::VectorXd& x) { return x.squaredNorm(); };
  serial_evaluator serial;
  {
    run_options ro;
    ro.checkpoint_every = -1;
    CHECK_THROWS_WITH(minimize(cma({}), sphere, serial, ro),
                      Contains("checkpoint_every") && Contains("-1"));
  }
  {
    run_options ro;
    ro.progress_interval = nan_;
    CHECK_THROWS_WITH(minimize(cma({}), sphere, serial, ro),
                      Contains("progress_interval") && Contains("nan"));
  }
  const auto make_opt = [&](std::size_t, const Eigen::VectorXd& start) {
    return sds(space, {.x0 = start, .stop = {.max_iterations = 1}});
  };
  const auto make_obj = [&](std::size_t) { return sphere; };
  CHECK_THROWS_WITH(continuation(0, Eigen::Vector2d(0.5, 0.5), make_opt, make_obj, serial),
                    Contains("num_stages") && Contains("got 0"));
  CHECK_THROWS_WITH(continuation(2, Eigen::Vector2d(0.5, nan_), make_opt, make_obj, serial),
                    Contains("continuation x0") && Contains("element 1") && Contains("nan"));
}
