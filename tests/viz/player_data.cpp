// The HTML player's data (viz/player/data.hpp, json.hpp): the numbers the page reads are exactly
// the recorded values rounded to the documented digits, and the same doubles the hand-written JSON
// of earlier versions gave; non-finite values and hostile names still give valid JSON that cannot
// leave its <script> element.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "gaitsynth/viz/html_player.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;
using viz_detail::page_number;
using viz_detail::player_digits;
using viz_detail::round_digits;

namespace {

std::string embedded_json(const std::string& html) {
  const std::string open = "<script id=\"gaitsynth-data\" type=\"application/json\">";
  const auto a = html.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = html.find("</script>", a);
  REQUIRE(b != std::string::npos);
  return html.substr(a + open.size(), b - a - open.size());
}

/// The double a browser reads from the JSON text written for x.
double written(double x, int sig) {
  return nlohmann::json::parse(viz_detail::script_json(page_number(x, sig))).get<double>();
}

bool same_bits(double a, double b) {
  return a == b && std::signbit(a) == std::signbit(b);
}

}  // namespace

TEST_CASE("player data: numbers read back as the rounded doubles, exactly", "[viz][html][json]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-12, 12);
  for (int k = 0; k < 5000; ++k) {
    const double x = mant(rng) * std::pow(10.0, expo(rng));
    for (int sig : {4, 5, 6, 8}) {
      const double r = written(x, sig);
      CHECK(same_bits(r, round_digits(x, sig)));
      // The same double as the %.{sig}g text the player wrote before it used nlohmann::json
      // (viz_detail::jnum), so the page draws exactly what it drew then.
      CHECK(same_bits(r, std::strtod(viz_detail::jnum(x, sig).c_str(), nullptr)));
    }
  }
  // Short text: integers without ".0", zeros unsigned, the digits asked for.
  CHECK(page_number(0.0, 6).dump() == "0");
  CHECK(page_number(-0.0, 6).dump() == "0");
  CHECK(page_number(2.0, 6).dump() == "2");
  CHECK(page_number(-1234567.0, 4).dump() == "-1235000");
  CHECK(page_number(0.1234567891, 6).dump() == "0.123457");
  CHECK(page_number(1e-7, 6).dump() == "1e-07");
  CHECK(same_bits(written(3e20, 6), 3e20));  // beyond 2^53 stays a double
  // Full precision when asked for.
  CHECK(same_bits(written(0.1 + 0.2, 17), 0.1 + 0.2));
}

TEST_CASE("player data: the page holds the recorded frames at the documented digits",
          "[viz][html][json]") {
  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 1.0, 0.01);
  std::ostringstream os;
  write_html_player(m, traj, os);
  const auto D = nlohmann::ordered_json::parse(embedded_json(os.str()));  // keeps the key order
  const std::size_t nb = m.bodies.size(), nc = m.contact_points.size(), nj = m.dofs.size();
  const std::size_t nf = D["t"].size();
  REQUIRE(nf == 61);  // 1 s at 60 frames per second, plus the first
  // Keys in the order the script's documentation (player/data.hpp) lists them.
  std::vector<std::string> keys;
  for (const auto& [k, v] : D.items()) keys.push_back(k);
  CHECK(keys ==
        std::vector<std::string>{"name",        "planar", "autoplay", "speed",       "size",
                                 "force_scale", "bodies", "contacts", "joint_names", "plot_joints",
                                 "obj_names",   "foot",   "cycles",   "terrain",     "t",
                                 "bp",          "bq",     "cm",       "cp",          "cf",
                                 "ca",          "pushes", "q",        "obj",         "cs"});
  for (std::size_t k = 0; k < nf; ++k) {
    // Recorded frames 0.01 s apart, kept one per 1/60 s tick: the nearest one.
    const int f = viz_detail::nearest_frame(traj, k / 60.0);
    const trajectory_frame& fr = traj.frames[f];
    CHECK(same_bits(D["t"][k].get<double>(), round_digits(fr.t, player_digits::time)));
    for (std::size_t b = 0; b < nb; ++b)
      for (int c = 0; c < 3; ++c)
        CHECK(same_bits(D["bp"][(k * nb + b) * 3 + c].get<double>(),
                        round_digits(fr.body_position[b][c], player_digits::length)));
    for (std::size_t j = 0; j < nj; ++j)
      CHECK(same_bits(D["q"][k * nj + j].get<double>(),
                      round_digits(fr.q[floating_root::nq + j], player_digits::rotation)));
    for (std::size_t c = 0; c < nc; ++c) {
      CHECK(D["ca"][k * nc + c] == int{fr.contact_active[c] != 0});
      CHECK(same_bits(D["cf"][(k * nc + c) * 3 + 2].get<double>(),
                      round_digits(fr.contact_force[c].z(), player_digits::force)));
    }
    CHECK(same_bits(D["obj"][k * 2 + 1].get<double>(),
                    round_digits(fr.objective_terms[1], player_digits::objective)));
    CHECK(D["cs"][k] == fr.controller_state);
  }
}

TEST_CASE("player data: non-finite values are written as null, the JSON stays valid",
          "[viz][html][json]") {
  const auto m = viz_test::make_biped<planar_root>();
  auto traj = viz_test::make_walk(m, 0.5, 0.01);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  traj.frames[0].objective_terms[0] = nan;
  traj.frames[0].objective_terms[1] = inf;
  traj.frames[0].contact_force[0] = Eigen::Vector3d(-inf, nan, inf);
  traj.frames[0].com = Eigen::Vector3d(nan, 0, 1);
  traj.frames.back().objective_terms.resize(1);  // a term missing is null too
  traj.terrain.nx = 2;
  traj.terrain.ny = 2;
  traj.terrain.dx = traj.terrain.dy = 1;
  traj.terrain.height = {0, nan, inf, 0};
  std::ostringstream os;
  write_html_player(m, traj, os);
  const std::string json = embedded_json(os.str());
  for (const char* token : {"nan", "NaN", "inf", "Infinity"})
    CHECK(json.find(token) == std::string::npos);
  const auto D = nlohmann::json::parse(json);  // strict: NaN or Infinity would throw
  CHECK(D["obj"][0].is_null());
  CHECK(D["obj"][1].is_null());
  CHECK(D["obj"][2].is_number());
  CHECK(D["obj"].back().is_null());
  for (int c = 0; c < 3; ++c) CHECK(D["cf"][c].is_null());
  CHECK(D["cm"][0].is_null());
  CHECK(D["cm"][2] == 1);
  CHECK(D["terrain"]["h"] == nlohmann::json::parse("[0, null, null, 0]"));
}

TEST_CASE("player data: names cannot end the script element, bad UTF-8 does not throw",
          "[viz][html][json]") {
  auto m = viz_test::make_biped<planar_root>();
  m.name = "walker</script><!--<b>&amp;";
  m.contact_points[0].name = "heel \xff\xfe";  // not UTF-8
  auto traj = viz_test::make_walk(m, 0.5, 0.01);
  traj.objective_term_names[0] = "a</SCRIPT>b";
  std::ostringstream os;
  write_html_player(m, traj, os);
  const std::string json = embedded_json(os.str());  // ends at the first </script>: the real one
  CHECK(json.find('<') == std::string::npos);
  CHECK(json.find('>') == std::string::npos);
  CHECK(json.find('&') == std::string::npos);
  const auto D = nlohmann::json::parse(json);
  CHECK(D["name"] == m.name);
  CHECK(D["obj_names"][0] == "a</SCRIPT>b");
  CHECK(D["contacts"][0]["n"] == "heel \xef\xbf\xbd\xef\xbf\xbd");  // U+FFFD for each bad byte
  CHECK(D["t"].size() == 31);
}
