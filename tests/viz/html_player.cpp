// HTML player (viz/html_player.hpp): one self-contained file with no network reference, the
// recorded data embedded as valid JSON of the right sizes. The page's own behaviour in a browser is
// tested by player_chromium.cpp.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "gaitsynth/viz/html_player.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

namespace {
std::string embedded_json(const std::string& html) {
  const std::string open = "<script id=\"gaitsynth-data\" type=\"application/json\">";
  const auto a = html.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = html.find("</script>", a);
  REQUIRE(b != std::string::npos);
  return html.substr(a + open.size(), b - a - open.size());
}
}  // namespace

TEST_CASE("HTML player: self-contained, data embedded", "[viz][html]") {
  auto m = viz_test::make_biped<floating_root>();
  auto traj = viz_test::make_walk(m, 2.0, 0.005);  // 401 frames, kept at <= 60 per second
  traj.terrain.nx = 4;
  traj.terrain.ny = 3;
  traj.terrain.height.assign(12, 0.0);
  traj.terrain.height[5] = 0.1;
  std::ostringstream os;
  write_html_player(m, traj, os, {.title = "Walk </script> & <b>test</b>"});
  const std::string html = os.str();
  // No network: no URL scheme, no external script, style, image or font.
  CHECK(html.find("http://") == std::string::npos);
  CHECK(html.find("https://") == std::string::npos);
  CHECK(html.find("src=") == std::string::npos);
  CHECK(html.find("<link") == std::string::npos);
  CHECK(html.find("@import") == std::string::npos);
  CHECK(html.find("url(") == std::string::npos);
  CHECK(html.find("//cdn") == std::string::npos);
  // One document, scripts and style inline.
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(html.find("</html>") != std::string::npos);
  CHECK(html.find("<canvas id=\"view\"") != std::string::npos);
  // The self-check line is there for tests but hidden from people (player_chromium.cpp checks
  // that it stays hidden once the script has run).
  CHECK(html.find("<div id=\"status\" hidden>") != std::string::npos);
  CHECK(html.find("window.onerror") != std::string::npos);
  // The title is escaped (it cannot close the script or inject markup).
  CHECK(html.find("Walk &lt;/script&gt; &amp; &lt;b&gt;test&lt;/b&gt;") != std::string::npos);
  const std::string json = embedded_json(html);
  CHECK(json.find("</") == std::string::npos);
  for (const auto& b : m.bodies) CHECK(json.find("\"" + b.name + "\"") != std::string::npos);
  const auto D = nlohmann::json::parse(json);
  const std::size_t nf = D["t"].size();
  CHECK(nf == 121);  // 2 s at 60 frames per second, plus the first
  const std::size_t nb = m.bodies.size(), nc = m.contact_points.size();
  CHECK(D["bodies"].size() == nb);
  CHECK(D["bp"].size() == nf * nb * 3);
  CHECK(D["bq"].size() == nf * nb * 4);
  CHECK(D["cm"].size() == nf * 3);
  CHECK(D["cp"].size() == nf * nc * 3);
  CHECK(D["cf"].size() == nf * nc * 3);
  CHECK(D["ca"].size() == nf * nc);
  CHECK(D["q"].size() == nf * m.dofs.size());
  CHECK(D["obj"].size() == nf * 2);
  CHECK(D["pushes"].size() == nf);
  CHECK(D["terrain"]["h"].size() == 12);
  CHECK(D["planar"] == false);
  CHECK(D["cycles"].size() >= 2);
  CHECK(D["foot"] == "lfoot");
  // The first and last recorded frames are kept; body positions are the recorded ones.
  CHECK(D["t"].front().get<double>() == 0.0);
  CHECK(D["t"].back().get<double>() == Approx(2.0));
  CHECK(D["bp"][0].get<double>() == Approx(traj.frames[0].body_position[0].x()).margin(1e-6));
  CHECK(D["bp"][2].get<double>() == Approx(traj.frames[0].body_position[0].z()).margin(1e-6));
  // Sagittal hip, knee and ankle of both sides are plotted at first.
  CHECK(D["plot_joints"].size() == 6);
  // Pushes appear in the frames inside [1.0, 1.2) s.
  int pushed = 0;
  for (const auto& p : D["pushes"]) pushed += p.empty() ? 0 : 1;
  CHECK(pushed > 5);
}

TEST_CASE("HTML player: bad input and file output", "[viz][html]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 0.5, 0.01);
  std::ostringstream os;
  CHECK_THROWS_WITH(write_html_player(m, trajectory{}, os), Catch::Contains("no frames"));
  CHECK_THROWS_WITH(write_html_player(m, traj, os, {.max_frame_rate = 0}),
                    Catch::Contains("max_frame_rate"));
  CHECK_THROWS_WITH(write_html_player(m, traj, os, {.plot_joints = {"elbow"}}),
                    Catch::Contains("elbow"));
  const std::string dir = std::string(GAITSYNTH_BINARY_DIR) + "/viz_outputs";
  std::filesystem::create_directories(dir);
  save_html_player(m, traj, dir + "/planar.html");
  CHECK(std::filesystem::file_size(dir + "/planar.html") > 10000);
  CHECK_THROWS_WITH(save_html_player(m, traj, dir + "/no/such/dir/x.html"),
                    Catch::Contains("cannot open"));
  // A hand-made trajectory with only q (no poses, contacts or names) is drawn too.
  trajectory bare;
  for (int k = 0; k < 3; ++k) {
    trajectory_frame f;
    f.t = 0.1 * k;
    f.q = neutral_configuration(m);
    f.q[1] = 1.0;
    bare.frames.push_back(f);
  }
  std::ostringstream o2;
  write_html_player(m, bare, o2);
  CHECK(o2.str().find("\"planar\":true") != std::string::npos);
}
