// The search space of the Wang et al. 2012 controller (synthesis/wang2012_search_space.hpp): every
// parameter named, its initial value inside its bounds, and a start outside them refused by name.
#include <catch2/catch.hpp>

#include <vector>

#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/synthesis/wang2012_search_space.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

TEST_CASE("wang2012 search space: 122 bounded parameters around the initial controller",
          "[synthesis][wang2012]") {
  const auto m = wang2012_humanoid();
  const std::vector<double> x0 = wang2012_reflex_controller::initial_parameters(m);
  const parameter_space space = wang2012_search_space(x0);
  REQUIRE(space.parameters().size() == 122);
  const auto names = wang2012_reflex_controller::parameter_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const parameter_spec& p = space.parameters()[i];
    INFO(p.name);
    CHECK(p.name == names[i]);
    CHECK(p.lower < p.initial);
    CHECK(p.initial < p.upper);
  }
  // A few bounds by kind (the file comment).
  CHECK(wang2012_parameter_bounds("p_SOL", 0.01) == std::pair(0.0, 1.0));
  CHECK(wang2012_parameter_bounds("G_SOL", 1.2) == std::pair(0.0, 5.0));
  CHECK(wang2012_parameter_bounds("kp_neck", 100.0) == std::pair(0.0, 3000.0));
  CHECK(wang2012_parameter_bounds("start.root_z", 1.0) == std::pair(0.9, 1.1));
  CHECK(wang2012_parameter_bounds("start.v.lknee", 0.0) == std::pair(-10.0, 10.0));
  std::vector<double> bad = x0;
  bad[5] = 2.0;  // p_HAM above 1
  CHECK_THROWS_WITH(wang2012_search_space(bad), Contains("p_HAM"));
  bad.pop_back();
  CHECK_THROWS_WITH(wang2012_search_space(bad), Contains("121"));
}
