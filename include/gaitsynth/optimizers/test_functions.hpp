#pragma once
/// \file test_functions.hpp
/// Standard benchmark functions for the optimizers (definitions as in pycma's `cma.ff`, minimum 0):
/// sphere, ellipsoid (condition 1e6), rotated ellipsoid, Rosenbrock, cigar, discus, Rastrigin, and
/// a shifted sphere. Used by the tests, the benchmarks and the statistics tool; handy to check an
/// optimizer set-up before spending hours of simulation on it.
#include <Eigen/Core>
#include <Eigen/QR>

#include <cmath>
#include <cstdint>
#include <random>

#include "gaitsynth/optimizers/random.hpp"

namespace gaitsynth::test_functions {

inline double sphere(const Eigen::VectorXd& x) {
  return x.squaredNorm();
}

/// sum_i 10^(6 i / (n - 1)) x_i^2 (condition number 1e6).
inline double ellipsoid(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size();
  double f = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    f += std::pow(10.0, n > 1 ? 6.0 * static_cast<double>(i) / static_cast<double>(n - 1) : 0.0) *
         x[i] * x[i];
  return f;
}

/// sum_{i<n-1} 100 (x_i^2 - x_{i+1})^2 + (x_i - 1)^2; minimum at (1, ..., 1). (A local minimum
/// near x_0 = -1 exists for n >= 4.)
inline double rosenbrock(const Eigen::VectorXd& x) {
  double f = 0;
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i] * x[i] - x[i + 1];
    const double b = x[i] - 1.0;
    f += 100.0 * a * a + b * b;
  }
  return f;
}

/// x_0^2 + 1e6 sum_{i>0} x_i^2.
inline double cigar(const Eigen::VectorXd& x) {
  return x[0] * x[0] + 1e6 * x.tail(x.size() - 1).squaredNorm();
}

/// 1e6 x_0^2 + sum_{i>0} x_i^2 (pycma's "tablet").
inline double discus(const Eigen::VectorXd& x) {
  return 1e6 * x[0] * x[0] + x.tail(x.size() - 1).squaredNorm();
}

/// 10 n + sum_i (x_i^2 - 10 cos(2 pi x_i)); global minimum 0 at 0, ~10^n local minima.
inline double rastrigin(const Eigen::VectorXd& x) {
  constexpr double two_pi = 6.283185307179586476925286766559;
  double f = 10.0 * static_cast<double>(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) f += x[i] * x[i] - 10.0 * std::cos(two_pi * x[i]);
  return f;
}

/// Random orthogonal matrix (QR of a Gaussian matrix, signs fixed), from an explicit seed.
inline Eigen::MatrixXd random_rotation(Eigen::Index n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Eigen::MatrixXd g(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd c(n);
    detail::fill_standard_normal(rng, c);
    g.col(j) = c;
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
  Eigen::MatrixXd q = qr.householderQ();
  const Eigen::MatrixXd r = qr.matrixQR().triangularView<Eigen::Upper>();
  for (Eigen::Index j = 0; j < n; ++j)
    if (r(j, j) < 0) q.col(j) = -q.col(j);
  return q;
}

/// ellipsoid(R x) for a fixed random rotation R (not separable).
struct rotated_ellipsoid {
  Eigen::MatrixXd rotation;
  explicit rotated_ellipsoid(Eigen::Index n, std::uint64_t seed = 12345)
      : rotation(random_rotation(n, seed)) {}
  double operator()(const Eigen::VectorXd& x) const { return ellipsoid(rotation * x); }
};

/// sum_i (x_i - c)^2.
struct shifted_sphere {
  double center = 0.9;
  double operator()(const Eigen::VectorXd& x) const { return (x.array() - center).square().sum(); }
};

}  // namespace gaitsynth::test_functions
