// Saved planned_walk controllers (controllers/end_effector/planned_walk_json.hpp): a round trip
// is exact (also for the side steps' asymmetric planner), values are matched by name (h_max
// dropped or taken from the file's entry), the options the file records are read back, a saved
// run of data/wu2010/ binds, and every malformed file is refused naming the file, the field and
// the value.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_names.hpp"
#include "gaitsynth/models/wu2010.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

fs::path scratch_file(const std::string& name) {
  const fs::path dir = fs::path(GAITSYNTH_BINARY_DIR) / "planned_walk_json";
  fs::create_directories(dir);
  return dir / name;
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = scratch_file(name);
  std::ofstream(p) << text;
  return p;
}

std::string message_of(const auto& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace

TEST_CASE("planned_walk JSON: a round trip is exact and values are matched by name",
          "[controllers][end_effector][json]") {
  const floating_model m = wu2010_biped();
  planned_walk_options o;
  o.helper_force = true;
  const planned_walk<> c(m, flat_terrain{}, o);
  const std::vector<std::string> names = c.parameter_names();
  std::vector<double> x = c.default_parameters();
  x[0] = 0.1 + 1e-16 * 3;  // digits a short decimal would lose
  x.back() = 12.345678901234567;
  nlohmann::ordered_json info;
  info["cost"] = 35.25;
  info["controller_rate"] = 600.0;
  info["stance_target"] = "touchdown";
  info["helper_force"] = true;
  info["pin_by"] = "link";
  info["half_cycle_timing"] = "touchdown";
  const fs::path p = scratch_file("round_trip.json");
  save_planned_walk(p, names, x, info);
  const planned_walk_saved s = load_planned_walk(p);
  CHECK(s.names == names);
  CHECK(s.values == x);  // bit for bit
  CHECK(s.info["cost"] == 35.25);
  CHECK(planned_walk_values(s, names, p) == x);
  // Without the helper: its h_max is dropped.
  const planned_walk<> plain(m);
  const std::vector<double> y = planned_walk_values(s, plain.parameter_names(), p);
  REQUIRE(y.size() == x.size() - 1);
  CHECK(std::equal(y.begin(), y.end(), x.begin()));
  // The options it ran with.
  const planned_walk_options r = saved_planned_walk_options(s, p);
  CHECK(r.period == Approx(1.0 / 600.0));
  CHECK(r.stance_target == stance_foot_target::touchdown);
  CHECK(r.helper_force);
  CHECK(r.lower.pin_by == pin_contact::link);
  CHECK(r.timing == half_cycle_end::touchdown);
  // A file from before "pin_by" ("half_cycle_timing") keeps the default contact test (timing).
  CHECK(saved_planned_walk_options(planned_walk_saved{}, p).lower.pin_by ==
        pin_contact::frame_geometry);
  CHECK(saved_planned_walk_options(planned_walk_saved{}, p).timing == half_cycle_end::fixed);
  // A file of the plain controller gives a helper controller's h_max from its "h_max" entry.
  nlohmann::ordered_json info2;
  info2["h_max"] = 7.5;
  const fs::path q = scratch_file("plain.json");
  save_planned_walk(q, plain.parameter_names(), y, info2);
  const std::vector<double> z = planned_walk_values(load_planned_walk(q), names, q);
  CHECK(z.back() == 7.5);
}

TEST_CASE("planned_walk JSON: an asymmetric controller (the side steps) round-trips",
          "[controllers][end_effector][json]") {
  const floating_model m = wu2010_biped();
  planned_walk_options o;
  o.symmetry = planned_walk_symmetry::asymmetric;
  const planned_walk<> c(m, flat_terrain{}, o);
  const std::vector<std::string> names = c.parameter_names();
  REQUIRE(names.size() == 74);
  std::vector<double> x = c.default_parameters();
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 1e-3 * static_cast<double>(i);
  const fs::path p = scratch_file("asymmetric.json");
  save_planned_walk(p, names, x, {}, planned_walk_symmetry::asymmetric);
  const planned_walk_saved s = load_planned_walk(p);
  CHECK(s.info["symmetry"] == "asymmetric");
  const planned_walk_options r = saved_planned_walk_options(s, p);
  CHECK(r.symmetry == planned_walk_symmetry::asymmetric);
  const planned_walk<> back(m, flat_terrain{}, r);
  CHECK(planned_walk_values(s, back.parameter_names(), p) == x);
  // A mirrored_planner controller lacks Omega_1: the asymmetric one refuses it, naming the first
  // missing parameter.
  const planned_walk<> symmetric(m);
  const fs::path q = scratch_file("symmetric.json");
  save_planned_walk(q, symmetric.parameter_names(), symmetric.default_parameters(), {});
  CHECK(saved_planned_walk_options(load_planned_walk(q), q).symmetry ==
        planned_walk_symmetry::mirrored_planner);
  CHECK_THROWS_WITH(
      planned_walk_values(load_planned_walk(q), names, q),
      Catch::Contains("symmetric.json: parameter 'omega1.") && Catch::Contains("is missing"));
}

TEST_CASE("planned_walk JSON: a saved run of data/wu2010 loads and binds",
          "[controllers][end_effector][json]") {
  const fs::path p =
      fs::path(GAITSYNTH_SOURCE_DIR) / "data/wu2010/runs/f3/wu2010_walk.controller.json";
  const planned_walk_saved s = load_planned_walk(p);
  const planned_walk_options o = saved_planned_walk_options(s, p);
  CHECK(o.stance_target == stance_foot_target::touchdown);
  CHECK(o.period == Approx(1.0 / 600.0));
  planned_walk_options with_helper = o;
  with_helper.helper_force = true;
  const floating_model m = wu2010_biped();
  planned_walk<> c(m, flat_terrain{}, with_helper);
  const std::vector<double> x = planned_walk_values(s, c.parameter_names(), p);
  CHECK(x.size() == 50);
  CHECK_NOTHROW(c.bind(x));
  CHECK(c.h_max() == s.info["h_max"].get<double>());
}

TEST_CASE("planned_walk JSON: malformed files are refused, named",
          "[controllers][end_effector][json]") {
  const floating_model m = wu2010_biped();
  const planned_walk<> c(m);
  const std::vector<std::string> names = c.parameter_names();
  auto load_error = [](const std::string& name, const std::string& text) {
    const fs::path p = write(name, text);
    return message_of([&] { (void)load_planned_walk(p); });
  };
  CHECK_THAT(load_error("a.json", "{ not json"),
             Catch::Contains("a.json") && Catch::Contains("not JSON"));
  CHECK_THAT(load_error("b.json", "[1, 2]"), Catch::Contains("no JSON object"));
  CHECK_THAT(load_error("c.json", R"({"controller": "fsm"})"),
             Catch::Contains("not a planned_walk controller") && Catch::Contains("\"fsm\""));
  CHECK_THAT(load_error("d.json", R"({"controller": "planned_walk", "symmetry": "lopsided",
                                      "parameter_names": [], "parameters": []})"),
             Catch::Contains("symmetry \"lopsided\" is not one of"));
  CHECK_THAT(load_error("e.json", R"({"controller": "planned_walk", "parameters": []})"),
             Catch::Contains("parameter_names"));
  CHECK_THAT(load_error("f.json", R"({"controller": "planned_walk",
                                      "parameter_names": ["omega0.t_e", "omega0.k_sw_plus.along"],
                                      "parameters": [0.1, null]})"),
             Catch::Contains("parameter 1 (omega0.k_sw_plus.along)") &&
                 Catch::Contains("not a finite number: null"));
  CHECK_THAT(load_error("g.json", R"({"controller": "planned_walk",
                                      "parameter_names": ["omega0.t_e"], "parameters": [1, 2]})"),
             Catch::Contains("1 parameter names but 2 values"));
  CHECK_THAT(message_of([] { (void)load_planned_walk("/no/such/file.json"); }),
             Catch::Contains("cannot read /no/such/file.json"));

  // Names: unknown, repeated, missing.
  auto values_error = [&](const std::string& name, const std::vector<std::string>& n,
                          const std::vector<double>& v) {
    planned_walk_saved s;
    s.names = n;
    s.values = v;
    return message_of([&] { (void)planned_walk_values(s, names, name); });
  };
  CHECK_THAT(values_error("u.json", {"omega0.bogus"}, {2.5}),
             Catch::Contains("u.json") && Catch::Contains("unknown parameter 'omega0.bogus'") &&
                 Catch::Contains("2.5"));
  CHECK_THAT(values_error("r.json", {names[0], names[0]}, {0.1, 0.2}),
             Catch::Contains("'" + names[0] + "' appears twice"));
  CHECK_THAT(values_error("m.json", {names[0]}, {0.1}),
             Catch::Contains("parameter '" + names[1] + "' is missing"));

  // Recorded options.
  auto option_error = [](const char* key, nlohmann::json v) {
    planned_walk_saved s;
    s.info[key] = v;
    return message_of([&] { (void)saved_planned_walk_options(s, "o.json"); });
  };
  CHECK_THAT(option_error("controller_rate", 1.0),
             Catch::Contains("o.json: controller_rate must be 0 or above 2 Hz, got 1.0"));
  CHECK_THAT(option_error("controller_rate", "fast"), Catch::Contains("got \"fast\""));
  CHECK_THAT(option_error("stance_target", "heel"), Catch::Contains("stance_target") &&
                                                        Catch::Contains("\"heel\"") &&
                                                        Catch::Contains("\"first_contact\""));
  {
    planned_walk_saved s;
    s.info["stance_target"] = "first_contact";
    CHECK(saved_planned_walk_options(s, "o.json").stance_target ==
          stance_foot_target::first_contact);
  }
  CHECK_THAT(option_error("helper_force", 1),
             Catch::Contains("helper_force must be true or false"));
  CHECK_THAT(option_error("pin_by", "toe"),
             Catch::Contains("o.json: pin_by must be") && Catch::Contains("\"toe\""));
  CHECK_THAT(option_error("half_cycle_timing", "early"),
             Catch::Contains("o.json: half_cycle_timing must be") && Catch::Contains("\"early\""));
  CHECK_THAT(option_error("symmetry", "lopsided"),
             Catch::Contains("o.json: symmetry must be") && Catch::Contains("\"lopsided\""));
  // A name must be a string: a number is refused, not converted.
  CHECK_THAT(option_error("pin_by", 0),
             Catch::Contains("o.json: pin_by must be \"frame_geometry\" or \"link\", got 0"));
  // A size mismatch on saving.
  CHECK_THROWS_WITH(save_planned_walk(scratch_file("s.json"), names, std::vector<double>{1.0}, {}),
                    Catch::Contains("parameter names but 1 values"));
}

namespace {
/// Every entry's name reads back as its value, names are unique, and an unknown name is nothing.
template <class E, std::size_t N>
void check_names_table(const enum_names<E, N>& table) {
  for (std::size_t i = 0; i < N; ++i) {
    CAPTURE(table[i].name);
    CHECK(value_of(table, table[i].name) == table[i].value);
    CHECK(name_of(table, table[i].value) == table[i].name);
    for (std::size_t k = 0; k < i; ++k) CHECK(table[k].name != table[i].name);
  }
  CHECK_FALSE(value_of(table, "no such name").has_value());
  CHECK(names_of(table).size() == N);
}
}  // namespace

TEST_CASE("planned_walk JSON: the enum name tables read back and quote their choices",
          "[controllers][end_effector][json]") {
  check_names_table(stance_foot_target_names);
  check_names_table(half_cycle_end_names);
  check_names_table(planned_walk_symmetry_names);
  check_names_table(pin_contact_names);
  CHECK(quoted_choices(stance_foot_target_names) ==
        "\"planned_landing\", \"touchdown\" or \"first_contact\"");
  CHECK(quoted_choices(pin_contact_names) == "\"frame_geometry\" or \"link\"");
  // What a saved file records is what the tables name: every value round-trips through a file.
  for (const auto& e : half_cycle_end_names) {
    planned_walk_saved s;
    s.info["half_cycle_timing"] = std::string(e.name);
    CHECK(saved_planned_walk_options(s, "o.json").timing == e.value);
  }
}
