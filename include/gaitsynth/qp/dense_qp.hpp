#pragma once
/// \file qp/dense_qp.hpp
/// A dense convex quadratic program, its solver's options and its result:
///
///   minimize    1/2 x' H x + g' x
///   subject to  A x = b,  c_lower <= C x <= c_upper,  x_lower <= x <= x_upper,
///
/// H symmetric positive definite (the dual active-set method of qp/goldfarb_idnani.hpp needs a
/// strictly convex objective). One-sided rows and free variables take infinite bounds. Wu &
/// Popovic 2010 solve one such program per control tick (their eq. 5: end-effector forces from
/// ideal ones under force and torque bounds), so the data is sized once (make_dense_qp) and
/// overwritten in place each tick.
#include <Eigen/Core>
#include <limits>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

struct dense_qp {
  Eigen::MatrixXd H;                 ///< n x n, symmetric positive definite
  Eigen::VectorXd g;                 ///< n
  Eigen::MatrixXd A;                 ///< me x n: equality rows
  Eigen::VectorXd b;                 ///< me
  Eigen::MatrixXd C;                 ///< mi x n: two-sided inequality rows
  Eigen::VectorXd c_lower, c_upper;  ///< mi each; -inf / +inf for a side that does not exist
  Eigen::VectorXd x_lower, x_upper;  ///< n each; -inf / +inf for an unbounded variable

  Eigen::Index num_variables() const { return g.size(); }
  Eigen::Index num_equalities() const { return b.size(); }
  Eigen::Index num_inequalities() const { return c_lower.size(); }
};

/// A program of n variables, me equality and mi inequality rows: H = identity, the rest zero,
/// every bound infinite (unconstrained).
inline dense_qp make_dense_qp(Eigen::Index n, Eigen::Index me = 0, Eigen::Index mi = 0) {
  check_argument(n >= 1 && me >= 0 && mi >= 0, "make_dense_qp: sizes must be n >= 1, me >= 0, ",
                 "mi >= 0, got n = ", n, ", me = ", me, ", mi = ", mi);
  constexpr double inf = std::numeric_limits<double>::infinity();
  dense_qp qp;
  qp.H = Eigen::MatrixXd::Identity(n, n);
  qp.g = Eigen::VectorXd::Zero(n);
  qp.A = Eigen::MatrixXd::Zero(me, n);
  qp.b = Eigen::VectorXd::Zero(me);
  qp.C = Eigen::MatrixXd::Zero(mi, n);
  qp.c_lower = Eigen::VectorXd::Constant(mi, -inf);
  qp.c_upper = Eigen::VectorXd::Constant(mi, inf);
  qp.x_lower = Eigen::VectorXd::Constant(n, -inf);
  qp.x_upper = Eigen::VectorXd::Constant(n, inf);
  return qp;
}

/// Throws std::invalid_argument naming the member whose size does not fit the others.
inline void check_dense_qp_sizes(const dense_qp& qp) {
  const Eigen::Index n = qp.g.size(), me = qp.b.size(), mi = qp.c_lower.size();
  check_argument(n >= 1, "dense_qp: g must have at least one entry (the number of variables)");
  check_argument(qp.H.rows() == n && qp.H.cols() == n, "dense_qp: H must be ", n, " x ", n,
                 " (g has ", n, " entries), got ", qp.H.rows(), " x ", qp.H.cols());
  check_argument(qp.A.rows() == me && qp.A.cols() == n, "dense_qp: A must be ", me, " x ", n,
                 " (b has ", me, " entries), got ", qp.A.rows(), " x ", qp.A.cols());
  check_argument(qp.C.rows() == mi && qp.C.cols() == n, "dense_qp: C must be ", mi, " x ", n,
                 " (c_lower has ", mi, " entries), got ", qp.C.rows(), " x ", qp.C.cols());
  check_size(qp.c_upper.size(), mi, "dense_qp: c_upper (one per row of C)");
  check_size(qp.x_lower.size(), n, "dense_qp: x_lower (one per variable)");
  check_size(qp.x_upper.size(), n, "dense_qp: x_upper (one per variable)");
}

enum class qp_status {
  optimal,              ///< x minimizes the program; the multipliers satisfy its KKT conditions
  infeasible,           ///< no x satisfies the constraints (or equality rows contradict)
  not_strictly_convex,  ///< H is not symmetric positive definite (its Cholesky factor fails)
  iteration_limit,      ///< qp_options::max_iterations ran out before optimality
  invalid_input,        ///< NaN in the data, +-inf where only a bound may be infinite, or a
                        ///< lower bound of +inf / upper of -inf (qp_result::bad_field names it)
};

inline const char* to_string(qp_status s) {
  switch (s) {
    case qp_status::optimal:
      return "optimal";
    case qp_status::infeasible:
      return "infeasible";
    case qp_status::not_strictly_convex:
      return "not strictly convex";
    case qp_status::iteration_limit:
      return "iteration limit";
    case qp_status::invalid_input:
      return "invalid input";
  }
  return "unknown";
}

struct qp_options {
  /// A constraint counts as violated when its row's distance past the bound (violation divided
  /// by the row's norm) exceeds this; the solution satisfies every row to this distance.
  double feasibility_tolerance = 1e-9;
  /// Additions and removals of active constraints before qp_status::iteration_limit; 0 means
  /// 10 (n + number of finite bounds and equality rows) + 10.
  int max_iterations = 0;
  /// Try the constraints active at the previous optimal solve first (a warm start: the dual
  /// method may add any violated constraint next, and these are the likely ones).
  bool warm_start = true;
  /// Reuse the previous solve's factorization of H: the caller guarantees that H is unchanged
  /// (Wu & Popovic's H is the constant weight matrix W; only g and the constraints change).
  bool reuse_factorization = false;
};

/// Multipliers follow H x + g = A' y + C' lambda_c + lambda_x: lambda_c[i] >= 0 when row i is
/// held at its lower bound, <= 0 at its upper bound, 0 when inactive (lambda_x alike).
struct qp_result {
  qp_status status = qp_status::optimal;
  Eigen::VectorXd x;         ///< n; the last iterate unless optimal (zero if no iterate exists)
  Eigen::VectorXd y;         ///< me
  Eigen::VectorXd lambda_c;  ///< mi
  Eigen::VectorXd lambda_x;  ///< n
  double objective = 0.0;    ///< 1/2 x' H x + g' x
  int iterations = 0;        ///< constraint additions and removals
  int active_constraints = 0;
  /// For qp_status::invalid_input: the member ("H", "g", "c_lower", ...) and the entry (row-major
  /// index for a matrix) of the first bad value, and that value.
  const char* bad_field = "";
  Eigen::Index bad_index = -1;
  double bad_value = 0.0;
};

}  // namespace gaitsynth
