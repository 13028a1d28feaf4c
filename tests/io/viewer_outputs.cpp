// io/viewer_outputs.hpp writes every requested file. (The examples' viewer flags are an option
// group of examples/command_line.hpp, checked by tests/examples/command_lines.sh.)
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "gaitsynth/io/viewer_outputs.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

TEST_CASE("write_viz_outputs writes every requested file", "[io][viewer_outputs]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 2.2, 0.01);
  const std::string dir = std::string(GAITSYNTH_BINARY_DIR) + "/viz_outputs/viewer_outputs";
  std::filesystem::create_directories(dir);
  viz_outputs out;
  out.html = dir + "/p.html";
  out.filmstrip_svg = dir + "/f.svg";
  out.gait_svg = dir + "/g.svg";
  out.bvh = dir + "/m.bvh";
  out.trajectory_csv = dir + "/t.csv";
  out.mjcf_replay = dir + "/r.xml";
  std::ostringstream log;
  write_viz_outputs(m, traj, out, &log);
  for (const auto& p :
       {out.html, out.filmstrip_svg, out.gait_svg, out.bvh, out.trajectory_csv, out.mjcf_replay}) {
    CHECK(std::filesystem::file_size(p) > 100);
    CHECK(log.str().find(p) != std::string::npos);
  }
  CHECK_FALSE(viz_outputs{}.any());
}
