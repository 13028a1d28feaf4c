#pragma once
/// \file controllers/end_effector/height_hull.hpp
/// The collision-free height hull of Wu & Popovic 2010, appendix A.3 (Fig. 8): the upper convex
/// hull h(u) of sampled points (u_i, h_i), a concave piecewise-linear function of u that lies on or
/// above every sample and touches the first and the last. Built with Andrew's monotone chain (the
/// samples come sorted by u, so it is one O(N) pass); fixed capacity, no allocation.
#include <array>
#include <cstddef>
#include <utility>

namespace gaitsynth {

template <std::size_t N>
struct height_hull {
  std::array<double, N> u{};  ///< vertices, increasing u
  std::array<double, N> h{};
  int size = 0;

  /// h(x): linear between vertices, constant beyond the first and last.
  double operator()(double x) const { return value_and_slope(x).first; }

  /// h(x) and dh/du at x (the left segment's slope at a vertex; 0 outside).
  std::pair<double, double> value_and_slope(double x) const {
    if (size <= 0) return {0.0, 0.0};
    if (size == 1 || !(x > u[0])) return {h[0], 0.0};
    if (x >= u[size - 1]) return {h[size - 1], 0.0};
    int lo = 0, hi = size - 1;  // u[lo] < x <= u[hi]
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (u[mid] < x ? lo : hi) = mid;
    }
    const double slope = (h[hi] - h[lo]) / (u[hi] - u[lo]);
    return {h[lo] + slope * (x - u[lo]), slope};
  }
};

/// The upper convex hull of points (u[i], h[i]), i < n, with u strictly increasing. Collinear
/// points are dropped.
template <std::size_t N>
height_hull<N> upper_convex_hull(const std::array<double, N>& u, const std::array<double, N>& h,
                                 int n = static_cast<int>(N)) {
  height_hull<N> hull;
  int& m = hull.size;
  for (int i = 0; i < n; ++i) {
    // Pop while the last two vertices and the new point do not turn clockwise (cross >= 0).
    while (m >= 2) {
      const double ux = hull.u[m - 1] - hull.u[m - 2], hx = hull.h[m - 1] - hull.h[m - 2];
      const double px = u[i] - hull.u[m - 2], py = h[i] - hull.h[m - 2];
      if (ux * py - hx * px >= 0.0)
        --m;
      else
        break;
    }
    hull.u[m] = u[i];
    hull.h[m] = h[i];
    ++m;
  }
  return hull;
}

}  // namespace gaitsynth
