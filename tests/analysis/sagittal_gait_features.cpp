// sagittal_gait_features_of (analysis/sagittal_gait_features.hpp): Wang et al. 2012 Sec. 6.2's
// comparison numbers from a hand-built mean cycle, channels found by label, bad input refused.
#include <catch2/catch.hpp>

#include <vector>

#include "gaitsynth/analysis/sagittal_gait_features.hpp"
#include "gaitsynth/analysis/standard_score.hpp"

using namespace gaitsynth;

namespace {

/// One cycle of 101 points (percent 0..100) with the channels of human_sagittal_channels in the
/// order ankle, knee, hip (not the usual one: channels are found by label).
gait_cycle_data hand_cycle() {
  gait_cycle_data g;
  const std::vector<gait_channel> c = human_sagittal_channels("l");
  g.channels = {c[2], c[1], c[0]};
  g.cycle_starts = {2.0, 3.1};
  std::vector<double> ankle, knee, hip;
  for (int i = 0; i <= 100; ++i) {
    g.percent.push_back(i);
    ankle.push_back(i >= 90 ? 10.0 + (i - 90) : -5.0);  // 10..20 in terminal swing: mean 15
    knee.push_back(i < 15 ? 30.0 : i <= 50 ? 5.0 + (i - 15) * 0.2 : 60.0 - (i - 50) * 0.1);
    hip.push_back(0.0);
  }
  g.mean = {ankle, knee, hip};
  return g;
}

}  // namespace

TEST_CASE("sagittal_gait_features_of: the mid-stance, swing and terminal-swing numbers",
          "[analysis]") {
  const sagittal_gait_features f = sagittal_gait_features_of(hand_cycle());
  CHECK(f.knee_flexion_mid_stance_min == Approx(5.0));   // at 15 %
  CHECK(f.knee_flexion_mid_stance_mean == Approx(8.5));  // 5 .. 12 linearly
  CHECK(f.knee_flexion_swing_max == Approx(58.8));       // at 62 %: 60 - 1.2
  CHECK(f.ankle_dorsiflexion_terminal_swing_mean == Approx(15.0));
}

TEST_CASE("sagittal_gait_features_of: a missing channel or no cycle is refused", "[analysis]") {
  gait_cycle_data g = hand_cycle();
  g.channels[1].label = "knee_angle";
  CHECK_THROWS_WITH(sagittal_gait_features_of(g), Catch::Contains("'knee_flexion_angle'"));
  g = hand_cycle();
  g.cycle_starts = {2.0};
  CHECK_THROWS_WITH(sagittal_gait_features_of(g), Catch::Contains("no complete gait cycle"));
}
