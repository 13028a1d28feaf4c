// compare_with_human (analysis/human_gait_comparison.hpp): a hand-made walk of the 30-DOF humanoid
// whose joints follow the adult data's mean curves (and its moments, times the model's mass)
// scores 0 on every channel; the knee one s.d. above and the ankle moment two below score 1 and
// 2; the start's transient (t < t_from) is left out; bad input is refused by name.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gaitsynth/analysis/human_gait_comparison.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/wang2009.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

const normative_gait& adult() {
  static const normative_gait h = load_normative_gait(
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv");
  return h;
}

/// y(p) of a curve by linear interpolation (the data's grid is not 0, 1, ..., 100 exactly).
double at(const normative_curve& c, double p, double sd_offset) {
  return detail::interpolate_curve(c.percent, c.mean, p) +
         sd_offset * detail::interpolate_curve(c.percent, c.sd, p);
}

/// 1000 frames per second for `seconds`; one gait cycle per second from t = 0. Before t = 1 s the
/// joints sit at 30 degrees from the data (a transient that t_from must leave out).
trajectory hand_walk(const floating_model& m, double seconds, double knee_sd, double ankle_sd) {
  constexpr double deg = std::numbers::pi / 180.0;
  const normative_gait& h = adult();
  const double mass = m.total_mass();
  trajectory tr;
  for (int f = 0; f <= static_cast<int>(seconds * 1000); ++f) {
    trajectory_frame fr;
    fr.t = f / 1000.0;
    fr.q = neutral_configuration(m);
    fr.v = Eigen::VectorXd::Zero(m.nv());
    fr.tau = Eigen::VectorXd::Zero(m.nv());
    const double p = 100.0 * (fr.t - std::floor(fr.t));
    const double junk = fr.t < 1.0 ? 30.0 : 0.0;
    auto set = [&](const char* dof, double sign, double angle_deg, double moment_per_kg) {
      const int j = m.dof_index(std::string("l") + dof);
      fr.q[floating_root::nq + j] = sign * (angle_deg + junk) * deg;
      fr.tau[floating_root::nv + j] = sign * (moment_per_kg + junk) * mass;
    };
    set("hip_y", -1.0, at(h.curve("hip_flexion_angle"), p, 0.0),
        at(h.curve("hip_flexion_moment_per_kg"), p, 0.0));
    set("knee", 1.0, at(h.curve("knee_flexion_angle"), p, knee_sd),
        at(h.curve("knee_flexion_moment_per_kg"), p, 0.0));
    set("ankle_y", -1.0, at(h.curve("ankle_dorsiflexion_angle"), p, 0.0),
        at(h.curve("ankle_dorsiflexion_moment_per_kg"), p, ankle_sd));
    tr.frames.push_back(std::move(fr));
  }
  return tr;
}

}  // namespace

TEST_CASE("compare_with_human: the data's own curves score 0, offsets by s.d. score their size",
          "[analysis]") {
  const floating_model m = wang2009_humanoid();
  human_comparison_options o;
  o.t_from = 1.0;
  o.cycle_starts = {1.0, 2.0, 3.0, 4.0};
  const human_gait_comparison same = compare_with_human(m, hand_walk(m, 4.0, 0.0, 0.0), adult(), o);
  REQUIRE(same.labels == std::vector<std::string>{
                             "hip_flexion_angle", "knee_flexion_angle", "ankle_dorsiflexion_angle",
                             "hip_flexion_moment_per_kg", "knee_flexion_moment_per_kg",
                             "ankle_dorsiflexion_moment_per_kg"});
  REQUIRE(same.cycles.num_cycles() == 3);
  REQUIRE(same.scores.size() == 6);
  // Not exactly 0: the data's cycle does not close (its 100 % value is not its 0 % one), and the
  // walk's 100 % point is the next cycle's 0 %; with resampling at 1 ms that leaves up to 0.016
  // s.d. (the moments), 0.002-0.004 for the angles.
  for (std::size_t k = 0; k < 6; ++k) {
    INFO(same.labels[k]);
    CHECK_THAT(same.scores[k], WithinAbs(0.0, 0.02));
  }
  const human_gait_comparison off = compare_with_human(m, hand_walk(m, 4.0, 1.0, -2.0), adult(), o);
  REQUIRE(off.scores.size() == 6);
  CHECK_THAT(off.scores[0], WithinAbs(0.0, 0.02));
  CHECK_THAT(off.scores[1], WithinAbs(1.0, 0.02));
  CHECK_THAT(off.scores[5], WithinAbs(2.0, 0.02));
  // The signed mean differences: the knee lies one s.d. above (its mean s.d. over the cycle), the
  // ankle moment two below, the hip on the data.
  const normative_curve& knee = adult().curve("knee_flexion_angle");
  const normative_curve& ankle = adult().curve("ankle_dorsiflexion_moment_per_kg");
  double knee_sd = 0.0, ankle_sd = 0.0;
  for (int i = 0; i < 100; ++i) {
    knee_sd += detail::interpolate_curve(knee.percent, knee.sd, 100.0 * i / 99) / 100;
    ankle_sd += detail::interpolate_curve(ankle.percent, ankle.sd, 100.0 * i / 99) / 100;
  }
  REQUIRE(off.mean_differences.size() == 6);
  CHECK_THAT(off.mean_differences[0], WithinAbs(0.0, 0.01));
  CHECK_THAT(off.mean_differences[1], WithinAbs(knee_sd, 0.01 * knee_sd));
  CHECK_THAT(off.mean_differences[5], WithinAbs(-2.0 * ankle_sd, 0.02 * ankle_sd));

  // With the transient kept (t_from 0 and a cycle from 0), the knee lies far off.
  o.t_from = 0.0;
  o.cycle_starts = {0.0, 1.0, 2.0, 3.0, 4.0};
  const human_gait_comparison all = compare_with_human(m, hand_walk(m, 4.0, 0.0, 0.0), adult(), o);
  CHECK(all.scores[1] > 1.0);
}

TEST_CASE("compare_with_human: no complete cycle leaves no scores", "[analysis]") {
  const floating_model m = wang2009_humanoid();
  human_comparison_options o;
  o.t_from = 1.0;
  o.cycle_starts = {1.0};
  const human_gait_comparison c = compare_with_human(m, hand_walk(m, 2.0, 0.0, 0.0), adult(), o);
  CHECK(c.cycles.num_cycles() == 0);
  CHECK(c.scores.empty());
  CHECK(c.mean_differences.empty());
  CHECK(c.labels.size() == 6);
}

TEST_CASE("compare_with_human: bad input is refused by name", "[analysis][bad_input]") {
  const floating_model m = wang2009_humanoid();
  const trajectory tr = hand_walk(m, 2.0, 0.0, 0.0);
  human_comparison_options o;
  o.side = "left";
  CHECK_THROWS_WITH(compare_with_human(m, tr, adult(), o), Contains("\"left\""));
  o = {};
  o.t_from = NAN;
  CHECK_THROWS_WITH(compare_with_human(m, tr, adult(), o), Contains("t_from"));
  normative_gait partial = adult();
  std::erase_if(partial.curves, [](const normative_curve& c) {
    return c.variable == "knee_flexion_moment_per_kg";
  });
  CHECK_THROWS_WITH(compare_with_human(m, tr, partial, {}), Contains("knee_flexion_moment_per_kg"));
}
