#pragma once
/// \file qp/kkt.hpp
/// The Karush-Kuhn-Tucker conditions of a dense_qp at a point and multipliers: a certificate of
/// optimality that does not depend on how the point was found (for a convex program, a point
/// whose residuals are all zero is a global minimum). Checks and tests, not the hot loop: it
/// allocates.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "gaitsynth/qp/dense_qp.hpp"

namespace gaitsynth {

struct qp_kkt_residuals {
  double stationarity = 0.0;     ///< ||H x + g - A' y - C' lambda_c - lambda_x||_inf
  double equality = 0.0;         ///< ||A x - b||_inf
  double inequality = 0.0;       ///< largest violation of a bound of C x or x
  double multiplier_sign = 0.0;  ///< largest multiplier pushing against a side that is absent
  double complementarity = 0.0;  ///< largest |lambda| times the distance to its own bound

  double max() const {
    return std::max({stationarity, equality, inequality, multiplier_sign, complementarity});
  }
};

/// The residuals at x with multipliers y, lambda_c, lambda_x (qp_result's convention).
inline qp_kkt_residuals kkt_residuals(const dense_qp& qp, const Eigen::VectorXd& x,
                                      const Eigen::VectorXd& y, const Eigen::VectorXd& lambda_c,
                                      const Eigen::VectorXd& lambda_x) {
  check_dense_qp_sizes(qp);
  check_size(x.size(), qp.num_variables(), "kkt_residuals: x");
  check_size(y.size(), qp.num_equalities(), "kkt_residuals: y");
  check_size(lambda_c.size(), qp.num_inequalities(), "kkt_residuals: lambda_c");
  check_size(lambda_x.size(), qp.num_variables(), "kkt_residuals: lambda_x");
  qp_kkt_residuals k;
  const Eigen::VectorXd grad =
      qp.H * x + qp.g - qp.A.transpose() * y - qp.C.transpose() * lambda_c - lambda_x;
  k.stationarity = grad.size() ? grad.cwiseAbs().maxCoeff() : 0.0;
  if (qp.num_equalities() > 0) k.equality = (qp.A * x - qp.b).cwiseAbs().maxCoeff();
  auto sides = [&k](const Eigen::VectorXd& v, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                    const Eigen::VectorXd& lambda) {
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      k.inequality = std::max({k.inequality, lo[i] - v[i], v[i] - hi[i]});
      const double l = lambda[i];
      if (l > 0.0) {  // holds the lower side
        k.multiplier_sign = std::max(k.multiplier_sign, std::isfinite(lo[i]) ? 0.0 : l);
        if (std::isfinite(lo[i]))
          k.complementarity = std::max(k.complementarity, l * (v[i] - lo[i]));
      } else if (l < 0.0) {
        k.multiplier_sign = std::max(k.multiplier_sign, std::isfinite(hi[i]) ? 0.0 : -l);
        if (std::isfinite(hi[i]))
          k.complementarity = std::max(k.complementarity, -l * (hi[i] - v[i]));
      }
    }
  };
  sides(qp.C * x, qp.c_lower, qp.c_upper, lambda_c);
  sides(x, qp.x_lower, qp.x_upper, lambda_x);
  return k;
}

}  // namespace gaitsynth
