// Carrying a Wang 2009 controller to another body shape (controllers/fsm/
// wang2009_shape_transfer.hpp): Table 2 for stocky carries to Table 2 for every other shape (the
// paper's own rule), and a round trip gives the vector back.
#include <catch2/catch.hpp>

#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/fsm/wang2009_shape_transfer.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

TEST_CASE("wang2009_transfer_parameters carries Table 2 from stocky to every shape",
          "[controllers][wang2009]") {
  const auto stocky = wang2009_humanoid(wang2009_shape::stocky);
  const wang2009_controller cs(stocky);
  const std::vector<double> p = wang2009_table2_parameters(stocky, cs);
  for (const char* name : {"short", "tall", "long_arm", "thin", "overweight"}) {
    INFO(name);
    const auto m = wang2009_humanoid(wang2009_preset(name));
    const wang2009_controller c(m);
    const std::vector<double> expected = wang2009_table2_parameters(m, c);
    const std::vector<double> carried = wang2009_transfer_parameters(stocky, cs, p, m, c);
    REQUIRE(carried.size() == expected.size());
    for (std::size_t i = 0; i < carried.size(); ++i) {
      INFO(c.parameter_names()[i]);
      CHECK(carried[i] == Approx(expected[i]).epsilon(1e-12).margin(1e-12));
    }
    const std::vector<double> back = wang2009_transfer_parameters(m, c, carried, stocky, cs);
    for (std::size_t i = 0; i < back.size(); ++i)
      CHECK(back[i] == Approx(p[i]).epsilon(1e-12).margin(1e-12));
  }
  // To its own shape a vector is carried bit for bit (a replay must retrace the optimized walk).
  CHECK(wang2009_transfer_parameters(stocky, cs, p, stocky, cs) == p);
  const std::string saved = std::string(GAITSYNTH_SOURCE_DIR) +
                            "/data/wang2009/walkers/overweight_robust.controller.json";
  const auto ow = wang2009_humanoid(wang2009_shape::overweight);
  const wang2009_controller co(ow);
  const std::vector<double> q = load_wang2009_controller(saved, co).parameters;
  CHECK(wang2009_transfer_parameters(ow, co, q, ow, co) == q);
  const std::vector<double> short_vector(p.begin(), p.end() - 1);
  CHECK_THROWS_AS(wang2009_transfer_parameters(stocky, cs, short_vector, stocky, cs),
                  std::invalid_argument);
}
