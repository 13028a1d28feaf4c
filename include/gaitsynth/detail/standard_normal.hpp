#pragma once
/// \file standard_normal.hpp
/// Standard normal variates from an explicitly seeded std::mt19937_64, the same on every standard
/// library (optimizers/random.hpp says why not std::normal_distribution). Used by the optimizers,
/// the seeded start perturbations of rollout/start_perturbations.hpp and random_configuration.
#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <random>

#include "gaitsynth/detail/uniform01.hpp"

namespace gaitsynth::detail {

/// Uniform double in (0, 1] (safe for log).
inline double uniform01_open_below(std::mt19937_64& rng) {
  return static_cast<double>((rng() >> 11) + 1) * 0x1.0p-53;
}

/// Fills z with independent standard normal variates (Box-Muller, one pair per two entries; an odd
/// last entry uses the cosine branch only). Stateless: no variate is carried over between calls.
inline void fill_standard_normal(std::mt19937_64& rng, Eigen::Ref<Eigen::VectorXd> z) {
  constexpr double two_pi = 6.283185307179586476925286766559;
  const Eigen::Index n = z.size();
  for (Eigen::Index i = 0; i < n; i += 2) {
    const double r = std::sqrt(-2.0 * std::log(uniform01_open_below(rng)));
    const double theta = two_pi * uniform01(rng);
    z[i] = r * std::cos(theta);
    if (i + 1 < n) z[i + 1] = r * std::sin(theta);
  }
}

}  // namespace gaitsynth::detail
