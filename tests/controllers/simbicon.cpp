// SIMBICON (controllers/fsm/simbicon.hpp), the baseline of Wang et al. 2009: its parameters, the
// mirror symmetry of its torques, and the claim of issue 11 item 1: with Yin et al.'s walk it walks
// 100 s on flat ground, also from 10 starts with joint velocities perturbed by N(0, 0.05 rad/s).
#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "support/fsm_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::mirrored;
using gaitsynth::testing::sensed;

namespace {
simbicon_controller walk_controller(const floating_model& m) {
  const auto [kp, kd] = simbicon_walk_gains(m);
  simbicon_controller c(m, kp, kd);
  c.bind(simbicon_walk_parameters());
  return c;
}

/// A 100 s walk from `start`: the reason it stopped, the time, the distance along x.
rollout_result walk(const floating_model& m, const simbicon_controller& c, const sim_state& start,
                    double seconds) {
  rollout_options o = walk_options({});  // stall detection on (rollout/walk_check.hpp)
  o.contact.mu = 10.0;
  o.fall_height = 0.7;
  o.duration = seconds;
  o.initial_state = start;
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> p = c.parameters();
  return rollout(m, mixed_pd_actuator{}, c, distance_objective(), flat_terrain{},
                 semi_implicit_euler{}, std::span<const double>(p), o, scratch);
}
}  // namespace

TEST_CASE("simbicon: named parameters, checked at bind", "[controllers][simbicon]") {
  const auto m = wang2009_humanoid();
  simbicon_controller c = walk_controller(m);
  REQUIRE(c.num_parameters() == 22);
  CHECK(c.parameter_names()[0] == "s0.duration");
  CHECK(c.parameter_names()[18] == "s1.swing_knee");
  std::vector<double> p = simbicon_walk_parameters();
  p[0] = 0.0;
  CHECK_THROWS_WITH(c.bind(p), Catch::Contains("s0.duration"));
  p[0] = std::nan("");
  CHECK_THROWS_WITH(c.bind(p), Catch::Contains("parameter 0 is not finite"));
}

TEST_CASE("simbicon: states 2 and 3 mirror 0 and 1", "[controllers][simbicon]") {
  const auto m = wang2009_humanoid();
  const simbicon_controller c = walk_controller(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  Eigen::VectorXd q = neutral_configuration(m), v = Eigen::VectorXd::Zero(m.nv());
  q.head<3>() << 0.1, -0.04, 0.93;
  q.segment<4>(3) = Eigen::Vector4d(1.0, -0.04, 0.1, 0.06).normalized();
  for (int i = 7; i < m.nq(); ++i) q[i] = u(rng);
  for (int i = 0; i < m.nv(); ++i) v[i] = 3.0 * u(rng);
  const auto [qm, vm] = mirrored(m, q, v);
  std::vector<int> counts(m.num_bodies(), 0), counts_m(m.num_bodies(), 0);
  counts[m.body_index("rfoot")] = 4;
  for (int b = 0; b < m.num_bodies(); ++b) counts_m[m.mirror_body[b]] = counts[b];
  const sensed a(m, q, v, counts), b(m, qm, vm, counts_m);
  for (int phase : {0, 1}) {
    Eigen::VectorXd cmd(4 * m.num_joint_dofs()), t(m.num_joint_dofs()), tm(m.num_joint_dofs());
    simbicon_controller::state_type st{.phase = phase, .phase_start = 0.0, .swing_lifted = false};
    c.command(a.sen, st, cmd);
    REQUIRE(st.phase == phase);
    mixed_pd_actuator{}.torques(m, a.s, cmd, {}, t);
    st = {.phase = phase + 2, .phase_start = 0.0, .swing_lifted = false};
    c.command(b.sen, st, cmd);
    REQUIRE(st.phase == phase + 2);
    mixed_pd_actuator{}.torques(m, b.s, cmd, {}, tm);
    for (int j = 0; j < m.num_joint_dofs(); ++j) {
      INFO("phase " << phase << " DOF " << m.dofs[j].name);
      CHECK(tm[m.mirror_dof[j]] == Approx(m.mirror_sign[j] * t[j]).margin(1e-9));
    }
  }
}

TEST_CASE("simbicon walks 100 s on flat ground, also from 10 perturbed starts",
          "[controllers][simbicon][claim]") {
  const auto m = wang2009_humanoid();
  const simbicon_controller c = walk_controller(m);
  const sim_state start = simbicon_start_state(m);
  const rollout_result r = walk(m, c, start, 100.0);
  CHECK(walked(r));
  CHECK(r.com_final.x() - r.com_initial.x() > 50.0);  // about 0.7 m/s
  // The claim tests' perturbed starts (rollout/start_perturbations.hpp: portable, seed 2009).
  const std::vector<Eigen::VectorXd> dv = joint_velocity_perturbations(m, 10, 0.05, 2009);
  int walking = 0;
  for (int k = 0; k < 10; ++k) {
    sim_state s = start;
    s.v += dv[static_cast<std::size_t>(k)];
    const rollout_result rk = walk(m, c, s, 100.0);
    INFO("perturbed start " << k << ": " << to_string(rk.reason) << " after " << rk.time << " s");
    CHECK(walked(rk));
    walking += walked(rk);
  }
  CHECK(walking == 10);
}
