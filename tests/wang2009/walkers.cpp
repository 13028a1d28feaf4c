// The claims of Wang, Fleet & Hertzmann 2009 (issue 11), checked on the optimized walkers saved in
// data/wang2009/walkers/ (written by examples/wang2009_walk.cpp; docs/reproductions/wang2009.md
// has the commands). Each test re-simulates a walker without optimizing anything.
//
// "Walks 100 s" is the library's walked() (rollout/walk_check.hpp): the 100 s rollout ends at its
// horizon, not by a fall (COM below E_fail's height), divergence or a stall (less than 0.1 m of
// progress in a 5 s window). Every walker is also walked from 10 starts whose joint velocities are
// perturbed by a seeded N(0, 0.05 rad/s) (rollout/start_perturbations.hpp, seed 2009; the
// optimizations never saw these starts), and the test checks the number that walk against the
// number the reproduction page reports. The speed, step length, power ratio (eqs. 13-14) and
// push-off are checked against the page's figures too, so the page cannot drift from the data.
//
// Under the sanitizers (GAITSYNTH_SANITIZED_BUILD) each walker walks its 10 s once: eleven 100 s
// walks per walker take minutes there and check the same code paths; the Release suite checks
// the claims.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "gaitsynth/analysis/ankle_push_off.hpp"
#include "gaitsynth/analysis/arm_swing.hpp"
#include "gaitsynth/analysis/torso_lean.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

using namespace gaitsynth;

namespace {

/// What docs/reproductions/wang2009.md reports for a walker.
struct reported {
  const char* file;              ///< under data/wang2009/walkers/
  double speed;                  ///< m/s over the 100 s walk
  double step_length;            ///< m
  std::array<double, 3> ratio;   ///< hip, knee, ankle (eqs. 13-14)
  int perturbed_walked;          ///< of the 10 perturbed starts, those that walk 100 s
  std::array<bool, 2> push_off;  ///< left, right: the ankle's mean power curve peaks in late stance
  bool human_ratio = false;      ///< claimed: every component within 0.05 of [0.43, 0.04, 0.53]
  /// The torso's mean world pitch after 2 s, degrees, when the page reports it (within 1.5).
  std::optional<double> torso_pitch_deg = std::nullopt;
  /// Where both ankles' mean power curves peak, as a fraction of stance (the start of the peak
  /// tenth), at least, when the page claims it.
  std::optional<double> push_off_peak_from = std::nullopt;
  /// The pelvis's mean world pitch after 2 s, degrees, when the page reports it (within 1.5).
  std::optional<double> pelvis_pitch_deg = std::nullopt;
};

template <class Terrain>
void check_walker_on(const reported& w, const Terrain& ground) {
  const std::string path = std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/walkers/" + w.file;
  const std::string shape = wang2009_saved_shape(path);
  const floating_model m = wang2009_humanoid(wang2009_preset(shape));
  wang2009_controller c(m);
  const wang2009_saved_controller saved = load_wang2009_controller(path, c);
  const std::vector<double>& p = saved.parameters;
  c.bind(p);
  wang2009_objective_options oo;
  oo.target_speed = saved.target_speed;
  oo.target_step_length = saved.target_step_length;
  oo.fail_height = wang2009_fail_height(shape);
  const auto obj = wang2009_objective(m, oo);
  rollout_options opt = wang2009_rollout_options(m, oo.fail_height);
  // The ground it was optimized on: friction and slope from the file (check_walker).
  opt.contact.mu = saved.info.value("mu", 10.0);
  auto scratch = make_rollout_scratch(m);
  semi_implicit_euler integ;
#ifdef GAITSYNTH_SANITIZED_BUILD
  wang2009_controller c10 = c;
  const rollout_result r10 = rollout(m, mixed_pd_actuator{}, c10, obj, ground, integ,
                                     std::span<const double>(p), opt, scratch);
  CHECK(r10.reason == stop_reason::horizon);
  return;
#endif
  opt.duration = 100.0;
  opt = walk_options(opt);  // rollout/walk_check.hpp: a stall is not a walk

  trajectory tr;
  opt.record = &tr;
  opt.record_every = 40;
  rollout_policy_states<mixed_pd_actuator, wang2009_controller, wang2009_objective_type> states;
  wang2009_controller cc = c;
  const rollout_result r = rollout(m, mixed_pd_actuator{}, cc, obj, ground, integ,
                                   std::span<const double>(p), opt, scratch, states);
  INFO(w.file << ": " << to_string(r.reason) << " after " << r.time << " s");
  REQUIRE(walked(r));
  const wang2009_breakdown rep = wang2009_report(obj, *states.objective, r, opt);
  // The page reports what GCC 12 -O3 (CI's build) measures. A 100 s walk is chaotic: clang 14
  // and GCC with FMA contraction (-ffp-contract=fast -march=x86-64-v3) retrace it with averages
  // up to 3.4 % (speed, step) and 0.011 (a ratio component) away from those
  // (scripts/claims_other_builds.sh, 2026-12-03), so the reported values are checked to 5 % and
  // 0.02, which every build meets; the claims (100 s, the perturbed starts, the human ratio
  // within 0.05, push-off) are checked as stated.
  CHECK(rep.average_speed == Approx(w.speed).epsilon(0.05));
  CHECK(rep.step_length == Approx(w.step_length).epsilon(0.05));
  for (int k = 0; k < 3; ++k) CHECK(rep.power_ratio[k] == Approx(w.ratio[k]).margin(0.02));
  constexpr std::array<double, 3> r_walk{0.43, 0.04, 0.53};  // eq. 15, Novacheck 1998
  if (w.human_ratio)
    for (int k = 0; k < 3; ++k) CHECK(std::abs(rep.power_ratio[k] - r_walk[k]) <= 0.05);
  if (w.torso_pitch_deg)
    CHECK(torso_lean(m, tr, 2.0).mean_pitch * 180.0 / std::numbers::pi ==
          Approx(*w.torso_pitch_deg).margin(1.5));
  if (w.pelvis_pitch_deg)
    CHECK(torso_lean(m, tr, 2.0, "pelvis").mean_pitch * 180.0 / std::numbers::pi ==
          Approx(*w.pelvis_pitch_deg).margin(1.5));
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? "l" : "r";
    const ankle_push_off_report a = ankle_push_off(m, tr, s + "ankle_y", s + "foot", s + "toes");
    INFO(s << " ankle: mean power curve peaks at " << a.mean_curve_peak_fraction << " of stance");
    CHECK(a.stances.size() > 50u);
    CHECK((a.mean_curve_peak_fraction >= 0.5) == w.push_off[static_cast<std::size_t>(side)]);
    if (w.push_off_peak_from) CHECK(a.mean_curve_peak_fraction >= *w.push_off_peak_from - 1e-9);
  }

  opt.record = nullptr;
  int walking = 0;
  int k = 0;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2009)) {
    opt.initial_velocity_offset = dv;
    wang2009_controller ck = c;
    const rollout_result rk = rollout(m, mixed_pd_actuator{}, ck, distance_objective(), ground,
                                      integ, std::span<const double>(p), opt, scratch);
    UNSCOPED_INFO("perturbed start " << k++ << ": " << to_string(rk.reason) << " after " << rk.time
                                     << " s");
    walking += walked(rk);
  }
  // Every claimed walker walks from at least 8 of the 10 perturbed starts (issue 15's rule; the
  // page gives the count of CI's build, other builds' rounding may lose one or two above 8). A
  // walker below that is a run record, not a claim (Fig. 4 without E_ang, the first overweight).
  INFO(walking << " of 10 perturbed starts walk; the page reports " << w.perturbed_walked);
  REQUIRE(w.perturbed_walked >= 8);
  CHECK(walking >= 8);
}

/// Checks walker w on the ground it was optimized on: its info's slope (uphill along +x).
void check_walker(const reported& w) {
  const std::string path = std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/walkers/" + w.file;
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  const double slope_deg =
      load_wang2009_controller(path, wang2009_controller(m)).info.value("slope_deg", 0.0);
  if (slope_deg == 0.0) return check_walker_on(w, flat_terrain{});
  check_walker_on(w, slope_terrain(slope_deg * std::numbers::pi / 180.0));
}

/// The saved controller `file` (under data/wang2009/) walked for `seconds` on `ground` with
/// friction mu, recorded into `record` when given: how the rollout ended.
template <class Terrain>
rollout_result walk_saved(const std::string& file, const Terrain& ground, double mu, double seconds,
                          trajectory* record = nullptr) {
  const std::string path = std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/" + file;
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  wang2009_controller c(m);
  const std::vector<double> p = load_wang2009_controller(path, c).parameters;
  rollout_options opt = wang2009_rollout_options(m);
  opt.contact.mu = mu;
  opt.duration = seconds;
  opt.record = record;
  opt.record_every = 40;
  auto scratch = make_rollout_scratch(m);
  semi_implicit_euler integ;
  return rollout(m, mixed_pd_actuator{}, c, distance_objective(), ground, integ,
                 std::span<const double>(p), opt, scratch);
}

/// The saved controller `file` (under data/wang2009/) on flat ground at mu = 10 for `seconds`, from
/// its own start and then from the claim tests' first `perturbed` perturbed starts (seed 2009),
/// ended by rollout/walk_check.hpp's stall rule too when `walk_rule`: the own start's end first.
std::vector<rollout_result> walk_saved_from_starts(const std::string& file, double seconds,
                                                   int perturbed, bool walk_rule) {
  const std::string path = std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/" + file;
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  wang2009_controller c(m);
  const std::vector<double> p = load_wang2009_controller(path, c).parameters;
  rollout_options opt = wang2009_rollout_options(m);
  opt.duration = seconds;
  if (walk_rule) opt = walk_options(opt);
  auto scratch = make_rollout_scratch(m);
  std::vector<Eigen::VectorXd> starts{Eigen::VectorXd()};
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, perturbed, 0.05, 2009))
    starts.push_back(dv);
  std::vector<rollout_result> out;
  for (const Eigen::VectorXd& dv : starts) {
    opt.initial_velocity_offset = dv;
    wang2009_controller ck = c;
    out.push_back(rollout(m, mixed_pd_actuator{}, ck, distance_objective(), flat_terrain{},
                          semi_implicit_euler{}, std::span<const double>(p), opt, scratch));
  }
  return out;
}

/// The saved walker `file` (under data/wang2009/walkers/) on flat ground with its optimization's
/// settings: calls check(trial), where trial(force, velocity_offset) runs Table 1's protocol
/// (rollout/push_test.hpp: 40 s, a 0.4 s push of `force` to the torso every 4 s) from the start
/// offset by velocity_offset (empty: its own start).
template <class Check>
void with_saved_push_trial(const std::string& file, Check&& check) {
  const std::string path = std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/walkers/" + file;
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  wang2009_controller c(m);
  const std::vector<double> p = load_wang2009_controller(path, c).parameters;
  const rollout_options opt =
      wang2009_rollout_options(m, wang2009_fail_height(wang2009_saved_shape(path)));
  const int torso = m.body_index("torso");
  check(m, [&](const vec3& force, const Eigen::VectorXd& velocity_offset) {
    rollout_options o = opt;
    o.initial_velocity_offset = velocity_offset;
    return push_trial_run(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                          std::span<const double>(p), o, torso, force);
  });
}

/// Table 1's protocol on the saved walker `file` from its own start, with `forces[k]` newtons
/// along Table 1's direction k: it must pass in each. The Release suite checks it; a sanitized
/// build only runs the walk of check_walker, the same code paths.
void check_survives_table1(const std::string& file, const std::array<double, 8>& forces) {
#ifdef GAITSYNTH_SANITIZED_BUILD
  (void)file;
  (void)forces;
  return;
#endif
  with_saved_push_trial(file, [&](const floating_model&, const auto& trial) {
    for (std::size_t k = 0; k < 8; ++k) {
      const push_trial t = trial(forces[k] * table1_directions()[k], Eigen::VectorXd());
      INFO(file << ", direction " << table1_directions()[k].transpose() << " at " << forces[k]
                << " N: " << to_string(t.result.reason) << " after " << t.result.time
                << " s, final speed " << t.final_speed << " m/s");
      CHECK(t.passed);
    }
  });
}

/// Table 1 beyond one rounding: along Table 1's direction k at `forces[k]` newtons, at least
/// `required` of the 10 perturbed starts (seed 2009) pass the protocol. The page's figures are
/// `wang2009_push_test --perturbed 10`'s: the largest force that 8 of 10 starts survive at every
/// force up to it; this checks that force itself (the scan's last level). A direction stops as
/// soon as its verdict is known. Release only, as above.
void check_survives_table1_from_starts(const std::string& file, const std::array<double, 8>& forces,
                                       int required = 8) {
#ifdef GAITSYNTH_SANITIZED_BUILD
  (void)file;
  (void)forces;
  (void)required;
  return;
#endif
  with_saved_push_trial(file, [&](const floating_model& m, const auto& trial) {
    const std::vector<Eigen::VectorXd> starts = joint_velocity_perturbations(m, 10, 0.05, 2009);
    for (std::size_t k = 0; k < 8; ++k) {
      int passed = 0, failed = 0;
      for (std::size_t i = 0; i < starts.size() && passed < required && failed <= 10 - required;
           ++i)
        (trial(forces[k] * table1_directions()[k], starts[i]).passed ? passed : failed) += 1;
      INFO(file << ", direction " << table1_directions()[k].transpose() << " at " << forces[k]
                << " N: " << passed << " perturbed starts passed before the verdict, " << failed
                << " failed");
      CHECK(passed >= required);
    }
  });
}

/// A level walker (optimized on flat ground, mu = 10; by default the stocky walker of Table 2) for
/// 30 s on `ground` with friction mu.
template <class Terrain>
rollout_result stocky_walker_on(const Terrain& ground, double mu,
                                const char* file = "stocky_table2.controller.json") {
  return walk_saved(std::string("walkers/") + file, ground, mu, 30.0);
}

}  // namespace

TEST_CASE("wang2009: the Table 2 stocky walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"stocky_table2.controller.json", 1.378, 0.568, {0.794, 0.103, 0.104}, 10, {false, false}});
}

// Ours: the Table 2 walker, 1000 iterations with E_ratio's weight 10 instead of 1. It reaches
// the human power ratio (the claim 2) but not the push-off, with short steps.
TEST_CASE("wang2009: the stocky walker with the human power ratio walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_human_ratio.controller.json",
                1.183,
                0.341,
                {0.433, 0.040, 0.527},
                9,
                {false, false},
                true});
}

// Ours: the human-ratio walker, 1000 iterations with E_posture (the torso's tilt beyond
// 0.15 rad) weighted 10 beside E_ratio's 10. It stands upright (2 degrees against 31), with
// short, quick steps; its plantarflexors' power peaks at 40-50 % of stance, not in late stance.
TEST_CASE("wang2009: the upright stocky walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_upright.controller.json",
                0.985,
                0.220,
                {0.428, 0.044, 0.528},
                10,
                {false, false},
                true,
                2.2});
}

// Its steps lengthened by a continuation: 400 iterations at a 0.3 m target, 400 at 0.4 m.
TEST_CASE("wang2009: the upright walker after the 0.4 m step stage walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_upright_step04.controller.json",
                1.651,
                0.363,
                {0.422, 0.048, 0.530},
                10,
                {false, false},
                true,
                6.9});
}

// Ours: the 0.4 m step walker with c_trans raised stage by stage from -0.05 to 0.026 m (two
// perturbed starts in every cost; data/wang2009/runs/stocky_upright_ctrans/). State 1 now begins
// once the COM is past the stance ankle, and the plantarflexors' power peaks at 50-60 % of
// stance on both sides: the late-stance push-off of claim 2, with the human ratio.
TEST_CASE("wang2009: the push-off walker walks 100 s and pushes off in late stance",
          "[wang2009][claim]") {
  check_walker({"stocky_push_off.controller.json",
                1.769,
                0.302,
                {0.434, 0.044, 0.521},
                10,
                {true, true},
                true,
                -1.5});
}

// The c_trans continuation on (ours): two more stages on 20 s evaluations with three perturbed
// starts in every candidate's cost, to c_trans >= 0.05 m (session 27). The plantarflexors' power
// peaks at 70-80 % of stance (a person's: 80-90 %), with the human ratio, upright.
TEST_CASE("wang2009: the late push-off walker walks 100 s and pushes off at 70-80 % of stance",
          "[wang2009][claim]") {
  check_walker({"stocky_late_push_off.controller.json",
                1.671,
                0.239,
                {0.416, 0.048, 0.536},
                10,
                {true, true},
                true,
                -7.0,
                0.7});
}

// One more stage from it with E_pelvis (ours, the pelvis's tilt) weighted 10 as well (session 28):
// the pelvis stays tilted back (-15 degrees against -17) but the plantarflexors' power now peaks
// at 80-90 % of stance, a person's tenth, on both ankles, with the human ratio.
TEST_CASE("wang2009: the 80-90 % push-off walker walks 100 s and pushes off at 80-90 % of stance",
          "[wang2009][claim]") {
  check_walker({"stocky_push_off_80.controller.json",
                1.822,
                0.241,
                {0.429, 0.051, 0.520},
                10,
                {true, true},
                true,
                -4.5,
                0.8});
}

// And one more with E_pelvis weighted 100 (60 iterations): the pelvis within 8 degrees of level
// (-7.7, from -15.3), the torso upright, the push-off still at 80-90 % with less before it.
TEST_CASE("wang2009: the 80-90 % push-off walker with a levelled pelvis walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_push_off_80_pelvis.controller.json",
                1.884,
                0.237,
                {0.427, 0.046, 0.527},
                10,
                {true, true},
                true,
                -0.4,
                0.8,
                -7.7});
}

// The upright walker asked for 0.6 m steps at once (1000 iterations): longer steps, the ratio
// and a nearly upright torso kept.
TEST_CASE("wang2009: the upright walker with longer steps walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_upright_step06.controller.json",
                1.697,
                0.500,
                {0.423, 0.058, 0.519},
                10,
                {false, false},
                true,
                10.7});
}

// The same with the step-length target of the paper's slope continuation (0.65 m): the best of
// the first 520 iterations (the run's final best falls at 18.6 s).
TEST_CASE("wang2009: the level stocky walker for the slope continuation walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_step065.controller.json",
                1.553,
                0.521,
                {0.434, 0.056, 0.510},
                10,
                {false, false},
                true});
}

// The paper's own weights (E_ratio back to 1) from that walker, 500 iterations: the ratio stays
// near the human one (the ankle 0.052 from it) and the steps reach the 0.65 m target.
TEST_CASE("wang2009: the 0.65 m walker at the paper's weights walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_step065_paper_weights.controller.json",
                1.844,
                0.637,
                {0.473, 0.048, 0.478},
                10,
                {false, false}});
}

// Sec. 5, "Changing terrain": the uphill continuation from the level 0.65 m walker, 3 degrees
// at a time, 300 iterations each, with the 0.65 m step target (E_ratio weighted 10, as its
// start). The 3 degree stage walks its 10 s and falls at 21.9 s (a run record only, as the
// paper's intermediate slopes were "not run to convergence"); 6, 9 and 12 degrees walk 100 s.
// Each is walked up its own slope (info.slope_deg).
TEST_CASE("wang2009: the 6 degree uphill walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_slope06.controller.json",
                1.622,
                0.616,
                {0.441, 0.031, 0.528},
                8,
                {false, false},
                true});
}

TEST_CASE("wang2009: the 9 degree uphill walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_slope09.controller.json",
                1.662,
                0.630,
                {0.443, 0.029, 0.528},
                10,
                {false, false},
                true});
}

TEST_CASE("wang2009: the 12 degree uphill walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_slope12.controller.json",
                1.744,
                0.630,
                {0.445, 0.031, 0.524},
                10,
                {false, false},
                true});
}

// Beyond the paper: robust optimization (2 perturbed starts, 4 push sequences of 40 N per
// candidate) from the human-ratio walker, 150 iterations. Stronger, but the ratio drifts just
// outside 0.05 (hip 0.480, ankle 0.474).
TEST_CASE("wang2009: the robust human-ratio walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_robust_ratio.controller.json",
                0.993,
                0.319,
                {0.480, 0.046, 0.474},
                10,
                {false, false}});
}

// Beyond the paper: Table 1's push structure in training (eight rollouts of 14 s, each pushing
// one direction with 60 N every 4 s, the phase redrawn every iteration, one perturbed start), 90
// iterations from the robust human-ratio walker; CMA's mean at 90. Stronger than the paper's
// optimized stocky walker in every direction of Table 1, at the cost of a hip-driven ratio.
TEST_CASE("wang2009: the Table 1-trained walker walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_robust_table1.controller.json",
                1.129,
                0.412,
                {0.640, 0.025, 0.335},
                10,
                {false, false}});
}

TEST_CASE("wang2009: the Table 1-trained walker survives the paper's stocky column of Table 1",
          "[wang2009][claim]") {
  // The page's scan finds this walker's largest forces at or above them in every direction
  // (equal in (1,1) and (-1,1)).
  check_survives_table1("stocky_robust_table1.controller.json", {50, 65, 125, 75, 50, 50, 125, 50});
}

TEST_CASE("wang2009: the Table 1-trained walker's forces from perturbed starts",
          "[wang2009][claim]") {
  // The page's scan from 10 perturbed starts (8 of 10 at every force up to these): at or above
  // the paper's stocky column in seven directions, not (-1,1) (65 against 75 N).
  check_survives_table1_from_starts("stocky_robust_table1.controller.json",
                                    {70, 65, 160, 65, 75, 65, 140, 65});
}

// The human-ratio walker of the 30 s stage trained with Table 1's structure (50 N, then 80 N; one
// perturbed start) with the power ratio as a constraint instead of a penalty (`--ratio-within
// 0.04`, rollout/problem_with_constraint.hpp): CMA's mean at 100 of the 80 N stage
// (data/wang2009/runs/stocky_ratio_constraint80/). It keeps the human ratio and is stronger than
// the paper's optimized stocky walker in six directions of eight.
TEST_CASE("wang2009: the ratio-constrained push walker walks 100 s with the human ratio",
          "[wang2009][claim]") {
  check_walker({"stocky_ratio_constraint.controller.json",
                1.175,
                0.328,
                {0.436, 0.030, 0.534},
                10,
                {false, false},
                true,
                33.0});
}

TEST_CASE("wang2009: the ratio-constrained push walker survives its Table 1 forces",
          "[wang2009][claim]") {
  // The page's scan (5 N steps): at or above the paper's stocky column (50, 65, 125, 75, 50, 50,
  // 125, 50) in all but (0,1) and (0,-1); the library's SIMBICON's in (1,0) and (-1,1).
  check_survives_table1("stocky_ratio_constraint.controller.json",
                        {85, 85, 105, 80, 105, 90, 105, 85});
}

TEST_CASE("wang2009: the ratio-constrained push walker's forces from perturbed starts",
          "[wang2009][claim]") {
  // The page's scan from 10 perturbed starts (8 of 10 at every force up to these): at or above
  // the paper's stocky column in all but (0,1) and (0,-1), as from its own start.
  check_survives_table1_from_starts("stocky_ratio_constraint.controller.json",
                                    {80, 85, 100, 85, 100, 85, 105, 85});
}

// One more stage of the same at 100 N (data/wang2009/runs/stocky_ratio_constraint100/, CMA's mean
// at 80): the robust goal, the human ratio within 0.05 and the library's SIMBICON's Table
// 1 force (75, 100, 150, 75, 150, 125, 200, 100) in six directions of eight (not (-1,0), (0,-1)).
TEST_CASE("wang2009: the 100 N ratio-constrained walker walks 100 s with the human ratio",
          "[wang2009][claim]") {
  check_walker({"stocky_ratio_constraint100.controller.json",
                1.433,
                0.363,
                {0.444, 0.023, 0.533},
                10,
                {false, false},
                true,
                33.5});
}

TEST_CASE("wang2009: the 100 N ratio-constrained walker survives its Table 1 forces",
          "[wang2009][claim]") {
  // The page's scan (5 N steps) from its own start; at or above the library's SIMBICON on the
  // same grid (75, 110, 160, 95, 160, 125, 165, 120) in five directions of eight.
  check_survives_table1("stocky_ratio_constraint100.controller.json",
                        {120, 125, 155, 115, 140, 125, 155, 125});
}

TEST_CASE(
    "wang2009: the 100 N ratio-constrained walker, SIMBICON's force in 6 of 8 from "
    "perturbed starts",
    "[wang2009][claim]") {
  // The robust goal, beyond one start: the page's scan from 10 perturbed starts (8 of 10
  // at every force up to these) is at or above the library's SIMBICON's, from the same starts
  // (75, 105, 180, 95, 130, 90, 165, 105), in all but (0,1) and (0,-1).
  check_survives_table1_from_starts("stocky_ratio_constraint100.controller.json",
                                    {120, 125, 140, 95, 135, 105, 145, 125});
}

// One more stage at 120 N (data/wang2009/runs/stocky_ratio_constraint120/, CMA's mean at 80): the
// issue's robust goal with room to spare, from perturbed starts.
TEST_CASE("wang2009: the 120 N ratio-constrained walker walks 100 s with the human ratio",
          "[wang2009][claim]") {
  check_walker({"stocky_ratio_constraint120.controller.json",
                1.412,
                0.307,
                {0.425, 0.026, 0.550},
                10,
                {false, false},
                true,
                29.4});
}

TEST_CASE("wang2009: the 120 N ratio-constrained walker survives its Table 1 forces",
          "[wang2009][claim]") {
  // The page's scan (5 N steps) from its own start: at or above the library's SIMBICON on the
  // same grid (75, 110, 160, 95, 160, 125, 165, 120) in seven directions (equal in (-1,-1)), not
  // (-1,0) (155 against 160).
  check_survives_table1("stocky_ratio_constraint120.controller.json",
                        {195, 155, 220, 125, 155, 125, 215, 170});
}

TEST_CASE(
    "wang2009: the 120 N ratio-constrained walker, SIMBICON's force in 8 of 8 from "
    "perturbed starts",
    "[wang2009][claim]") {
  // The robust goal: the page's scan from 10 perturbed starts (8 of 10 at every force up
  // to these) is 25-110 N above the library's SIMBICON's from the same starts (75, 105, 180, 95,
  // 130, 90, 165, 105) in every direction.
  check_survives_table1_from_starts("stocky_ratio_constraint120.controller.json",
                                    {185, 150, 220, 125, 155, 125, 220, 150});
}

// The same robust goal with longer steps and a straighter torso (data/wang2009/runs/
// stocky_natural120/, CMA's mean at 90): from the upright walker with 0.5 m steps, push stages at
// 50, 80, 100 and 120 N with the mean step length (>= 0.5 m) and the ratio as constraints.
TEST_CASE("wang2009: the longer-stride robust walker walks 100 s with the human ratio",
          "[wang2009][claim]") {
  check_walker({"stocky_natural120.controller.json",
                1.949,
                0.517,
                {0.428, 0.053, 0.520},
                10,
                {false, false},
                true,
                17.5});
}

TEST_CASE("wang2009: the longer-stride robust walker survives its Table 1 forces",
          "[wang2009][claim]") {
  // The page's scan (5 N steps) from its own start: at or above the library's SIMBICON on the
  // same grid (75, 110, 160, 95, 160, 125, 165, 120) in every direction (equal in (0,-1)).
  check_survives_table1("stocky_natural120.controller.json",
                        {145, 125, 175, 140, 205, 140, 165, 125});
}

TEST_CASE(
    "wang2009: the longer-stride robust walker, SIMBICON's force in 7 of 8 from perturbed "
    "starts",
    "[wang2009][claim]") {
  // The robust goal: from 10 perturbed starts (8 of 10 at every force up to these) at or
  // above the library's SIMBICON from the same starts (75, 105, 180, 95, 130, 90, 165, 105) in
  // every direction but (0,1) (170 against 180).
  check_survives_table1_from_starts("stocky_natural120.controller.json",
                                    {160, 110, 170, 135, 210, 120, 170, 115});
}

// Sec. 5, "Variation in body shape": cost-of-transport walkers (no speed or step target) for the
// other shapes, each carried from the stocky walker and optimized 250 iterations.
TEST_CASE("wang2009: the tall walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"tall_cot.controller.json", 1.246, 0.380, {0.568, 0.049, 0.384}, 10, {false, false}});
}

TEST_CASE("wang2009: the short walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"short_cot.controller.json", 1.424, 0.580, {0.756, 0.115, 0.130}, 9, {false, false}});
}

TEST_CASE("wang2009: the thin walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"thin_cot.controller.json", 1.341, 0.549, {0.719, 0.129, 0.152}, 10, {false, false}});
}

// The overweight shape's 250 iterations walked 100 s from only 7 of 10 perturbed starts (kept in
// data/wang2009/runs/overweight_cot/); 100 more with 2 perturbed starts in every cost and 20 s
// horizons give this one (data/wang2009/runs/overweight_robust/).
TEST_CASE("wang2009: the overweight walker walks 100 s", "[wang2009][claim]") {
  check_walker({"overweight_robust.controller.json",
                0.995,
                0.331,
                {0.745, 0.122, 0.133},
                10,
                {false, false}});
}

// Fig. 4's set-up (stocky, 1.8 m/s, 0.7 m steps) without E_ang. Its 250 iterations gave a walker
// that walks 100 s only in CI's build and from 7 of 10 perturbed starts (it falls at 95.8 s with
// FMA contraction; data/wang2009/runs/stocky_fig4_without_ang/, no claim). The robust stage that
// gives the E_ang walker its 100 s from 10 of 10 perturbed starts (below: 150 iterations, 2
// perturbed starts in every cost, sigma 0.005, seed 3) gives, without E_ang, a walker that walks
// its 10 s horizon and falls soon after, from its own start and from perturbed ones: the paper's
// "does not walk successfully much beyond" 10 s
// (data/wang2009/runs/stocky_fig4_without_ang_robust/).
TEST_CASE("wang2009: Fig. 4 without E_ang, the robust stage walks 10 s and then falls",
          "[wang2009][claim]") {
  const std::string file = "runs/stocky_fig4_without_ang_robust/wang2009_stocky.controller.json";
#ifdef GAITSYNTH_SANITIZED_BUILD
  CHECK(walk_saved_from_starts(file, 10.0, 0, false)[0].reason == stop_reason::horizon);
  return;
#endif
  const std::vector<rollout_result> r = walk_saved_from_starts(file, 100.0, 10, false);
  const rollout_result& own = r[0];
  INFO("own start: " << to_string(own.reason) << " after " << own.time << " s");
  CHECK(own.reason == stop_reason::fell);
  CHECK(own.time >= 10.0);  // 18.6 s in CI's build; when exactly is rounding, that it falls is not
  int after_horizon = 0, before_100 = 0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    UNSCOPED_INFO("perturbed start " << k - 1 << ": " << to_string(r[k].reason) << " after "
                                     << r[k].time << " s");
    after_horizon += r[k].time >= 10.0;
    before_100 += r[k].reason != stop_reason::horizon;
  }
  CHECK(after_horizon >= 8);
  CHECK(before_100 >= 8);
}

// The same 30 s stage without E_ang (same seed, sigma, iterations; from the paper's-procedure
// walker of that set-up, data/wang2009/runs/stocky_fig4_without_ang_h30/) walks its 30 s and
// falls before 100 s, from its own start and from perturbed ones, where the E_ang walker of that
// stage walks 100 s from 10 of 10 (above).
TEST_CASE("wang2009: Fig. 4 without E_ang, the 30 s stage falls before 100 s",
          "[wang2009][claim]") {
  const std::string file = "runs/stocky_fig4_without_ang_h30/wang2009_stocky.controller.json";
#ifdef GAITSYNTH_SANITIZED_BUILD
  CHECK(walk_saved_from_starts(file, 10.0, 0, true)[0].reason == stop_reason::horizon);
  return;
#endif
  const std::vector<rollout_result> r = walk_saved_from_starts(file, 100.0, 10, true);
  const rollout_result& own = r[0];
  INFO("own start: " << to_string(own.reason) << " after " << own.time << " s");
  CHECK(!walked(own));
  CHECK(own.time >= 30.0);  // 50.6 s in CI's build; when exactly is rounding, that it falls is not
  int walking = 0, after_horizon = 0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    UNSCOPED_INFO("perturbed start " << k - 1 << ": " << to_string(r[k].reason) << " after "
                                     << r[k].time << " s");
    walking += walked(r[k]);
    after_horizon += r[k].time >= 30.0;
  }
  CHECK(walking <= 2);        // 0 of 10 in CI's build
  CHECK(after_horizon >= 8);  // 10 of 10: they fall at 34-48 s
}

// Fig. 4's set-up with E_ang: the walker that fell at 19.5 s (its run record), 150 more iterations
// with 2 perturbed starts in every candidate's cost
// (data/wang2009/runs/stocky_fig4_with_ang_robust/).
TEST_CASE("wang2009: Fig. 4's walker with E_ang walks 100 s", "[wang2009][claim]") {
  check_walker({"stocky_fig4_with_ang.controller.json",
                1.667,
                0.638,
                {0.788, 0.054, 0.158},
                10,
                {false, false},
                false,
                23.2});
}

// Fig. 4's set-up with E_ang: the same start as the robust stage (the restart's best, which falls
// at 24.8 s), 150 iterations of the paper's objective on 30 s evaluations instead of 10 s and no
// perturbed starts (data/wang2009/runs/stocky_fig4_with_ang_h30/): it walks 100 s and keeps the
// arms swinging with the opposite legs (the arm-swing case below), which the robust stage lost.
TEST_CASE("wang2009: Fig. 4's walker with E_ang from 30 s evaluations walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_fig4_with_ang_h30.controller.json",
                1.742,
                0.669,
                {0.800, 0.080, 0.120},
                10,
                {false, false},
                false,
                25.0});
}

// Fig. 4 from one start, E_ang the only difference (session 32). The 30 s stage above, run from
// the start the other side used: with E_ang from the walker made without it (whose own 30 s stage
// without E_ang falls at 50.6 s, above), and without E_ang from the E_ang run's restart (whose
// own 30 s stage with E_ang walks 100 s, above); data/wang2009/runs/stocky_fig4_*_same_start/.
// From the without-E_ang start, E_ang decides between walking 100 s and falling, the paper's
// contrast; from the E_ang start, both walk 100 s.
TEST_CASE("wang2009: Fig. 4 with E_ang from the without-E_ang start walks 100 s",
          "[wang2009][claim]") {
  check_walker({"stocky_fig4_with_ang_h30_same_start.controller.json",
                1.916,
                0.538,
                {0.619, 0.054, 0.327},
                10,
                {false, false},
                false,
                29.8});
}
TEST_CASE("wang2009: Fig. 4 without E_ang from the E_ang start walks 100 s too",
          "[wang2009][claim]") {
  check_walker({"stocky_fig4_without_ang_h30_same_start.controller.json",
                1.792,
                0.686,
                {0.807, 0.056, 0.137},
                10,
                {false, false},
                false,
                49.0});
}

// Fig. 3's set-up (short, 1.0 m/s) with and without E_ratio.
TEST_CASE("wang2009: Fig. 3's walker with E_ratio walks 100 s", "[wang2009][claim]") {
  check_walker({"short_fig3_with_ratio.controller.json",
                1.026,
                0.347,
                {0.786, 0.112, 0.103},
                10,
                {false, false}});
}

TEST_CASE("wang2009: Fig. 3's walker without E_ratio walks 100 s", "[wang2009][claim]") {
  check_walker({"short_fig3_without_ratio.controller.json",
                0.997,
                0.346,
                {0.791, 0.130, 0.080},
                10,
                {false, false}});
}

TEST_CASE("wang2009: the long-arm walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"long_arm_cot.controller.json", 1.306, 0.241, {0.545, 0.124, 0.331}, 10, {false, false}});
}

// Beyond the paper: the stocky walker optimized further with perturbed starts and pushes in every
// candidate's cost (wang2009_walk --robust-starts 2 --robust-pushes 4 --push-force 40).
TEST_CASE("wang2009: the robustly optimized stocky walker walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"stocky_robust.controller.json", 1.082, 0.380, {0.793, 0.070, 0.137}, 10, {false, false}});
}

// Sec. 5's low-friction sequence: the stocky walker optimized on mu = 0.8 ("walks more gingerly, at
// a slower rate"), then on mu = 0.3.
TEST_CASE("wang2009: the stocky walker for mu = 0.8 walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"stocky_mu08.controller.json", 1.146, 0.396, {0.722, 0.134, 0.144}, 10, {false, false}});
}

TEST_CASE("wang2009: the stocky walker for mu = 0.3 walks 100 s", "[wang2009][claim]") {
  check_walker(
      {"stocky_mu03.controller.json", 1.231, 0.307, {0.668, 0.106, 0.227}, 10, {false, false}});
}

// Sec. 5, "Changing terrain": "the level-ground walker fails at the 3-degree slope"; and the
// friction sequence is needed: the walker optimized on mu = 10 slips and falls on mu = 0.8.
TEST_CASE("wang2009: the level stocky walker falls on a 3 degree slope and on mu = 0.8",
          "[wang2009][claim]") {
  const rollout_result slope =
      stocky_walker_on(slope_terrain(3.0 * std::numbers::pi / 180.0), 10.0);
  INFO("3 degrees: " << to_string(slope.reason) << " after " << slope.time << " s");
  CHECK(slope.reason == stop_reason::fell);
  CHECK(slope.time < 15.0);  // 9.7 s
  const rollout_result slippery = stocky_walker_on(flat_terrain{}, 0.8);
  INFO("mu = 0.8: " << to_string(slippery.reason) << " after " << slippery.time << " s");
  CHECK(slippery.reason == stop_reason::fell);
  CHECK(slippery.time < 15.0);  // 7.7 s
  // The level walker that starts the slope continuation (0.65 m step target) fails there too.
  const rollout_result step065 = stocky_walker_on(slope_terrain(3.0 * std::numbers::pi / 180.0),
                                                  10.0, "stocky_step065.controller.json");
  INFO("0.65 m walker on 3 degrees: " << to_string(step065.reason) << " after " << step065.time
                                      << " s");
  CHECK(step065.reason == stop_reason::fell);
  CHECK(step065.time < 25.0);  // 18.9 s
}

// Fig. 4: "The resulting motion correctly exhibits in-phase arm-swing, with the arms
// counter-oscillating with respect to the legs" with E_ang. Both walkers of our Fig. 4 runs swing
// each arm with the opposite leg, and the one optimized with E_ang (it falls at 19.5 s: its run
// record's controller) much more so; analysis/arm_swing.hpp, over 2-15 s.
TEST_CASE("wang2009: Fig. 4, E_ang swings the arms with the opposite legs", "[wang2009][claim]") {
  const auto opposite_leg_correlation = [](const std::string& file) {
    trajectory tr;
    const rollout_result r = walk_saved(file, flat_terrain{}, 10.0, 15.0, &tr);
    INFO(file << ": " << to_string(r.reason) << " after " << r.time << " s");
    REQUIRE(r.reason == stop_reason::horizon);
    const floating_model m = wang2009_humanoid(wang2009_preset(
        wang2009_saved_shape(std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/" + file)));
    return arm_swing(m, tr, 2.0).opposite_leg_correlation;
  };
  const double with_ang =
      opposite_leg_correlation("runs/stocky_fig4_with_ang/wang2009_stocky.controller.json");
  const double without_ang =
      opposite_leg_correlation("runs/stocky_fig4_without_ang/wang2009_stocky.controller.json");
  // The walker of the same set-up that walks 100 s (robust stage) swings them less.
  const double with_ang_robust =
      opposite_leg_correlation("walkers/stocky_fig4_with_ang.controller.json");
  // The one from 30 s evaluations walks 100 s too and keeps the swing.
  const double with_ang_h30 =
      opposite_leg_correlation("walkers/stocky_fig4_with_ang_h30.controller.json");
  // The same stage from the other side's start: the swing follows the start, not the stage.
  const double with_ang_from_without =
      opposite_leg_correlation("walkers/stocky_fig4_with_ang_h30_same_start.controller.json");
  const double without_ang_from_with =
      opposite_leg_correlation("walkers/stocky_fig4_without_ang_h30_same_start.controller.json");
  INFO("with E_ang " << with_ang << ", without " << without_ang << ", with E_ang (robust stage) "
                     << with_ang_robust << ", with E_ang (30 s evaluations) " << with_ang_h30
                     << "; 30 s stage with E_ang from the without-E_ang start "
                     << with_ang_from_without << ", without E_ang from the E_ang start "
                     << without_ang_from_with);
  CHECK(with_ang == Approx(0.82).margin(0.02));
  CHECK(without_ang == Approx(0.33).margin(0.02));
  CHECK(with_ang_robust == Approx(0.24).margin(0.02));
  CHECK(with_ang_h30 == Approx(0.70).margin(0.02));
  CHECK(with_ang_from_without == Approx(0.11).margin(0.02));
  CHECK(without_ang_from_with == Approx(0.81).margin(0.02));
}
