// analysis/arm_swing.hpp on hand-made trajectories whose segment pitches are known, and on two
// saved walkers of Wang et al. 2009.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gaitsynth/analysis/arm_swing.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

namespace {

/// 100 Hz frames over [0, 2) s at 1 Hz: the left arm pitches by a sin(wt), the right arm by -a
/// sin(wt); the thighs by +-0.5 sin(wt + lag), the right thigh with the left arm's sign.
trajectory swing(const floating_model& m, double a, double lag) {
  trajectory tr;
  const auto pose = [](double pitch) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()));
  };
  for (int k = 0; k < 200; ++k) {
    trajectory_frame f;
    f.t = 0.01 * k;
    f.body_orientation.assign(static_cast<std::size_t>(m.num_bodies()),
                              Eigen::Quaterniond::Identity());
    const double s = std::sin(2 * std::numbers::pi * f.t);
    const double sl = std::sin(2 * std::numbers::pi * f.t + lag);
    f.body_orientation[static_cast<std::size_t>(m.body_index("lupper_arm"))] = pose(a * s);
    f.body_orientation[static_cast<std::size_t>(m.body_index("rupper_arm"))] = pose(-a * s);
    f.body_orientation[static_cast<std::size_t>(m.body_index("rthigh"))] = pose(0.5 * sl);
    f.body_orientation[static_cast<std::size_t>(m.body_index("lthigh"))] = pose(-0.5 * sl);
    tr.frames.push_back(f);
  }
  return tr;
}

}  // namespace

TEST_CASE("arm_swing: correlations and amplitude of known swings", "[analysis][arm_swing]") {
  const floating_model m = wang2009_humanoid(wang2009_preset("stocky"));
  // Each arm with the opposite thigh: the human pattern.
  const arm_swing_report human = arm_swing(m, swing(m, 0.3, 0.0));
  CHECK(human.opposite_leg_correlation == Approx(1.0));
  CHECK(human.same_leg_correlation == Approx(-1.0));
  CHECK(human.arm_pitch_amplitude == Approx(0.3).epsilon(1e-3));
  CHECK(human.frames == 200);
  // Each arm with its own thigh (the legs half a cycle later): the "wrong legs" of Fig. 4.
  const arm_swing_report wrong = arm_swing(m, swing(m, 0.2, std::numbers::pi), 1.0);
  CHECK(wrong.opposite_leg_correlation == Approx(-1.0));
  CHECK(wrong.same_leg_correlation == Approx(1.0));
  CHECK(wrong.arm_pitch_amplitude == Approx(0.2).epsilon(1e-3));
  CHECK(wrong.frames == 100);  // one whole cycle from 1 s
  // A quarter cycle apart: uncorrelated.
  const arm_swing_report quarter = arm_swing(m, swing(m, 0.3, std::numbers::pi / 2));
  CHECK(std::abs(quarter.opposite_leg_correlation) < 1e-9);
  // Arms held still: no swing, correlation 0, not NaN.
  const arm_swing_report still = arm_swing(m, swing(m, 0.0, 0.0));
  CHECK(still.opposite_leg_correlation == 0.0);
  CHECK(still.arm_pitch_amplitude == 0.0);
}

TEST_CASE("arm_swing: bad input is named", "[analysis][arm_swing]") {
  const floating_model m = wang2009_humanoid(wang2009_preset("stocky"));
  const trajectory tr = swing(m, 0.3, 0.0);
  CHECK_THROWS_WITH(arm_swing(m, tr, 0.0, {.left_arm = "lwing"}), Catch::Contains("lwing"));
  CHECK_THROWS_WITH(arm_swing(m, tr, 1.99),
                    Catch::Contains("1 frames") && Catch::Contains("at least 3"));
  trajectory bare = tr;
  bare.frames[150].body_orientation.clear();
  CHECK_THROWS_WITH(arm_swing(m, bare),
                    Catch::Contains("t = 1.5") && Catch::Contains("record body poses"));
}
