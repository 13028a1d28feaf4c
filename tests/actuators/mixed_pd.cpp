// mixed_pd_actuator (command_kind::mixed): torque DOFs pass through clamped, target DOFs follow
// the PD law with the gains given in the command, gains may change between calls; mixed_command
// writes the layout; pose_hold's mixed mode with mixed_pd_actuator reproduces pd_actuator.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

/// A planar chain with three joints of different torque limits (10, 20, 1e9 N m).
planar_model three_joint_chain() {
  model_builder<planar_root> b("chain3");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "base", .mass = 5, .inertia = I});
  b.add_body({.name = "a",
              .parent = "base",
              .mass = 1,
              .inertia = I,
              .dofs = {{.name = "ja", .torque_limit = 10}}});
  b.add_body({.name = "b",
              .parent = "a",
              .mass = 1,
              .inertia = I,
              .dofs = {{.name = "jb", .torque_limit = 20}}});
  b.add_body({.name = "c", .parent = "b", .mass = 1, .inertia = I, .dofs = {{.name = "jc"}}});
  return b.build();
}

}  // namespace

static_assert(actuator<mixed_pd_actuator, planar_root>);
static_assert(actuator<mixed_pd_actuator, floating_root>);
static_assert(!actuator_with_advance<mixed_pd_actuator, planar_root>);
static_assert(mixed_pd_actuator::input_kind() == command_kind::mixed);
static_assert(actuator_with_static_input_kind<mixed_pd_actuator>);

TEST_CASE("mixed_pd_actuator: the command is [target | kp | kd | torque] per joint DOF",
          "[actuators][mixed]") {
  const auto m = three_joint_chain();
  const mixed_pd_actuator act;
  const auto st = act.make_state(m);
  REQUIRE(act.command_size(m) == 12);
  REQUIRE(act.input_kind() == command_kind::mixed);

  sim_state s = make_state(m);
  s.q.tail(3) << 0.1, -0.2, 0.3;
  s.v.tail(3) << 1.0, -2.0, 0.5;
  Eigen::VectorXd cmd(12);
  mixed_command c(cmd);
  REQUIRE(c.num_joint_dofs() == 3);
  c.set_torque(0, 7.5);                  // torque DOF, inside its limit (10)
  c.set_target(1, 0.0, 50.0, 5.0);       // target DOF: 50 (0 + 0.2) - 5 (-2) = 20, at its limit
  c.set_target(2, 0.5, 40.0, 2.0, 1.5);  // with feed-forward: 40 (0.2) - 2 (0.5) + 1.5 = 8.5
  Eigen::Vector3d tau;
  act.torques(m, s, cmd, st, tau);
  CHECK(tau[0] == 7.5);  // exactly: the zero gains add +-0
  CHECK(tau[1] == Approx(20.0).epsilon(1e-14));
  CHECK(tau[2] == Approx(8.5).epsilon(1e-14));
  // The blocks, as documented.
  CHECK(cmd.segment(0, 3) == Eigen::Vector3d(0.0, 0.0, 0.5));
  CHECK(cmd.segment(3, 3) == Eigen::Vector3d(0.0, 50.0, 40.0));
  CHECK(cmd.segment(6, 3) == Eigen::Vector3d(0.0, 5.0, 2.0));
  CHECK(cmd.segment(9, 3) == Eigen::Vector3d(7.5, 0.0, 1.5));
  CHECK(c.target() == cmd.segment(0, 3));
  CHECK(c.kp() == cmd.segment(3, 3));
  CHECK(c.kd() == cmd.segment(6, 3));
  CHECK(c.torque() == cmd.segment(9, 3));
}

TEST_CASE("mixed_pd_actuator: torque DOFs pass through, clamped, and NaN stays NaN",
          "[actuators][mixed]") {
  const auto m = three_joint_chain();
  const mixed_pd_actuator act;
  const auto st = act.make_state(m);
  sim_state s = make_state(m);
  s.q.tail(3) << 0.7, -0.4, 1.1;  // a state that zero gains must ignore
  s.v.tail(3) << -3.0, 2.0, 9.0;
  Eigen::VectorXd cmd(12);
  mixed_command c(cmd);
  const double u[3] = {-25.0, 19.75, 1e6};
  for (int j = 0; j < 3; ++j) c.set_torque(j, u[j]);
  Eigen::Vector3d tau;
  act.torques(m, s, cmd, st, tau);
  CHECK(tau[0] == -10.0);
  CHECK(tau[1] == 19.75);
  CHECK(tau[2] == 1e6);
  c.set_torque(1, std::numeric_limits<double>::quiet_NaN());
  act.torques(m, s, cmd, st, tau);
  CHECK(std::isnan(tau[1]));
}

TEST_CASE(
    "mixed_pd_actuator: target DOFs follow pd_torque with the command's gains, which may change "
    "between calls",
    "[actuators][mixed]") {
  const auto m = three_joint_chain();
  const mixed_pd_actuator act;
  const auto st = act.make_state(m);
  const double limits[3] = {10, 20, 1e9};
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Eigen::VectorXd cmd(12);
  mixed_command c(cmd);
  for (int call = 0; call < 50; ++call) {
    sim_state s = make_state(m);
    for (int i = 0; i < m.nq(); ++i) s.q[i] = U(rng);
    for (int i = 0; i < m.nv(); ++i) s.v[i] = 3 * U(rng);
    // New gains every call (an FSM state change), one DOF switching to torque every third call.
    for (int j = 0; j < 3; ++j) c.set_target(j, U(rng), 100 * (1 + U(rng)), 10 * (1 + U(rng)));
    const int torque_dof = call % 3 == 0 ? call % 2 : -1;
    if (torque_dof >= 0) c.set_torque(torque_dof, 30 * U(rng));
    Eigen::Vector3d tau;
    act.torques(m, s, cmd, st, tau);
    for (int j = 0; j < 3; ++j) {
      const double expected =
          j == torque_dof ? cmd[9 + j]
                          : pd_torque(c.kp()[j], c.kd()[j], c.target()[j], s.q[3 + j], s.v[3 + j]);
      INFO("call " << call << " DOF " << j);
      CHECK(tau[j] == clamp_torque(expected, limits[j]));
    }
  }
}

TEST_CASE("pose_hold in mixed mode drives mixed_pd_actuator as pd_actuator with its gains",
          "[actuators][mixed][rollout]") {
  const planar_model m = sharon2005_human7();
  const double dt = 1.0 / 2400.0;
  const pd_actuator pd = standing_pd(m, dt);
  const pose_hold mixed(m, {.output = command_kind::mixed, .kp = pd.kp, .kd = pd.kd});
  REQUIRE(mixed.output_kind() == command_kind::mixed);

  // One command: [target | kp | kd | 0].
  {
    pose_hold c = mixed;
    Eigen::VectorXd target = Eigen::VectorXd::LinSpaced(m.num_joint_dofs(), -0.2, 0.3);
    c.bind(std::span<const double>(target.data(), static_cast<std::size_t>(target.size())));
    sim_state s = make_state(m);
    sensors<planar_root> sen;
    sen.model_ptr = &m;
    sen.q_ptr = &s.q;
    sen.v_ptr = &s.v;
    const int nj = m.num_joint_dofs();
    Eigen::VectorXd cmd(4 * nj);
    auto st = c.make_state(m);
    c.command(sen, st, cmd);
    CHECK(cmd.segment(0, nj) == target);
    CHECK(cmd.segment(nj, nj) == pd.kp);
    CHECK(cmd.segment(2 * nj, nj) == pd.kd);
    CHECK(cmd.segment(3 * nj, nj).isZero(0.0));
  }

  // A pushed standing rollout: the same trajectory as pd_actuator with those gains.
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.5;
  opt.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain(), opt.initial_state.q);
  opt.pushes.push_back(push{0, vec3(60.0, 0.0, 0.0), 0.1, 0.2});
  const Eigen::VectorXd pose = Eigen::VectorXd::Zero(m.num_joint_dofs());
  auto scr_pd = make_rollout_scratch(m), scr_mixed = make_rollout_scratch(m);
  const auto r_pd = rollout(m, pd, pose_hold(m), distance_objective(), flat_terrain{},
                            semi_implicit_euler{}, pose, opt, scr_pd);
  const auto r_mixed = rollout(m, mixed_pd_actuator{}, mixed, distance_objective(), flat_terrain{},
                               semi_implicit_euler{}, pose, opt, scr_mixed);
  REQUIRE(r_pd.reason == stop_reason::horizon);
  REQUIRE(r_mixed.reason == r_pd.reason);
  CHECK(r_mixed.steps == r_pd.steps);
  // pd + 0 torque is the pd torque exactly (only -0 becomes +0), so the states agree exactly.
  CHECK(scr_mixed.state.q == scr_pd.state.q);
  CHECK(scr_mixed.state.v == scr_pd.state.v);
  CHECK(r_mixed.cost == r_pd.cost);
}

TEST_CASE("pose_hold names the output kind it rejects", "[actuators][mixed][bad_input]") {
  CHECK_THROWS_WITH(
      pose_hold(3, {.output = static_cast<command_kind>(9)}),
      Catch::Contains("joint_target, joint_torque, mixed or excitation, got unknown"));
  CHECK_THROWS_WITH(pose_hold(3, {.output = command_kind::excitation, .excitation = 1.5}),
                    Catch::Contains("excitation must be in [0, 1], got 1.5"));
}
