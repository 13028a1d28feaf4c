// io/viewer_outputs.hpp writes every requested file; the examples' viewer flags
// (examples/viewer_flags.hpp) are recognized and removed from argv.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "../../examples/viewer_flags.hpp"
#include "gaitsynth/io/viewer_outputs.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

TEST_CASE("viewer_flags::extract removes the output flags and keeps the rest",
          "[io][viewer_flags]") {
  std::vector<std::string> args{"prog",          "--seed",      "3",           "--html",
                                "a.html",        "--bvh=b.bvh", "--gait-svg",  "g.svg",
                                "--csv",         "c.csv",       "--filmstrip", "f.svg",
                                "--mjcf-replay", "r.xml",       "--out",       "dir"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int argc = static_cast<int>(args.size());
  const viz_outputs out = viewer_flags::extract(argc, argv.data());
  CHECK(out.html == "a.html");
  CHECK(out.bvh == "b.bvh");
  CHECK(out.gait_svg == "g.svg");
  CHECK(out.trajectory_csv == "c.csv");
  CHECK(out.filmstrip_svg == "f.svg");
  CHECK(out.mjcf_replay == "r.xml");
  CHECK(out.any());
  REQUIRE(argc == 5);
  CHECK(std::string(argv[1]) == "--seed");
  CHECK(std::string(argv[2]) == "3");
  CHECK(std::string(argv[3]) == "--out");
  CHECK(std::string(argv[4]) == "dir");
  CHECK(argv[5] == nullptr);
  std::string p0 = "prog", p1 = "--html";
  char* missing[] = {p0.data(), p1.data(), nullptr};
  int n = 2;
  CHECK_THROWS_WITH(viewer_flags::extract(n, missing), Catch::Contains("--html needs a file name"));
  CHECK(std::string(viewer_flags::help()).find("--html FILE") != std::string::npos);
}

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
