#pragma once
/// \file sincos.hpp
/// Batched sine and cosine for joint angles. Forward kinematics needs sin and cos of every joint
/// angle at every step; libm's scalar sincos costs a third of the kinematics of a 30-DOF humanoid.
/// This is the classic fdlibm kernel (k_sin.c / k_cos.c: minimax polynomials on [-pi/4, pi/4],
/// error below 1 ulp there) after a three-part Cody-Waite reduction by pi/2, written branch-free so
/// the compiler can vectorize the loop. Arguments with |x| > 2^20 (never a joint angle) fall back
/// to std::sin / std::cos.
#include <cmath>
#include <cstdint>

namespace gaitsynth::spatial {

namespace detail {
inline void sincos_kernel(double x_in, double& s_out, double& c_out) {
  // Out-of-range arguments (and NaN) are replaced by 0 here, so the conversion to an integer below
  // is always defined; sincos_batch recomputes them with libm.
  const double x = std::abs(x_in) <= 1048576.0 ? x_in : 0.0;
  constexpr double two_over_pi = 6.36619772367581382433e-01;
  constexpr double pio2_1 = 1.57079632673412561417e+00;  // first 33 bits of pi/2
  constexpr double pio2_2 = 6.07710050630396597660e-11;  // next 33 bits
  constexpr double pio2_3 = 2.02226624871116645580e-21;  // next 33 bits
  constexpr double round_magic = 6755399441055744.0;      // 1.5 * 2^52: x + magic - magic = rint(x)
  const double kd = (x * two_over_pi + round_magic) - round_magic;
  const double r = ((x - kd * pio2_1) - kd * pio2_2) - kd * pio2_3;
  const double z = r * r;
  // fdlibm __kernel_sin(r, 0, 0)
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                   S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                   S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const double ps = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
  const double sr = r + (z * r) * (S1 + z * ps);
  // fdlibm __kernel_cos(r, 0)
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                   C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                   C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double pc = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  const double cr = w + (((1.0 - w) - hz) + z * pc);
  // Quadrant k mod 4: (sin, cos) = (sr, cr), (cr, -sr), (-sr, -cr), (-cr, sr).
  const auto k = static_cast<std::int64_t>(kd);
  const bool swap = (k & 1) != 0;
  const double s = swap ? cr : sr;
  const double c = swap ? sr : cr;
  s_out = (k & 2) ? -s : s;
  c_out = ((k + 1) & 2) ? -c : c;
}
}  // namespace detail

/// s[i] = sin(x[i]), c[i] = cos(x[i]) for i < n (within 1-2 ulp of libm).
inline void sincos_batch(const double* x, double* s, double* c, int n) {
  for (int i = 0; i < n; ++i) detail::sincos_kernel(x[i], s[i], c[i]);
  for (int i = 0; i < n; ++i)
    if (!(std::abs(x[i]) <= 1048576.0)) {  // also catches NaN and inf (libm's results)
      s[i] = std::sin(x[i]);
      c[i] = std::cos(x[i]);
    }
}

}  // namespace gaitsynth::spatial
