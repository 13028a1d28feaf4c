// CMA-ES bound handling compared (cmaes_options::bounds: resample, repair, transform) on bounded
// test functions: for each case, dimension and method, runs several seeds and prints the success
// rate, the median and range of the evaluations needed to reach f - f* < 1e-8, the samples drawn
// per evaluation (rejection sampling redraws) and the share of evaluated points that were
// repaired (projected). The table of docs/optimizers.md ("Bound handling compared") comes from
// this program.
//
//   bound_handling_statistics [--dims 10,40,184] [--seeds 5] [--seed 0] [--cases ...]
//                             [--methods resample,repair,transform] [--csv FILE]
//
// Every case is on the box [0, 1]^n, mean 0.5, sigma0 = 0.3 (Wu 2010's setting), budget 5000 n
// evaluations:
//   sphere_0.9       sum (x_i - 0.9)^2: optimum inside, 0.1 from the upper bound (f* = 0);
//   sphere_on_bound  sum (x_i - 1)^2: optimum on the upper bound in every coordinate (f* = 0);
//   sphere_beyond    sum (x_i - c_i)^2, c_i = -0.5 (even i) or 0.7 (odd i): half the coordinates
//                    want to go beyond the lower bound, the optimum has them on it
//                    (f* = 0.25 ceil(n / 2));
//   ellipsoid_beyond the ellipsoid (condition 1e6) of x - c with the same c (f* = the ellipsoid
//                    of the clamped shift).
// The objective costs nothing here: the time is the strategy's O(n^2) per sample (and, for
// rejection sampling, per redraw), so the runs are serial.
#include <gaitsynth/optimizers/optimizers.hpp>
#include <gaitsynth/optimizers/test_functions.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"

using namespace gaitsynth;

namespace {

struct bounded_case {
  std::function<double(const Eigen::VectorXd&)> f;
  double f_star = 0;
};

Eigen::VectorXd beyond_center(int n) {
  Eigen::VectorXd c(n);
  for (int i = 0; i < n; ++i) c[i] = i % 2 == 0 ? -0.5 : 0.7;
  return c;
}

bounded_case make_case(const std::string& name, int n) {
  if (name == "sphere_0.9") return {test_functions::shifted_sphere{0.9}, 0.0};
  if (name == "sphere_on_bound") return {test_functions::shifted_sphere{1.0}, 0.0};
  const Eigen::VectorXd c = beyond_center(n);
  const Eigen::VectorXd at_bound = c.cwiseMax(0.0).cwiseMin(1.0);
  if (name == "sphere_beyond")
    return {[c](const Eigen::VectorXd& x) { return (x - c).squaredNorm(); },
            (at_bound - c).squaredNorm()};
  if (name == "ellipsoid_beyond")
    return {[c](const Eigen::VectorXd& x) { return test_functions::ellipsoid(x - c); },
            test_functions::ellipsoid(at_bound - c)};
  throw std::invalid_argument("--cases: unknown case '" + name + "'");
}

bound_handling method_of(const std::string& m) {
  if (m == "resample") return bound_handling::resample;
  if (m == "repair") return bound_handling::repair;
  if (m == "transform") return bound_handling::transform;
  throw std::invalid_argument("--methods: unknown method '" + m + "'");
}

struct run_outcome {
  bool success = false;
  std::int64_t evaluations = 0, resamples = 0, repairs = 0;
  double excess = 0;  // best f - f*
  stop_criterion stopped = stop_criterion::none;
};

run_outcome run(const bounded_case& c, int n, bound_handling bh, std::uint64_t seed) {
  cmaes_options o;
  o.sigma0 = 0.3;
  o.seed = seed;
  o.bounds = bh;
  o.stop.target_value = c.f_star + 1e-8;
  o.stop.max_evaluations = 5000LL * n;
  cmaes es(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                Eigen::VectorXd::Constant(n, 0.5)),
           o);
  const auto r = minimize(es, c.f);
  return {r.stopped == stop_criterion::target_value,
          r.evaluations,
          es.resample_count(),
          es.repair_count(),
          r.value - c.f_star,
          r.stopped};
}

}  // namespace

int main(int argc, char** argv) try {
  std::vector<int> dims = {10, 40};
  long long seeds = 5;
  unsigned long long first_seed = 0;
  const std::vector<std::string> all_cases = {"sphere_0.9", "sphere_on_bound", "sphere_beyond",
                                              "ellipsoid_beyond"};
  const std::vector<std::string> all_methods = {"resample", "repair", "transform"};
  std::vector<std::string> cases = all_cases, methods = all_methods;
  std::string csv;
  CLI::App app{
      "CMA-ES bound handling compared (resample, repair, transform): evaluations to reach f - f* "
      "< 1e-8 on bounded test functions, redraws and repairs, over several seeds.",
      "bound_handling_statistics"};
  app.option_defaults()->always_capture_default();
  app.add_option("--dims", dims, "dimensions, comma-separated (e.g. 10,40,184)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(example_cli::integer_in(1, 10000));
  app.add_option("--seeds", seeds, "number of seeds per case, dimension and method")
      ->check(example_cli::integer_in(0, 1000000));
  example_cli::add_seed(app, first_seed)
      ->description("first seed (runs --seed .. --seed + --seeds - 1)");
  app.add_option("--cases", cases, "cases, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(all_cases));
  app.add_option("--methods", methods, "bound handling methods, comma-separated")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(all_methods));
  app.add_option("--csv", csv, "write every run as a CSV row to this file");
  example_cli::parse(app, argc, argv);

  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    if (!out) throw std::runtime_error("cannot write --csv " + csv);
    out << "case,n,method,seed,success,evaluations,resamples,repairs,excess,stopped\n";
  }
  std::printf("%-17s %4s %-10s %8s %9s %17s %11s %9s %7s\n", "case", "n", "method", "success",
              "median", "range", "draws/eval", "repaired", "time");
  for (const auto& name : cases) {
    for (int n : dims) {
      const bounded_case c = make_case(name, n);
      for (const auto& m : methods) {
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<std::int64_t> ev;
        std::int64_t evals = 0, resamples = 0, repairs = 0;
        int ok = 0;
        for (long long s = 0; s < seeds; ++s) {
          const auto seed =
              static_cast<std::uint64_t>(first_seed + static_cast<unsigned long long>(s));
          const run_outcome r = run(c, n, method_of(m), seed);
          evals += r.evaluations;
          resamples += r.resamples;
          repairs += r.repairs;
          if (r.success) {
            ++ok;
            ev.push_back(r.evaluations);
          }
          if (out.is_open())
            out << name << ',' << n << ',' << m << ',' << seed << ',' << r.success << ','
                << r.evaluations << ',' << r.resamples << ',' << r.repairs << ',' << r.excess << ','
                << to_string(r.stopped) << std::endl;
        }
        std::sort(ev.begin(), ev.end());
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char median[32] = "-", range[48] = "-";
        if (!ev.empty()) {
          const std::size_t k = ev.size();
          const double med = k % 2 ? static_cast<double>(ev[k / 2])
                                   : 0.5 * static_cast<double>(ev[k / 2 - 1] + ev[k / 2]);
          std::snprintf(median, sizeof median, "%.0f", med);
          std::snprintf(range, sizeof range, "%lld-%lld", static_cast<long long>(ev.front()),
                        static_cast<long long>(ev.back()));
        }
        // Over all runs of the row: samples drawn per evaluation, and repaired evaluations.
        const double e = std::max<double>(1.0, static_cast<double>(evals));
        std::printf("%-17s %4d %-10s %5d/%-2lld %9s %17s %11.2f %8.1f%% %6.1fs\n", name.c_str(), n,
                    m.c_str(), ok, seeds, median, range,
                    (static_cast<double>(evals) + static_cast<double>(resamples)) / e,
                    100.0 * static_cast<double>(repairs) / e, secs);
        std::fflush(stdout);
      }
    }
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "bound_handling_statistics: " << e.what() << "\n";
  return 1;
}
