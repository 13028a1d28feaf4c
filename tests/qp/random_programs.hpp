#pragma once
// Random dense convex QPs with a known feasible point, for the solver's tests (seeded).
#include <random>

#include "gaitsynth/qp/dense_qp.hpp"

namespace gaitsynth::test {

struct random_program_sizes {
  Eigen::Index n = 10, me = 2, mi = 6;
  double bounded = 0.5;    ///< share of variables with finite bounds
  double one_sided = 0.3;  ///< share of C rows with one side infinite
};

/// H = M M' + 0.1 I (condition up to about 1e3), g large enough that the unconstrained minimum
/// violates many rows; equalities and bounds hold at a random x_feasible, so the program is
/// feasible.
inline dense_qp random_program(const random_program_sizes& s, std::mt19937& rng) {
  std::normal_distribution<double> N(0.0, 1.0);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  constexpr double inf = std::numeric_limits<double>::infinity();
  dense_qp qp = make_dense_qp(s.n, s.me, s.mi);
  const Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(s.n, s.n, [&] { return N(rng); });
  qp.H = M * M.transpose() / static_cast<double>(s.n) + 0.1 * Eigen::MatrixXd::Identity(s.n, s.n);
  qp.g = Eigen::VectorXd::NullaryExpr(s.n, [&] { return 5.0 * N(rng); });
  const Eigen::VectorXd xf = Eigen::VectorXd::NullaryExpr(s.n, [&] { return N(rng); });
  qp.A = Eigen::MatrixXd::NullaryExpr(s.me, s.n, [&] { return N(rng); });
  qp.b = qp.A * xf;
  qp.C = Eigen::MatrixXd::NullaryExpr(s.mi, s.n, [&] { return N(rng); });
  const Eigen::VectorXd cx = qp.C * xf;
  for (Eigen::Index i = 0; i < s.mi; ++i) {
    qp.c_lower[i] = cx[i] - 0.5 * U(rng);
    qp.c_upper[i] = cx[i] + 0.5 * U(rng);
    if (U(rng) < s.one_sided) {
      if (U(rng) < 0.5)
        qp.c_lower[i] = -inf;
      else
        qp.c_upper[i] = inf;
    }
  }
  for (Eigen::Index j = 0; j < s.n; ++j)
    if (U(rng) < s.bounded) {
      qp.x_lower[j] = xf[j] - U(rng);
      qp.x_upper[j] = xf[j] + U(rng);
    }
  return qp;
}

}  // namespace gaitsynth::test
