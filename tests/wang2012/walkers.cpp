// The claims of Wang, Hamner, Delp & Koltun 2012 (issue 13), checked on the optimized muscle
// walkers saved in data/wang2012/walkers/ (written by examples/wang2012_walk.cpp;
// docs/reproductions/wang2012.md has the commands). Each test re-simulates a walker without
// optimizing anything.
//
// "Walks 100 s" is the library's walked() (rollout/walk_check.hpp): the 100 s rollout ends at its
// horizon, not by a fall, a divergence or a stall. Every walker is also walked for 100 s from 10
// starts whose joint velocities are perturbed by a seeded N(0, 0.05 rad/s) (seed 2012, starts the
// optimization never saw), and the count that walk is checked against the page's. The average
// speed is checked against the page's figure (to 3 %: a 100 s walk is chaotic, other builds retrace
// it with small differences) and against the target when the page claims it (0.05 m/s).
//
// Under the sanitizers (GAITSYNTH_SANITIZED_BUILD) each walker walks 10 s once: the same code
// paths, checked for memory and undefined behaviour; the Release suite checks the claims.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/analysis/leg_overlap.hpp"
#include "gaitsynth/analysis/muscle_recording.hpp"
#include "gaitsynth/analysis/sagittal_gait_features.hpp"
#include "gaitsynth/analysis/standard_score.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

using namespace gaitsynth;

namespace {

/// What docs/reproductions/wang2012.md reports for a walker.
struct reported {
  const char* file;      ///< under data/wang2012/walkers/
  double speed;          ///< m/s, average over the 100 s walk
  bool speed_on_target;  ///< claimed: within 0.05 m/s of the saved target speed
  int perturbed_walked;  ///< of the 10 perturbed starts, those that walk 100 s
  /// Claimed: the legs collide (saved "leg_collisions") and over the 100 s walk no pair of
  /// analysis/leg_overlap.hpp overlaps deeper than 1 cm (the penalty contact's give).
  bool legs_apart = false;
};

/// A saved walker ready to re-simulate: the model, the saved controller, the muscles it was
/// optimized with (Geyer & Herr's, weakened as its info says: Sec. 6.2's weakness studies) and
/// the controller. Not copyable: the members are built in order from `file`.
struct saved_walker {
  explicit saved_walker(const char* file)
      : saved(load_wang2012_controller(std::string(GAITSYNTH_SOURCE_DIR) +
                                       "/data/wang2012/walkers/" + file)),
        act(muscles(m, saved)),
        c(m) {}
  saved_walker(const saved_walker&) = delete;
  saved_walker& operator=(const saved_walker&) = delete;

  static std::vector<musculotendon::unit> muscles(const floating_model& m,
                                                  const wang2012_saved_controller& s) {
    auto units = musculotendon::geyer_herr_leg_muscles(m);
    for (const auto& [name, f] : s.info.value("weaken", std::map<std::string, double>{}))
      musculotendon::scale_max_isometric_force(units, name, f);
    return units;
  }
  std::span<const double> parameters() const { return saved.parameters; }
  /// As examples/wang2012_walk.cpp simulates it, the legs colliding when the walker was optimized
  /// so (wang2012_walk --leg-collisions on, saved as "leg_collisions").
  rollout_options options() const {
    rollout_options opt = wang2009_rollout_options(m);
    if (legs_collide()) opt.self_contact.pairs = leg_capsule_pairs(m);
    return opt;
  }
  bool legs_collide() const { return saved.info.value("leg_collisions", false); }

  floating_model m = wang2012_humanoid();
  wang2012_saved_controller saved;
  musculotendon_actuator act;
  wang2012_reflex_controller c;
};

/// What Sec. 6.2 compares walkers by, from 20 s of walking (the left leg after the first 2 s):
/// the four angles of analysis/sagittal_gait_features.hpp and each MTU's mean activation.
struct study_numbers {
  sagittal_gait_features angles;
  std::map<std::string, double> activation;  ///< "TA" -> mean activation of lTA
};

study_numbers study_numbers_of(const char* file) {
  const saved_walker w(file);
  const floating_model& m = w.m;
  rollout_options opt = w.options();
  opt.duration = 20.0;
  trajectory tr;
  opt.record = &tr;
  opt.record_every = 40;
  muscle_recording mr;
  auto scratch = make_rollout_scratch(m);
  const rollout_result r =
      rollout(m, w.act, w.c, distance_objective(), flat_terrain{}, semi_implicit_euler{},
              w.parameters(), opt, scratch, musculotendon_recorder(w.act, &mr, opt.record_every));
  REQUIRE(r.reason == stop_reason::horizon);
  std::erase_if(tr.frames, [](const trajectory_frame& f) { return f.t < 2.0; });
  gait_cycle_options go;
  go.channels = human_sagittal_channels("l");
  go.samples = 100;
  study_numbers out;
  out.angles = sagittal_gait_features_of(gait_cycles(m, tr, go));
  const std::vector<double> a = mean_activation(mr, 2.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (mr.names[i].starts_with("l")) out.activation[mr.names[i].substr(1)] = a[i];
  return out;
}

/// The eight MTUs' mean activations summed (Sec. 6.2's "total amount of activations").
double summed_activation(const study_numbers& s) {
  double sum = 0.0;
  for (const auto& [name, a] : s.activation) sum += a;
  return sum;
}

void check_walker(const reported& w) {
  const saved_walker walker(w.file);
  const floating_model& m = walker.m;
  const musculotendon_actuator& act = walker.act;
  const wang2012_reflex_controller& c = walker.c;
  const std::span<const double> p = walker.parameters();
  const wang2012_saved_controller& saved = walker.saved;
  rollout_options opt = walker.options();
  CHECK(walker.legs_collide() == w.legs_apart);
  auto scratch = make_rollout_scratch(m);
#ifdef GAITSYNTH_SANITIZED_BUILD
  const rollout_result r10 = rollout(m, act, c, distance_objective(), flat_terrain{},
                                     semi_implicit_euler{}, p, opt, scratch);
  CHECK(r10.reason == stop_reason::horizon);
  return;
#endif
  opt.duration = 100.0;
  opt = walk_options(opt);
  trajectory tr;
  if (w.legs_apart) {
    opt.record = &tr;
    opt.record_every = 40;
  }
  const walk_check r = judge_walk(rollout(m, act, c, distance_objective(), flat_terrain{},
                                          semi_implicit_euler{}, p, opt, scratch));
  opt.record = nullptr;
  INFO(w.file << ": " << verdict(r) << " after " << r.seconds << " s at " << r.average_speed
              << " m/s");
  REQUIRE(r.walked);
  CHECK(r.average_speed == Approx(w.speed).epsilon(0.03));
  if (w.legs_apart) CHECK(leg_overlap(m, tr, leg_capsule_pairs(m), 2.0).max_depth <= 0.01);
  if (w.speed_on_target) CHECK(std::abs(r.average_speed - saved.target_speed) <= 0.05);
  int walking = 0, k = 0;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2012)) {
    opt.initial_velocity_offset = dv;
    const walk_check rk = judge_walk(rollout(m, act, c, distance_objective(), flat_terrain{},
                                             semi_implicit_euler{}, p, opt, scratch));
    UNSCOPED_INFO("perturbed start " << k++ << ": " << verdict(rk) << " after " << rk.seconds
                                     << " s");
    walking += rk.walked;
  }
  // Robust: at least 8 of 10 (the page gives CI's count); below 8 not claimed robust, only kept
  // from getting worse, with one start of slack for other builds' rounding.
  INFO(walking << " of 10 perturbed starts walk; the page reports " << w.perturbed_walked);
  if (w.perturbed_walked >= 8)
    CHECK(walking >= 8);
  else
    CHECK(walking >= w.perturbed_walked - 1);
}

}  // namespace

TEST_CASE("wang2012: nwalk walks 100 s at 1.25 m/s, from 10 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "nwalk.controller.json",
                .speed = 1.2284,
                .speed_on_target = true,
                .perturbed_walked = 10});
}

// nwalk re-optimized with colliding legs (wang2012_walk --leg-collisions on, ours): the saved
// nwalk swings a shin through the other and falls within 2 s once they collide.
TEST_CASE(
    "wang2012: nwalk with colliding legs walks 100 s at 1.25 m/s, legs apart, 10 of 10 "
    "perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "nwalk_legs.controller.json",
                .speed = 1.2374,
                .speed_on_target = true,
                .perturbed_walked = 10,
                .legs_apart = true});
}

TEST_CASE("wang2012: fwalk walks 100 s at 1.5 m/s, from 10 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "fwalk.controller.json",
                .speed = 1.5346,
                .speed_on_target = true,
                .perturbed_walked = 10});
}

// fwalk re-optimized with colliding legs (one stage of 20 iterations with two perturbed starts).
TEST_CASE(
    "wang2012: fwalk with colliding legs walks 100 s at 1.5 m/s, legs apart, 8 of 10 "
    "perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "fwalk_legs.controller.json",
                .speed = 1.5013,
                .speed_on_target = true,
                .perturbed_walked = 8,
                .legs_apart = true});
}

TEST_CASE("wang2012: swalk walks 100 s at 1.0 m/s, from 10 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "swalk.controller.json",
                .speed = 0.9917,
                .speed_on_target = true,
                .perturbed_walked = 10});
}

// swalk re-optimized with colliding legs: a stage as fwalk_legs, then swalk's own 30 s stage.
TEST_CASE(
    "wang2012: swalk with colliding legs walks 100 s at 1.0 m/s, legs apart, 10 of 10 "
    "perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "swalk_legs.controller.json",
                .speed = 0.9981,
                .speed_on_target = true,
                .perturbed_walked = 10,
                .legs_apart = true});
}

TEST_CASE("wang2012: vwalk walks 100 s at 1.75 m/s, from 10 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "vwalk.controller.json",
                .speed = 1.7424,
                .speed_on_target = true,
                .perturbed_walked = 10});
}

TEST_CASE("wang2012: min_torque walks 100 s at 1.25 m/s, from 8 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "min_torque.controller.json",
                .speed = 1.2252,
                .speed_on_target = true,
                .perturbed_walked = 8});
}

TEST_CASE("wang2012: min_act walks 100 s at 1.25 m/s, from 10 of 10 perturbed starts",
          "[wang2012][claim]") {
  check_walker({.file = "min_act.controller.json",
                .speed = 1.2513,
                .speed_on_target = true,
                .perturbed_walked = 10});
}

TEST_CASE("wang2012: min_act activates its muscles less in total than nwalk (Sec. 6.2)",
          "[wang2012][claim]") {
#ifdef GAITSYNTH_SANITIZED_BUILD
  return;  // the same code paths as the walks above; the Release suite checks the claim
#endif
  // "While the total amount of activations is reduced": the sum of the eight MTUs' mean
  // activations, 1.60 against nwalk's 1.70 (the page's table). The paper's shift from GAS/SOL
  // to VAS is not reproduced (the page says so), so it is not claimed here.
  const double act = summed_activation(study_numbers_of("min_act.controller.json"));
  const double normal = summed_activation(study_numbers_of("nwalk.controller.json"));
  INFO("summed mean activation: min_act " << act << ", nwalk " << normal);
  CHECK(act < 0.97 * normal);
}

// min_act re-optimized with colliding legs (one stage of 20 iterations with two perturbed
// starts, as fwalk_legs).
TEST_CASE(
    "wang2012: min_act with colliding legs walks 100 s at 1.25 m/s, legs apart, 8 of 10 "
    "perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "min_act_legs.controller.json",
                .speed = 1.2531,
                .speed_on_target = true,
                .perturbed_walked = 8,
                .legs_apart = true});
}

TEST_CASE(
    "wang2012: with colliding legs too, min_act activates its muscles less in total than nwalk",
    "[wang2012][claim]") {
#ifdef GAITSYNTH_SANITIZED_BUILD
  return;  // the same code paths as the walks above; the Release suite checks the claim
#endif
  // 1.60 against nwalk_legs' 1.69 (the page's table), as min_act and nwalk.
  const double act = summed_activation(study_numbers_of("min_act_legs.controller.json"));
  const double normal = summed_activation(study_numbers_of("nwalk_legs.controller.json"));
  INFO("summed mean activation: min_act_legs " << act << ", nwalk_legs " << normal);
  CHECK(act < 0.97 * normal);
}

TEST_CASE("wang2012: HAM at 1/4 strength walks 100 s at 1.25 m/s, from 9 of 10 perturbed starts",
          "[wang2012][claim]") {
  // Re-simulated with the weakened HAM it was optimized with (the file's info.weaken).
  check_walker({.file = "weak_ham.controller.json",
                .speed = 1.2744,
                .speed_on_target = true,
                .perturbed_walked = 9});
}

// weak_ham re-optimized with colliding legs (one stage of 20 iterations, as fwalk_legs).
TEST_CASE(
    "wang2012: HAM at 1/4 strength with colliding legs walks 100 s at 1.25 m/s, legs apart, 10 of "
    "10 perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "weak_ham_legs.controller.json",
                .speed = 1.2761,
                .speed_on_target = true,
                .perturbed_walked = 10,
                .legs_apart = true});
}

TEST_CASE(
    "wang2012: GAS and SOL at 1/4 strength walk 100 s at 1.25 m/s, from 8 of 10 perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "weak_gassol.controller.json",
                .speed = 1.2702,
                .speed_on_target = true,
                .perturbed_walked = 8});
}

// weak_gassol re-optimized with colliding legs (one stage of 20 iterations, as fwalk_legs).
TEST_CASE(
    "wang2012: GAS and SOL at 1/4 strength with colliding legs walk 100 s at 1.25 m/s, legs "
    "apart, 9 of 10 perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "weak_gassol_legs.controller.json",
                .speed = 1.2946,
                .speed_on_target = true,
                .perturbed_walked = 9,
                .legs_apart = true});
}

// GAS and SOL at 1/4 from Geyer & Herr's initialization, not from nwalk: half strength for 360
// iterations, then a quarter for 100 with two perturbed starts (data/wang2012/README.md).
TEST_CASE(
    "wang2012: GAS and SOL at 1/4 strength optimized from the initialization walk 100 s at 1.25 "
    "m/s, legs apart, 10 of 10 perturbed starts",
    "[wang2012][claim]") {
  check_walker({.file = "weak_gassol_from_init.controller.json",
                .speed = 1.2190,
                .speed_on_target = true,
                .perturbed_walked = 10,
                .legs_apart = true});
}

TEST_CASE(
    "wang2012: GAS and SOL at 1/4 straighten the stance knee, from nwalk and from the "
    "initialization alike (not the paper's crouch)",
    "[wang2012][claim]") {
#ifdef GAITSYNTH_SANITIZED_BUILD
  return;  // the same code paths as the walks above; the Release suite checks the claim
#endif
  // The page's finding against the paper's "mild crouch": mid-stance knee flexion 10.8 and 9.8
  // degrees on average against nwalk_legs' 22.5. 5 degrees of margin: a crouch would be the
  // other side of nwalk's figure, not within a few degrees of it.
  const double normal =
      study_numbers_of("nwalk_legs.controller.json").angles.knee_flexion_mid_stance_mean;
  for (const char* file :
       {"weak_gassol_legs.controller.json", "weak_gassol_from_init.controller.json"}) {
    const double weak = study_numbers_of(file).angles.knee_flexion_mid_stance_mean;
    INFO(file << ": mid-stance knee flexion " << weak << " deg, nwalk_legs " << normal);
    CHECK(weak < normal - 5.0);
  }
}

TEST_CASE("wang2012: VAS at 1/10 strength walks 100 s (at 0.95 m/s), from 8 of 10 perturbed starts",
          "[wang2012][claim]") {
  // Not on the 1.25 m/s target: the page says so, and that its stance knee hyperextends.
  check_walker({.file = "weak_vas.controller.json",
                .speed = 0.9537,
                .speed_on_target = false,
                .perturbed_walked = 8});
}

// weak_vas re-optimized with colliding legs: 40 and 80 iterations at the paper's 10 s, then a
// 30 s stage with one perturbed start (data/wang2012/README.md).
TEST_CASE(
    "wang2012: VAS at 1/10 strength with colliding legs walks 100 s (at 0.84 m/s), legs apart, 6 "
    "of 10 perturbed starts",
    "[wang2012][claim]") {
  // Below 8 of 10: kept from getting worse, not claimed robust (check_walker).
  check_walker({.file = "weak_vas_legs.controller.json",
                .speed = 0.8439,
                .speed_on_target = false,
                .perturbed_walked = 6,
                .legs_apart = true});
}

TEST_CASE("wang2012: min_torque keeps TA more active than nwalk (Sec. 6.2)", "[wang2012][claim]") {
#ifdef GAITSYNTH_SANITIZED_BUILD
  return;  // the same code paths as the walks above; the Release suite checks the claim
#endif
  // "the TA muscle ... is highly activated throughout the gait when only torque is being
  // minimized": its mean activation 0.248 against nwalk's 0.208 (the page's table).
  const study_numbers torque = study_numbers_of("min_torque.controller.json");
  const study_numbers normal = study_numbers_of("nwalk.controller.json");
  INFO("TA: min_torque " << torque.activation.at("TA") << ", nwalk " << normal.activation.at("TA"));
  CHECK(torque.activation.at("TA") > 1.1 * normal.activation.at("TA"));
}
