#pragma once
// Bit-for-bit equality where the compiler cannot fuse a * b + c. With FMA instructions available
// (e.g. -march=native) GCC contracts expressions per inlined context, so one expression may round
// differently in two callers by an ulp or two; there, equality to 4 ulp is what can be asked.
#include <cmath>
#include <limits>

namespace gaitsynth_test {

inline bool same_bits_unless_fused(double a, double b) {
#ifdef __FMA__
  return std::abs(a - b) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(a);
#else
  return a == b;
#endif
}

}  // namespace gaitsynth_test
