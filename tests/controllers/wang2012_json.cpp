// Saving and loading a Wang 2012 reflex controller (controllers/reflex/wang2012_json.hpp):
// bit-exact round trip, and errors that name the file, the field and the bad value.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/models/wang2012.hpp"

using namespace gaitsynth;

namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("gaitsynth_wang2012_json_" + name)).string();
}

/// The initial parameters, a few of them moved to values with no short decimal.
wang2012_saved_controller perturbed_controller() {
  wang2012_saved_controller s;
  s.target_speed = 1.0 / 3.0;
  s.cost = 0.1 + 0.2;
  s.parameters = wang2012_reflex_controller::initial_parameters(wang2012_humanoid());
  s.parameters[0] = 1.0 / 7.0;
  s.parameters[17] = std::nextafter(s.parameters[17], std::numeric_limits<double>::infinity());
  s.parameters[60] = -0.1 * std::acos(-1.0);
  s.parameters[90] = 1e-300 / 3.0;
  s.parameters.back() = 2.0 / 3.0 + 1e-9;
  s.info["command"] = "wang2012_walk --speed 0.333";
  return s;
}

/// A saved controller as JSON, to break one field of.
nlohmann::json saved_json() {
  const std::string path = temp_path("template.json");
  save_wang2012_controller(path, perturbed_controller());
  std::ifstream in(path);
  nlohmann::json j = nlohmann::json::parse(in);
  in.close();
  std::remove(path.c_str());
  return j;
}

/// Writes j as `name`, loads it and requires std::invalid_argument naming the file and each of
/// `expected`; removes the file.
void require_refused(const std::string& name, const nlohmann::json& j,
                     const std::vector<std::string>& expected) {
  const std::string path = temp_path(name);
  std::ofstream(path) << j.dump(1);
  INFO(name);
  std::string what;
  try {
    (void)load_wang2012_controller(path);
  } catch (const std::invalid_argument& e) {
    what = e.what();
  }
  std::remove(path.c_str());
  INFO("what(): " << what);
  REQUIRE_FALSE(what.empty());  // no std::invalid_argument
  CHECK_THAT(what, Catch::Contains(path));
  for (const std::string& s : expected) CHECK_THAT(what, Catch::Contains(s));
}

}  // namespace

TEST_CASE("a saved wang2012 controller reads back bit for bit", "[controllers][wang2012][io]") {
  const wang2012_saved_controller s = perturbed_controller();
  REQUIRE(s.parameters.size() == wang2012_reflex_controller::parameter_names().size());
  const std::string path = temp_path("round_trip.json");
  save_wang2012_controller(path, s);
  const wang2012_saved_controller r = load_wang2012_controller(path);
  std::remove(path.c_str());
  CHECK(r.target_speed == s.target_speed);
  CHECK(r.cost == s.cost);
  CHECK(r.parameters == s.parameters);  // exact, in the controller's order
  CHECK(r.info == s.info);
  // What is read back binds to the controller.
  const floating_model m = wang2012_humanoid();
  wang2012_reflex_controller c(m);
  CHECK_NOTHROW(c.bind(r.parameters));
  // Saving a wrong parameter count is refused.
  wang2012_saved_controller short_one = s;
  short_one.parameters.pop_back();
  CHECK_THROWS_AS(save_wang2012_controller(path, short_one), std::invalid_argument);
}

TEST_CASE("a wang2012 controller file without cost or info loads with their defaults",
          "[controllers][wang2012][io]") {
  nlohmann::json j = saved_json();
  j.erase("cost");
  j.erase("info");
  const std::string path = temp_path("minimal.json");
  std::ofstream(path) << j.dump();
  const wang2012_saved_controller r = load_wang2012_controller(path);
  std::remove(path.c_str());
  CHECK(r.cost == 0.0);
  CHECK(r.info.empty());
  CHECK(r.parameters == perturbed_controller().parameters);
}

TEST_CASE("a wang2012 controller file's defects are refused naming the file, field and value",
          "[controllers][wang2012][io]") {
  const std::vector<std::string> names = wang2012_reflex_controller::parameter_names();
  SECTION("target_speed missing") {
    nlohmann::json j = saved_json();
    j.erase("target_speed");
    require_refused("missing_target_speed.json", j, {"field 'target_speed'", "missing"});
  }
  SECTION("target_speed a string") {
    nlohmann::json j = saved_json();
    j["target_speed"] = "1.25";
    require_refused("target_speed_string.json", j,
                    {"field 'target_speed'", "\"1.25\"", "(string)"});
  }
  SECTION("parameters not an object") {
    nlohmann::json j = saved_json();
    nlohmann::json values = nlohmann::json::array();
    for (const auto& [name, value] : j["parameters"].items()) values.push_back(value);
    j["parameters"] = values;
    require_refused("parameters_array.json", j, {"field 'parameters'", "got array"});
  }
  SECTION("an unknown parameter name") {
    nlohmann::json j = saved_json();
    j["parameters"]["G_SOLL"] = 1.2;
    require_refused("unknown_parameter.json", j,
                    {"field 'parameters.G_SOLL'", "unknown parameter 'G_SOLL'",
                     "has " + std::to_string(names.size()) + " parameters"});
  }
  SECTION("a missing parameter") {
    nlohmann::json j = saved_json();
    j["parameters"].erase(names[40]);
    require_refused("missing_parameter.json", j,
                    {"field 'parameters." + names[40] + "'", "missing"});
  }
  SECTION("a parameter that is a string") {
    nlohmann::json j = saved_json();
    j["parameters"][names[5]] = "0.2";
    require_refused("parameter_string.json", j,
                    {"field 'parameters." + names[5] + "'", "\"0.2\"", "(string)"});
  }
  SECTION("a parameter that is null (how nlohmann::json writes a NaN)") {
    nlohmann::json j = saved_json();
    j["parameters"][names[7]] = std::numeric_limits<double>::quiet_NaN();
    require_refused("parameter_nan.json", j,
                    {"field 'parameters." + names[7] + "'", "null", "(null)"});
  }
  SECTION("not an object at the top level") {
    require_refused("top_level_array.json", nlohmann::json::array({1.25, 0.0}),
                    {"field '(top level)'", "got array"});
  }
}

TEST_CASE("an unreadable wang2012 controller file is refused naming it",
          "[controllers][wang2012][io]") {
  const std::string missing = temp_path("does_not_exist.json");
  std::remove(missing.c_str());
  CHECK_THROWS_AS(load_wang2012_controller(missing), std::invalid_argument);
  CHECK_THROWS_WITH(load_wang2012_controller(missing),
                    Catch::Contains("cannot open controller file '" + missing + "'"));
  // Text that is not JSON: the parser's message, with the file and the place.
  const std::string garbage = temp_path("garbage.json");
  std::ofstream(garbage) << "{\"target_speed\": 1.25, \"parameters\": {\"G_SOL\": 1.2";
  CHECK_THROWS_WITH(load_wang2012_controller(garbage), Catch::Contains(garbage) &&
                                                           Catch::Contains("malformed JSON") &&
                                                           Catch::Contains("line 1"));
  std::remove(garbage.c_str());
}
