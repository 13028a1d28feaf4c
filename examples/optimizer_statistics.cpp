// Statistics of the optimizers on the standard test functions: for each case, runs over several
// seeds and prints the median, range and success rate of the evaluations needed to reach
// f < 1e-8 (the numbers in docs/optimizers.md come from this program).
//
//   optimizer_statistics [--dims 10,40] [--seeds 11] [--cases sphere,ellipsoid,...] [--csv FILE]
//                        [--threads 1] [--log-dir DIR] [--log-seed 0]
//
// With --log-dir, the run of seed --log-seed (default 0) of every case writes its per-iteration
// CSV log to DIR/<case>_<n>.csv (input of scripts/plot_convergence.py).
//
// Cases: sphere ellipsoid rotated_ellipsoid rosenbrock cigar discus (CMA-ES, x0 ~ U[-3, 3]^n,
// sigma0 = 2, target 1e-8), rastrigin_ipop rastrigin_bipop (same start, up to 9 restarts, 2e6
// evaluations), bounded_sphere bounded_sphere_repair (optimum 0.9 in [0, 1]^n, mean 0.5,
// sigma0 = 0.3, rejection sampling / repair), sds_quadratic (sum (i+1)(x_i - 1)^2 to 1e-8) and
// sds_rosenbrock (to 1e-6), SDS from x0 ~ U[-3, 3]^n with alpha0 = 0.5.
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
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace gaitsynth;

namespace {

std::string g_log_dir;   // --log-dir
std::string g_log_name;  // <case>_<n>.csv of the current run, "" if not logged
int g_log_seed = 0;      // --log-seed

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

run_outcome run_rastrigin(int n, std::uint64_t seed, restart_strategy strategy, unsigned threads) {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = seed;
  o.stop.target_value = 1e-8;
  o.stop.max_evaluations = 2'000'000;
  restart_options ro;
  ro.strategy = strategy;
  ro.max_restarts = 9;
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

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> dims = {10, 40};
  int seeds = 11;
  unsigned threads = 1;
  std::vector<std::string> cases = {"sphere",
                                    "ellipsoid",
                                    "rotated_ellipsoid",
                                    "rosenbrock",
                                    "cigar",
                                    "discus",
                                    "rastrigin_ipop",
                                    "rastrigin_bipop",
                                    "bounded_sphere",
                                    "bounded_sphere_repair",
                                    "sds_quadratic",
                                    "sds_rosenbrock"};
  std::string csv;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "missing value after " << a << "\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--dims") {
      dims.clear();
      for (const auto& d : split(next())) dims.push_back(std::stoi(d));
    } else if (a == "--seeds") {
      seeds = std::stoi(next());
    } else if (a == "--cases") {
      cases = split(next());
    } else if (a == "--csv") {
      csv = next();
    } else if (a == "--log-dir") {
      g_log_dir = next();
    } else if (a == "--log-seed") {
      g_log_seed = std::stoi(next());
    } else if (a == "--threads") {
      threads = static_cast<unsigned>(std::stoi(next()));
    } else {
      std::cerr << "usage: optimizer_statistics [--dims 10,40] [--seeds 11] [--cases a,b] "
                   "[--csv FILE] [--threads T] [--log-dir DIR] [--log-seed S]\n";
      return 2;
    }
  }

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
      for (int s = 0; s < seeds; ++s) {
        const auto seed = static_cast<std::uint64_t>(s);
        g_log_name =
            (!g_log_dir.empty() && s == g_log_seed) ? c + "_" + std::to_string(n) + ".csv" : "";
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
        else {
          std::cerr << "unknown case " << c << "\n";
          return 2;
        }
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
      std::printf("%-24s %5d %5d/%-2d %10s %22s %5.1fs\n", c.c_str(), n, ok, seeds, median, range,
                  secs);
      std::fflush(stdout);
    }
  }
  return 0;
}
