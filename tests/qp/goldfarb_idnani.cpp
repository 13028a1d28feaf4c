// The dual active-set QP solver (qp/goldfarb_idnani.hpp): closed-form cases, KKT certificates on
// random programs of the sizes Wu & Popovic's controller produces, warm starts, degenerate,
// infeasible, non-convex and malformed input. tests/qp/cgal.cgal.cpp compares it with CGAL's
// exact solver.
#include <Eigen/Cholesky>
#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/qp/goldfarb_idnani.hpp"
#include "gaitsynth/qp/kkt.hpp"
#include "qp/random_programs.hpp"

using namespace gaitsynth;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();

qp_kkt_residuals kkt(const dense_qp& qp, const qp_result& r) {
  return kkt_residuals(qp, r.x, r.y, r.lambda_c, r.lambda_x);
}
}  // namespace

TEST_CASE("qp: a box-constrained distance is the clamped point, with the clamp's multipliers") {
  // min 1/2 ||x - c||^2 on [lo, hi]: x = clamp(c), lambda_x = x - c (H x + g = lambda_x).
  dense_qp qp = make_dense_qp(4);
  const Eigen::Vector4d c(2.0, -3.0, 0.5, -0.2);
  qp.g = -c;
  qp.x_lower << -1.0, -1.0, -1.0, 0.0;
  qp.x_upper << 1.0, 1.0, 1.0, inf;
  qp_workspace ws(4);
  const qp_result& r = solve_qp(qp, ws);
  REQUIRE(r.status == qp_status::optimal);
  CHECK(r.x.isApprox(Eigen::Vector4d(1.0, -1.0, 0.5, 0.0), 1e-14));
  CHECK(r.lambda_x.isApprox(Eigen::Vector4d(-1.0, 2.0, 0.0, 0.2), 1e-14));
  CHECK(r.active_constraints == 3);
  CHECK(r.objective == Approx(0.5 * (1.0 + 4.0 + 0.0 + 0.04) - 0.5 * c.squaredNorm()));
}

TEST_CASE("qp: the least-norm solution of equalities is A' (A A')^-1 b") {
  std::mt19937 rng(7);
  std::normal_distribution<double> N;
  dense_qp qp = make_dense_qp(8, 3);
  qp.A = Eigen::MatrixXd::NullaryExpr(3, 8, [&] { return N(rng); });
  qp.b = Eigen::Vector3d(1.0, -2.0, 0.5);
  qp_workspace ws(8, 3);
  const qp_result& r = solve_qp(qp, ws);
  REQUIRE(r.status == qp_status::optimal);
  const Eigen::MatrixXd AAt = qp.A * qp.A.transpose();
  const Eigen::VectorXd y = AAt.ldlt().solve(qp.b);
  CHECK((r.x - qp.A.transpose() * y).norm() < 1e-12);
  CHECK((r.y - y).norm() < 1e-12);  // H x = A' y with H = I, g = 0
}

TEST_CASE("qp: random programs of 5 to 70 variables satisfy the KKT conditions") {
  std::mt19937 rng(2010);
  int solved = 0;
  for (const auto& s :
       {test::random_program_sizes{5, 1, 4}, test::random_program_sizes{12, 0, 20},
        test::random_program_sizes{24, 6, 16}, test::random_program_sizes{46, 6, 40},
        test::random_program_sizes{70, 12, 60, 0.8}}) {
    qp_workspace ws(s.n, s.me, s.mi);
    for (int k = 0; k < 20; ++k) {
      const dense_qp qp = test::random_program(s, rng);
      const qp_result& r = solve_qp(qp, ws);
      INFO("n = " << s.n << ", program " << k << ": " << to_string(r.status));
      REQUIRE(r.status == qp_status::optimal);
      const qp_kkt_residuals e = kkt(qp, r);
      CHECK(e.stationarity < 1e-9 * (1.0 + qp.g.cwiseAbs().maxCoeff()));
      CHECK(e.equality < 1e-9);
      CHECK(e.inequality < 1e-9);
      CHECK(e.multiplier_sign == 0.0);
      CHECK(e.complementarity < 1e-8);
      CHECK(r.active_constraints > 0);  // the unconstrained minimum was infeasible
      ++solved;
    }
  }
  CHECK(solved == 100);
}

TEST_CASE("qp: a warm start and a kept factorization give the cold solution in fewer steps") {
  // A sequence of programs as from consecutive control ticks: g and the bounds drift slightly.
  std::mt19937 rng(64);
  std::normal_distribution<double> N;
  dense_qp qp = test::random_program({46, 6, 40}, rng);
  qp_workspace cold(46, 6, 40), warm(46, 6, 40);
  qp_options cold_opt;
  cold_opt.warm_start = false;
  qp_options warm_opt;
  warm_opt.reuse_factorization = true;
  int cold_steps = 0, warm_steps = 0;
  for (int tick = 0; tick < 30; ++tick) {
    for (Eigen::Index i = 0; i < qp.g.size(); ++i) qp.g[i] += 0.05 * N(rng);
    const qp_result& a = solve_qp(qp, cold, cold_opt);
    const qp_result& b = solve_qp(qp, warm, warm_opt);
    REQUIRE(a.status == qp_status::optimal);
    REQUIRE(b.status == qp_status::optimal);
    CHECK((a.x - b.x).cwiseAbs().maxCoeff() < 1e-10);
    CHECK((a.lambda_c - b.lambda_c).cwiseAbs().maxCoeff() < 1e-8);
    if (tick > 0) {  // the first warm solve has no previous active set
      cold_steps += a.iterations;
      warm_steps += b.iterations;
    }
  }
  INFO("cold " << cold_steps << " steps, warm " << warm_steps);
  CHECK(warm_steps <= cold_steps);
}

TEST_CASE("qp: degenerate constraints (duplicates, redundant equalities, a crowded vertex)") {
  SECTION("a duplicated row and a redundant, consistent equality") {
    dense_qp qp = make_dense_qp(3, 2, 3);
    qp.g << -1.0, -1.0, -1.0;
    qp.A << 1.0, 1.0, 0.0, 2.0, 2.0, 0.0;  // the second is twice the first
    qp.b << 1.0, 2.0;
    qp.C << 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0;
    qp.c_upper << 0.25, 0.25, 0.5;  // three copies of x_2 <= 0.25
    qp_workspace ws(3, 2, 3);
    const qp_result& r = solve_qp(qp, ws);
    REQUIRE(r.status == qp_status::optimal);
    CHECK(r.x.isApprox(Eigen::Vector3d(0.5, 0.5, 0.25), 1e-14));
    CHECK(kkt(qp, r).max() < 1e-12);
  }
  SECTION("more active rows than variables at the solution's vertex") {
    // min 1/2 ||x - (2, 2)||^2 with x0 <= 1, x1 <= 1, x0 + x1 <= 2, 2 x0 + x1 <= 3: all four hold
    // with equality at (1, 1).
    dense_qp qp = make_dense_qp(2, 0, 4);
    qp.g << -2.0, -2.0;
    qp.C << 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 1.0;
    qp.c_upper << 1.0, 1.0, 2.0, 3.0;
    qp_workspace ws(2, 0, 4);
    const qp_result& r = solve_qp(qp, ws);
    REQUIRE(r.status == qp_status::optimal);
    CHECK(r.x.isApprox(Eigen::Vector2d(1.0, 1.0), 1e-14));
    CHECK(r.active_constraints <= 2);
    CHECK(kkt(qp, r).max() < 1e-12);
  }
  SECTION("an equality row written also as two inequality sides") {
    dense_qp qp = make_dense_qp(2, 1, 1);
    qp.g << 1.0, -3.0;
    qp.A << 1.0, -1.0;
    qp.C << 1.0, -1.0;
    qp.c_lower << 0.0;
    qp.c_upper << 0.0;
    qp_workspace ws(2, 1, 1);
    const qp_result& r = solve_qp(qp, ws);
    REQUIRE(r.status == qp_status::optimal);
    CHECK(r.x.isApprox(Eigen::Vector2d(1.0, 1.0), 1e-14));
    CHECK(kkt(qp, r).max() < 1e-12);
  }
}

TEST_CASE("qp: infeasible programs are reported, with a finite point") {
  SECTION("rows that exclude each other") {
    dense_qp qp = make_dense_qp(2, 0, 2);
    qp.C << 1.0, 1.0, 1.0, -1.0;
    qp.c_lower << 2.0, -inf;
    qp.x_upper << 0.5, 0.5;  // x0 + x1 >= 2 is out of reach
    qp_workspace ws(2, 0, 2);
    const qp_result& r = solve_qp(qp, ws);
    CHECK(r.status == qp_status::infeasible);
    CHECK(r.x.allFinite());
  }
  SECTION("contradicting equalities") {
    dense_qp qp = make_dense_qp(2, 2);
    qp.A << 1.0, 1.0, 1.0, 1.0;
    qp.b << 1.0, 2.0;
    qp_workspace ws(2, 2);
    CHECK(solve_qp(qp, ws).status == qp_status::infeasible);
  }
  SECTION("a lower bound above its upper bound") {
    dense_qp qp = make_dense_qp(2, 0, 1);
    qp.C << 1.0, 0.0;
    qp.c_lower << 1.0;
    qp.c_upper << 0.0;
    qp_workspace ws(2, 0, 1);
    CHECK(solve_qp(qp, ws).status == qp_status::infeasible);
    qp.c_upper << 2.0;
    qp.x_lower[1] = 3.0;
    qp.x_upper[1] = 2.0;
    CHECK(solve_qp(qp, ws).status == qp_status::infeasible);
  }
  SECTION("a zero row that cannot hold") {
    dense_qp qp = make_dense_qp(2, 0, 1);
    qp.c_lower << 1.0;  // 0 x >= 1
    qp_workspace ws(2, 0, 1);
    CHECK(solve_qp(qp, ws).status == qp_status::infeasible);
  }
}

TEST_CASE("qp: a Hessian that is not symmetric positive definite is a status, never NaN") {
  qp_workspace ws(3);
  dense_qp qp = make_dense_qp(3);
  qp.g << 1.0, 2.0, 3.0;
  SECTION("indefinite") {
    qp.H.diagonal() << 1.0, -1.0, 1.0;
  }
  SECTION("singular (convex but not strictly)") {
    qp.H.diagonal() << 1.0, 0.0, 1.0;
  }
  SECTION("not symmetric") {
    qp.H(0, 1) = 0.5;
  }
  const qp_result& r = solve_qp(qp, ws);
  CHECK(r.status == qp_status::not_strictly_convex);
  CHECK(r.x == Eigen::Vector3d::Zero());
}

TEST_CASE("qp: NaN or a misplaced infinity names the field and entry") {
  dense_qp qp = make_dense_qp(3, 1, 2);
  qp.A << 1.0, 1.0, 1.0;
  qp_workspace ws(3, 1, 2);
  const char* field = "";
  Eigen::Index index = -1;
  SECTION("g") {
    qp.g[2] = std::nan("");
    field = "g";
    index = 2;
  }
  SECTION("H") {
    qp.H(1, 2) = inf;  // row-major index 5
    field = "H";
    index = 5;
  }
  SECTION("C") {
    qp.C(1, 0) = std::nan("");
    field = "C";
    index = 3;
  }
  SECTION("a lower bound of +inf") {
    qp.c_lower[1] = inf;
    field = "c_lower";
    index = 1;
  }
  SECTION("an upper bound of -inf") {
    qp.x_upper[0] = -inf;
    field = "x_upper";
    index = 0;
  }
  const qp_result& r = solve_qp(qp, ws);
  CHECK(r.status == qp_status::invalid_input);
  CHECK(std::string(r.bad_field) == field);
  CHECK(r.bad_index == index);
  CHECK(r.x.allFinite());
  // The same workspace solves the next, valid program.
  qp = make_dense_qp(3, 1, 2);
  CHECK(solve_qp(qp, ws).status == qp_status::optimal);
}

TEST_CASE("qp: members of the wrong size throw, naming the member and both sizes") {
  dense_qp qp = make_dense_qp(3, 1, 2);
  qp_workspace ws(3, 1, 2);
  qp.C.resize(2, 4);
  CHECK_THROWS_WITH(solve_qp(qp, ws),
                    Catch::Contains("C must be 2 x 3") && Catch::Contains("got 2 x 4"));
  qp = make_dense_qp(3, 1, 2);
  qp.x_upper.resize(2);
  CHECK_THROWS_WITH(solve_qp(qp, ws), Catch::Contains("x_upper"));
  qp = make_dense_qp(4, 1, 2);
  CHECK_THROWS_WITH(solve_qp(qp, ws), Catch::Contains("sized for n = 3"));
}

TEST_CASE("qp: the iteration limit stops the solve with that status") {
  std::mt19937 rng(3);
  const dense_qp qp = test::random_program({24, 4, 30}, rng);
  qp_workspace ws(24, 4, 30);
  qp_options opt;
  opt.max_iterations = 5;
  const qp_result& r = solve_qp(qp, ws, opt);
  CHECK(r.status == qp_status::iteration_limit);
  CHECK(r.iterations == 5);
  CHECK(r.x.allFinite());
}
