#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
using Catch::Matchers::Contains;
namespace tf = gaitsynth::test_functions;

namespace {
// Separable quadratic with different curvatures, minimum 0 at (1, ..., 1).
double quadratic(const Eigen::VectorXd& x) {
  double f = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) f += (i + 1.0) * (x[i] - 1.0) * (x[i] - 1.0);
  return f;
}
}  // namespace

TEST_CASE("SDS solves a separable quadratic to 1e-8", "[optimizers]") {
  for (std::uint64_t seed : {0u, 1u, 2u}) {
    sds_options o;
    o.initial_step = 0.5;
    o.stop.target_value = 1e-8;
    const auto r =
        minimize(sds(parameter_space::unbounded(uniform_x0(10, -3, 3, seed)), o), quadratic);
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK(r.value <= 1e-8);
    CHECK((r.x.array() - 1.0).abs().maxCoeff() < 1e-4);
  }
}

TEST_CASE("SDS solves the 10-D Rosenbrock function to 1e-6 from x = 0", "[optimizers]") {
  sds_options o;
  o.initial_step = 0.5;
  o.min_step = 1e-12;
  o.stop.target_value = 1e-6;
  o.stop.max_evaluations = 1'000'000;
  const auto r =
      minimize(sds(parameter_space::unbounded(Eigen::VectorXd::Zero(10)), o), tf::rosenbrock);
  CHECK(r.stopped == stop_criterion::target_value);
  CHECK((r.x.array() - 1.0).abs().maxCoeff() < 0.01);
}

TEST_CASE("SDS follows Sharon 2005 Fig. 2: greedy coordinate moves, alpha shrinks",
          "[optimizers]") {
  // f = |x0 - 0.3| + |x1 + 0.2| on the grid of alpha = 0.1: one probe per coordinate and sweep.
  sds_options o;
  o.initial_step = 0.1;
  o.shrink = 0.5;
  o.min_step = 0.01;
  sds s(parameter_space::unbounded(Eigen::Vector2d(0, 0)), o);
  auto f = [](const Eigen::VectorXd& x) { return std::abs(x[0] - 0.3) + std::abs(x[1] + 0.2); };
  // Batch 1: the initial point.
  REQUIRE(s.ask().size() == 1);
  s.tell(std::vector<double>{f(s.ask()[0])});
  // Batch 2: coordinate 0, theta +- alpha.
  auto xs = s.ask();
  REQUIRE(xs.size() == 2);
  CHECK(xs[0][0] == Approx(0.1));
  CHECK(xs[1][0] == Approx(-0.1));
  CHECK(xs[0][1] == 0.0);
  s.tell(std::vector<double>{f(xs[0]), f(xs[1])});
  CHECK(s.theta()[0] == Approx(0.1));  // accepted at once
  // Batch 3: coordinate 1 starts from the new theta (greedy).
  xs = s.ask();
  CHECK(xs[0][0] == Approx(0.1));
  CHECK(xs[0][1] == Approx(0.1));
  CHECK(xs[1][1] == Approx(-0.1));
  const auto r = minimize(s, f);
  CHECK(r.stopped == stop_criterion::min_step);
  CHECK(s.step() < 0.01);
  CHECK(r.value < 0.02);
}

TEST_CASE("SDS respects bounds, skips non-moves, ignores non-finite values", "[optimizers]") {
  sds_options o;
  o.initial_step = 0.25;
  o.min_step = 1e-9;
  sds s(parameter_space::box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(1, 0.5)),
        o);
  bool inside = true;
  int nan_count = 0;
  auto f = [&](const Eigen::VectorXd& x) {
    inside = inside && (x.array() >= 0).all() && (x.array() <= 1).all();
    if (x[1] > 0.6) {
      ++nan_count;
      return std::numeric_limits<double>::quiet_NaN();
    }
    return (x[0] - 1.2) * (x[0] - 1.2) + (x[1] - 0.4) * (x[1] - 0.4);
  };
  // First probe of coordinate 0: theta = 1 is on the upper bound, only the minus move remains.
  s.tell(std::vector<double>{f(s.ask()[0])});
  CHECK(s.ask().size() == 1);
  const auto r = minimize(s, f);
  CHECK(inside);
  CHECK(nan_count > 0);
  CHECK(r.non_finite == nan_count);
  CHECK(r.x[0] == 1.0);
  CHECK(r.x[1] == Approx(0.4).margin(1e-8));
}

TEST_CASE("SDS rejects bad options, naming the value", "[optimizers]") {
  const auto space = parameter_space::unbounded(Eigen::VectorXd::Zero(3));
  sds_options o;
  o.initial_step = 0;
  CHECK_THROWS_WITH(sds(space, o), Contains("initial_step") && Contains("got 0"));
  o = {};
  o.shrink = 1.5;
  CHECK_THROWS_WITH(sds(space, o), Contains("shrink") && Contains("1.5"));
  o = {};
  o.deltas = Eigen::VectorXd::Ones(2);
  CHECK_THROWS_WITH(sds(space, o), Contains("deltas") && Contains("expected 3, got 2"));
  o = {};
  o.x0 = Eigen::VectorXd::Ones(5);
  CHECK_THROWS_WITH(sds(space, o), Contains("x0") && Contains("expected 3, got 5"));
}

TEST_CASE("SDS: target_value is strict, a best value equal to it does not stop", "[optimizers]") {
  const auto space = parameter_space::unbounded(Eigen::VectorXd::Zero(3));
  const auto [at, below] = gaitsynth::testing::minimize_flat_at_and_below_target([&](double t) {
    sds_options o;
    o.stop.max_iterations = 5;
    o.stop.target_value = t;
    return sds(space, o);
  });
  CHECK(at.value == 1.0);
  CHECK(at.stopped == stop_criterion::max_iterations);
  CHECK(at.iterations == 5);
  CHECK(below.stopped == stop_criterion::target_value);
  CHECK(below.iterations == 1);  // the evaluation of the initial point
}
