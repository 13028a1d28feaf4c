#pragma once
/// \file qp/goldfarb_idnani.hpp
/// The dual active-set method of Goldfarb & Idnani (1983, "A numerically stable dual method for
/// solving strictly convex quadratic programs", Math. Programming 27) for qp/dense_qp.hpp.
///
/// It starts at the unconstrained minimum -H^-1 g and adds violated constraints one at a time,
/// dropping an active one whenever its multiplier would turn negative, so every iterate is the
/// optimum of the program restricted to its active set (dual feasible) and the objective rises
/// monotonically; it stops when nothing is violated. The factorization is the paper's: with
/// H = L L' and N the active normals, J = L^-T Q and J' N = [R; 0] (R upper triangular), kept
/// up to date by Givens rotations as constraints come and go (Sec. 4 of the paper), so a step
/// costs O(n^2). Equality rows are added first and never dropped.
///
/// Usage (sizes fixed once; no allocation per solve):
///   dense_qp qp = make_dense_qp(n, me, mi);  qp_workspace ws(n, me, mi);
///   ... fill qp ...;  const qp_result& r = solve_qp(qp, ws);  if (r.status == qp_status::optimal)
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/qp/dense_qp.hpp"

namespace gaitsynth {

/// Scratch and result of solve_qp for programs of one size (Pinocchio's Data).
struct qp_workspace {
  Eigen::Index n = 0, me = 0, mi = 0;
  Eigen::MatrixXd L;   ///< Cholesky factor of H (lower)
  Eigen::MatrixXd J0;  ///< L^-T, kept for qp_options::reuse_factorization
  Eigen::MatrixXd J;   ///< L^-T Q, rotated as constraints come and go
  Eigen::MatrixXd R;   ///< upper triangular, the first q columns used
  Eigen::VectorXd d, z, r, u, normal, Cx, row_norm;
  /// Constraint ids: [0, me) equality rows, me + 2 i (+1) row i's lower (upper) side,
  /// me + 2 mi + 2 j (+1) variable j's lower (upper) bound.
  std::vector<int> active;  ///< ids of the q active constraints, in R's column order
  std::vector<unsigned char> is_active;
  std::vector<int> warm;  ///< inequality ids active at the last optimal solve
  int q = 0;
  bool factorized = false;
  qp_result result;

  qp_workspace() = default;
  qp_workspace(Eigen::Index n_, Eigen::Index me_ = 0, Eigen::Index mi_ = 0)
      : n(n_), me(me_), mi(mi_) {
    check_argument(n >= 1 && me >= 0 && mi >= 0, "qp_workspace: sizes must be n >= 1, me >= 0, ",
                   "mi >= 0, got n = ", n, ", me = ", me, ", mi = ", mi);
    L.setZero(n, n);
    J0.setZero(n, n);
    J.setZero(n, n);
    R.setZero(n, n);
    d.setZero(n);
    z.setZero(n);
    r.setZero(n);
    u.setZero(n);
    normal.setZero(n);
    Cx.setZero(mi);
    row_norm.setZero(mi);
    active.assign(static_cast<std::size_t>(n), -1);
    is_active.assign(static_cast<std::size_t>(me + 2 * mi + 2 * n), 0);
    warm.reserve(static_cast<std::size_t>(n));
    result.x.setZero(n);
    result.y.setZero(me);
    result.lambda_c.setZero(mi);
    result.lambda_x.setZero(n);
  }
};

namespace detail {

/// Givens rotation taking (a, b) to (h, 0): returns false (nothing to do) when b == 0.
inline bool givens(double a, double b, double& c, double& s, double& h) {
  if (b == 0.0) return false;
  h = std::sqrt(a * a + b * b);  // std::hypot's over/underflow guard costs 10x; d's entries are
                                 // far from 1e+-150 for any program in double precision
  c = a / h;
  s = b / h;
  return true;
}

/// Columns j and k of M become c M_j + s M_k and -s M_j + c M_k.
inline void rotate_columns(Eigen::MatrixXd& M, Eigen::Index j, Eigen::Index k, double c, double s,
                           Eigen::Index rows) {
  double* mj = M.col(j).data();
  double* mk = M.col(k).data();
  for (Eigen::Index i = 0; i < rows; ++i) {
    const double a = mj[i], b = mk[i];
    mj[i] = c * a + s * b;
    mk[i] = -s * a + c * b;
  }
}

struct qp_constraint_data {
  double rhs;   ///< the row n' x >= rhs (or = rhs)
  double norm;  ///< ||n||
};

/// Sets ws.normal to constraint id's normal n (n' x >= rhs, or = rhs for an equality).
inline qp_constraint_data qp_load_normal(const dense_qp& qp, qp_workspace& ws, int id) {
  const Eigen::Index me = ws.me, mi = ws.mi;
  if (id < me) {
    ws.normal = qp.A.row(id).transpose();
    return {qp.b[id], ws.normal.norm()};
  }
  if (id < me + 2 * mi) {
    const Eigen::Index i = (id - me) / 2;
    const bool upper = (id - me) % 2 == 1;
    ws.normal = qp.C.row(i).transpose();
    if (upper) ws.normal = -ws.normal;
    return {upper ? -qp.c_upper[i] : qp.c_lower[i], ws.row_norm[i]};
  }
  const Eigen::Index j = (id - me - 2 * mi) / 2;
  const bool upper = (id - me - 2 * mi) % 2 == 1;
  ws.normal.setZero();
  ws.normal[j] = upper ? -1.0 : 1.0;
  return {upper ? -qp.x_upper[j] : qp.x_lower[j], 1.0};
}

/// d = J' n, z = J2 d2 (the primal step: the part of H^-1 n that keeps the active constraints),
/// r = R^-1 d1 (the active multipliers' rate). Returns ||d2||^2 = z' n.
inline double qp_step_directions(qp_workspace& ws, int id) {
  const Eigen::Index n = ws.n, q = ws.q, first_bound = ws.me + 2 * ws.mi;
  if (id >= first_bound) {  // a variable bound: n = +-e_j, so J' n is a row of J, O(n)
    const Eigen::Index j = (id - first_bound) / 2;
    ws.d = ws.J.row(j).transpose();
    if ((id - first_bound) % 2) ws.d = -ws.d;
  } else {
    ws.d.noalias() = ws.J.transpose() * ws.normal;
  }
  ws.z.noalias() = ws.J.rightCols(n - q) * ws.d.tail(n - q);
  for (Eigen::Index i = q - 1; i >= 0; --i) {  // R r = d1, back substitution
    double v = ws.d[i];
    for (Eigen::Index k = i + 1; k < q; ++k) v -= ws.R(i, k) * ws.r[k];
    ws.r[i] = v / ws.R(i, i);
  }
  return ws.d.tail(n - q).squaredNorm();
}

/// Makes constraint id active, with d = J' n current: rotates d's tail onto its first entry
/// (and J's columns with it) and appends that column to R.
inline void qp_add_active(qp_workspace& ws, int id) {
  const Eigen::Index n = ws.n, q = ws.q;
  for (Eigen::Index j = n - 1; j > q; --j) {
    double c, s, h;
    if (!givens(ws.d[j - 1], ws.d[j], c, s, h)) continue;
    ws.d[j - 1] = h;
    ws.d[j] = 0.0;
    rotate_columns(ws.J, j - 1, j, c, s, n);
  }
  for (Eigen::Index i = 0; i <= q; ++i) ws.R(i, q) = ws.d[i];
  ws.active[static_cast<std::size_t>(q)] = id;
  ws.is_active[static_cast<std::size_t>(id)] = 1;
  ++ws.q;
}

/// Drops the active constraint at position k: removes R's column k and restores the triangle
/// with rotations of its rows (and of J's columns alike); multipliers shift with it.
inline void qp_drop_active(qp_workspace& ws, Eigen::Index k) {
  const Eigen::Index n = ws.n, q = ws.q;
  ws.is_active[static_cast<std::size_t>(ws.active[static_cast<std::size_t>(k)])] = 0;
  for (Eigen::Index j = k; j + 1 < q; ++j) {
    ws.R.col(j).head(j + 2) = ws.R.col(j + 1).head(j + 2);
    ws.active[static_cast<std::size_t>(j)] = ws.active[static_cast<std::size_t>(j + 1)];
    ws.u[j] = ws.u[j + 1];
  }
  ws.R.col(q - 1).setZero();
  for (Eigen::Index j = k; j + 1 < q; ++j) {  // R(j + 1, j) is the subdiagonal to remove
    double c, s, h;
    if (!givens(ws.R(j, j), ws.R(j + 1, j), c, s, h)) continue;
    ws.R(j, j) = h;
    ws.R(j + 1, j) = 0.0;
    for (Eigen::Index col = j + 1; col + 1 < q; ++col) {
      const double a = ws.R(j, col), b = ws.R(j + 1, col);
      ws.R(j, col) = c * a + s * b;
      ws.R(j + 1, col) = -s * a + c * b;
    }
    rotate_columns(ws.J, j, j + 1, c, s, n);
  }
  --ws.q;
}

/// The first non-finite entry of v (row-major for a matrix), or -1.
template <class M>
Eigen::Index first_nan_or_inf(const M& v) {
  if (v.allFinite()) return -1;  // vectorized; the row-major scan below only names the first bad
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    for (Eigen::Index j = 0; j < v.cols(); ++j)
      if (!std::isfinite(v(i, j))) return i * v.cols() + j;
  return -1;
}

/// Checks the data; fills result.bad_* and returns false on the first bad value.
inline bool qp_input_valid(const dense_qp& qp, qp_result& res) {
  auto bad = [&](const char* field, Eigen::Index i, double v) {
    res.bad_field = field;
    res.bad_index = i;
    res.bad_value = v;
    return false;
  };
  struct named {
    const char* name;
    const Eigen::MatrixXd* m;
  };
  for (const named& f : {named{"H", &qp.H}, named{"A", &qp.A}, named{"C", &qp.C}})
    if (const Eigen::Index i = first_nan_or_inf(*f.m); i >= 0)
      return bad(f.name, i, f.m->data()[(i % f.m->cols()) * f.m->rows() + i / f.m->cols()]);
  if (const Eigen::Index i = first_nan_or_inf(qp.g); i >= 0) return bad("g", i, qp.g[i]);
  if (const Eigen::Index i = first_nan_or_inf(qp.b); i >= 0) return bad("b", i, qp.b[i]);
  // Bounds may be infinite on their own side only.
  auto bounds = [&](const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, const char* lo_name,
                    const char* hi_name) {
    for (Eigen::Index i = 0; i < lo.size(); ++i) {
      if (std::isnan(lo[i]) || lo[i] == std::numeric_limits<double>::infinity())
        return bad(lo_name, i, lo[i]);
      if (std::isnan(hi[i]) || hi[i] == -std::numeric_limits<double>::infinity())
        return bad(hi_name, i, hi[i]);
    }
    return true;
  };
  return bounds(qp.c_lower, qp.c_upper, "c_lower", "c_upper") &&
         bounds(qp.x_lower, qp.x_upper, "x_lower", "x_upper");
}

/// Cholesky H = L L' (lower) and J = L^-T; false unless H is symmetric positive definite (to
/// rounding: a pivot must exceed n eps times H's largest diagonal entry).
inline bool qp_factorize(const Eigen::MatrixXd& H, qp_workspace& ws) {
  const Eigen::Index n = ws.n;
  double diag_max = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) diag_max = std::max(diag_max, std::abs(H(i, i)));
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = j + 1; i < n; ++i)
      if (!(std::abs(H(i, j) - H(j, i)) <= 1e-10 * diag_max)) return false;
  const double pivot_min = static_cast<double>(n) * std::numeric_limits<double>::epsilon() *
                           std::max(diag_max, std::numeric_limits<double>::min());
  Eigen::MatrixXd& L = ws.L;
  for (Eigen::Index j = 0; j < n; ++j) {
    double djj = H(j, j);
    for (Eigen::Index k = 0; k < j; ++k) djj -= L(j, k) * L(j, k);
    if (!(djj > pivot_min)) return false;
    const double ljj = std::sqrt(djj);
    L(j, j) = ljj;
    for (Eigen::Index i = j + 1; i < n; ++i) {
      double v = H(i, j);
      for (Eigen::Index k = 0; k < j; ++k) v -= L(i, k) * L(j, k);
      L(i, j) = v / ljj;
    }
  }
  // J0 = L^-T (upper triangular): L' J0 = I, column by column by back substitution.
  Eigen::MatrixXd& J = ws.J0;
  J.setZero();
  for (Eigen::Index c = 0; c < n; ++c)
    for (Eigen::Index i = c; i >= 0; --i) {
      double v = i == c ? 1.0 : 0.0;
      for (Eigen::Index k = i + 1; k <= c; ++k) v -= L(k, i) * J(k, c);
      J(i, c) = v / L(i, i);
    }
  return true;
}

}  // namespace detail

/// Solves qp (qp/dense_qp.hpp) with the workspace's scratch; returns ws.result.
/// \throws std::invalid_argument if qp's members do not fit each other or the workspace's sizes.
/// Bad data (NaN, a non-convex H, contradicting constraints) is a status, never an exception.
inline const qp_result& solve_qp(const dense_qp& qp, qp_workspace& ws, const qp_options& opt = {}) {
  check_dense_qp_sizes(qp);
  check_argument(
      qp.num_variables() == ws.n && qp.num_equalities() == ws.me && qp.num_inequalities() == ws.mi,
      "solve_qp: the workspace is sized for n = ", ws.n, ", me = ", ws.me, ", mi = ", ws.mi,
      ", the program has n = ", qp.num_variables(), ", me = ", qp.num_equalities(),
      ", mi = ", qp.num_inequalities());
  const Eigen::Index n = ws.n, me = ws.me, mi = ws.mi;
  qp_result& res = ws.result;
  res.iterations = 0;
  res.bad_field = "";
  res.bad_index = -1;
  res.bad_value = 0.0;
  res.y.setZero();
  res.lambda_c.setZero();
  res.lambda_x.setZero();
  ws.q = 0;
  std::fill(ws.is_active.begin(), ws.is_active.end(), 0);
  auto finish = [&](qp_status s) -> const qp_result& {
    res.status = s;
    res.active_constraints = static_cast<int>(ws.q);
    if (s != qp_status::optimal) return res;
    for (Eigen::Index k = 0; k < ws.q; ++k) {
      const int id = ws.active[static_cast<std::size_t>(k)];
      if (id < me) {
        res.y[id] = ws.u[k];
      } else if (id < me + 2 * mi) {
        res.lambda_c[(id - me) / 2] += (id - me) % 2 ? -ws.u[k] : ws.u[k];
      } else {
        res.lambda_x[(id - me - 2 * mi) / 2] += (id - me - 2 * mi) % 2 ? -ws.u[k] : ws.u[k];
      }
    }
    ws.warm.clear();
    for (Eigen::Index k = 0; k < ws.q; ++k)
      if (ws.active[static_cast<std::size_t>(k)] >= me)
        ws.warm.push_back(ws.active[static_cast<std::size_t>(k)]);  // capacity n: no allocation
    ws.z.noalias() = qp.H * res.x;
    res.objective = 0.5 * res.x.dot(ws.z) + qp.g.dot(res.x);
    return res;
  };
  if (!detail::qp_input_valid(qp, res)) {
    res.x.setZero();
    return finish(qp_status::invalid_input);
  }
  if (!(opt.reuse_factorization && ws.factorized)) {
    ws.factorized = detail::qp_factorize(qp.H, ws);
    if (!ws.factorized) {
      res.x.setZero();
      return finish(qp_status::not_strictly_convex);
    }
  }
  ws.J = ws.J0;
  for (Eigen::Index i = 0; i < mi; ++i) {
    if (qp.c_lower[i] > qp.c_upper[i]) {
      res.x.setZero();
      return finish(qp_status::infeasible);
    }
    ws.row_norm[i] = qp.C.row(i).norm();
  }
  for (Eigen::Index j = 0; j < n; ++j)
    if (qp.x_lower[j] > qp.x_upper[j]) {
      res.x.setZero();
      return finish(qp_status::infeasible);
    }
  int max_iterations = opt.max_iterations;
  if (max_iterations <= 0) {
    int sides = static_cast<int>(me);
    for (Eigen::Index i = 0; i < mi; ++i)
      sides += std::isfinite(qp.c_lower[i]) + std::isfinite(qp.c_upper[i]);
    for (Eigen::Index j = 0; j < n; ++j)
      sides += std::isfinite(qp.x_lower[j]) + std::isfinite(qp.x_upper[j]);
    max_iterations = 10 * (static_cast<int>(n) + sides) + 10;
  }

  // The unconstrained minimum x = -H^-1 g = -J J' g.
  Eigen::VectorXd& x = res.x;
  ws.d.noalias() = ws.J.transpose() * qp.g;
  x.noalias() = -ws.J * ws.d;
  constexpr double dependent = 1e-24;  // ||d2||^2 <= this ||d||^2: n lies in the active span

  // Equality rows: full steps onto each, never dropped.
  for (int id = 0; id < me; ++id) {
    const detail::qp_constraint_data c = detail::qp_load_normal(qp, ws, id);
    const double d2 = detail::qp_step_directions(ws, id);
    const double residual = ws.normal.dot(x) - c.rhs;
    if (d2 <= dependent * ws.d.squaredNorm()) {
      // The row depends on earlier ones: redundant if satisfied, contradicting otherwise.
      if (std::abs(residual) <= opt.feasibility_tolerance * std::max(c.norm, 1.0)) continue;
      return finish(qp_status::infeasible);
    }
    const double t = -residual / d2;
    x += t * ws.z;
    ws.u.head(ws.q) -= t * ws.r.head(ws.q);
    ws.u[ws.q] = t;
    detail::qp_add_active(ws, id);
    ++res.iterations;
  }

  const int first_bound = static_cast<int>(me + 2 * mi);
  // The most violated inactive constraint (distance past its bound), the warm set's first.
  auto choose = [&](double& slack) -> int {
    ws.Cx.noalias() = qp.C * x;
    auto violation = [&](int id) {  // > 0 when violated: distance past the bound
      if (id < first_bound) {
        const Eigen::Index i = (id - me) / 2;
        const double nrm = std::max(ws.row_norm[i], std::numeric_limits<double>::min());
        return (id - me) % 2 ? (ws.Cx[i] - qp.c_upper[i]) / nrm : (qp.c_lower[i] - ws.Cx[i]) / nrm;
      }
      const Eigen::Index j = (id - first_bound) / 2;
      return (id - first_bound) % 2 ? x[j] - qp.x_upper[j] : qp.x_lower[j] - x[j];
    };
    if (opt.warm_start)
      for (const int id : ws.warm)
        if (!ws.is_active[static_cast<std::size_t>(id)] &&
            violation(id) > opt.feasibility_tolerance) {
          slack = -violation(id);
          return id;
        }
    int best = -1;
    double worst = opt.feasibility_tolerance;
    const int total = static_cast<int>(me + 2 * mi + 2 * n);
    for (int id = static_cast<int>(me); id < total; ++id) {
      if (ws.is_active[static_cast<std::size_t>(id)]) continue;
      const double v = violation(id);  // -inf (never violated) for an infinite bound
      if (v > worst) {
        worst = v;
        best = id;
      }
    }
    slack = -worst;
    return best;
  };

  for (;;) {
    double slack_unused;
    const int p = choose(slack_unused);
    if (p < 0) return finish(qp_status::optimal);
    double u_plus = 0.0;  // the multiplier of p while it is being added
    for (;;) {
      if (res.iterations >= max_iterations) return finish(qp_status::iteration_limit);
      const detail::qp_constraint_data c = detail::qp_load_normal(qp, ws, p);
      const double d2 = detail::qp_step_directions(ws, p);
      const double s_p = ws.normal.dot(x) - c.rhs;  // < 0 while p is violated
      // Partial step: the first active inequality whose multiplier reaches zero.
      double t1 = std::numeric_limits<double>::infinity();
      Eigen::Index drop = -1;
      for (Eigen::Index k = 0; k < ws.q; ++k) {
        if (ws.active[static_cast<std::size_t>(k)] < me || !(ws.r[k] > 0.0)) continue;
        const double tk = std::max(ws.u[k], 0.0) / ws.r[k];  // u >= 0 up to rounding
        if (tk < t1) {
          t1 = tk;
          drop = k;
        }
      }
      const bool in_span = d2 <= dependent * ws.d.squaredNorm();
      const double t2 = in_span ? std::numeric_limits<double>::infinity() : -s_p / d2;
      if (!std::isfinite(t1) && !std::isfinite(t2)) return finish(qp_status::infeasible);
      if (t2 <= t1) {  // full step: p becomes active
        if (t2 > 0.0) x += t2 * ws.z;
        ws.u.head(ws.q) -= t2 * ws.r.head(ws.q);
        ws.u[ws.q] = u_plus + t2;
        detail::qp_add_active(ws, p);
        ++res.iterations;
        break;
      }
      // Partial step (in the dual only when n is in the active span), then drop the blocker.
      if (!in_span) x += t1 * ws.z;
      ws.u.head(ws.q) -= t1 * ws.r.head(ws.q);
      u_plus += t1;
      detail::qp_drop_active(ws, drop);
      ++res.iterations;
    }
  }
}

}  // namespace gaitsynth
