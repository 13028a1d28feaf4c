// The QP solver against an independent one: CGAL's exact QP solver (Fischer & Gaertner's
// simplex-like method on exact Gmpzf arithmetic, a test-only dependency: libcgal-dev). On random
// programs both report the same status and, when optimal, the same point and objective.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/qp/goldfarb_idnani.hpp"
#include "qp/random_programs.hpp"

using namespace gaitsynth;

namespace {

struct exact_solution {
  bool optimal = false, infeasible = false;
  Eigen::VectorXd x;
  double objective = 0.0;
};

/// CGAL minimizes x' D x + c' x with D = H / 2 (set_d takes entries of 2D = H, lower triangle).
exact_solution solve_exactly(const dense_qp& qp) {
  using program = CGAL::Quadratic_program<double>;
  const int n = static_cast<int>(qp.num_variables());
  program p(CGAL::SMALLER, false, 0.0, false, 0.0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= i; ++j)
      if (qp.H(i, j) != 0.0) p.set_d(i, j, qp.H(i, j));
    p.set_c(i, qp.g[i]);
    if (std::isfinite(qp.x_lower[i])) p.set_l(i, true, qp.x_lower[i]);
    if (std::isfinite(qp.x_upper[i])) p.set_u(i, true, qp.x_upper[i]);
  }
  int row = 0;
  auto add_row = [&](auto coefficient, double rhs, CGAL::Comparison_result rel) {
    for (int j = 0; j < n; ++j)
      if (const double a = coefficient(j); a != 0.0) p.set_a(j, row, a);
    p.set_b(row, rhs);
    p.set_r(row, rel);
    ++row;
  };
  for (Eigen::Index i = 0; i < qp.num_equalities(); ++i)
    add_row([&](int j) { return qp.A(i, j); }, qp.b[i], CGAL::EQUAL);
  for (Eigen::Index i = 0; i < qp.num_inequalities(); ++i) {
    if (std::isfinite(qp.c_lower[i]))
      add_row([&](int j) { return qp.C(i, j); }, qp.c_lower[i], CGAL::LARGER);
    if (std::isfinite(qp.c_upper[i]))
      add_row([&](int j) { return qp.C(i, j); }, qp.c_upper[i], CGAL::SMALLER);
  }
  const CGAL::Quadratic_program_solution<CGAL::Gmpzf> s =
      CGAL::solve_quadratic_program(p, CGAL::Gmpzf());
  exact_solution out;
  out.optimal = s.is_optimal();
  out.infeasible = s.is_infeasible();
  if (out.optimal) {
    out.x.resize(n);
    int j = 0;
    for (auto it = s.variable_values_begin(); it != s.variable_values_end(); ++it, ++j)
      out.x[j] = CGAL::to_double(*it);
    out.objective = CGAL::to_double(s.objective_value());
  }
  return out;
}

}  // namespace

TEST_CASE("qp: the dual active-set solver agrees with CGAL's exact solver") {
  std::mt19937 rng(1983);
  int compared = 0;
  for (const auto& s : {test::random_program_sizes{6, 1, 6}, test::random_program_sizes{15, 3, 12},
                        test::random_program_sizes{46, 6, 24}}) {
    qp_workspace ws(s.n, s.me, s.mi);
    for (int k = 0; k < (s.n > 20 ? 3 : 6); ++k) {  // exact arithmetic is slow at n = 46
      const dense_qp qp = test::random_program(s, rng);
      const qp_result& r = solve_qp(qp, ws);
      const exact_solution e = solve_exactly(qp);
      INFO("n = " << s.n << ", program " << k);
      REQUIRE(e.optimal);
      REQUIRE(r.status == qp_status::optimal);
      CHECK((r.x - e.x).cwiseAbs().maxCoeff() < 1e-8 * (1.0 + e.x.cwiseAbs().maxCoeff()));
      CHECK(r.objective == Approx(e.objective).epsilon(1e-10).margin(1e-10));
      ++compared;
    }
  }
  CHECK(compared == 15);
}

TEST_CASE("qp: CGAL and the solver agree that a program is infeasible") {
  std::mt19937 rng(1);
  for (int k = 0; k < 5; ++k) {
    dense_qp qp = test::random_program({8, 2, 6}, rng);
    // Two rows that contradict: c' x >= 1 and c' x <= -1 for a random c.
    qp.C.row(0) = qp.C.row(1);
    qp.c_lower[0] = 1.0 + qp.c_upper[1];
    qp.c_upper[0] = std::numeric_limits<double>::infinity();
    qp_workspace ws(8, 2, 6);
    CHECK(solve_exactly(qp).infeasible);
    CHECK(solve_qp(qp, ws).status == qp_status::infeasible);
  }
}
