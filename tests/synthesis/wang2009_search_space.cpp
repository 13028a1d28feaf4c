// The search space of Wang et al. 2009 (synthesis/wang2009_search_space.hpp): 184 bounded
// parameters holding Table 2's initialization for every body shape, and CMA-ES's default
// population for that dimension (Sec. 4.3: M = 19, N = 9).
#include <catch2/catch.hpp>

#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/synthesis/wang2009_search_space.hpp"

using namespace gaitsynth;

TEST_CASE("wang2009 search space: Table 2 inside the bounds for every shape, 19 samples",
          "[synthesis][wang2009]") {
  for (const wang2009_shape shape : wang2009_shapes) {
    const auto m = wang2009_humanoid(shape);
    const wang2009_controller c(m);
    const std::vector<double> x0 = wang2009_table2_parameters(m, c);
    const parameter_space space = wang2009_search_space(m, c, x0);  // throws if outside
    REQUIRE(space.size() == 184);
    const Eigen::VectorXd u = space.to_normalized(space.initial());
    INFO(wang2009_preset(shape).name);
    CHECK(u.minCoeff() >= 0.0);
    CHECK(u.maxCoeff() <= 1.0);
    CHECK(space.to_user(u).isApprox(space.initial(), 1e-12));
  }
  const auto m = wang2009_humanoid();
  const wang2009_controller c(m);
  std::vector<double> x0 = wang2009_table2_parameters(m, c);
  cmaes_options co;
  co.sigma0 = 0.0025;
  const cmaes opt(wang2009_search_space(m, c, x0), co);
  CHECK(opt.parameters().lambda == 19);
  CHECK(opt.parameters().mu == 9);
  x0[c.layout().kp(0, 0)] = -1.0;  // a negative gain is outside [0, 2000 w]
  CHECK_THROWS_WITH(wang2009_search_space(m, c, x0), Catch::Contains("s0.kp.swing_hip_x"));
}
