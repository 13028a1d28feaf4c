// musculotendon_actuator on the Wang 2012 humanoid: the 16 leg MTUs act on the right DOFs in the
// right directions, their torques are the virtual work of their length (scaled by rho), their
// fibers start in equilibrium at a plausible length, and a muscle-driven rollout runs, repeats
// bit for bit and refuses bad input with messages that name it.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <map>
#include <string>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "support/same_bits.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gaitsynth_test::same_bits_unless_fused;

static_assert(actuator<musculotendon_actuator, floating_root>);
static_assert(actuator_with_advance<musculotendon_actuator, floating_root>);
static_assert(actuator_with_start<musculotendon_actuator, floating_root>);
static_assert(actuator_with_sensing<musculotendon_actuator, floating_root>);
static_assert(actuator_with_reset_state<musculotendon_actuator, floating_root>);
static_assert(!actuator_with_continuous_state<musculotendon_actuator, floating_root>);

namespace {
constexpr double dt = 1.0 / 2400.0;

/// Every MTU at excitation u, every joint DOF servoed to 0 with standing_pd's gains (pose_hold's
/// excitation mode).
pose_hold muscle_hold(const floating_model& m, int num_units, double u) {
  const pd_actuator g = standing_pd(m, dt);
  return pose_hold(m, {.output = command_kind::excitation,
                       .kp = g.kp,
                       .kd = g.kd,
                       .num_excitations = num_units,
                       .excitation = u});
}
}  // namespace

TEST_CASE("the leg MTUs act on the sagittal hip, knee and ankle in the anatomical directions",
          "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  REQUIRE(units.size() == 16);
  // Sign of the torque of a pulling MTU at the standing pose, in the model's DOF signs (hip_y +
  // extension, knee + flexion, ankle_y + plantarflexion); 0 where the MTU does not cross.
  const std::map<std::string, std::array<int, 3>> expected{
      {"GLU", {+1, 0, 0}}, {"HFL", {-1, 0, 0}},  {"VAS", {0, -1, 0}}, {"TA", {0, 0, -1}},
      {"SOL", {0, 0, +1}}, {"HAM", {+1, +1, 0}}, {"RF", {-1, -1, 0}}, {"GAS", {0, +1, +1}}};
  const Eigen::VectorXd qj = Eigen::VectorXd::Constant(m.num_joint_dofs(), 0.05);
  for (const std::string side : {"l", "r"}) {
    const int dofs[3] = {m.dof_index(side + "hip_y"), m.dof_index(side + "knee"),
                         m.dof_index(side + "ankle_y")};
    for (const auto& [name, signs] : expected) {
      const auto& u = *std::find_if(units.begin(), units.end(),
                                    [&](const auto& x) { return x.name == side + name; });
      Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.num_joint_dofs());
      u.add_torques(qj, 1000.0, tau);
      for (int k = 0; k < 3; ++k) {
        INFO(u.name << " on " << m.dofs[dofs[k]].name);
        CHECK((tau[dofs[k]] > 0.0 ? 1 : tau[dofs[k]] < 0.0 ? -1 : 0) == signs[k]);
        tau[dofs[k]] = 0.0;
      }
      CHECK(tau.cwiseAbs().maxCoeff() == 0.0);  // no other DOF
    }
  }
}

TEST_CASE("each crossing's torque is the virtual work of its length change, over rho",
          "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  for (const auto& u : musculotendon::geyer_herr_leg_muscles(m))
    for (int c = 0; c < u.num_crossings; ++c) {
      const auto& x = u.crossings[c];
      for (double q : {-0.6, -0.2, 0.0, 0.3, 0.9}) {
        const double e = 1e-6;
        const double dldq = (x.length_change(q + e) - x.length_change(q - e)) / (2 * e);
        INFO(u.name << " crossing " << c << " at q = " << q);
        CHECK_THAT(x.torque(q, 1.0), WithinAbs(-dldq / x.length_factor, 1e-8));
      }
    }
}

TEST_CASE(
    "length_and_arms gives unit::length and each crossing's arm to the bit, and the sum "
    "of the crossings' length changes",
    "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  Eigen::VectorXd qj = Eigen::VectorXd::Constant(m.num_joint_dofs(), 0.0);
  for (const auto& u : musculotendon::geyer_herr_leg_muscles(m)) {
    const std::array<double, 2> sines = u.reference_sines();
    CHECK(sines[0] == u.crossings[0].reference_sine());
    for (double q : {-0.7, -0.1, 0.0, 0.4, 1.1}) {
      qj.setConstant(q);
      std::array<double, 2> arms{};
      INFO(u.name << " at q = " << q);
      CHECK(same_bits_unless_fused(u.length_and_arms(qj, sines, arms), u.length(qj)));
      double l = u.parameters.optimal_fiber_length + u.parameters.tendon_slack_length;
      for (int c = 0; c < u.num_crossings; ++c) l += u.crossings[c].length_change(q);
      CHECK_THAT(l, WithinAbs(u.length(qj), 1e-15));  // the definition, up to a contracted FMA
      for (int c = 0; c < u.num_crossings; ++c)
        CHECK(same_bits_unless_fused(arms[static_cast<std::size_t>(c)], u.crossings[c].arm(q)));
    }
  }
}

TEST_CASE(
    "torques at the configuration of the last advance reuse its force and arms to the bit; "
    "elsewhere they are recomputed",
    "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m), 0.3);
  const int nj = m.num_joint_dofs(), M = act.num_units();
  auto st = act.make_state(m);
  sim_state s = make_state(m);
  s.q.tail(nj).setConstant(0.1);
  act.start(m, s, st);
  Eigen::VectorXd cmd = Eigen::VectorXd::Zero(act.command_size(m));
  cmd.head(M).setConstant(0.6);
  // What the MTUs' torques are at q with the state's fibers, from the path alone.
  auto muscle_torques = [&](const Eigen::VectorXd& q) {
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(nj);
    for (int i = 0; i < M; ++i) {
      const auto& u = act.units()[static_cast<std::size_t>(i)];
      const double f =
          musculotendon::forces_at(u.parameters, u.length(q), st.fiber_length[i]).tendon;
      u.add_torques(q, f, tau);
    }
    return tau;
  };
  Eigen::VectorXd tau(nj);
  for (int k = 0; k < 5; ++k) {  // the rollout's order: advance at the new pose, then torques
    s.q.tail(nj).array() += 0.01 * (k + 1);
    act.advance(m, s, cmd, st, dt);
    act.torques(m, s, cmd, st, tau);  // the mixed block is zero: muscles only
    const Eigen::VectorXd expected = muscle_torques(s.q.tail(nj));
    for (int j = 0; j < nj; ++j) CHECK(same_bits_unless_fused(tau[j], expected[j]));
    CHECK(tau.cwiseAbs().maxCoeff() > 1.0);
  }
  s.q.tail(nj).array() += 0.05;  // a pose the state was not advanced at
  act.torques(m, s, cmd, st, tau);
  const Eigen::VectorXd moved = muscle_torques(s.q.tail(nj));
  for (int j = 0; j < nj; ++j) CHECK(same_bits_unless_fused(tau[j], moved[j]));
  CHECK((st.joint_angles.array() != s.q.tail(nj).array()).any());
}

TEST_CASE("at the standing pose every fiber starts in isometric equilibrium, on its working range",
          "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m), 0.05);
  auto st = act.make_state(m);
  CHECK(std::isnan(st.fiber_length[0]));  // until start
  sim_state s = make_state(m);
  act.start(m, s, st);
  std::vector<double> sensed(static_cast<std::size_t>(act.sensed_size(m)));
  act.sense(m, st, sensed);
  for (int i = 0; i < act.num_units(); ++i) {
    const auto& u = act.units()[static_cast<std::size_t>(i)];
    const double l = st.fiber_length[i] / u.parameters.optimal_fiber_length;
    INFO(u.name << ": l_CE = " << l << " l_opt, F = " << st.force[i] << " N");
    // Within f_L's working range (f_L > 0.4). The straight knee puts Geyer & Herr's VAS at its
    // shortest, 0.52 l_opt (its reference angle is 55 deg of flexion); the others lie in 0.68-0.99
    // at a = 0.05.
    CHECK(l > 0.5);
    CHECK(l < 1.4);
    CHECK_THAT(musculotendon::equilibrium_velocity(u.parameters, st.activation[i], st.mtu_length[i],
                                                   st.fiber_length[i]),
               WithinAbs(0.0, 1e-9));
    CHECK(st.force[i] > 0.0);
    CHECK(sensed[static_cast<std::size_t>(i)] == st.force[i] / u.parameters.max_isometric_force);
    CHECK(sensed[static_cast<std::size_t>(act.num_units() + i)] == l);
  }
}

TEST_CASE("the muscle torques add to the mixed block's PD torques", "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m), 0.3);
  auto st = act.make_state(m);
  sim_state s = make_state(m);
  s.q.tail(m.num_joint_dofs()).setConstant(0.1);
  s.v.tail(m.num_joint_dofs()).setConstant(-0.2);
  act.start(m, s, st);
  const int nj = m.num_joint_dofs(), M = act.num_units();
  Eigen::VectorXd cmd = Eigen::VectorXd::Zero(act.command_size(m));
  const pd_actuator g = standing_pd(m, dt);
  const auto hold = muscle_hold(m, M, 0.3);
  auto ctrl_state = hold.make_state(m);
  hold.command(sensors<floating_root>{}, ctrl_state, cmd);
  CHECK(cmd.head(M).isConstant(0.3));
  CHECK(hold.command_size(m) == act.command_size(m));
  Eigen::VectorXd tau(nj), muscles = Eigen::VectorXd::Zero(nj);
  act.torques(m, s, cmd, st, tau);
  for (int i = 0; i < M; ++i)
    act.units()[static_cast<std::size_t>(i)].add_torques(s.q.tail(nj), st.force[i], muscles);
  for (int j = 0; j < nj; ++j) {
    const double pd =
        clamp_torque(pd_torque(g.kp[j], g.kd[j], 0.0, 0.1, -0.2), m.dofs[j].torque_limit);
    INFO(m.dofs[j].name);
    CHECK_THAT(tau[j], WithinAbs(pd + muscles[j], 1e-9 * (1.0 + std::abs(tau[j]))));
  }
  CHECK(muscles.cwiseAbs().maxCoeff() > 10.0);  // the muscles do contribute
}

TEST_CASE("a muscle-driven rollout runs, advances the muscles and repeats bit for bit",
          "[actuators][musculotendon][rollout]") {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m));
  const auto hold = muscle_hold(m, act.num_units(), 0.2);
  rollout_options opt;
  opt.duration = 0.3;
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> params(static_cast<std::size_t>(m.num_joint_dofs()), 0.0);
  auto ctrl = hold;
  auto obj = distance_objective();
  semi_implicit_euler integ;
  rollout_policy_states<musculotendon_actuator, pose_hold, decltype(obj)> states;
  auto run = [&] {
    return rollout(m, act, ctrl, obj, flat_terrain(), integ, std::span<const double>(params), opt,
                   scratch, states);
  };
  const rollout_result a = run();
  CHECK(a.reason == stop_reason::horizon);
  const rollout_result b = run();  // the second reuses (resets) the actuator state in place
  CHECK(a.com_final == b.com_final);
  CHECK(a.cost == b.cost);
  // The activations rose from 0.01 toward the excitation 0.2 with the 10 ms time constant.
  const auto& st = *states.actuator;
  CHECK_THAT(st.activation[0], WithinRel(0.2 - 0.19 * std::pow(1.0 - 100.0 * dt, 720), 1e-9));
  CHECK(st.fiber_velocity.allFinite());
}

TEST_CASE("a controller writing another number of excitations is refused at set-up",
          "[actuators][musculotendon][bad_input]") {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m));
  rollout_options opt;
  opt.duration = 0.01;
  auto scratch = make_rollout_scratch(m);
  const Eigen::VectorXd pose = Eigen::VectorXd::Zero(m.num_joint_dofs());
  CHECK_THROWS_WITH(rollout(m, act, muscle_hold(m, 14, 0.1), distance_objective(), flat_terrain(),
                            semi_implicit_euler(), pose, opt, scratch),
                    Contains("writes 134 command entries, the actuator takes 136"));
}

TEST_CASE("bad musculotendon input is refused naming the MTU and the value",
          "[actuators][musculotendon][bad_input]") {
  const auto m = wang2012_humanoid();
  auto units = musculotendon::geyer_herr_leg_muscles(m);
  CHECK_THROWS_WITH(musculotendon_actuator(units, 1.5),
                    Contains("initial_activation") && Contains("1.5"));
  auto bad = units;
  bad[3].parameters.optimal_fiber_length = -0.0625;
  CHECK_THROWS_WITH(musculotendon_actuator(bad), Contains("lTA") && Contains("-0.0625"));
  bad = units;
  bad[0].crossings[0].dof = 77;
  const musculotendon_actuator far(bad);
  CHECK_THROWS_WITH(far.make_state(m), Contains("lGLU") && Contains("77"));
  CHECK_THROWS_WITH(musculotendon::geyer_herr_leg_muscles(m, {.hip = "hip_pitch"}),
                    Contains("lhip_pitch"));
  // A pose that folds an MTU shorter than its fiber can be.
  bad = units;
  bad[2].parameters.tendon_slack_length = 0.001;
  bad[2].parameters.optimal_fiber_length = 0.001;
  const musculotendon_actuator short_mtu(bad);
  auto st = short_mtu.make_state(m);
  sim_state s = make_state(m);
  s.q[floating_root::nq + m.dof_index("lknee")] = -1.0;  // hyperextended: VAS shortest
  CHECK_THROWS_WITH(short_mtu.start(m, s, st), Contains("lVAS"));
}

TEST_CASE("scale_max_isometric_force weakens one MTU in both legs, or one leg's, and nothing else",
          "[actuators][musculotendon]") {
  const auto m = wang2012_humanoid();
  const auto base = musculotendon::geyer_herr_leg_muscles(m);
  auto weak = base;
  musculotendon::scale_max_isometric_force(weak, "GAS", 0.25);
  musculotendon::scale_max_isometric_force(weak, "rVAS", 0.1);
  REQUIRE(weak.size() == base.size());
  for (std::size_t i = 0; i < base.size(); ++i) {
    INFO(base[i].name);
    const double f = base[i].name == "lGAS" || base[i].name == "rGAS" ? 0.25
                     : base[i].name == "rVAS"                         ? 0.1
                                                                      : 1.0;
    CHECK(weak[i].parameters.max_isometric_force == base[i].parameters.max_isometric_force * f);
    CHECK(weak[i].parameters.optimal_fiber_length == base[i].parameters.optimal_fiber_length);
  }
  CHECK_THROWS_WITH(musculotendon::scale_max_isometric_force(weak, "QUAD", 0.5),
                    Contains("'QUAD'") && Contains("lGLU"));
  CHECK_THROWS_WITH(musculotendon::scale_max_isometric_force(weak, "GAS", -1.0),
                    Contains("'GAS'") && Contains("-1"));
  CHECK_THROWS_WITH(musculotendon::scale_max_isometric_force(weak, "GAS", std::nan("")),
                    Contains("nan"));
}
