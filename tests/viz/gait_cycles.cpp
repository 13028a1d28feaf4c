// Heel-strike detection and gait-cycle statistics (viz/gait_cycles.hpp) on the synthetic walk,
// whose period and joint-angle curves are known in closed form.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

TEST_CASE("heel strikes of the synthetic walk are one period apart", "[viz][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  const double period = 0.8;
  const auto traj = viz_test::make_walk(m, 4.0, 0.01, period);
  const int lfoot = default_foot_body(traj, "l");
  REQUIRE(lfoot == m.body_index("lfoot"));
  CHECK(default_foot_body(traj, "r") == m.body_index("rfoot"));
  CHECK(default_foot_body(m, "l") == lfoot);
  // With contact points on thighs, knees and hands (for falls), only soles and toes make a foot.
  const auto h = wang2009_humanoid();
  CHECK(default_foot_body(h, "l") == h.body_index("lfoot"));
  CHECK(default_foot_body(h, "r") == h.body_index("rfoot"));
  const auto strikes = heel_strike_times(traj, lfoot, 0.25);
  REQUIRE(strikes.size() >= 4);
  for (std::size_t k = 1; k < strikes.size(); ++k)
    CHECK(strikes[k] - strikes[k - 1] == Approx(period).margin(0.0101));
  // Left and right strikes alternate half a period apart.
  const auto right = heel_strike_times(traj, m.body_index("rfoot"), 0.25);
  REQUIRE(!right.empty());
  double d = std::fmod(right[0] - strikes[0] + 10 * period, period);
  CHECK(d == Approx(period / 2).margin(0.0201));
  // Contact chatter within min_interval is ignored; a zero interval keeps everything.
  CHECK(heel_strike_times(traj, lfoot, 10.0).size() == 1);
  CHECK(heel_strike_times(traj, -1).empty());
}

TEST_CASE("gait_cycles: mean of a periodic motion is its curve, spread is zero", "[viz][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  const double period = 1.0;
  const auto traj = viz_test::make_walk(m, 4.0, 0.01, period);
  const gait_cycle_data d = gait_cycles(m, traj);
  REQUIRE(d.channels.size() == 3);
  CHECK(d.channels[0].name == "lhip");
  CHECK(d.channels[1].name == "lknee");
  CHECK(d.channels[2].name == "lankle");
  CHECK(d.foot == "lfoot");
  REQUIRE(d.num_cycles() >= 2);
  REQUIRE(d.percent.size() == 101);
  const double t0 = d.cycle_starts[0];
  for (std::size_t s = 0; s < d.percent.size(); s += 10) {
    const double ph = 2 * std::numbers::pi * (t0 + d.percent[s] / 100.0 * period) / period;
    CHECK(d.mean[0][s] ==
          Approx(viz_test::walk_angle("lhip", ph) * 180 / std::numbers::pi).margin(1e-6));
    CHECK(d.mean[1][s] ==
          Approx(viz_test::walk_angle("lknee", ph) * 180 / std::numbers::pi).margin(1e-6));
    CHECK(d.stddev[0][s] < 1e-6);
  }
}

TEST_CASE("gait_cycles: segment and relative pitch channels, given starts", "[viz][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 3.0, 0.01, 1.0);
  gait_cycle_options o;
  o.cycle_starts = {0.5, 1.5, 2.5};
  o.samples = 11;
  gait_channel thigh{.type = gait_channel::kind::segment_pitch, .label = "thigh", .name = "lthigh"};
  gait_channel knee{.type = gait_channel::kind::relative_pitch,
                    .label = "knee",
                    .name = "lshin",
                    .reference = "lthigh"};
  gait_channel hip{.type = gait_channel::kind::joint_angle, .name = "lhip", .scale = 1.0};
  o.channels = {thigh, knee, hip};
  const gait_cycle_data d = gait_cycles(m, traj, o);
  REQUIRE(d.num_cycles() == 2);
  CHECK(d.foot.empty());
  CHECK(d.channels[2].label == "lhip");  // empty label -> name
  for (std::size_t s = 0; s < d.percent.size(); ++s) {
    const double t = 0.5 + d.percent[s] / 100.0;
    const double ph = 2 * std::numbers::pi * t;
    const double pitch = 0.04 * std::sin(2 * ph);
    const double deg = 180 / std::numbers::pi;
    // thigh pitch in the world = root pitch + hip angle; shin relative to thigh = knee angle.
    CHECK(d.mean[0][s] == Approx((pitch + viz_test::walk_angle("lhip", ph)) * deg).margin(1e-6));
    CHECK(d.mean[1][s] == Approx(viz_test::walk_angle("lknee", ph) * deg).margin(1e-6));
    CHECK(d.mean[2][s] == Approx(viz_test::walk_angle("lhip", ph)).margin(1e-9));
  }
  o.cycle_starts = {1.0, 0.5};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Catch::Contains("cycle_starts must increase"));
  o.cycle_starts = {};
  o.channels = {gait_channel{.name = "nope"}};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Catch::Contains("nope"));
  o.channels = {};
  o.side = "x";
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Catch::Contains("hip/knee/ankle"));
}

TEST_CASE("gait_cycles: a joint torque channel reads the recorded torques", "[viz][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  auto traj = viz_test::make_walk(m, 3.0, 0.01, 1.0);
  const int j = m.dof_index("lknee");
  // A torque known in closed form: 10 sin(2 pi t) + 3 N m.
  for (auto& f : traj.frames) {
    f.tau = Eigen::VectorXd::Zero(m.nv());
    f.tau[planar_root::nv + j] = 10.0 * std::sin(2 * std::numbers::pi * f.t) + 3.0;
  }
  gait_cycle_options o;
  o.cycle_starts = {0.5, 1.5, 2.5};
  o.samples = 11;
  o.channels = {{.type = gait_channel::kind::joint_torque, .name = "lknee", .scale = -0.5}};
  const gait_cycle_data d = gait_cycles(m, traj, o);
  REQUIRE(d.num_cycles() == 2);
  for (std::size_t s = 0; s < d.percent.size(); ++s) {
    const double t = 0.5 + d.percent[s] / 100.0;
    CHECK(d.mean[0][s] ==
          Approx(-0.5 * (10.0 * std::sin(2 * std::numbers::pi * t) + 3.0)).margin(1e-9));
  }
  traj.frames[3].tau.resize(0);  // a frame recorded without torques
  CHECK_THROWS_WITH(gait_cycles(m, traj, o),
                    Catch::Contains("lknee") && Catch::Contains("no recorded torques"));
}

TEST_CASE("gait_cycles: a trajectory without strikes has no cycle, not an error", "[viz][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  auto traj = viz_test::make_walk(m, 0.3, 0.01, 1.0);
  for (auto& f : traj.frames) std::fill(f.contact_active.begin(), f.contact_active.end(), 0);
  const auto d = gait_cycles(m, traj);
  CHECK(d.num_cycles() == 0);
  CHECK(d.curves[0].empty());
}
