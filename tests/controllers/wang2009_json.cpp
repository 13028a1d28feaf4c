// Saving and loading a Wang 2009 controller (controllers/fsm/wang2009_json.hpp): bit-exact round
// trip, and errors that name the file and the field.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

TEST_CASE("a saved wang2009 controller reads back bit for bit", "[controllers][wang2009][io]") {
  const auto m = wang2009_humanoid(wang2009_shape::tall);
  const wang2009_controller c(m);
  wang2009_saved_controller s;
  s.shape = "tall";
  s.target_speed = 1.0 / 3.0;
  s.cost = 0.1 + 0.2;
  s.parameters = wang2009_table2_parameters(m, c);
  s.parameters[7] = 1.0 / 7.0;
  s.info["command"] = "wang2009_walk --shape tall";
  const auto path =
      (std::filesystem::temp_directory_path() / "gaitsynth_wang2009_json.json").string();
  save_wang2009_controller(path, c, s);
  CHECK(wang2009_saved_shape(path) == "tall");
  const wang2009_saved_controller r = load_wang2009_controller(path, c);
  CHECK(r.shape == "tall");
  REQUIRE(r.target_speed);
  CHECK(*r.target_speed == s.target_speed);
  CHECK(!r.target_step_length);
  CHECK(r.cost == s.cost);
  CHECK(r.parameters == s.parameters);  // exact
  CHECK(r.info["command"] == "wang2009_walk --shape tall");

  // A missing parameter is named with the file.
  {
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    j["parameters"].erase(c.parameter_names()[3]);
    std::ofstream(path) << j.dump();
  }
  CHECK_THROWS_WITH(
      load_wang2009_controller(path, c),
      Catch::Contains(path) && Catch::Contains("parameters." + c.parameter_names()[3]));
  std::remove(path.c_str());
  CHECK_THROWS_WITH(load_wang2009_controller(path, c), Catch::Contains("cannot open"));
  s.parameters.pop_back();
  CHECK_THROWS_AS(save_wang2009_controller(path, c, s), std::invalid_argument);
}
