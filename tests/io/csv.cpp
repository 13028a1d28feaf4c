// A recorded rollout written as CSV (io/csv.hpp over io/trajectory_csv.hpp): every column named
// with its unit, values exact, and the file reads back into the same trajectory.
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

TEST_CASE("a recorded rollout as CSV: every column has a unit, values read back exactly",
          "[io][csv]") {
  const auto m = wang2009_humanoid();
  const trajectory tr = record(m, 0.05, 12);
  REQUIRE(tr.frames.size() == 11);  // steps 0, 12, ..., 108 and the final state at 120
  std::stringstream ss;
  write_csv(ss, tr);
  const std::string text = ss.str();

  std::istringstream is(text);
  std::string line;
  while (std::getline(is, line) && !line.empty() && line[0] == '#') {
  }
  const auto header = split(line);
  const std::regex with_unit(R"(^[^\[\]]+ \[[^\]]+\]$)");
  for (const auto& h : header) {
    INFO(h);
    CHECK(std::regex_match(h, with_unit));
  }
  auto has = [&](const std::string& name) {
    return std::find(header.begin(), header.end(), name) != header.end();
  };
  CHECK(header.front() == "t [s]");
  CHECK(has("q:root_x [m]"));
  CHECK(has("q:root_qw [1]"));
  CHECK(has("q:lknee [rad]"));
  CHECK(has("v:root_x [m/s]"));
  CHECK(has("v:lknee [rad/s]"));
  CHECK(has("tau:lknee [N m]"));
  CHECK(has("com:z [m]"));
  CHECK(has("contact:" + m.contact_points[0].name + ":fz [N]"));
  std::size_t rows = 0;
  while (std::getline(is, line)) {
    CHECK(split(line).size() == header.size());
    ++rows;
  }
  CHECK(rows == tr.frames.size());

  std::istringstream back_in(text);
  const trajectory back = read_csv(back_in);
  REQUIRE(back.frames.size() == tr.frames.size());
  CHECK(back.q_names == tr.q_names);
  CHECK(back.objective_term_names == tr.objective_term_names);
  for (std::size_t i = 0; i < tr.frames.size(); ++i) {
    CHECK(back.frames[i].t == tr.frames[i].t);
    CHECK(back.frames[i].q == tr.frames[i].q);
    CHECK(back.frames[i].tau == tr.frames[i].tau);
    CHECK(back.frames[i].objective_terms == tr.frames[i].objective_terms);
  }
  // The running distance term is the COM's displacement along +x since the first step.
  CHECK(tr.frames.back().objective_terms.size() == 1);
  CHECK(tr.frames.back().objective_terms[0] ==
        Approx(tr.frames[tr.frames.size() - 2].com.x() - tr.frames[0].com.x()).margin(1e-4));
}

TEST_CASE("CSV of a planar character names its planar root coordinates", "[io][csv]") {
  const auto m = sharon2005_human7();
  const trajectory tr = record(m, 0.01, 24);
  std::stringstream ss;
  write_csv(ss, tr);
  const std::string text = ss.str();
  CHECK(text.find("q:root_pitch [rad]") != std::string::npos);
  CHECK(text.find("v:root_z [m/s]") != std::string::npos);
  CHECK(text.find("tau:root_pitch [N m]") != std::string::npos);
}

TEST_CASE("CSV writing rejects inconsistent frames and unwritable paths", "[io][csv][bad_input]") {
  const auto m = sharon2005_human7();
  trajectory tr = record(m, 0.01, 24);
  std::stringstream ss;
  CHECK_THROWS_AS(save_csv("/nonexistent-dir/x.csv", tr), std::runtime_error);
  tr.frames[0].q.resize(2);
  CHECK_THROWS_AS(write_csv(ss, tr), std::invalid_argument);
}
