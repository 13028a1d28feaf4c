#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
namespace tf = gaitsynth::test_functions;

namespace {
// Criteria after which a restart follows (the global ones end the sequence).
bool local_criterion(stop_criterion c) {
  return c != stop_criterion::none && c != stop_criterion::target_value &&
         c != stop_criterion::max_evaluations && c != stop_criterion::callback;
}

// The per-run records add up to the whole result, and every run but the last ended locally.
void check_run_records(const optimization_result& r) {
  REQUIRE(r.runs.size() == static_cast<std::size_t>(r.restarts) + 1);
  std::int64_t evaluations = 0, iterations = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    INFO("run " << k);
    evaluations += r.runs[k].evaluations;
    iterations += r.runs[k].iterations;
    best = std::min(best, r.runs[k].best_value);
    if (k + 1 < r.runs.size()) CHECK(local_criterion(r.runs[k].stopped));
  }
  CHECK(evaluations == r.evaluations);
  CHECK(iterations == r.iterations);
  CHECK(best == r.value);
  CHECK(r.runs.back().stopped == r.stopped);
  CHECK_FALSE(r.runs.front().small_population);
}

cmaes_restarts make_rastrigin(restart_strategy strategy, std::uint64_t seed) {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = seed;
  o.stop.target_value = 1e-8;
  o.stop.max_evaluations = 1'000'000;
  restart_options ro;
  ro.strategy = strategy;
  ro.max_restarts = 9;
  return cmaes_restarts(parameter_space::unbounded(uniform_x0(10, -3, 3, seed)), o, ro);
}
}  // namespace

TEST_CASE("Rastrigin 10-D is solved with IPOP and BIPOP restarts", "[optimizers]") {
  for (auto strategy : {restart_strategy::ipop, restart_strategy::bipop}) {
    for (std::uint64_t seed : {0u, 1u}) {
      auto es = make_rastrigin(strategy, seed);
      std::vector<int> lambdas;
      const auto r = minimize(es, tf::rastrigin, run_options{}, [&](const optimizer_status& s) {
        if (lambdas.empty() || lambdas.back() != s.batch_size) lambdas.push_back(s.batch_size);
      });
      INFO("strategy " << static_cast<int>(strategy) << " seed " << seed);
      CHECK(r.stopped == stop_criterion::target_value);
      CHECK(r.value <= 1e-8);
      CHECK(r.x.cwiseAbs().maxCoeff() < 1e-4);  // the global minimum, not a local one
      CHECK(r.restarts > 0);  // default-population CMA-ES rarely solves it: restarts did
      CHECK(r.restarts == es.restarts());
      check_run_records(r);
      CHECK(r.runs == es.runs());
      if (strategy == restart_strategy::ipop) {
        // IPOP doubles lambda on every restart: 10, 20, 40, ...
        for (std::size_t i = 1; i < lambdas.size(); ++i) CHECK(lambdas[i] == 2 * lambdas[i - 1]);
        for (std::size_t k = 0; k < r.runs.size(); ++k) {
          CHECK(r.runs[k].population_size == 10 << k);
          CHECK_FALSE(r.runs[k].small_population);
        }
      }
    }
  }
}

TEST_CASE("IPOP multiplies the rounded or, as pycma does, the unrounded default", "[optimizers]") {
  // A flat objective ends each run after its 2 iterations: the sequence of populations alone.
  auto populations = [](int n, bool unrounded, int lambda) {
    cmaes_options o;
    o.stop.max_iterations = 2;  // per run
    o.population_size = lambda;
    restart_options ro;
    ro.strategy = restart_strategy::ipop;
    ro.max_restarts = 4;
    ro.unrounded_population_base = unrounded;
    cmaes_restarts es(parameter_space::unbounded(Eigen::VectorXd::Zero(n)), o, ro);
    const auto r = minimize(es, [](const Eigen::VectorXd&) { return 1.0; });
    std::vector<int> lambdas;
    for (const run_record& run : r.runs) lambdas.push_back(run.population_size);
    return lambdas;
  };
  // n = 10: 4 + 3 ln 10 = 10.908 -> 10, then 20, 40, ... or floor(21.8), floor(43.6), ...
  CHECK(populations(10, false, 0) == std::vector<int>{10, 20, 40, 80, 160});
  CHECK(populations(10, true, 0) == std::vector<int>{10, 21, 43, 87, 174});
  // n = 40: 4 + 3 ln 40 = 15.067 -> 15, 30, 60, ... or 30, 60, 120, 241 (floor(241.07)).
  CHECK(populations(40, false, 0) == std::vector<int>{15, 30, 60, 120, 240});
  CHECK(populations(40, true, 0) == std::vector<int>{15, 30, 60, 120, 241});
  // A population set by the user is the base either way.
  CHECK(populations(10, true, 12) == std::vector<int>{12, 24, 48, 96, 192});
}

TEST_CASE("Restarts without restarting equal plain CMA-ES", "[optimizers]") {
  cmaes_options o;
  o.seed = 4;
  o.stop.max_iterations = 50;
  const auto space = parameter_space::unbounded(Eigen::VectorXd::Constant(5, 1.0));
  cmaes plain(space, o);
  cmaes_restarts wrapped(space, o, {restart_strategy::none});
  const auto a = minimize(plain, tf::rosenbrock);
  const auto b = minimize(wrapped, tf::rosenbrock);
  CHECK(identical(a.x, b.x));
  CHECK(a.evaluations == b.evaluations);
  CHECK(b.stopped == stop_criterion::max_iterations);
  CHECK(b.restarts == 0);
}

TEST_CASE("Restarts honour the global evaluation budget and max_restarts", "[optimizers]") {
  cmaes_options o;
  o.seed = 2;
  o.stop.max_evaluations = 3000;
  restart_options ro;
  ro.strategy = restart_strategy::ipop;
  auto es = cmaes_restarts(parameter_space::unbounded(uniform_x0(10, -3, 3, 2)), o, ro);
  const auto r = minimize(es, tf::rastrigin);
  CHECK(r.stopped == stop_criterion::max_evaluations);
  CHECK(r.evaluations >= 3000);
  CHECK(r.evaluations < 3000 + 4 * 10 * 16);  // overshoot below one generation of the last run
  check_run_records(r);
  CHECK(r.runs.back().stopped == stop_criterion::max_evaluations);  // its share of the budget

  o.stop.max_evaluations = 0;
  o.tol_fun = 1e-3;  // short runs
  ro.max_restarts = 2;
  auto es2 = cmaes_restarts(parameter_space::unbounded(uniform_x0(10, -3, 3, 2)), o, ro);
  const auto r2 = minimize(es2, tf::rastrigin);
  CHECK(r2.restarts == 2);
  CHECK(r2.stopped == stop_criterion::tol_fun);  // the last run's criterion
  check_run_records(r2);
  CHECK(r2.runs.size() == 3);
}

TEST_CASE("Each run's stop criterion is reported, the target one strictly", "[optimizers]") {
  // A flat objective: every value, hence every best value, is exactly 1 (the target 1 is reached
  // with equality only: no stop; the next double above it is reached strictly: a stop).
  const auto space = parameter_space::unbounded(Eigen::VectorXd::Zero(10));
  const auto [at, below] = gaitsynth::testing::minimize_flat_at_and_below_target([&](double t) {
    cmaes_options o;
    o.stop.max_iterations = 3;  // per run
    o.stop.target_value = t;
    restart_options ro;
    ro.strategy = restart_strategy::ipop;
    ro.max_restarts = 1;
    return cmaes_restarts(space, o, ro);
  });
  CHECK(at.stopped == stop_criterion::max_iterations);
  CHECK(at.restarts == 1);
  check_run_records(at);
  REQUIRE(at.runs.size() == 2);
  CHECK(at.runs[0].population_size == 10);
  CHECK(at.runs[1].population_size == 20);
  for (const run_record& run : at.runs) {
    CHECK(run.stopped == stop_criterion::max_iterations);
    CHECK(run.iterations == 3);
    CHECK(run.best_value == 1.0);
  }

  CHECK(below.stopped == stop_criterion::target_value);
  CHECK(below.restarts == 0);
  check_run_records(below);
  CHECK(below.runs[0].iterations == 1);
}

TEST_CASE("BIPOP draws small populations in [lambda_default, lambda_large / 2]", "[optimizers]") {
  // Short runs (tol_fun 1e-4) so that each seed makes several restarts of both regimes;
  // lambda_large is the population of the latest large run before each small one.
  auto check_regimes = [](double population_factor, std::uint64_t seed) {
    cmaes_options o;
    o.sigma0 = 2.0;
    o.seed = seed;
    o.tol_fun = 1e-4;
    o.stop.max_evaluations = 60'000;
    restart_options ro;
    ro.strategy = restart_strategy::bipop;
    ro.population_factor = population_factor;
    ro.max_restarts = 4;
    auto es = cmaes_restarts(parameter_space::unbounded(uniform_x0(10, -3, 3, seed)), o, ro);
    const auto r = minimize(es, tf::rastrigin);
    INFO("population_factor " << population_factor << " seed " << seed);
    check_run_records(r);
    constexpr int lambda_default = 10;  // 4 + floor(3 ln 10)
    REQUIRE(r.runs.size() >= 3);
    CHECK(r.runs[0].population_size == lambda_default);
    // Run 0 counts as small, so the first restart is a large one.
    CHECK_FALSE(r.runs[1].small_population);
    int large_runs = 0, small_runs = 0, lambda_large = lambda_default;
    for (std::size_t k = 1; k < r.runs.size(); ++k) {
      const run_record& run = r.runs[k];
      INFO("run " << k << " lambda " << run.population_size << " lambda_large " << lambda_large);
      if (run.small_population) {
        ++small_runs;
        CHECK(run.population_size >= lambda_default);
        CHECK(run.population_size <= std::max(lambda_default, lambda_large / 2));
        CHECK(run.sigma0 <= o.sigma0);
        CHECK(run.sigma0 >= o.sigma0 / 100);
      } else {
        ++large_runs;
        lambda_large =
            static_cast<int>(std::lround(lambda_default * std::pow(population_factor, large_runs)));
        CHECK(run.population_size == lambda_large);
        CHECK(run.sigma0 == o.sigma0);
      }
    }
    return small_runs;
  };
  int small_runs = 0;
  for (std::uint64_t seed : {0u, 1u, 2u, 3u, 4u}) small_runs += check_regimes(2.0, seed);
  CHECK(small_runs >= 10);  // the check above did run
  // A factor below 2: until lambda_large reaches 2 lambda_default, small runs use the default.
  CHECK(check_regimes(1.5, 5) > 0);
}
