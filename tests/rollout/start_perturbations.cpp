// Seeded joint-velocity perturbations (rollout/start_perturbations.hpp) and
// rollout_options::initial_velocity_offset, which adds one to the start state after a controller
// that owns its start state (Wang et al. 2009's) has written it.
#include <catch2/catch.hpp>
#include <cmath>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"

using namespace gaitsynth;

TEST_CASE("joint_velocity_perturbations: seeded N(0, sigma) on the joints, zero on the root",
          "[rollout][perturbation]") {
  const auto m = wang2009_humanoid();
  const auto a = joint_velocity_perturbations(m, 400, 0.05, 7);
  REQUIRE(a.size() == 400u);
  double sum = 0.0, sum2 = 0.0;
  long n = 0;
  for (const Eigen::VectorXd& v : a) {
    REQUIRE(v.size() == m.nv());
    CHECK(v.head(6).isZero(0.0));
    for (int j = 6; j < m.nv(); ++j) {
      sum += v[j];
      sum2 += v[j] * v[j];
      ++n;
    }
  }
  // 12000 samples: the mean's standard error is 0.05 / sqrt(12000) = 4.6e-4, the standard
  // deviation's about 0.05 / sqrt(2 * 12000) = 3.2e-4; the margins are 5 of those.
  const double mean = sum / static_cast<double>(n);
  CHECK(std::abs(mean) < 2.3e-3);
  CHECK(std::sqrt(sum2 / static_cast<double>(n) - mean * mean) == Approx(0.05).margin(1.6e-3));

  // Offset k depends on (seed, k) alone; another seed gives other offsets.
  const auto b = joint_velocity_perturbations(m, 3, 0.05, 7);
  for (int k = 0; k < 3; ++k)
    CHECK(b[static_cast<std::size_t>(k)] == a[static_cast<std::size_t>(k)]);
  CHECK(joint_velocity_perturbations(m, 1, 0.05, 8)[0] != a[0]);
  CHECK(joint_velocity_perturbations(m, 0, 0.05, 7).empty());

  CHECK_THROWS_WITH(joint_velocity_perturbations(m, -1, 0.05, 7),
                    Catch::Contains("count must be >= 0, got -1"));
  CHECK_THROWS_WITH(joint_velocity_perturbations(m, 2, std::nan(""), 7),
                    Catch::Contains("sigma must be finite and >= 0, got nan"));
}

TEST_CASE("initial_velocity_offset is added after the controller writes its start state",
          "[rollout][perturbation]") {
  const auto m = wang2009_humanoid();
  wang2009_controller c(m);
  const std::vector<double> p = wang2009_table2_parameters(m, c);
  c.bind(p);
  sim_state start = make_state(m);
  c.initial_state(m, start);

  rollout_options opt;
  opt.duration = 10.0 / 2400.0;
  opt.initial_state = make_state(m);  // overwritten by the controller's start state
  opt.initial_velocity_offset = joint_velocity_perturbations(m, 1, 0.05, 1)[0];
  trajectory tr;
  opt.record = &tr;
  auto scratch = make_rollout_scratch(m);
  semi_implicit_euler integ;
  wang2009_controller cc = c;
  (void)rollout(m, mixed_pd_actuator{}, cc, distance_objective(), flat_terrain{}, integ,
                std::span<const double>(p), opt, scratch);
  REQUIRE(!tr.frames.empty());
  const Eigen::VectorXd expected = start.v + opt.initial_velocity_offset;
  CHECK(tr.frames.front().v.isApprox(expected, 1e-15));
  CHECK(!tr.frames.front().v.isApprox(start.v, 1e-6));

  SECTION("a wrong size or a non-finite entry throws, naming the option") {
    opt.initial_velocity_offset = Eigen::VectorXd::Zero(m.nv() - 1);
    CHECK_THROWS_WITH(rollout(m, mixed_pd_actuator{}, cc, distance_objective(), flat_terrain{},
                              integ, std::span<const double>(p), opt, scratch),
                      Catch::Contains("initial_velocity_offset"));
    opt.initial_velocity_offset = Eigen::VectorXd::Zero(m.nv());
    opt.initial_velocity_offset[9] = std::nan("");
    CHECK_THROWS_WITH(rollout(m, mixed_pd_actuator{}, cc, distance_objective(), flat_terrain{},
                              integ, std::span<const double>(p), opt, scratch),
                      Catch::Contains("initial_velocity_offset"));
  }
}
