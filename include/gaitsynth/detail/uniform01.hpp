#pragma once
/// \file uniform01.hpp
/// The one uniform variate every seeded generator in gaitsynth uses (optimizers, terrain,
/// random_configuration).
/// std::mt19937_64's sequence is fixed by the standard while std::uniform_real_distribution's
/// mapping is not, so this gives the same numbers for the same seed on every standard library.
#include <random>

namespace gaitsynth::detail {

/// Uniform double in [0, 1) from the top 53 bits of a 64-bit Mersenne twister draw.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace gaitsynth::detail
