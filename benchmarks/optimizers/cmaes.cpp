// Optimizer overhead and parallel evaluation efficiency (figures in docs/performance.md).
//
//   bench_optimizers --benchmark_filter=generation     ask + tell for n = 184, 500, 1000
//   bench_optimizers --benchmark_filter=eigen          one eigendecomposition of C (amortized
//                                                       over `eigen_gap_iterations` generations)
//   bench_optimizers --benchmark_filter=parallel       one generation of lambda = 32 candidates,
//                                                       ~1 ms each, on 1..T threads
// GCC 12 with -march=native (AVX-512) warns falsely inside its own avx512fintrin.h when Eigen's
// kernels are inlined (GCC PR 105593); the warning is not about this code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <benchmark/benchmark.h>

#include <gaitsynth/optimizers/optimizers.hpp>
#include <gaitsynth/optimizers/test_functions.hpp>

#include <chrono>
#include <cmath>
#include <ctime>
#include <thread>
#include <vector>

using namespace gaitsynth;

namespace {

// One CMA-ES generation with a trivial objective (sphere, computed inline): the strategy's own
// cost, including the lazy eigendecomposition amortized over the generations it serves.
void BM_cmaes_generation(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  cmaes_options o;
  o.seed = 1;
  o.tol_fun = 0;
  o.tol_x = 0;
  o.stop.max_iterations = std::numeric_limits<std::int64_t>::max() / 2;
  cmaes es(parameter_space::unbounded(Eigen::VectorXd::Constant(n, 1.0)), o);
  std::vector<double> f(static_cast<std::size_t>(es.population_size()));
  for (auto _ : state) {
    const auto& xs = es.ask();
    for (std::size_t k = 0; k < xs.size(); ++k) f[k] = xs[k].squaredNorm();
    es.tell(f);
    benchmark::DoNotOptimize(es.sigma());
  }
  state.counters["lambda"] = es.population_size();
  state.counters["eigen_gap"] = static_cast<double>(es.parameters().eigen_gap_iterations);
}
BENCHMARK(BM_cmaes_generation)
    ->Arg(184)
    ->Arg(500)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond)
    ->MinTime(2.0);

// The eigendecomposition alone (Eigen's SelfAdjointEigenSolver on an n x n SPD matrix).
void BM_cmaes_eigen(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Eigen::MatrixXd a = test_functions::random_rotation(n, 1);
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = std::pow(10.0, 3.0 * i / (n - 1));
  const Eigen::MatrixXd C = a * d.asDiagonal() * a.transpose();
  for (auto _ : state) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C);
    benchmark::DoNotOptimize(es.eigenvalues().data());
  }
}
BENCHMARK(BM_cmaes_eigen)->Arg(184)->Arg(500)->Arg(1000)->Unit(benchmark::kMillisecond);

// A synthetic objective of about 1 ms of CPU work (a fixed loop, not a sleep, so that threads
// really compete for cores as rollouts would).
double synthetic_objective(const Eigen::VectorXd& x, long iterations) {
  double s = x.sum();
  for (long i = 0; i < iterations; ++i) s = std::sin(s) + 1e-3 * static_cast<double>(i & 7);
  return s;
}

long calibrate_iterations() {
  static const long iterations = [] {
    const Eigen::VectorXd x = Eigen::VectorXd::Ones(4);
    long n = 1000;
    for (;;) {
      // Calibrated on CPU time: on a shared machine wall time would include waiting.
      const std::clock_t t0 = std::clock();
      benchmark::DoNotOptimize(synthetic_objective(x, n));
      const double dt = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
      if (dt > 0.02) return static_cast<long>(static_cast<double>(n) * 1e-3 / dt);
      n *= 2;
    }
  }();
  return iterations;
}

// One generation of lambda = 32 candidates of ~1 ms each, evaluated by a pool of T threads.
// Efficiency = (time on 1 thread) / (T * time on T threads); compare the rows.
void BM_parallel_evaluation(benchmark::State& state) {
  const unsigned threads = static_cast<unsigned>(state.range(0));
  const long iters = calibrate_iterations();
  auto f = [iters](const Eigen::VectorXd& x) { return synthetic_objective(x, iters); };
  cmaes_options o;
  o.population_size = 32;
  o.stop.max_iterations = std::numeric_limits<std::int64_t>::max() / 2;
  cmaes es(parameter_space::unbounded(Eigen::VectorXd::Zero(184)), o);
  thread_pool_evaluator pool(threads);
  std::vector<double> values(32);
  for (auto _ : state) {
    const auto& xs = es.ask();
    pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(values));
    es.tell(values);
  }
  state.counters["threads"] = threads;
  state.counters["evals_per_s"] = benchmark::Counter(32.0 * static_cast<double>(state.iterations()),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(BM_parallel_evaluation)
    ->DenseRange(1, 4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->MinTime(1.0);

// The pool's own cost: dispatching a batch of 32 trivial evaluations to T threads and waiting for
// them (wake-up, atomic work counter, join). With ~1 ms objectives this is what parallel
// evaluation adds per generation, besides load imbalance.
void BM_pool_dispatch(benchmark::State& state) {
  const unsigned threads = static_cast<unsigned>(state.range(0));
  thread_pool_evaluator pool(threads);
  const std::vector<Eigen::VectorXd> xs(32, Eigen::VectorXd::Ones(184));
  std::vector<double> values(32);
  auto f = [](const Eigen::VectorXd& x) { return x[0]; };
  for (auto _ : state) {
    pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(values));
    benchmark::DoNotOptimize(values.data());
  }
}
BENCHMARK(BM_pool_dispatch)->DenseRange(1, 4)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
