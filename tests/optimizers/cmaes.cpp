#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
using Catch::Matchers::Contains;

namespace tf = gaitsynth::test_functions;

namespace {
constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_v = std::numeric_limits<double>::infinity();

struct case_stats {
  int successes = 0;
  double median_evals = 0;
};

template <class F>
case_stats run_seeds(F f, int n, int seeds) {
  case_stats st;
  std::vector<double> evals;
  for (int s = 0; s < seeds; ++s) {
    auto es = make_benchmark_cmaes(n, static_cast<std::uint64_t>(s));
    const auto r = minimize(es, f);
    if (r.stopped == stop_criterion::target_value) {
      ++st.successes;
      evals.push_back(static_cast<double>(r.evaluations));
      REQUIRE(r.value <= 1e-8);
      REQUIRE(f(r.x) == r.value);  // the reported point has the reported value
    }
  }
  if (!evals.empty()) st.median_evals = median(evals);
  return st;
}
}  // namespace

TEST_CASE("cmaes default strategy parameters follow the tutorial (Table 1)", "[optimizers]") {
  SECTION("n = 10: pycma reports (5_w,10)-aCMA-ES, mu_w = 3.2, w_1 = 45%") {
    const auto p =
        cmaes_parameters::make(10, 4 + static_cast<int>(std::floor(3 * std::log(10))), true, 0.5);
    CHECK(p.lambda == 10);
    CHECK(p.mu == 5);
    CHECK(p.mu_eff == Approx(3.1672).epsilon(1e-4));
    CHECK(p.weights[0] == Approx(0.4563).epsilon(1e-3));
  }
  SECTION("n = 184: Wang 2009 reports M = 19 samples and N = 9 parents") {
    cmaes es(parameter_space::unbounded(Eigen::VectorXd::Zero(184)), {});
    CHECK(es.population_size() == 19);
    CHECK(es.parameters().mu == 9);
  }
  for (int n : {2, 10, 40, 184}) {
    const int lambda = 4 + static_cast<int>(std::floor(3 * std::log(n)));
    const auto p = cmaes_parameters::make(n, lambda, true, 0.5);
    const Eigen::VectorXd& w = p.weights;
    // Positive weights sum to one and decrease; for n >= 5 the negative ones are scaled such that
    // C does not decay: c_1 + c_mu * sum(w) = 0 ([T] Eq. (53) with alpha_mu^-; for n <= 3 the
    // smaller alpha_mueff^- applies).
    CHECK(w.head(p.mu).sum() == Approx(1.0));
    for (int i = 0; i + 1 < lambda; ++i) CHECK(w[i] >= w[i + 1]);
    CHECK(w[p.mu - 1] > 0);
    CHECK(w[lambda - 1] < 0);
    if (n >= 5) CHECK(p.c_1 + p.c_mu * w.sum() == Approx(0.0).margin(1e-12));
    CHECK(p.c_1 + p.c_mu * w.sum() >= -1e-12);
    CHECK(p.c_1 + p.c_mu <= 1.0);
    CHECK(p.chi_n == Approx(std::sqrt(n) * (1 - 1.0 / (4 * n) + 1.0 / (21.0 * n * n))));
    // Without active update the negative weights are zero.
    const auto q = cmaes_parameters::make(n, lambda, false, 0.5);
    CHECK(q.weights.tail(lambda - q.mu).cwiseAbs().maxCoeff() == 0.0);
  }
}

TEST_CASE("cmaes reaches 1e-8 on the 10-D benchmark functions like pycma", "[optimizers]") {
  // 11 seeds each, x0 ~ U[-3, 3]^10, sigma0 = 2. pycma's medians: sphere ~1500, ellipsoid ~4000,
  // Rosenbrock ~5500 evaluations; we accept +-25 %.
  const int n = 10, seeds = 11;
  SECTION("sphere") {
    const auto st = run_seeds(tf::sphere, n, seeds);
    CHECK(st.successes == seeds);
    CHECK(st.median_evals == Approx(1500).epsilon(0.25));
  }
  SECTION("ellipsoid") {
    const auto st = run_seeds(tf::ellipsoid, n, seeds);
    CHECK(st.successes == seeds);
    CHECK(st.median_evals == Approx(4000).epsilon(0.25));
  }
  SECTION("rotated ellipsoid (same cost as the separable one: rotation invariance)") {
    const auto st = run_seeds(tf::rotated_ellipsoid(n), n, seeds);
    CHECK(st.successes == seeds);
    CHECK(st.median_evals == Approx(4000).epsilon(0.25));
  }
  SECTION("Rosenbrock (a run may end in the local minimum near x_0 = -1)") {
    const auto st = run_seeds(tf::rosenbrock, n, seeds);
    CHECK(st.successes >= 9);
    CHECK(st.median_evals == Approx(5500).epsilon(0.25));
  }
  SECTION("cigar") {
    const auto st = run_seeds(tf::cigar, n, seeds);
    CHECK(st.successes == seeds);
  }
  SECTION("discus") {
    const auto st = run_seeds(tf::discus, n, seeds);
    CHECK(st.successes == seeds);
  }
}

TEST_CASE("cmaes reaches 1e-8 on the 40-D benchmark functions", "[optimizers]") {
  const int n = 40, seeds = 2;  // more seeds in docs/optimizers.md (optimizer_statistics)
  CHECK(run_seeds(tf::sphere, n, seeds).successes == seeds);
  CHECK(run_seeds(tf::cigar, n, seeds).successes == seeds);
  CHECK(run_seeds(tf::discus, n, seeds).successes == seeds);
  CHECK(run_seeds(tf::ellipsoid, n, seeds).successes == seeds);
  CHECK(run_seeds(tf::rotated_ellipsoid(n), n, 1).successes == 1);
  CHECK(run_seeds(tf::rosenbrock, n, 1).successes == 1);
}

TEST_CASE("cmaes solves the bounded 40-D shifted sphere (optimum 0.9 in [0, 1]^n)",
          "[optimizers]") {
  const int n = 40;
  for (auto bh : {bound_handling::resample, bound_handling::repair}) {
    cmaes_options o;
    o.sigma0 = 0.3;  // Wu 2010: mean 0.5, sigma 0.3
    o.seed = 7;
    o.bounds = bh;
    o.stop.target_value = 1e-8;
    cmaes es(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                  Eigen::VectorXd::Constant(n, 0.5)),
             o);
    bool all_inside = true;
    auto f = [&](const Eigen::VectorXd& x) {
      all_inside = all_inside && (x.array() >= 0).all() && (x.array() <= 1).all();
      return tf::shifted_sphere{0.9}(x);
    };
    const auto r = minimize(es, f);
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK((r.x.array() - 0.9).abs().maxCoeff() < 1e-3);
    CHECK(all_inside);  // the objective never sees a point outside the bounds
    if (bh == bound_handling::resample) CHECK(es.resample_count() > 0);
    if (bh == bound_handling::repair) CHECK(es.repair_count() > 0);
  }
}

TEST_CASE("cmaes handles an optimum on the bound (resampling falls back to repair)",
          "[optimizers]") {
  const int n = 10;
  cmaes_options o;
  o.seed = 3;
  o.stop.target_value = 1e-10;
  cmaes es(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                Eigen::VectorXd::Constant(n, 0.5)),
           o);
  // Minimum of the unconstrained function at -0.5: the constrained optimum is 0 everywhere.
  const auto r = minimize(es, [](const Eigen::VectorXd& x) {
    return (x.array() + 0.5).square().sum() - 0.25 * static_cast<double>(x.size());
  });
  CHECK(r.stopped == stop_criterion::target_value);
  CHECK(r.x.maxCoeff() < 1e-6);
  CHECK(es.repair_count() > 0);
}

TEST_CASE("cmaes ranks non-finite values worst and counts them", "[optimizers]") {
  SECTION("one generation, checked against the recombination formula") {
    cmaes_options o;
    o.population_size = 4;  // mu = 2
    o.sigma0 = 0.5;
    cmaes es(parameter_space::unbounded(Eigen::Vector3d(1, 2, 3)), o);
    const auto xs = es.ask();
    const std::vector<double> f = {nan_v, 3.0, 1.0, inf_v};
    es.tell(f);
    const auto& w = es.parameters().weights;
    // c_m = 1 and the positive weights sum to 1: m' = w_1 x_(1) + w_2 x_(2) with x_(1) = xs[2].
    const Eigen::VectorXd expected = w[0] * xs[2] + w[1] * xs[1];
    CHECK((es.mean() - expected).norm() < 1e-12);
    CHECK(es.non_finite_count() == 2);
    CHECK(es.status().non_finite == 2);
    CHECK(es.best_value() == 1.0);
    CHECK(identical(es.best_x(), xs[2]));
  }
  SECTION("a region where the objective fails does not stop convergence") {
    auto f = [](const Eigen::VectorXd& x) { return x[0] > 1.0 ? nan_v : x.squaredNorm(); };
    cmaes_options o;
    o.sigma0 = 2.0;
    o.seed = 11;
    o.stop.target_value = 1e-8;
    cmaes es(parameter_space::unbounded(Eigen::VectorXd::Constant(10, -0.5)), o);
    const auto r = minimize(es, f);
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK(r.non_finite > 0);
    CHECK(std::isfinite(r.value));
  }
  SECTION("all values non-finite: nothing breaks, nothing is 'best'") {
    cmaes es(parameter_space::unbounded(Eigen::VectorXd::Zero(5)), {});
    for (int g = 0; g < 5; ++g) {
      es.ask();
      std::vector<double> f(static_cast<std::size_t>(es.population_size()), nan_v);
      es.tell(f);
    }
    CHECK(es.non_finite_count() == 5 * es.population_size());
    CHECK(std::isnan(es.best_value()));
    CHECK(es.mean().allFinite());
    CHECK(es.covariance().allFinite());
  }
}

TEST_CASE("cmaes rejects bad options with std::invalid_argument naming the value", "[optimizers]") {
  const auto space = parameter_space::unbounded(Eigen::VectorXd::Zero(4));
  cmaes_options o;
  o.population_size = 1;
  CHECK_THROWS_WITH(cmaes(space, o), Contains("population_size") && Contains("got 1"));
  o.population_size = -3;
  CHECK_THROWS_WITH(cmaes(space, o), Contains("got -3"));
  o = {};
  o.sigma0 = 0.0;
  CHECK_THROWS_WITH(cmaes(space, o), Contains("sigma0") && Contains("got 0"));
  o.sigma0 = -0.5;
  CHECK_THROWS_WITH(cmaes(space, o), Contains("sigma0") && Contains("got -0.5"));
  o.sigma0 = nan_v;
  CHECK_THROWS_AS(cmaes(space, o), std::invalid_argument);
  o = {};
  o.x0 = Eigen::VectorXd::Zero(3);
  CHECK_THROWS_WITH(cmaes(space, o), Contains("x0") && Contains("expected 4, got 3"));
  o = {};
  o.stop.max_evaluations = -1;
  CHECK_THROWS_WITH(cmaes(space, o), Contains("max_evaluations") && Contains("-1"));
  CHECK_THROWS_AS(cmaes(parameter_space{}, {}), std::invalid_argument);
  // lower >= upper is caught by the parameter space.
  CHECK_THROWS_WITH(cmaes(parameter_space::box(Eigen::Vector2d(0, 2), Eigen::Vector2d(1, 2),
                                               Eigen::Vector2d(0.5, 2)),
                          {}),
                    Contains("lower bound (2)") && Contains("upper bound (2)"));
  // Population size 2 is the smallest allowed and works.
  o = {};
  o.population_size = 2;
  o.stop.max_iterations = 20;
  CHECK(minimize(cmaes(space, o), tf::sphere).iterations == 20);
}

TEST_CASE("cmaes ask/tell protocol", "[optimizers]") {
  cmaes es(parameter_space::unbounded(Eigen::VectorXd::Zero(3)), {});
  CHECK_THROWS_AS(es.tell(std::vector<double>(static_cast<std::size_t>(es.population_size()), 0.0)),
                  std::logic_error);
  const auto a = es.ask();
  const auto b = es.ask();  // same batch until told
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) CHECK(identical(a[k], b[k]));
  CHECK_THROWS_AS(es.tell(std::vector<double>(2, 0.0)), std::invalid_argument);
}

TEST_CASE("cmaes seeds: 0 is a seed, equal seeds give equal runs", "[optimizers]") {
  auto run = [](std::uint64_t seed) {
    cmaes_options o;
    o.seed = seed;
    o.stop.max_iterations = 30;
    cmaes es(parameter_space::unbounded(Eigen::VectorXd::Constant(6, 1.0)), o);
    minimize(es, tf::ellipsoid);
    return es.mean();
  };
  CHECK(identical(run(0), run(0)));
  CHECK_FALSE(identical(run(0), run(1)));
}

TEST_CASE("cmaes stopping criteria are reported", "[optimizers]") {
  const auto space10 = parameter_space::unbounded(Eigen::VectorXd::Constant(10, 1.0));
  SECTION("max_iterations") {
    cmaes_options o;
    o.stop.max_iterations = 7;
    const auto r = minimize(cmaes(space10, o), tf::sphere);
    CHECK(r.stopped == stop_criterion::max_iterations);
    CHECK(r.iterations == 7);
  }
  SECTION("max_iterations default is pycma's 100 + 150 (n+3)^2 / sqrt(lambda)") {
    cmaes es(space10, {});
    CHECK(es.max_iterations() == static_cast<std::int64_t>(100 + 150 * 169 / std::sqrt(10.0)));
  }
  SECTION("target_value is strict: a best value equal to the target does not stop") {
    const auto [at, below] = gaitsynth::testing::minimize_flat_at_and_below_target([&](double t) {
      cmaes_options o;
      o.stop.max_iterations = 5;
      o.stop.target_value = t;
      return cmaes(space10, o);
    });
    CHECK(at.value == 1.0);
    CHECK(at.stopped == stop_criterion::max_iterations);
    CHECK(at.iterations == 5);
    CHECK(below.stopped == stop_criterion::target_value);
    CHECK(below.iterations == 1);
  }
  SECTION("max_evaluations") {
    cmaes_options o;
    o.stop.max_evaluations = 55;
    const auto r = minimize(cmaes(space10, o), tf::sphere);
    CHECK(r.stopped == stop_criterion::max_evaluations);
    CHECK(r.evaluations == 60);  // whole generations of 10
  }
  SECTION("no_improvement (Wang 2009: no better value for N iterations)") {
    cmaes_options o;
    o.stop.no_improvement_iterations = 20;
    o.tol_fun = 0;  // a flat function would otherwise stop on tol_fun
    const auto r = minimize(cmaes(space10, o), [](const Eigen::VectorXd&) { return 1.0; });
    CHECK(r.stopped == stop_criterion::no_improvement);
    CHECK(r.iterations == 21);
  }
  SECTION("mean_change (Wu 2010: mean moves less than 1e-3)") {
    cmaes_options o;
    o.tol_mean_change = 1e-3;
    const int n = 10;
    const auto r =
        minimize(cmaes(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                            Eigen::VectorXd::Constant(n, 0.5)),
                       o),
                 tf::shifted_sphere{0.9});
    CHECK(r.stopped == stop_criterion::mean_change);
    CHECK((r.x.array() - 0.9).abs().maxCoeff() < 0.05);
  }
  SECTION("tol_fun") {
    const auto r = minimize(cmaes(space10, {}), tf::sphere);
    CHECK(r.stopped == stop_criterion::tol_fun);
    CHECK(r.value < 1e-11);
  }
  SECTION("tol_x") {
    cmaes_options o;
    o.tol_fun = 0;
    o.tol_x = 1e-6;
    const auto r = minimize(cmaes(space10, o), tf::sphere);
    CHECK(r.stopped == stop_criterion::tol_x);
    CHECK(r.x.cwiseAbs().maxCoeff() < 1e-5);
  }
  SECTION("condition_number") {
    cmaes_options o;
    o.max_condition = 1e4;  // the ellipsoid's Hessian has condition 1e6
    const auto r = minimize(cmaes(space10, o), tf::ellipsoid);
    CHECK(r.stopped == stop_criterion::condition_number);
  }
  SECTION("tol_up_sigma (a linear function: sigma diverges)") {
    cmaes_options o;
    o.tol_up_sigma = 1e6;
    const auto r = minimize(cmaes(space10, o), [](const Eigen::VectorXd& x) { return x[0]; });
    CHECK(r.stopped == stop_criterion::tol_up_sigma);
  }
  SECTION("no_effect_axis / no_effect_coordinate (steps below the resolution of the mean)") {
    auto f = [](const Eigen::VectorXd& x) { return (x.array() - 1e8).square().sum(); };
    cmaes_options o;
    o.tol_fun = 0;
    o.tol_x = 0;
    const auto space = parameter_space::unbounded(Eigen::VectorXd::Constant(4, 1e8 + 1.0));
    const auto r = minimize(cmaes(space, o), f);
    CHECK((r.stopped == stop_criterion::no_effect_axis ||
           r.stopped == stop_criterion::no_effect_coordinate));
    o.no_effect_axis = false;
    CHECK(minimize(cmaes(space, o), f).stopped == stop_criterion::no_effect_coordinate);
  }
  SECTION("callback") {
    int calls = 0;
    const auto r =
        minimize(cmaes(space10, {}), tf::sphere, run_options{},
                 [&](const optimizer_status& s) { return ++calls < 5 && s.iteration < 100; });
    CHECK(r.stopped == stop_criterion::callback);
    CHECK(r.iterations == 5);
  }
}

TEST_CASE("cmaes keeps C symmetric positive definite and status consistent", "[optimizers]") {
  cmaes_options o;
  o.seed = 5;
  o.stop.max_iterations = 200;
  cmaes es(parameter_space::unbounded(Eigen::VectorXd::Constant(8, 2.0)), o);
  minimize(es, tf::rotated_ellipsoid(8, 3), run_options{}, [&](const optimizer_status& s) {
    REQUIRE(s.axis_ratio >= 1.0);
    REQUIRE(s.iteration_best <= s.iteration_median);
    REQUIRE(s.iteration_median <= s.iteration_worst);
    REQUIRE(s.best_value <= s.iteration_best);
    REQUIRE(s.evaluations == s.iteration * es.population_size());
  });
  const Eigen::MatrixXd& C = es.covariance();
  CHECK((C - C.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * C.cwiseAbs().maxCoeff());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
  CHECK(eig.eigenvalues().minCoeff() > 0);
  // After adaptation C approximates the inverse Hessian's shape: axis ratio ~ sqrt(1e6) = 1e3.
  CHECK(es.status().axis_ratio > 300);
  CHECK(es.status().axis_ratio < 3000);
}
