// Statistics of the optimizers on the standard test functions: for each case, runs over several
// seeds and prints the median, range and success rate of the evaluations needed to reach
// f < 1e-8 (the numbers in docs/optimizers.md come from this program).
//
//   optimizer_statistics [--dims 10,40] [--seeds 11] [--seed 0] [--cases sphere,ellipsoid,...]
//                        [--csv FILE] [--threads N] [--log-dir DIR] [--log-seed K]
//
// --seeds N runs seeds --seed, --seed + 1, ..., --seed + N - 1 (default 0..10) of every case and
// dimension; --threads N evaluates on N threads (default 0: every core; the results do not depend
// on it). With --log-dir (an existing folder), the run of seed --log-seed (default: the first,
// --seed) of every case writes its per-iteration CSV log to DIR/<case>_<n>.csv (input of
// scripts/plot_convergence.py). --help lists every flag with its default and range.
//
// Cases: sphere ellipsoid rotated_ellipsoid rosenbrock cigar discus (CMA-ES, x0 ~ U[-3, 3]^n,
// sigma0 = 2, target 1e-8), rastrigin_ipop rastrigin_ipop_unrounded rastrigin_bipop (same
// start, up to 9 restarts, 2e6 evaluations; _unrounded:
// restart_options::unrounded_population_base), bounded_sphere bounded_sphere_repair (optimum 0.9 in
// [0, 1]^n, mean 0.5, sigma0 = 0.3, rejection sampling / repair), sds_quadratic (sum (i+1)(x_i -
// 1)^2 to 1e-8) and sds_rosenbrock (to 1e-6), SDS from x0 ~ U[-3, 3]^n with alpha0 = 0.5.
#include <gaitsynth/optimizers/optimizers.hpp>
#include <gaitsynth/optimizers/test_functions.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"

using namespace gaitsynth;

namespace {

std::string g_log_dir;   // --log-dir
std::string g_log_name;  // <case>_<n>.csv of the current run, "" if not logged

run_options logging() {
  run_options ro;
  if (!g_log_name.empty()) ro.log_file = g_log_dir + "/" + g_log_name;
  return ro;
}

struct run_outcome {
  bool success = false;
  std::int64_t evaluations = 0;
  double value = 0;
  stop_criterion stopped = stop_criterion::none;
  int restarts = 0;
};

Eigen::VectorXd uniform_x0(int n, double a, double b, std::uint64_t seed) {
  // The start point comes from its own stream (seed + 1000), independent of the optimizer's.
  std::mt19937_64 rng(seed + 1000);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = a + (b - a) * detail::uniform01(rng);
  return x;
}

template <class F>
run_outcome run_cmaes(F f, int n, std::uint64_t seed, unsigned threads) {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = seed;
  o.stop.target_value = 1e-8;
  cmaes es(parameter_space::unbounded(uniform_x0(n, -3, 3, seed)), o);
  thread_pool_evaluator pool(threads);
  const auto r = minimize(es, f, pool, logging());
  return {r.stopped == stop_criterion::target_value, r.evaluations, r.value, r.stopped, 0};
}

run_outcome run_rastrigin(int n, std::uint64_t seed, restart_strategy strategy, unsigned threads,
                          bool unrounded = false) {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = seed;
  o.stop.target_value = 1e-8;
  o.stop.max_evaluations = 2'000'000;
  restart_options ro;
  ro.strategy = strategy;
  ro.max_restarts = 9;
  ro.unrounded_population_base = unrounded;
  cmaes_restarts es(parameter_space::unbounded(uniform_x0(n, -3, 3, seed)), o, ro);
  thread_pool_evaluator pool(threads);
  const auto r = minimize(es, test_functions::rastrigin, pool, logging());
  return {r.stopped == stop_criterion::target_value, r.evaluations, r.value, r.stopped, r.restarts};
}

run_outcome run_bounded(int n, std::uint64_t seed, bound_handling bh, unsigned threads) {
  cmaes_options o;
  o.sigma0 = 0.3;  // Wu 2010's setting: mean 0.5, sigma 0.3 in [0, 1]
  o.seed = seed;
  o.bounds = bh;
  o.stop.target_value = 1e-8;
  cmaes es(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                Eigen::VectorXd::Constant(n, 0.5)),
           o);
  thread_pool_evaluator pool(threads);
  const auto r = minimize(es, test_functions::shifted_sphere{0.9}, pool, logging());
  return {r.stopped == stop_criterion::target_value, r.evaluations, r.value, r.stopped, 0};
}

template <class F>
run_outcome run_sds(F f, int n, std::uint64_t seed, double target, std::int64_t budget) {
  sds_options o;
  o.initial_step = 0.5;
  o.min_step = 1e-12;
  o.stop.target_value = target;
  o.stop.max_evaluations = budget;
  sds s(parameter_space::unbounded(uniform_x0(n, -3, 3, seed)), o);
  const auto r = minimize(s, f, logging());
  return {r.stopped == stop_criterion::target_value, r.evaluations, r.value, r.stopped, 0};
}

}  // namespace

int main(int argc, char** argv) try {
  std::vector<int> dims = {10, 40};
  long long seeds = 11;
  unsigned long long first_seed = 0;
  std::optional<unsigned long long> log_seed;
  unsigned threads = 0;  // every core
  const std::vector<std::string> all_cases = {
      "sphere",          "ellipsoid",      "rotated_ellipsoid",     "rosenbrock",
      "cigar",           "discus",         "rastrigin_ipop",        "rastrigin_ipop_unrounded",
      "rastrigin_bipop", "bounded_sphere", "bounded_sphere_repair", "sds_quadratic",
      "sds_rosenbrock"};
  std::vector<std::string> cases = all_cases;
  std::string csv;
  CLI::App app{
      "Statistics of the optimizers on the standard test functions: evaluations to reach the "
      "target over several seeds per case and dimension.",
      "optimizer_statistics"};
  app.option_defaults()->always_capture_default();
  app.add_option("--dims", dims, "dimensions, comma-separated (e.g. 10,40)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(example_cli::integer_in(1, 10000));
  app.add_option("--seeds", seeds, "number of seeds per case and dimension")
      ->check(example_cli::integer_in(0, 1000000));
  example_cli::add_seed(app, first_seed)
      ->description("first seed (runs --seed .. --seed + --seeds - 1)");
  app.add_option("--cases", cases, "cases, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(all_cases));
  app.add_option("--csv", csv, "write every run as a CSV row to this file");
  example_cli::add_threads(app, threads);
  CLI::Option* log_dir =
      app.add_option("--log-dir", g_log_dir, "write per-iteration CSV logs into this folder")
          ->check(CLI::ExistingDirectory);
  app.add_option("--log-seed", log_seed, "seed whose runs are logged (default: the first, --seed)")
      ->check(example_cli::integer_in(0, std::numeric_limits<long long>::max()))
      ->needs(log_dir);
  example_cli::parse(app, argc, argv);
  threads = example_cli::resolve_threads(threads);
  const unsigned long long logged = log_seed.value_or(first_seed);
  if (!g_log_dir.empty() &&
      (logged < first_seed || logged - first_seed >= static_cast<unsigned long long>(seeds)))
    throw std::invalid_argument(
        "--log-seed " + std::to_string(logged) + " is not one of the seeds run (--seed " +
        std::to_string(first_seed) + " --seeds " + std::to_string(seeds) + ")");

  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "case,n,seed,success,evaluations,value,stopped,restarts\n";
  }
  std::printf("%-24s %5s %8s %10s %22s %6s\n", "case", "n", "success", "median", "range", "time");
  for (const auto& c : cases) {
    for (int n : dims) {
      const auto t0 = std::chrono::steady_clock::now();
      std::vector<run_outcome> rs;
      for (long long s = 0; s < seeds; ++s) {
        const auto seed =
            static_cast<std::uint64_t>(first_seed + static_cast<unsigned long long>(s));
        g_log_name =
            (!g_log_dir.empty() && seed == logged) ? c + "_" + std::to_string(n) + ".csv" : "";
        run_outcome r;
        if (c == "sphere")
          r = run_cmaes(test_functions::sphere, n, seed, threads);
        else if (c == "ellipsoid")
          r = run_cmaes(test_functions::ellipsoid, n, seed, threads);
        else if (c == "rotated_ellipsoid")
          r = run_cmaes(test_functions::rotated_ellipsoid(n), n, seed, threads);
        else if (c == "rosenbrock")
          r = run_cmaes(test_functions::rosenbrock, n, seed, threads);
        else if (c == "cigar")
          r = run_cmaes(test_functions::cigar, n, seed, threads);
        else if (c == "discus")
          r = run_cmaes(test_functions::discus, n, seed, threads);
        else if (c == "rastrigin_ipop")
          r = run_rastrigin(n, seed, restart_strategy::ipop, threads);
        else if (c == "rastrigin_ipop_unrounded")
          r = run_rastrigin(n, seed, restart_strategy::ipop, threads, true);
        else if (c == "rastrigin_bipop")
          r = run_rastrigin(n, seed, restart_strategy::bipop, threads);
        else if (c == "bounded_sphere")
          r = run_bounded(n, seed, bound_handling::resample, threads);
        else if (c == "bounded_sphere_repair")
          r = run_bounded(n, seed, bound_handling::repair, threads);
        else if (c == "sds_quadratic")
          r = run_sds(
              [](const Eigen::VectorXd& x) {
                double f = 0;
                for (Eigen::Index i = 0; i < x.size(); ++i)
                  f += (i + 1.0) * (x[i] - 1.0) * (x[i] - 1.0);
                return f;
              },
              n, seed, 1e-8, 1'000'000);
        else if (c == "sds_rosenbrock")
          r = run_sds(test_functions::rosenbrock, n, seed, 1e-6, 2'000'000);
        else
          throw std::invalid_argument("--cases: unknown case '" + c + "'");
        rs.push_back(r);
        if (out.is_open())
          out << c << ',' << n << ',' << seed << ',' << r.success << ',' << r.evaluations << ','
              << r.value << ',' << to_string(r.stopped) << ',' << r.restarts << std::endl;
      }
      std::vector<std::int64_t> ev;
      int ok = 0;
      for (const auto& r : rs) {
        if (r.success) {
          ++ok;
          ev.push_back(r.evaluations);
        }
      }
      std::sort(ev.begin(), ev.end());
      const double secs =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      char range[64] = "-";
      char median[32] = "-";
      if (!ev.empty()) {
        const std::size_t m = ev.size();
        const double med = m % 2 ? static_cast<double>(ev[m / 2])
                                 : 0.5 * static_cast<double>(ev[m / 2 - 1] + ev[m / 2]);
        std::snprintf(median, sizeof median, "%.0f", med);
        std::snprintf(range, sizeof range, "%lld-%lld", static_cast<long long>(ev.front()),
                      static_cast<long long>(ev.back()));
      }
      std::printf("%-24s %5d %5d/%-2lld %10s %22s %5.1fs\n", c.c_str(), n, ok, seeds, median, range,
                  secs);
      std::fflush(stdout);
    }
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "optimizer_statistics: " << e.what() << "\n";
  return 1;
}
