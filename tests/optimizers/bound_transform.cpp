// The boundary transformation of bound_transform.hpp (pycma's linear-quadratic one) and
// bound_handling::transform in cmaes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
using Catch::Detail::Approx;

namespace tf = gaitsynth::test_functions;

namespace {
constexpr double inf_v = std::numeric_limits<double>::infinity();

struct box {
  double lb, ub;
};
// [0, 1] (cmaes' normalized box), a wide asymmetric one, negative and narrow ones (the narrow
// ones have no identity part: al = au = (ub - lb) / 2), and one whose margins differ 1000-fold.
const std::vector<box> two_sided = {{0.0, 1.0},  {-3.0, 5.0}, {-10.0, -9.5}, {-100.0, 0.5},
                                    {1e-3, 1e3}, {2.0, 2.01}, {-7.0, -2.0}};

double T(double x, box b) {
  return bound_transform(x, b.lb, b.ub);
}
}  // namespace

TEST_CASE("bound_transform: margins and hand-computed values on [0, 1]", "[optimizers]") {
  // al = min(1/2, (1 + 0)/20) = 0.05, au = min(1/2, (1 + 1)/20) = 0.1.
  const auto m = bound_transform_margin(0.0, 1.0);
  CHECK(m.lower == Approx(0.05));
  CHECK(m.upper == Approx(0.1));
  const box b{0.0, 1.0};
  // Lower parabola 0 + (x + 0.05)^2 / 0.2 on [-0.05, 0.05).
  CHECK(T(0.0, b) == Approx(0.0125));               // 0.05^2 / 0.2
  CHECK(T(0.02, b) == Approx(0.0245));              // 0.07^2 / 0.2
  CHECK(T(-0.05, b) == Approx(0.0).margin(1e-15));  // the mirror point maps onto the bound
  CHECK(T(0.05, b) == Approx(0.05));                // 0.1^2 / 0.2: meets the identity
  // Identity on [0.05, 0.9].
  for (double x : {0.05, 0.1, 0.3, 0.5, 0.77, 0.89}) CHECK(T(x, b) == x);
  CHECK(T(0.9, b) == Approx(0.9));  // (computed on the parabola: 1 - 0.2^2 / 0.4)
  // Upper parabola 1 - (x - 1.1)^2 / 0.4 on [0.9, 1.1].
  CHECK(T(0.95, b) == Approx(0.94375));  // 1 - 0.15^2 / 0.4
  CHECK(T(1.0, b) == Approx(0.975));     // 1 - 0.1^2 / 0.4
  CHECK(T(1.1, b) == Approx(1.0));
  // Mirrors: about 1.1 and about -0.05.
  CHECK(T(1.2, b) == Approx(0.975));    // 2.2 - 1.2 = 1.0
  CHECK(T(-0.1, b) == Approx(0.0125));  // -0.1 - 2 (-0.1 + 0.05) = 0.0
  // Shifts by the period r = 2 (1 + 0.15) = 2.3 from s = -0.05 - 0.05 - 0.5 = -0.6:
  CHECK(T(-1.0, b) == Approx(0.9));  // -1 + 2.3 = 1.3, mirrored about 1.1: 0.9
  CHECK(T(3.0, b) == Approx(0.7));   // 3 - 2.3 = 0.7
  CHECK(T(3.0 + 10 * 2.3, b) == Approx(0.7));
}

TEST_CASE("bound_transform reproduces pycma's documented examples", "[optimizers]") {
  // BoxConstraintsLinQuadTransformation([[1, 2], [1, 11], [1, 11]]), the last box recycled:
  // [1.52, -2.2, -0.2, 2, 4, 10.4] -> [1.52, 4.0, 2.0, 2.0, 4.0, 10.4]; upper margins 0.15, 0.6.
  CHECK(bound_transform_margin(1, 2).upper == Approx(0.15));
  CHECK(bound_transform_margin(1, 11).upper == Approx(0.6));
  CHECK(bound_transform(1.52, 1, 2) == Approx(1.52));
  const std::vector<std::pair<double, double>> on_1_11 = {
      {-2.2, 4.0}, {-0.2, 2.0}, {2.0, 2.0}, {4.0, 4.0}, {10.4, 10.4}};
  for (auto [x, y] : on_1_11) CHECK(bound_transform(x, 1, 11) == Approx(y));
  // BoundTransform([None, 1]): [0, 1, 2] -> [0, 0.975, 0.2]; BoundTransform([0, None]):
  // [-1, 0, 1, 2] -> [0.9, 0.0125, 1, 2].
  CHECK(bound_transform(0.0, -inf_v, 1.0) == 0.0);
  CHECK(bound_transform(1.0, -inf_v, 1.0) == Approx(0.975));
  CHECK(bound_transform(2.0, -inf_v, 1.0) == Approx(0.2));
  CHECK(bound_transform(-1.0, 0.0, inf_v) == Approx(0.9));
  CHECK(bound_transform(0.0, 0.0, inf_v) == Approx(0.0125));
  CHECK(bound_transform(1.0, 0.0, inf_v) == 1.0);
  CHECK(bound_transform(2.0, 0.0, inf_v) == 2.0);
}

TEST_CASE("bound_transform is the identity on [lb + al, ub - au]", "[optimizers]") {
  for (const auto b : two_sided) {
    const auto [al, au] = bound_transform_margin(b.lb, b.ub);
    for (int i = 0; i <= 1000; ++i) {
      const double x = b.lb + al + (b.ub - au - b.lb - al) * i / 1000.0;
      CHECK(T(x, b) == Approx(x).epsilon(1e-15).margin(1e-15));
    }
  }
}

TEST_CASE("bound_transform is C^1: continuous with matching slopes at the four junctions",
          "[optimizers]") {
  for (const auto b : two_sided) {
    const auto [al, au] = bound_transform_margin(b.lb, b.ub);
    // Slope 0 at the mirror points (where T touches a bound), 1 where a parabola meets the
    // identity (also in the narrow boxes, where the two parabolas meet each other).
    const std::vector<std::pair<double, double>> junctions = {
        {b.lb - al, 0.0}, {b.lb + al, 1.0}, {b.ub - au, 1.0}, {b.ub + au, 0.0}};
    for (auto [j, slope] : junctions) {
      INFO("box [" << b.lb << ", " << b.ub << "], junction " << j);
      const double h = 1e-6 * std::min(al, au);
      const double left = (T(j, b) - T(j - h, b)) / h;
      const double right = (T(j + h, b) - T(j, b)) / h;
      // One-sided difference quotients of a parabola with T'' = 1 / (2 a) are off by h / (4 a).
      CHECK(left == Approx(slope).margin(1e-5));
      CHECK(right == Approx(slope).margin(1e-5));
      CHECK(std::abs(T(j + h, b) - T(j - h, b)) < 3 * h);  // continuous
    }
  }
}

TEST_CASE("bound_transform maps everything into the box", "[optimizers]") {
  std::vector<box> boxes = two_sided;
  boxes.push_back({0.0, inf_v});
  boxes.push_back({-inf_v, 1.0});
  boxes.push_back({-inf_v, -2.0});
  boxes.push_back({3.5, inf_v});
  for (const auto b : boxes) {
    INFO("box [" << b.lb << ", " << b.ub << "]");
    bool inside = true;
    for (int i = 0; i <= 200000; ++i) {
      const double y = T(-50.0 + 100.0 * i / 200000.0, b);
      inside = inside && y >= b.lb && y <= b.ub;
    }
    // Far away, where x - r floor((x - s) / r) would have no digits left.
    for (double x : {1e6, -1e6, 1e17, -1e17, 1e300, -1e300, 3e-310}) {
      const double y = T(x, b);
      inside = inside && y >= b.lb && y <= b.ub;
    }
    CHECK(inside);
  }
  CHECK(std::isnan(bound_transform(std::numeric_limits<double>::quiet_NaN(), 0, 1)));
  CHECK(std::isnan(bound_transform(inf_v, 0, 1)));
  CHECK(bound_transform(1e300, -inf_v, inf_v) == 1e300);  // no bounds: the identity
}

TEST_CASE("bound_transform is mirror symmetric about lb - al and ub + au, and periodic",
          "[optimizers]") {
  for (const auto b : two_sided) {
    INFO("box [" << b.lb << ", " << b.ub << "]");
    const auto [al, au] = bound_transform_margin(b.lb, b.ub);
    const double r = 2.0 * (b.ub - b.lb + al + au);
    const double tol = 1e-9 * (1.0 + std::abs(b.lb) + std::abs(b.ub));
    for (int i = 0; i <= 400; ++i) {
      const double d = 1.5 * r * i / 400.0;  // beyond one period, through the shift
      CHECK(std::abs(T(b.ub + au + d, b) - T(b.ub + au - d, b)) < tol);
      CHECK(std::abs(T(b.lb - al + d, b) - T(b.lb - al - d, b)) < tol);
    }
    for (int i = 0; i <= 400; ++i) {
      const double x = b.lb - r + 3.0 * r * i / 400.0;
      CHECK(std::abs(T(x + r, b) - T(x, b)) < tol);
      CHECK(std::abs(T(x - 3 * r, b) - T(x, b)) < tol);
    }
    // A million periods away (the shift must keep the remainder's digits).
    const double x = b.lb + 0.3 * (b.ub - b.lb);
    CHECK(std::abs(T(x + 1e6 * r, b) - T(x, b)) < 1e-6 * r);
    CHECK(std::abs(T(x - 1e6 * r, b) - T(x, b)) < 1e-6 * r);
  }
}

TEST_CASE("bound_transform one-sided bounds: identity on the unbounded side", "[optimizers]") {
  // [0, inf): al = 0.05; identity from 0.05 on, parabola below, mirrored about -0.05.
  for (double x : {0.05, 0.5, 1.0, 7.0, 1e6}) CHECK(bound_transform(x, 0.0, inf_v) == x);
  CHECK(bound_transform(0.0, 0.0, inf_v) == Approx(0.0125));
  CHECK(bound_transform(-0.05 - 3.0, 0.0, inf_v) == Approx(-0.05 + 3.0));
  // (-inf, -2]: au = min(inf, 3 / 20) = 0.15; identity below -2.15, mirrored about -1.85.
  for (double x : {-2.16, -3.0, -1e6}) CHECK(bound_transform(x, -inf_v, -2.0) == x);
  CHECK(bound_transform(-2.0, -inf_v, -2.0) == Approx(-2.0 - 0.15 * 0.15 / 0.6));
  CHECK(bound_transform(-1.85 + 4.0, -inf_v, -2.0) == Approx(-1.85 - 4.0));
  CHECK(bound_transform_margin(-inf_v, -2.0).upper == Approx(0.15));
}

TEST_CASE("bound_transform_inverse inverts T on the invertible domain", "[optimizers]") {
  for (const auto b : two_sided) {
    const auto [al, au] = bound_transform_margin(b.lb, b.ub);
    for (int i = 0; i <= 1000; ++i) {
      const double y = b.lb + (b.ub - b.lb) * i / 1000.0;
      CHECK(T(bound_transform_inverse(y, b.lb, b.ub), b) ==
            Approx(y).margin(1e-12 * (1 + std::abs(y))));
      const double x = b.lb - al + (b.ub + au - b.lb + al) * i / 1000.0;
      CHECK(bound_transform_inverse(T(x, b), b.lb, b.ub) ==
            Approx(x).margin(1e-6 * (b.ub - b.lb)));  // sqrt near the mirror points
    }
  }
  CHECK(bound_transform_inverse(0.0, 0.0, 1.0) == Approx(-0.05));
  CHECK(bound_transform_inverse(1.0, 0.0, 1.0) == Approx(1.1));
  CHECK(bound_transform_inverse(0.5, 0.0, inf_v) == 0.5);
}

TEST_CASE("bound_transform on vectors is the scalar map per coordinate", "[optimizers]") {
  const Eigen::VectorXd lo = (Eigen::VectorXd(4) << 0, -3, -inf_v, -inf_v).finished();
  const Eigen::VectorXd hi = (Eigen::VectorXd(4) << 1, 5, 1, inf_v).finished();
  const Eigen::VectorXd x = (Eigen::VectorXd(4) << 0.0, -4, 2, -9).finished();
  const Eigen::VectorXd y = bound_transform(x, lo, hi);
  for (Eigen::Index i = 0; i < 4; ++i) CHECK(y[i] == bound_transform(x[i], lo[i], hi[i]));
  CHECK(y[0] == Approx(0.0125));
  CHECK(y[3] == -9);
  const Eigen::VectorXd back = bound_transform_inverse(y, lo, hi);
  for (Eigen::Index i = 0; i < 4; ++i)
    CHECK(back[i] == bound_transform_inverse(y[i], lo[i], hi[i]));
  CHECK_THROWS_AS(bound_transform(x, lo.head(3), hi), std::invalid_argument);
  CHECK_THROWS_AS(bound_transform_inverse(x, lo, hi.head(2)), std::invalid_argument);
}

namespace {
cmaes_options transform_options(std::uint64_t seed, double target) {
  cmaes_options o;
  o.sigma0 = 0.3;  // Wu 2010: mean 0.5, sigma 0.3 in [0, 1]
  o.seed = seed;
  o.bounds = bound_handling::transform;
  o.stop.target_value = target;
  return o;
}
parameter_space unit_box(int n, double initial = 0.5) {
  return parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                              Eigen::VectorXd::Constant(n, initial));
}
}  // namespace

TEST_CASE("cmaes with bound_handling::transform: optimum beyond the bound", "[optimizers]") {
  // Unconstrained minimum at -0.5: the constrained one is 0 everywhere, f = 0 there.
  const int n = 10;
  for (std::uint64_t seed : {3u, 4u}) {
    cmaes es(unit_box(n), transform_options(seed, 1e-10));
    bool all_inside = true;
    const auto r = minimize(es, [&](const Eigen::VectorXd& x) {
      all_inside = all_inside && (x.array() >= 0).all() && (x.array() <= 1).all();
      return (x.array() + 0.5).square().sum() - 0.25 * static_cast<double>(x.size());
    });
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK(r.x.maxCoeff() < 1e-9);  // f - f* ~ sum x_i (slope 1 at 0)
    CHECK(all_inside);
    CHECK(es.resample_count() == 0);
    CHECK(es.repair_count() == 0);
    // The strategy's mean sits near the mirror point -al = -0.05 (outside the box); the mean in
    // user coordinates is its image, on the bound.
    CHECK((es.mean().array() + 0.05).abs().maxCoeff() < 1e-3);
    CHECK(es.mean_user().maxCoeff() < 1e-5);
    CHECK(es.mean_user().minCoeff() >= 0.0);
  }
}

TEST_CASE("cmaes with bound_handling::transform: optimum inside the box", "[optimizers]") {
  const int n = 40;
  for (double center : {0.9, 0.3}) {
    cmaes es(unit_box(n), transform_options(7, 1e-8));
    bool all_inside = true;
    const auto r = minimize(es, [&](const Eigen::VectorXd& x) {
      all_inside = all_inside && (x.array() >= 0).all() && (x.array() <= 1).all();
      return tf::shifted_sphere{center}(x);
    });
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK((r.x.array() - center).abs().maxCoeff() < 1e-3);
    CHECK((es.mean_user().array() - center).abs().maxCoeff() < 1e-3);
    CHECK(all_inside);
    CHECK(es.resample_count() == 0);
    CHECK(es.repair_count() == 0);
  }
}

TEST_CASE("cmaes with bound_handling::transform: half-bounded, start on a bound, unbounded",
          "[optimizers]") {
  SECTION("lower bound 1 on a sphere centred at 0 (user units, one-sided)") {
    parameter_space s;
    for (int i = 0; i < 5; ++i)
      s.add({"p" + std::to_string(i), 1.0, inf_v, 3.0, 0.0, parameter_scaling::linear});
    cmaes_options o = transform_options(1, 5.0 + 1e-9);
    o.sigma0 = 1.0;
    cmaes es(s, o);
    bool all_inside = true;
    const auto r = minimize(es, [&](const Eigen::VectorXd& x) {
      all_inside = all_inside && (x.array() >= 1).all();
      return x.squaredNorm();
    });
    CHECK(r.stopped == stop_criterion::target_value);
    CHECK((r.x.array() - 1.0).abs().maxCoeff() < 1e-6);
    CHECK(all_inside);
    CHECK(es.repair_count() == 0);
  }
  SECTION("the mean starts at T^-1(x0), so the mean the user sees is x0") {
    Eigen::VectorXd x0(3);
    x0 << 0.0, 1.0, 0.5;  // on both bounds and in the middle
    cmaes es(parameter_space::box(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Ones(3), x0),
             transform_options(0, -inf_v));
    CHECK(es.mean()[0] == Approx(-0.05));
    CHECK(es.mean()[1] == Approx(1.1));
    CHECK(es.mean()[2] == 0.5);
    CHECK((es.mean_user() - x0).cwiseAbs().maxCoeff() < 1e-12);
  }
  SECTION("without bounds, transform is the default bit for bit") {
    auto run = [](bound_handling bh) {
      cmaes_options o;
      o.seed = 5;
      o.bounds = bh;
      o.stop.max_iterations = 40;
      cmaes es(parameter_space::unbounded(Eigen::VectorXd::Constant(6, 1.0)), o);
      minimize(es, tf::ellipsoid);
      return es.mean();
    };
    CHECK(identical(run(bound_handling::transform), run(bound_handling::resample)));
  }
}

TEST_CASE("cmaes with bound_handling::transform: checkpoint round trip", "[optimizers]") {
  const auto dir = scratch_dir("bound_transform");
  auto make = [] { return cmaes(unit_box(8, 0.0), transform_options(11, -inf_v)); };
  auto a = make();
  minimize(a, tf::shifted_sphere{0.98}, run_options{},
           [](const optimizer_status& s) { return s.iteration < 25; });
  save_checkpoint(a, dir / "a.ckpt");
  auto b = make();
  load_checkpoint(b, dir / "a.ckpt");
  CHECK(identical(a.mean_user(), b.mean_user()));
  const auto xa = a.ask();
  const auto xb = b.ask();
  for (std::size_t k = 0; k < xa.size(); ++k) CHECK(identical(xa[k], xb[k]));
}
