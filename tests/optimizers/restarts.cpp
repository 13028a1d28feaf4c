#include <catch2/catch.hpp>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
namespace tf = gaitsynth::test_functions;

namespace {
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
      if (strategy == restart_strategy::ipop) {
        // IPOP doubles lambda on every restart: 10, 20, 40, ...
        for (std::size_t i = 1; i < lambdas.size(); ++i) CHECK(lambdas[i] == 2 * lambdas[i - 1]);
      }
    }
  }
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

  o.stop.max_evaluations = 0;
  o.tol_fun = 1e-3;  // short runs
  ro.max_restarts = 2;
  auto es2 = cmaes_restarts(parameter_space::unbounded(uniform_x0(10, -3, 3, 2)), o, ro);
  const auto r2 = minimize(es2, tf::rastrigin);
  CHECK(r2.restarts == 2);
  CHECK(r2.stopped == stop_criterion::tol_fun);  // the last run's criterion
}
