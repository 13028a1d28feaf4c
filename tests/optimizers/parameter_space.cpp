#include <gaitsynth/optimizers/parameter_space.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gaitsynth;
using Catch::Matchers::Contains;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
}

TEST_CASE("parameter_space maps bounded parameters linearly onto [0, 1]", "[optimizers]") {
  parameter_space s({{"kp", 100.0, 500.0, 200.0}, {"angle", -0.5, 0.5, 0.0}});
  REQUIRE(s.size() == 2);
  CHECK(s[0].name == "kp");
  CHECK(s.normalized_lower() == Eigen::Vector2d(0, 0));
  CHECK(s.normalized_upper() == Eigen::Vector2d(1, 1));
  const Eigen::VectorXd u = s.initial_normalized();
  CHECK(u[0] == Approx(0.25));
  CHECK(u[1] == Approx(0.5));
  const Eigen::VectorXd x = s.to_user(Eigen::Vector2d(1.0, 0.0));
  CHECK(x[0] == 500.0);
  CHECK(x[1] == -0.5);
  CHECK(s.bounded());
}

TEST_CASE("parameter_space: logarithmic scaling maps equal ratios to equal steps", "[optimizers]") {
  parameter_space s({{"gain", 1.0, 1000.0, 10.0, 0.0, parameter_scaling::logarithmic}});
  CHECK(s.initial_normalized()[0] == Approx(1.0 / 3.0));
  CHECK(s.to_user(Eigen::VectorXd::Constant(1, 2.0 / 3.0))[0] == Approx(100.0));
  CHECK(s.to_user(Eigen::VectorXd::Constant(1, 1.0))[0] <= 1000.0);
  CHECK(s.to_user(Eigen::VectorXd::Constant(1, 0.0))[0] >= 1.0);
}

TEST_CASE("parameter_space: unbounded and half-bounded parameters use a scale", "[optimizers]") {
  parameter_space s({{"free", -inf, inf, 3.0, 2.0}, {"positive", 0.0, inf, 4.0}});
  const Eigen::VectorXd u = s.initial_normalized();
  CHECK(u[0] == Approx(1.5));  // x / scale
  CHECK(u[1] == Approx(4.0));  // (x - lower) / 1
  CHECK(s.normalized_lower()[1] == 0.0);
  CHECK(std::isinf(s.normalized_upper()[1]));
  const Eigen::VectorXd back = s.to_user(u);
  CHECK(back[0] == Approx(3.0));
  CHECK(back[1] == Approx(4.0));
  CHECK(s.project_normalized(Eigen::Vector2d(-7.0, -1.0)) == Eigen::Vector2d(-7.0, 0.0));

  const auto unb = parameter_space::unbounded(Eigen::Vector3d(1, 2, 3));
  CHECK_FALSE(unb.bounded());
  CHECK(unb.to_normalized(Eigen::Vector3d(4, 5, 6)) == Eigen::Vector3d(4, 5, 6));
  CHECK(unb[2].name == "x2");
}

TEST_CASE("parameter_space round trip user <-> normalized", "[optimizers]") {
  parameter_space s({{"a", -2.0, 3.0, 0.0},
                     {"b", 0.01, 100.0, 1.0, 0.0, parameter_scaling::logarithmic},
                     {"c", -inf, inf, 0.0, 0.1}});
  const Eigen::Vector3d x(1.7, 42.0, -0.3);
  const Eigen::VectorXd back = s.to_user(s.to_normalized(x));
  for (int i = 0; i < 3; ++i) CHECK(back[i] == Approx(x[i]).epsilon(1e-14));
}

TEST_CASE("parameter_space rejects bad parameters, naming the value", "[optimizers]") {
  CHECK_THROWS_WITH(parameter_space({{"kp", 1.0, 1.0, 1.0}}),
                    Contains("'kp'") && Contains("lower bound (1)") && Contains("upper bound (1)"));
  CHECK_THROWS_WITH(parameter_space({{"kd", 2.0, 1.0, 1.5}}), Contains("'kd'") && Contains("(2)"));
  CHECK_THROWS_AS(parameter_space({{"a", 0.0, 1.0, 2.0}}), std::invalid_argument);
  CHECK_THROWS_WITH(parameter_space({{"a", 0.0, 1.0, 2.0}}), Contains("initial value 2"));
  CHECK_THROWS_WITH(parameter_space({{"a", 0, 1, 0.5}, {"a", 0, 1, 0.5}}), Contains("duplicate"));
  CHECK_THROWS_WITH(parameter_space({{"g", 0.0, 10.0, 1.0, 0.0, parameter_scaling::logarithmic}}),
                    Contains("logarithmic"));
  CHECK_THROWS_WITH(parameter_space({{"s", -inf, inf, 0.0, -1.0}}), Contains("scale"));
  CHECK_THROWS_WITH(parameter_space({{"n", std::nan(""), 1.0, 0.0}}), Contains("NaN"));
  CHECK_THROWS_AS(parameter_space({{"", 0.0, 1.0, 0.5}}), std::invalid_argument);
  CHECK_THROWS_WITH(
      parameter_space::box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, -1), Eigen::Vector2d(0, 0)),
      Contains("'x1'") && Contains("lower bound (0)") && Contains("upper bound (-1)"));
}

TEST_CASE("parameter_space::with_initial checks size and bounds", "[optimizers]") {
  const auto s =
      parameter_space::box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(0.5, 0.5));
  CHECK(s.with_initial(Eigen::Vector2d(0.1, 0.9)).initial() == Eigen::Vector2d(0.1, 0.9));
  CHECK_THROWS_WITH(s.with_initial(Eigen::Vector3d(0, 0, 0)),
                    Contains("x0") && Contains("expected 2, got 3"));
  CHECK_THROWS_WITH(s.with_initial(Eigen::Vector2d(0.1, 1.5)), Contains("1.5"));
}

TEST_CASE("parameter_space::clamp_user clips a user point into the bounds", "[optimizers]") {
  // A bounded, a log-scaled and a half-bounded parameter: each clipped in user units.
  parameter_space s({{"box", -1.0, 2.0, 0.0},
                     {"gain", 10.0, 1000.0, 100.0, 0.0, parameter_scaling::logarithmic},
                     {"positive", 0.0, inf, 4.0}});
  CHECK(s.clamp_user(Eigen::Vector3d(5.0, 1.0, -3.0)) == Eigen::Vector3d(2.0, 10.0, 0.0));
  CHECK(s.clamp_user(Eigen::Vector3d(-1.5, 2e3, 1e9)) == Eigen::Vector3d(-1.0, 1000.0, 1e9));
  const Eigen::Vector3d inside(0.25, 55.0, 7.0);
  CHECK(s.clamp_user(inside) == inside);  // unchanged, bit for bit
  CHECK_THROWS_WITH(s.clamp_user(Eigen::Vector2d(0.0, 0.0)),
                    Contains("user point") && Contains("expected 3, got 2"));
}
