// The Wang et al. 2009 controller (controllers/fsm/wang2009_controller.hpp): its 184 parameters,
// the left/right mirror symmetry of its torques, its state transitions, the start state it writes,
// and Table 2's initial controller, which (as the paper says) does not walk.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <random>
#include <set>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "support/fsm_support.hpp"

using namespace gaitsynth;

using gaitsynth::testing::mirrored;
using gaitsynth::testing::sensed;

namespace {

/// Joint torques of the controller's command in state `phase` at sensors `x`.
Eigen::VectorXd torques_of(const floating_model& m, const wang2009_controller& c, int phase,
                           const sensed& x) {
  wang2009_controller::state_type st;
  st.phase = phase;
  st.swing_lifted = true;
  Eigen::VectorXd cmd(4 * m.num_joint_dofs()), tau(m.num_joint_dofs());
  c.command(x.sen, st, cmd);
  REQUIRE(st.phase == phase);  // no transition at the test states
  mixed_pd_actuator{}.torques(m, x.s, cmd, {}, tau);
  return tau;
}

}  // namespace

TEST_CASE("wang2009 controller: 184 named parameters, checked at bind", "[controllers][wang2009]") {
  const auto m = wang2009_humanoid();
  wang2009_controller c(m);
  REQUIRE(c.num_parameters() == 184);  // Sec. 3: "a 184 dimensional search space"
  const auto names = c.parameter_names();
  CHECK(std::set<std::string>(names.begin(), names.end()).size() == 184);
  const auto& L = c.layout();
  CHECK(names[L.kp(0, m.dof_index("lknee"))] == "s0.kp.swing_knee");
  CHECK(names[L.kd(1, m.dof_index("rhip_y"))] == "s1.kd.torso_y");
  CHECK(names[L.target(1, 11)] == "s1.target.stance_toe");
  CHECK(names[L.alpha_arm()] == "alpha_arm");
  CHECK(names.back() == "start.v.relbow_y");
  std::vector<double> p = wang2009_table2_parameters(m, c);
  c.bind(p);
  CHECK(c.parameters() == p);
  p[17] = std::nan("");
  CHECK_THROWS_WITH(c.bind(p), Catch::Contains("parameter 17 is not finite"));
  p.pop_back();
  CHECK_THROWS_WITH(c.bind(p), Catch::Contains("184"));
  CHECK_THROWS_WITH(wang2009_controller(wu2010_biped()), Catch::Contains("wu2010"));
  wang2009_controller d(m);
  d.landing_foot_angle = std::nan("");
  CHECK_THROWS_WITH(d.bind(wang2009_table2_parameters(m, d)),
                    Catch::Contains("landing_foot_angle") && Catch::Contains("nan"));
}

TEST_CASE("wang2009 controller: states 2 and 3 are the mirror images of 0 and 1",
          "[controllers][wang2009]") {
  const auto m = wang2009_humanoid();
  wang2009_controller c(m);
  std::vector<double> p = wang2009_table2_parameters(m, c);
  // Non-zero targets and feedback everywhere a parameter exists, so every role is exercised.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  const auto& L = c.layout();
  for (int k = 0; k < 11; ++k) p[L.target(0, k)] += u(rng);
  for (int k = 0; k < 12; ++k) p[L.target(1, k)] += u(rng);
  for (int k = 0; k < 4; ++k) p[L.balance(k)] = u(rng);
  p[L.c_trans()] = 10.0;  // no 0 -> 1 transition at the test state
  c.bind(p);
  Eigen::VectorXd q = neutral_configuration(m), v = Eigen::VectorXd::Zero(m.nv());
  q.head<3>() << 0.1, 0.05, 0.95;
  q.segment<4>(3) = Eigen::Vector4d(1.0, 0.05, -0.1, 0.08).normalized();
  for (int i = 7; i < m.nq(); ++i) q[i] = u(rng);
  for (int i = 0; i < m.nv(); ++i) v[i] = 3.0 * u(rng);
  const auto [qm, vm] = mirrored(m, q, v);
  std::vector<int> counts(m.num_bodies(), 0), counts_m(m.num_bodies(), 0);
  counts[m.body_index("rfoot")] = 4;  // the stance foot planted: its hip_z acts
  counts[m.body_index("ltoes")] = 0;
  for (int b = 0; b < m.num_bodies(); ++b) counts_m[m.mirror_body[b]] = counts[b];
  const sensed a(m, q, v, counts), b(m, qm, vm, counts_m);
  for (int phase : {0, 1}) {
    const Eigen::VectorXd t = torques_of(m, c, phase, a);
    const Eigen::VectorXd tm = torques_of(m, c, phase + 2, b);
    for (int j = 0; j < m.num_joint_dofs(); ++j) {
      INFO("phase " << phase << " DOF " << m.dofs[j].name);
      CHECK(tm[m.mirror_dof[j]] == Approx(m.mirror_sign[j] * t[j]).margin(1e-9));
    }
    CHECK(t.cwiseAbs().maxCoeff() > 1.0);  // the torques are not all zero
  }
}

TEST_CASE("wang2009 controller: transitions of Fig. 2", "[controllers][wang2009]") {
  const auto m = wang2009_humanoid();
  wang2009_controller c(m);
  std::vector<double> p = wang2009_table2_parameters(m, c);
  c.bind(p);
  const double c_trans = p[c.layout().c_trans()];
  Eigen::VectorXd q = neutral_configuration(m), v = Eigen::VectorXd::Zero(m.nv());
  q[2] = 1.0;
  const int lfoot = m.body_index("lfoot"), rfoot = m.body_index("rfoot");
  std::vector<int> airborne(m.num_bodies(), 0), left_down = airborne;
  left_down[lfoot] = 2;
  Eigen::VectorXd cmd(4 * m.num_joint_dofs());
  wang2009_controller::state_type st;
  // 0 -> 1: the COM passes c_trans ahead of the stance (right) ankle.
  {
    sensed x(m, q, v, left_down);  // the swing foot still down: no lift-off yet
    st = c.make_state(m);
    c.command(x.sen, st, cmd);
    CHECK(st.phase == 0);  // COM above the ankle, and a contact before lift-off is no landing
    x.sen.com.x() = x.sen.body_position[rfoot].x() + c_trans + 0.01;
    c.command(x.sen, st, cmd);
    CHECK(st.phase == 1);
  }
  // 1 -> 2 needs the swing foot lifted, then a heel-first touch (toes up by > 0.1 rad).
  {
    Eigen::VectorXd qf = q;
    qf[7 + m.dof_index("lankle_y")] = -0.3;  // toes up
    sensed up(m, qf, v, airborne), down(m, qf, v, left_down);
    st.phase = 1;
    st.swing_lifted = false;
    c.command(down.sen, st, cmd);
    CHECK(st.phase == 1);  // not lifted since the swing began
    c.command(up.sen, st, cmd);
    CHECK(st.swing_lifted);
    Eigen::VectorXd qt = q;
    qt[7 + m.dof_index("lankle_y")] = 0.3;  // toes down: a scuff, not a landing
    sensed scuff(m, qt, v, left_down);
    c.command(scuff.sen, st, cmd);
    CHECK(st.phase == 1);
    c.command(down.sen, st, cmd);
    CHECK(st.phase == 2);
    CHECK_FALSE(st.swing_lifted);  // the right leg swings now and is still down
  }
  // 2 -> 0 on an early contact of the swing (right) foot after it lifted.
  {
    std::vector<int> right_down(m.num_bodies(), 0);
    right_down[rfoot] = 1;
    sensed up(m, q, v, airborne), down(m, q, v, right_down);
    st.phase = 2;
    st.swing_lifted = false;
    c.command(up.sen, st, cmd);
    c.command(down.sen, st, cmd);
    CHECK(st.phase == 0);
  }
}

TEST_CASE("wang2009 controller: Table 2's start state, and Table 2 alone does not walk",
          "[controllers][wang2009]") {
  for (const wang2009_shape shape : {wang2009_shape::stocky, wang2009_shape::tall}) {
    const auto m = wang2009_humanoid(shape);
    wang2009_controller c(m);
    const std::vector<double> p = wang2009_table2_parameters(m, c);
    c.bind(p);
    CHECK(p[c.layout().kp(0, m.dof_index("back_y"))] ==
          Approx(300.0 * m.total_mass() / 70.0));  // gains scale with the weight
    sim_state s = make_state(m);
    c.initial_state(m, s);
    CHECK(s.v[0] == 1.3);
    CHECK(s.q[7 + m.dof_index("lknee")] == 1.35);
    CHECK(s.v[6 + m.dof_index("lankle_y")] == -15.0);
    // The lowest sole or toe point is on the ground.
    auto ws = make_workspace(m);
    forward_kinematics(m, ws, s.q);
    double lowest = 1e9;
    for (const auto& cp : m.contact_points)
      if (cp.role == contact_point::kind::sole || cp.role == contact_point::kind::toe)
        lowest = std::min(lowest, point_position(m, ws, cp.body, cp.position).z());
    CHECK(lowest == Approx(0.0).margin(1e-12));
    // "It is not stable ... but is sufficient for initialization": it falls within 10 s.
    auto scratch = make_rollout_scratch(m);
    rollout_options opt;
    opt.contact.mu = 10.0;
    opt.fall_height = 0.7;  // E_fail's height
    const rollout_result r =
        rollout(m, mixed_pd_actuator{}, c, distance_objective(), flat_terrain(),
                semi_implicit_euler(), std::span<const double>(p), opt, scratch);
    // It falls; the fall ends in a blow-up (COM faster than 100 m/s) before the fall test sees it,
    // which the rollout reports as a divergence since divergence_com_speed: either is a failure.
    CHECK((r.reason == stop_reason::fell || r.reason == stop_reason::non_finite));
    CHECK(r.time < 10.0);
  }
}
