// BVH export (io/bvh.hpp): structure, and the motion read back with the standard BVH forward
// kinematics (parsed here independently) reproduces the recorded body positions and orientations.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "gaitsynth/io/bvh.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

namespace {

struct bvh_joint {
  std::string name;
  int parent = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::vector<std::string> channels;
};
struct bvh_file {
  std::vector<bvh_joint> joints;
  int end_sites = 0;
  int frames = 0;
  double frame_time = 0;
  std::vector<std::vector<double>> motion;
};

bvh_file parse_bvh(const std::string& text) {
  bvh_file f;
  std::istringstream is(text);
  std::string tok;
  std::vector<int> stack;
  bool in_end = false;
  is >> tok;
  REQUIRE(tok == "HIERARCHY");
  while (is >> tok) {
    if (tok == "ROOT" || tok == "JOINT") {
      bvh_joint j;
      is >> j.name;
      j.parent = stack.empty() ? -1 : stack.back();
      f.joints.push_back(j);
      is >> tok;
      REQUIRE(tok == "{");
      stack.push_back(static_cast<int>(f.joints.size()) - 1);
    } else if (tok == "End") {
      is >> tok;
      REQUIRE(tok == "Site");
      is >> tok;
      REQUIRE(tok == "{");
      in_end = true;
      ++f.end_sites;
    } else if (tok == "OFFSET") {
      Eigen::Vector3d o;
      is >> o.x() >> o.y() >> o.z();
      if (!in_end) f.joints[stack.back()].offset = o;
    } else if (tok == "CHANNELS") {
      int n;
      is >> n;
      for (int k = 0; k < n; ++k) {
        is >> tok;
        f.joints[stack.back()].channels.push_back(tok);
      }
    } else if (tok == "}") {
      if (in_end)
        in_end = false;
      else
        stack.pop_back();
    } else if (tok == "MOTION") {
      break;
    } else {
      FAIL("unexpected token " << tok);
    }
  }
  REQUIRE(stack.empty());
  is >> tok;
  REQUIRE(tok == "Frames:");
  is >> f.frames;
  is >> tok >> tok;
  REQUIRE(tok == "Time:");
  is >> f.frame_time;
  std::size_t nch = 0;
  for (const auto& j : f.joints) nch += j.channels.size();
  std::string line;
  std::getline(is, line);
  while (std::getline(is, line)) {
    if (line.empty()) continue;
    std::istringstream ls(line);
    std::vector<double> v;
    double x;
    while (ls >> x) v.push_back(x);
    REQUIRE(v.size() == nch);
    f.motion.push_back(v);
  }
  return f;
}

Eigen::Matrix3d axis_rotation(const std::string& ch, double deg) {
  const double a = deg * std::numbers::pi / 180;
  const Eigen::Vector3d ax = ch[0] == 'X'   ? Eigen::Vector3d::UnitX()
                             : ch[0] == 'Y' ? Eigen::Vector3d::UnitY()
                                            : Eigen::Vector3d::UnitZ();
  return Eigen::AngleAxisd(a, ax).toRotationMatrix();
}

}  // namespace

TEST_CASE("euler_zxy and rotation_zxy are inverse", "[io][bvh]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Matrix3d R =
        Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    const Eigen::Vector3d a = euler_zxy(R);
    CHECK((rotation_zxy(a) - R).norm() < 1e-9);
    CHECK(std::abs(a[1]) <= std::numbers::pi / 2 + 1e-12);
  }
  // Gimbal lock (x = +-90 degrees) still reproduces the rotation.
  const Eigen::Matrix3d L = rotation_zxy({0.3, std::numbers::pi / 2, -0.4});
  CHECK((rotation_zxy(euler_zxy(L)) - L).norm() < 1e-9);
}

TEST_CASE("BVH: hierarchy, frame count and motion match the trajectory", "[io][bvh]") {
  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 1.0, 0.01);
  for (bool y_up : {true, false}) {
    const double scale = y_up ? 100.0 : 1.0;
    std::ostringstream os;
    write_bvh(m, traj, os, {.scale = scale, .y_up = y_up, .precision = 12});
    const bvh_file f = parse_bvh(os.str());
    REQUIRE(f.joints.size() == static_cast<std::size_t>(m.num_bodies()));
    CHECK(f.joints[0].name == "pelvis");
    CHECK(f.joints[0].channels.size() == 6);
    CHECK(f.joints[0].channels[0] == "Xposition");
    CHECK(f.joints[1].channels == std::vector<std::string>{"Zrotation", "Xrotation", "Yrotation"});
    CHECK(f.end_sites == 3);  // head and two feet
    CHECK(f.frames == static_cast<int>(traj.frames.size()));
    CHECK(f.motion.size() == traj.frames.size());
    CHECK(f.frame_time == Approx(0.01));
    Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
    if (y_up) C << 1, 0, 0, 0, 0, 1, 0, -1, 0;
    std::map<std::string, int> bvh_index;
    for (std::size_t j = 0; j < f.joints.size(); ++j)
      bvh_index[f.joints[j].name] = static_cast<int>(j);
    // Standard BVH forward kinematics on the parsed file.
    double max_pos = 0, max_rot = 0, max_jump = 0;
    std::vector<double> prev;
    for (std::size_t k = 0; k < f.motion.size(); ++k) {
      std::vector<Eigen::Vector3d> P(f.joints.size());
      std::vector<Eigen::Matrix3d> R(f.joints.size());
      std::size_t c = 0;
      for (std::size_t j = 0; j < f.joints.size(); ++j) {
        const bvh_joint& J = f.joints[j];
        Eigen::Vector3d t = J.offset;
        Eigen::Matrix3d local = Eigen::Matrix3d::Identity();
        for (const auto& ch : J.channels) {
          const double v = f.motion[k][c++];
          if (ch == "Xposition")
            t.x() = v;
          else if (ch == "Yposition")
            t.y() = v;
          else if (ch == "Zposition")
            t.z() = v;
          else
            local = local * axis_rotation(ch, v);
        }
        if (J.parent < 0) {
          P[j] = t;
          R[j] = local;
        } else {
          P[j] = P[J.parent] + R[J.parent] * t;
          R[j] = R[J.parent] * local;
        }
      }
      for (int b = 0; b < m.num_bodies(); ++b) {
        const int j = bvh_index.at(m.bodies[b].name);
        const Eigen::Vector3d expect = scale * (C * traj.frames[k].body_position[b]);
        max_pos = std::max(max_pos, (P[j] - expect).norm() / scale);
        const Eigen::Matrix3d Rexp =
            C * traj.frames[k].body_orientation[b].toRotationMatrix() * C.transpose();
        max_rot = std::max(max_rot, (R[j] - Rexp).norm());
      }
      if (!prev.empty())
        for (std::size_t i = 3; i < prev.size(); ++i)
          max_jump = std::max(max_jump, std::abs(f.motion[k][i] - prev[i]));
      prev = f.motion[k];
    }
    CHECK(max_pos < 1e-8);  // m
    CHECK(max_rot < 1e-8);
    CHECK(max_jump < 20.0);  // degrees per 10 ms frame: continuous angles, no 360 flips
  }
}

TEST_CASE("BVH: resampling and bad input", "[io][bvh]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 1.0, 0.01);
  std::ostringstream os;
  write_bvh(m, traj, os, {.frame_time = 0.05});
  const bvh_file f = parse_bvh(os.str());
  CHECK(f.frames == 21);
  CHECK(f.frame_time == Approx(0.05));
  CHECK_THROWS_WITH(write_bvh(m, traj, os, {.scale = 0}), Catch::Contains("scale"));
  trajectory empty;
  CHECK_THROWS_WITH(write_bvh(m, empty, os), Catch::Contains("no frames"));
  auto bad = traj;
  bad.frames[4].q.resize(2);
  CHECK_THROWS_WITH(write_bvh(m, bad, os), Catch::Contains("frame 4"));
}
