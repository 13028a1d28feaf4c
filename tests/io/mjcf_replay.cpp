// MJCF keyframes / replay (io/mjcf_replay.hpp): one key per kept frame, qpos in MuJoCo's order
// (io/mjcf.hpp's permutation), embedded in the exported model. MuJoCo itself loads the file in
// mjcf_replay.mujoco.cpp.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "gaitsynth/io/mjcf_replay.hpp"
#include "viz/viz_fixture.hpp"
#include "viz/xml_check.hpp"

using namespace gaitsynth;

namespace {
std::vector<double> attribute_numbers(const std::string& xml, std::size_t from,
                                      const std::string& attr) {
  const auto a = xml.find(attr + "=\"", from);
  const auto b = xml.find('"', a + attr.size() + 2);
  std::istringstream is(xml.substr(a + attr.size() + 2, b - a - attr.size() - 2));
  std::vector<double> v;
  double x;
  while (is >> x) v.push_back(x);
  return v;
}
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("MJCF keyframes: qpos and qvel in MuJoCo's order", "[io][mjcf_replay]") {
  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 1.0, 0.01);
  std::ostringstream os;
  write_mjcf_keyframes(m, traj, os);
  const std::string k = os.str();
  CHECK(viz_test::check_xml(k).root == "keyframe");
  CHECK(count(k, "<key ") == traj.frames.size());
  // Key 37: qpos is the frame's q permuted as to_mjcf_qpos says.
  const auto at = k.find("name=\"f37\"");
  REQUIRE(at != std::string::npos);
  const auto qpos = attribute_numbers(k, at, "qpos");
  const Eigen::VectorXd expect = to_mjcf_qpos(m, traj.frames[37].q);
  REQUIRE(qpos.size() == static_cast<std::size_t>(m.nq()));
  for (int i = 0; i < m.nq(); ++i) CHECK(qpos[i] == expect[i]);
  const auto qvel = attribute_numbers(k, at, "qvel");
  CHECK(qvel.size() == static_cast<std::size_t>(m.nv()));
  CHECK(attribute_numbers(k, at, "time")[0] == traj.frames[37].t);
  // Thinning: an interval, then a cap on the count.
  std::ostringstream o2;
  write_mjcf_keyframes(m, traj, o2, {.interval = 0.1});
  CHECK(count(o2.str(), "<key ") == 11);
  std::ostringstream o3;
  write_mjcf_keyframes(m, traj, o3, {.max_keys = 10});
  CHECK(count(o3.str(), "<key ") == 10);
  CHECK_THROWS_WITH(write_mjcf_keyframes(m, traj, o3, {.max_keys = 0}),
                    Catch::Contains("max_keys"));
}

TEST_CASE("MJCF replay: the exported model with the keys inside", "[io][mjcf_replay]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 0.5, 0.01);
  mjcf_replay_options o;
  o.model.keyframe_q = neutral_configuration(m);  // ignored: keys are the frames
  std::ostringstream os;
  write_mjcf_replay(m, traj, os, o);
  const std::string xml = os.str();
  const auto sum = viz_test::check_xml(xml);
  CHECK(sum.root == "mujoco");
  CHECK(sum.elements.at("keyframe") == 1);
  CHECK(sum.elements.at("key") == static_cast<int>(traj.frames.size()));
  CHECK(xml.find("name=\"initial\"") == std::string::npos);
  std::ostringstream csv;
  write_mjcf_qpos_csv(m, traj, csv);
  std::istringstream is(csv.str());
  std::string header;
  std::getline(is, header);
  CHECK(header.rfind("time,root_x,root_z,root_pitch,", 0) == 0);
  std::size_t rows = 0;
  for (std::string l; std::getline(is, l);) ++rows;
  CHECK(rows == traj.frames.size());
}
