#pragma once
/// \file objectives/wang2009/thresholded_quadratic.hpp
/// The thresholded quadratic of Wang, Fleet & Hertzmann 2009, eq. 3:
///     Q(d; eps) = d^2 if |d| > eps, 0 otherwise,
/// no penalty within eps of a target and the full quadratic beyond it, so that the optimizer
/// stops refining a quantity that is close enough and turns to the other terms (Sec. 4.1).
#include <cmath>

namespace gaitsynth::wang2009 {

/// Q(d; eps) of eq. 3. A NaN d gives NaN (the rollout reports it as +infinity), never 0.
inline double thresholded_quadratic(double d, double eps) {
  return std::abs(d) <= eps ? 0.0 : d * d;
}

}  // namespace gaitsynth::wang2009
