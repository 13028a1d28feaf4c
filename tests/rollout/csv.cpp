// io/csv.hpp: a recorded trajectory as CSV, every column named with its unit, values exact.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/csv.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "support/rollout_e2.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_e2;

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream is(line);
  while (std::getline(is, cell, ',')) out.push_back(cell);
  return out;
}

template <class Model>
trajectory record(const Model& m, double duration, int every) {
  auto scr = make_rollout_scratch(m);
  rollout_options o;
  o.dt = 1.0 / 2400.0;
  o.duration = duration;
  trajectory tr;
  o.record = &tr;
  o.record_every = every;
  o.pushes = {push{0, vec3(20, 0, 0), 0.0, 1.0}};
  rollout(m, standing_pd(m, o.dt), pose_hold(m), distance_travelled(), flat_terrain(),
          semi_implicit_euler(), standing_pose(m), o, scr);
  return tr;
}

}  // namespace

TEST_CASE("write_csv: a header naming every column with its unit, one exact row per frame",
          "[io][csv]") {
  const auto m = wang2009_humanoid();
  const trajectory tr = record(m, 0.05, 12);
  REQUIRE(tr.frames.size() == 11);
  std::stringstream ss;
  write_csv(ss, tr);

  std::string line;
  REQUIRE(std::getline(ss, line));
  const auto header = split(line);
  CHECK(header == csv_columns(tr));
  const std::regex with_unit(R"(^[A-Za-z0-9_ ]+ \[[^\]]+\]$)");
  for (const auto& h : header) {
    INFO(h);
    CHECK(std::regex_match(h, with_unit));
  }
  auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  };
  CHECK(column("t [s]") == 0);
  CHECK(column("q_root_x [m]") >= 0);
  CHECK(column("q_root_qw [1]") >= 0);
  CHECK(column("q_lknee [rad]") >= 0);
  CHECK(column("v_root_x [m/s]") >= 0);
  CHECK(column("v_root_wx [rad/s]") >= 0);
  CHECK(column("v_lknee [rad/s]") >= 0);
  CHECK(column("tau_lknee [N m]") >= 0);
  CHECK(column("com_z [m]") >= 0);
  CHECK(column("pelvis_qw [1]") >= 0);
  CHECK(column("push_fx [N]") >= 0);
  CHECK(column("objective_distance [m]") >= 0);
  // nq + 2 nv + 3 + 7 per body + 7 per contact point + 4 (push) + terms + time + controller state
  const std::size_t expected =
      1 + m.nq() + 2 * m.nv() + 3 + 7 * m.num_bodies() + 7 * m.contact_points.size() + 4 + 1 + 1;
  CHECK(header.size() == expected);

  std::size_t rows = 0;
  while (std::getline(ss, line)) {
    const auto cells = split(line);
    REQUIRE(cells.size() == header.size());
    const trajectory_frame& f = tr.frames[rows];
    CHECK(std::stod(cells[0]) == f.t);  // max_digits10: exact round trip
    CHECK(std::stod(cells[column("q_lknee [rad]")]) == f.q[7 + m.dof_index("lknee")]);
    CHECK(std::stod(cells[column("com_z [m]")]) == f.com.z());
    CHECK(std::stod(cells[column("push_fx [N]")]) == 20.0);
    CHECK(std::stoi(cells[column("push_body [index]")]) == 0);
    ++rows;
  }
  CHECK(rows == tr.frames.size());
}

TEST_CASE("write_csv of a planar character names its planar root coordinates", "[io][csv]") {
  const auto m = sharon2005_human7();
  const trajectory tr = record(m, 0.01, 24);
  const auto cols = csv_columns(tr);
  CHECK(cols[1] == "q_root_x [m]");
  CHECK(cols[2] == "q_root_z [m]");
  CHECK(cols[3] == "q_root_pitch [rad]");
  CHECK(cols[1 + m.nq()] == "v_root_x [m/s]");
  CHECK(cols[1 + m.nq() + m.nv()] == "tau_root_x [N]");
  CHECK(cols[1 + m.nq() + m.nv() + 2] == "tau_root_pitch [N m]");
}

TEST_CASE("write_csv rejects inconsistent frames and save_csv unwritable paths",
          "[io][csv][bad_input]") {
  const auto m = sharon2005_human7();
  trajectory tr = record(m, 0.01, 24);
  tr.frames[0].q.resize(2);
  std::stringstream ss;
  CHECK_THROWS_WITH(write_csv(ss, tr), Catch::Contains("frame 0") && Catch::Contains("q"));
  CHECK_THROWS_AS(save_csv("/nonexistent-dir/x.csv", record(m, 0.01, 24)), std::runtime_error);
}
