#pragma once
// Shared helpers of the optimizer tests.
#include <gaitsynth/optimizers/optimizers.hpp>
#include <gaitsynth/optimizers/test_functions.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace gaitsynth::testing {

/// x0 ~ U[a, b]^n from its own stream (independent of the optimizer's seed).
inline Eigen::VectorXd uniform_x0(int n, double a, double b, std::uint64_t seed) {
  std::mt19937_64 rng(seed + 1000);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = a + (b - a) * detail::uniform01(rng);
  return x;
}

/// The benchmark set-up: x0 ~ U[-3, 3]^n, sigma0 = 2, stop at f <= 1e-8.
inline cmaes make_benchmark_cmaes(int n, std::uint64_t seed) {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = seed;
  o.stop.target_value = 1e-8;
  return cmaes(parameter_space::unbounded(uniform_x0(n, -3, 3, seed)), o);
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size();
  return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
}

/// A fresh scratch directory under the build tree.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto dir =
      std::filesystem::path(GAITSYNTH_BINARY_DIR) / "test_scratch" / "optimizers" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Bitwise equality of two vectors (== on doubles, sizes first).
inline bool identical(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.array() == b.array()).all();
}
inline bool identical(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a.array() == b.array()).all();
}

/// The strict target on a flat objective (every value exactly 1): make(target) builds the
/// optimizer; returns its results with target_value = 1 (equality: must not stop on the target)
/// and with the next double above 1 (1 is then strictly below it: must stop at once).
template <class Make>
std::pair<optimization_result, optimization_result> minimize_flat_at_and_below_target(Make make) {
  const auto flat = [](const Eigen::VectorXd&) { return 1.0; };
  return {minimize(make(1.0), flat), minimize(make(std::nextafter(1.0, 2.0)), flat)};
}

}  // namespace gaitsynth::testing
