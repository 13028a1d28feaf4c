// Seeded joint-velocity perturbations (rollout/start_perturbations.hpp) and
// rollout_options::initial_velocity_offset, which adds one to the start state after a controller
// that owns its start state (Wang et al. 2009's) has written it.
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"

using namespace gaitsynth;

namespace {
/// The Wang 2009 controller bound to Table 2's parameters, and those parameters.
std::pair<wang2009_controller, std::vector<double>> table2_controller(const floating_model& m) {
  wang2009_controller c(m);
  std::vector<double> p = wang2009_table2_parameters(m, c);
  c.bind(p);
  return {c, p};
}
}  // namespace

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
  const auto [c, p] = table2_controller(m);
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

TEST_CASE("a robust cost over perturbed starts is the same for any thread count",
          "[rollout][perturbation][determinism]") {
  // The robust optimization of examples/wang2009_walk.cpp: the problem plus variants from seeded
  // perturbed starts, evaluated on a thread pool; the cost of a candidate must not depend on which
  // worker, or how many workers, evaluate it.
  const auto m = wang2009_humanoid();
  const auto [c, p0] = table2_controller(m);
  rollout_options opt;
  opt.initial_state = make_state(m);
  opt.implicit_joint_damping = true;
  const auto obj = wang2009_objective(m);
  const rollout_problem prob{m,  mixed_pd_actuator{}, c, obj, flat_terrain{}, semi_implicit_euler{},
                             opt};
  std::vector<std::decay_t<decltype(prob)>> variants;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 2, 0.05, 11)) {
    auto v = prob;
    v.options.initial_velocity_offset = dv;
    variants.push_back(v);
  }
  const auto robust = make_problem_with_variants(prob, std::move(variants));
  std::vector<Eigen::VectorXd> xs;
  const Eigen::VectorXd x0 = Eigen::Map<const Eigen::VectorXd>(p0.data(), std::ssize(p0));
  for (int k = 0; k < 5; ++k) {
    Eigen::VectorXd x = x0;
    x[static_cast<Eigen::Index>(k)] *= 1.0 + 0.01 * k;
    xs.push_back(x);
  }
  auto costs = [&](unsigned threads) {
    thread_pool_evaluator pool(threads);
    problem_contexts ctx(robust, pool.thread_count());
    problem_cost f(robust, 0.25, ctx);
    std::vector<double> out(xs.size());
    pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
    return out;
  };
  const std::vector<double> one = costs(1), two = costs(2), three = costs(3);
  CHECK(one == two);  // bit for bit
  CHECK(one == three);
  // The variants count: the robust cost is more than the nominal one alone.
  CHECK(one[0] > prob.cost(x0, 0.25));
}
