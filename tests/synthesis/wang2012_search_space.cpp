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

TEST_CASE(
    "wang2012 running start (Sec. 6.3): 3.05 m/s, GAS and SOL force gains doubled, elbows "
    "bent, inside the search space",
    "[synthesis][wang2012]") {
  const auto m = wang2012_humanoid();
  const std::vector<double> walk = wang2012_reflex_controller::initial_parameters(m);
  const std::vector<double> run = wang2012_reflex_controller::initial_running_parameters(m);
  const auto names = wang2012_reflex_controller::parameter_names();
  REQUIRE(run.size() == walk.size());
  auto at = [&](const std::vector<double>& x, const char* name) {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return x[i];
    FAIL("no parameter " << name);
    return 0.0;
  };
  CHECK(at(run, "start.root_vx") == 3.05);
  CHECK(at(walk, "start.root_vx") == 1.3);
  CHECK(at(run, "G_GAS") == 2.0 * at(walk, "G_GAS"));
  CHECK(at(run, "G_SOL") == 2.0 * at(walk, "G_SOL"));
  CHECK(at(run, "elbow_target") < at(walk, "elbow_target") - 1.0);  // flexion is negative
  int changed = 0;
  for (std::size_t i = 0; i < run.size(); ++i) changed += run[i] != walk[i];
  CHECK(changed == 4);  // nothing else
  // Inside the bounds, with room above the running start's speed; walking starts keep [0, 3].
  const parameter_space space = wang2012_search_space(run);
  for (const parameter_spec& p : space.parameters()) {
    INFO(p.name);
    CHECK(p.lower < p.initial);
    CHECK(p.initial < p.upper);
  }
  CHECK(wang2012_parameter_bounds("start.root_vx", 3.05) == std::pair(0.0, 6.1));
  CHECK(wang2012_parameter_bounds("start.root_vx", 1.3) == std::pair(0.0, 3.0));
}
