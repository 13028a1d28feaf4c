#pragma once
/// \file bound_transform.hpp
/// The piecewise linear-quadratic boundary transformation of pycma (its default bound handler,
/// BoundTransform, built on BoxConstraintsLinQuadTransformation), as free functions.
///
/// Why: a smooth map of the real line into [lb, ub] that is the identity well inside the box lets
/// CMA-ES sample without bounds while the objective only ever sees a point inside the box. There
/// is no rejection (whose acceptance rate falls like p^n with the dimension n when the optimum is
/// near a bound), no projection (many candidates share one point on the boundary, so the
/// ranking needs a penalty to tell them apart) and no penalty weight to tune.
///
/// Per coordinate with finite bounds lb < ub, margins
///   al = min((ub - lb) / 2, (1 + |lb|) / 20),   au = min((ub - lb) / 2, (1 + |ub|) / 20)
/// (on [0, 1]: al = 0.05, au = 0.1). First x is brought into [lb - al, ub + au], where the map is
/// invertible:
///  - far away (x < lb - 2 al - (ub - lb) / 2 or x > ub + 2 au + (ub - lb) / 2): shifted by a
///    multiple of the period r = 2 (ub - lb + al + au) into [s, s + r), s = lb - 2 al - (ub -
///    lb)/2;
///  - then mirrored: x > ub + au -> 2 (ub + au) - x; x < lb - al -> 2 (lb - al) - x.
/// Then
///   T(x) = lb + (x - (lb - al))^2 / (4 al)   for x < lb + al,
///          x                                 for lb + al <= x < ub - au,
///          ub - (x - (ub + au))^2 / (4 au)   for x >= ub - au.
/// T is continuous with a continuous first derivative (C^1): slope 1 at lb + al and ub - au, where
/// the parabolas meet the identity; slope 0 at lb - al and ub + au, the mirror points, where T
/// reaches the bound. So T is a periodic "triangle wave with rounded corners" of period r, and an
/// optimum on a bound is the image of a smooth minimum of f(T(x)) at a mirror point.
///
/// A side with an infinite bound is the identity on that side: no shift (the period is infinite);
/// the mirror and the parabola act at the finite bound only (as pycma, whose infinite margin is
/// never used). Both infinite: T(x) = x.
///
/// The margins depend on |lb| and |ub|, so T is not translation invariant; cmaes applies it in its
/// normalized coordinates, where every bounded parameter has the same box (usually [0, 1]) and
/// hence the same margins, whatever its user units.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// The margins {al, au} of the box [lower, upper] (a margin of an infinite bound is unused: 0).
struct bound_transform_margins {
  double lower = 0.0, upper = 0.0;
};

/// al and au of the file comment, for lower < upper.
inline bound_transform_margins bound_transform_margin(double lower, double upper) {
  bound_transform_margins m;
  if (std::isfinite(lower))
    m.lower = std::min((upper - lower) / 2.0, (1.0 + std::abs(lower)) / 20.0);
  if (std::isfinite(upper))
    m.upper = std::min((upper - lower) / 2.0, (1.0 + std::abs(upper)) / 20.0);
  return m;
}

/// T(x) for one coordinate with bounds lower < upper (either may be infinite; see the file
/// comment). The result lies in [lower, upper] for every finite x; NaN for a non-finite x.
inline double bound_transform(double x, double lower, double upper) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  const bool has_lb = std::isfinite(lower), has_ub = std::isfinite(upper);
  if (!has_lb && !has_ub) return x;
  const auto [al, au] = bound_transform_margin(lower, upper);
  if (has_lb && has_ub) {
    const double half = (upper - lower) / 2.0;
    if (x < lower - 2.0 * al - half || x > upper + 2.0 * au + half) {
      const double r = 2.0 * (upper - lower + al + au);
      const double s = lower - 2.0 * al - half;
      // fmod is exact, unlike x - r floor((x - s) / r), which for |x| >> r loses every digit of
      // the remainder (x = 1e17 on [0, 1] lands at -16, far outside [s, s + r]).
      double d = std::fmod(x - s, r);
      if (d < 0) d += r;
      x = s + d;
    }
  }
  if (has_ub && x > upper + au) x = 2.0 * (upper + au) - x;
  if (has_lb && x < lower - al) x = 2.0 * (lower - al) - x;
  double y = x;
  if (has_lb && x < lower + al) {
    const double t = x - (lower - al);
    y = lower + t * t / (4.0 * al);
  } else if (has_ub && x >= upper - au) {
    const double t = x - (upper + au);
    y = upper - t * t / (4.0 * au);
  }
  // In exact arithmetic y is in [lower, upper] already; the clamp only removes rounding (one ulp
  // past a bound after the shift) so the objective never sees a point outside the box.
  return std::clamp(y, lower, upper);
}

/// The inverse of T on [lower, upper] into [lower - al, upper + au] (the point of the invertible
/// domain that T maps to y). y outside [lower, upper] is clamped first (a point one ulp outside
/// after a change of coordinates).
inline double bound_transform_inverse(double y, double lower, double upper) {
  if (std::isnan(y)) return y;
  y = std::clamp(y, lower, upper);
  const auto [al, au] = bound_transform_margin(lower, upper);
  if (std::isfinite(lower) && y < lower + al)
    return (lower - al) + 2.0 * std::sqrt(al * (y - lower));
  if (std::isfinite(upper) && y > upper - au)
    return (upper + au) - 2.0 * std::sqrt(au * (upper - y));
  return y;
}

/// T applied coordinate-wise: x, lower and upper of equal size (throws std::invalid_argument
/// otherwise).
inline Eigen::VectorXd bound_transform(const Eigen::VectorXd& x, const Eigen::VectorXd& lower,
                                       const Eigen::VectorXd& upper) {
  check_size(lower.size(), x.size(), "bound_transform lower");
  check_size(upper.size(), x.size(), "bound_transform upper");
  Eigen::VectorXd y(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) y[i] = bound_transform(x[i], lower[i], upper[i]);
  return y;
}

/// The inverse of T, coordinate-wise (see the scalar version).
inline Eigen::VectorXd bound_transform_inverse(const Eigen::VectorXd& y,
                                               const Eigen::VectorXd& lower,
                                               const Eigen::VectorXd& upper) {
  check_size(lower.size(), y.size(), "bound_transform_inverse lower");
  check_size(upper.size(), y.size(), "bound_transform_inverse upper");
  Eigen::VectorXd x(y.size());
  for (Eigen::Index i = 0; i < y.size(); ++i)
    x[i] = bound_transform_inverse(y[i], lower[i], upper[i]);
  return x;
}

}  // namespace gaitsynth
