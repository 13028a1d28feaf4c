// The per-tick QP of Wu & Popovic 2010 (eq. 5) at the sizes their controller produces (46-70
// unknowns), solved by qp/goldfarb_idnani.hpp (figures in docs/performance.md, "QP").
//
//   bench_qp                 every case
//   BM_QP_Cold/n             factorize H and solve from the unconstrained minimum
//   BM_QP_Tick/n             a control tick: g drifts a little, H is kept (reuse_factorization)
//                            and the previous active set is tried first (warm_start)
//   BM_QP_UnconstrainedLLT/n the peer: Eigen's LLT of H and one solve, the floor of any method
//                            that factorizes H
// GCC 12 with -march=native (AVX-512) warns falsely inside its own avx512fintrin.h when Eigen's
// kernels are inlined (GCC PR 105593); the warning is not about this code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <benchmark/benchmark.h>

#include <Eigen/Cholesky>
#include <gaitsynth/qp/goldfarb_idnani.hpp>
#include <random>

using namespace gaitsynth;

namespace {

/// A program shaped like eq. 5: forces f (n) near ideal ones under a diagonal weight W,
/// |f_i| <= 2000 N, joint torques J' f within +-tau_max for mi joints, me null-space rows.
dense_qp wu2010_like_program(Eigen::Index n, std::mt19937& rng) {
  const Eigen::Index me = n / 8, mi = (n * 3) / 5;
  std::normal_distribution<double> N;
  std::uniform_real_distribution<double> U(0.5, 2.0);
  dense_qp qp = make_dense_qp(n, me, mi);
  qp.H.setZero();
  for (Eigen::Index i = 0; i < n; ++i) qp.H(i, i) = U(rng);
  const Eigen::VectorXd f_ideal = Eigen::VectorXd::NullaryExpr(n, [&] { return 600.0 * N(rng); });
  qp.g = -(qp.H * f_ideal);
  qp.A = Eigen::MatrixXd::NullaryExpr(me, n, [&] { return N(rng); });
  qp.b.setZero();
  qp.C = Eigen::MatrixXd::NullaryExpr(mi, n, [&] { return 0.1 * N(rng); });
  qp.c_lower.setConstant(-150.0);
  qp.c_upper.setConstant(150.0);
  qp.x_lower.setConstant(-2000.0);
  qp.x_upper.setConstant(2000.0);
  return qp;
}

void BM_QP_Cold(benchmark::State& state) {
  std::mt19937 rng(5);
  const dense_qp qp = wu2010_like_program(state.range(0), rng);
  qp_workspace ws(qp.num_variables(), qp.num_equalities(), qp.num_inequalities());
  qp_options opt;
  opt.warm_start = false;
  int active = 0, iterations = 0;
  for (auto _ : state) {
    const qp_result& r = solve_qp(qp, ws, opt);
    if (r.status != qp_status::optimal) state.SkipWithError("not optimal");
    active = r.active_constraints;
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.x.data());
  }
  state.counters["active"] = active;
  state.counters["iterations"] = iterations;
}

void BM_QP_Tick(benchmark::State& state) {
  std::mt19937 rng(5);
  dense_qp qp = wu2010_like_program(state.range(0), rng);
  const Eigen::VectorXd g0 = qp.g;
  std::normal_distribution<double> N;
  // 64 ticks of drift, cycled: each differs from the last by a few percent of g.
  std::vector<Eigen::VectorXd> gs;
  Eigen::VectorXd g = g0;
  for (int k = 0; k < 64; ++k) {
    for (Eigen::Index i = 0; i < g.size(); ++i) g[i] += 0.02 * std::abs(g0[i]) * N(rng);
    gs.push_back(g);
  }
  qp_workspace ws(qp.num_variables(), qp.num_equalities(), qp.num_inequalities());
  qp_options opt;
  opt.reuse_factorization = true;
  solve_qp(qp, ws);
  std::size_t k = 0;
  long iterations = 0, solves = 0;
  for (auto _ : state) {
    qp.g = gs[k++ % gs.size()];
    const qp_result& r = solve_qp(qp, ws, opt);
    if (r.status != qp_status::optimal) state.SkipWithError("not optimal");
    iterations += r.iterations;
    ++solves;
    benchmark::DoNotOptimize(r.x.data());
  }
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(solves);
}

void BM_QP_UnconstrainedLLT(benchmark::State& state) {
  std::mt19937 rng(5);
  const dense_qp qp = wu2010_like_program(state.range(0), rng);
  Eigen::LLT<Eigen::MatrixXd> llt(qp.num_variables());
  Eigen::VectorXd x(qp.num_variables());
  for (auto _ : state) {
    llt.compute(qp.H);
    x = -qp.g;
    llt.solveInPlace(x);
    benchmark::DoNotOptimize(x.data());
  }
}

}  // namespace

BENCHMARK(BM_QP_Cold)->Arg(46)->Arg(70)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QP_Tick)->Arg(46)->Arg(70)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QP_UnconstrainedLLT)->Arg(46)->Arg(70)->Unit(benchmark::kMicrosecond);
