// The claims of Sharon & van de Panne 2005, checked on the optimized controllers saved in
// data/sharon2005/ (written by examples/sharon2005_*.cpp; docs/reproductions/sharon2005.md has
// the commands). Each test re-simulates a controller without optimizing anything.
//
// "Walks 70 s" (the paper's test, section VI) means: the 70 s rollout ends at its horizon, not by
// a fall (COM below half its initial height) or divergence, and the COM advanced at more than
// 0.3 m/s on average (standing still for 70 s is not walking).
//
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

using namespace gaitsynth;

namespace {

std::string data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

Eigen::VectorXd params_of(const nearest_neighbor_controller<planar_root>& c) {
  const auto p = c.parameters();
  return Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size()));
}

/// 70 s rollout of a saved controller for model m (start: the keyframes' first state, placed on
/// the ground for a changed body), on terrain `ground`.
template <class Terrain>
walk_check walk_70s(const planar_model& m, const std::string& controller_file,
                    const std::string& keyframes_file, const Terrain& ground,
                    const planar_model* controller_model = nullptr, bool place = false,
                    const Eigen::VectorXd& velocity_offset = {}) {
  const planar_model& cm = controller_model ? *controller_model : m;
  const auto target = load_keyframes(cm, data(keyframes_file));
  const auto ctrl = load_nearest_neighbor(cm, data(controller_file));
  rollout_options ro;
  ro.initial_state = place ? sharon_scenarios::start_state_for(m, target) : target.initial_state();
  ro.initial_velocity_offset = velocity_offset;
  const rollout_problem prob{
      m,      torque_actuator{},     ctrl, mass_distance<planar_root>(m, target),
      ground, semi_implicit_euler{}, ro};
  return check_walk(prob, params_of(ctrl), 70.0, nullptr, 40, sharon2005_walk_criteria);
}

/// How many of 10 seeded perturbed starts (joint velocities + N(0, 0.05 rad/s), issue 15) walk
/// 70 s; `log` lists each start's distance.
template <class Terrain>
int perturbed_walks(const planar_model& m, const std::string& controller_file,
                    const std::string& keyframes_file, const Terrain& ground, std::string& log,
                    const planar_model* controller_model = nullptr, bool place = false) {
  int n = 0;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2015)) {
    const walk_check w =
        walk_70s(m, controller_file, keyframes_file, ground, controller_model, place, dv);
    n += w.walked ? 1 : 0;
    log += (w.walked ? " walked " : " failed at ") + std::to_string(w.seconds) + " s;";
  }
  return n;
}

/// The library's verdict (rollout/walk_check.hpp) with the paper's test: 70 s, no fall, no stall,
/// 0.3 m/s or more.
bool walks(const walk_check& w) {
  return w.walked;
}

#define REPORT(w)                                                                                  \
  INFO("walked " << (w).seconds << " s, " << (w).distance << " m, " << (w).average_speed << " m/s" \
                 << ((w).fell ? " (fell)" : "") << ((w).stalled ? " (stalled)" : ""))

}  // namespace

TEST_CASE("Fig. 5a/b: the normal-walk controller walks 70 s without falling",
          "[sharon2005][claims]") {
  const planar_model m = sharon2005_human7();
  const walk_check w =
      walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json", flat_terrain{});
  REPORT(w);
  CHECK(walks(w));
  WARN("normal walk: " << w.seconds << " s, " << w.average_speed << " m/s");
}

TEST_CASE("Fig. 5c/d: the 16-link human walks 70 s", "[sharon2005][claims]") {
  const planar_model m = sharon2005_human16();
  const walk_check w =
      walk_70s(m, "human16_walk.controller.json", "human16_walk.keyframes.json", flat_terrain{});
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 6a/b: the high-knee style (24 nodes) walks 70 s", "[sharon2005][claims]") {
  const planar_model m = sharon2005_human7();
  const walk_check w =
      walk_70s(m, "high_knee.controller.json", "high_knee.keyframes.json", flat_terrain{});
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 6c/d: the back-swing style (24 nodes, ordered activation) walks 70 s",
          "[sharon2005][claims]") {
  const planar_model m = sharon2005_human7();
  const auto c = load_nearest_neighbor(m, data("backswing.controller.json"));
  CHECK(c.opts().max_advance == 1);
  CHECK(c.num_nodes() == 24);
  const walk_check w =
      walk_70s(m, "backswing.controller.json", "backswing.keyframes.json", flat_terrain{});
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 7: the uphill controller walks up a 10 degree slope for 70 s",
          "[sharon2005][claims]") {
  const planar_model m = sharon2005_human7();
  const slope_terrain hill(10.0 * std::numbers::pi / 180.0);
  const walk_check w = walk_70s(m, "uphill.controller.json", "uphill.keyframes.json", hill);
  REPORT(w);
  CHECK(walks(w));
  // It climbed: the COM rose by the slope times the distance walked.
  CHECK(w.result.com_final.z() - w.result.com_initial.z() ==
        Approx(w.distance * std::tan(10.0 * std::numbers::pi / 180.0)).epsilon(0.05));
}

// ---- Figure 8: the unmodified normal-walk controller on changed bodies and terrain ------------

TEST_CASE("Fig. 8a: torso mass 40 -> 28 kg, walks 70 s", "[sharon2005][claims][robustness]") {
  const planar_model nominal = sharon2005_human7();
  const auto v = sharon_scenarios::figure8_bodies()[0];
  REQUIRE(v.params.torso_mass == 28.0);
  const planar_model m = sharon2005_human7(v.params);
  const walk_check w = walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json",
                                flat_terrain{}, &nominal, true);
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 8b: shin 0.44 -> 0.25 m, thigh 0.46 -> 0.6 m, walks 70 s",
          "[sharon2005][claims][robustness]") {
  const planar_model nominal = sharon2005_human7();
  const auto v = sharon_scenarios::figure8_bodies()[1];
  REQUIRE(v.params.shin_length == 0.25);
  REQUIRE(v.params.thigh_length == 0.6);
  const planar_model m = sharon2005_human7(v.params);
  const walk_check w = walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json",
                                flat_terrain{}, &nominal, true);
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 8c: shin 0.44 -> 0.8 m, walks 70 s", "[sharon2005][claims][robustness]") {
  const planar_model nominal = sharon2005_human7();
  const auto v = sharon_scenarios::figure8_bodies()[2];
  REQUIRE(v.params.shin_length == 0.8);
  const planar_model m = sharon2005_human7(v.params);
  const walk_check w = walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json",
                                flat_terrain{}, &nominal, true);
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 8d: bumpy terrain with gradients up to 11 degrees, walked blindly for 70 s",
          "[sharon2005][claims][robustness]") {
  const planar_model m = sharon2005_human7();
  const auto bumps = sharon_scenarios::bumpy_terrain();
  CHECK(sharon_scenarios::max_gradient_deg(bumps, -5.0, 110.0) == Approx(11.0).epsilon(0.01));
  const walk_check w = walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json",
                                bumps, nullptr, true);
  REPORT(w);
  CHECK(walks(w));
}

TEST_CASE("Fig. 8d is not one lucky profile: other seeds of the same terrain generator",
          "[sharon2005][claims][robustness]") {
  // The controller never saw these profiles (its training terrains have seeds 1-8, the test
  // profile above 2005). Eight of these ten must be walked for 70 s.
  const planar_model m = sharon2005_human7();
  int walked = 0;
  std::string log;
  for (std::uint64_t seed = 3001; seed <= 3010; ++seed) {
    const auto bumps = sharon_scenarios::bumpy_terrain(11.0, seed);
    const walk_check w = walk_70s(m, "normal_walk.controller.json", "normal_walk.keyframes.json",
                                  bumps, nullptr, true);
    walked += walks(w);
    log += ' ';  // (not " " + to_string: GCC 12 warns falsely there, -Wrestrict, PR 105329)
    log += std::to_string(static_cast<int>(w.seconds));
  }
  WARN("Fig. 8d, ten other 11 degree profiles: walked " << walked << " of 10 (seconds:" << log
                                                        << ")");
  CHECK(walked >= 8);
}

TEST_CASE("every saved walker also walks from at least 8 of 10 perturbed starts",
          "[sharon2005][claims][robustness]") {
  // Issue 15: a claim must not rest on one exact start. Joint velocities + N(0, 0.05 rad/s),
  // seeded (2015); the optimizations that use such starts draw other seeds (4242).
  const planar_model m7 = sharon2005_human7();
  const planar_model nominal = sharon2005_human7();
  std::string log;
  auto check = [&](const char* name, int walked) {
    INFO(name << ": " << walked << " of 10:" << log);
    CHECK(walked >= 8);
    WARN(name << ": " << walked << " of 10 perturbed starts walk 70 s");
    log.clear();
  };
  SECTION("Fig. 5a normal walk") {
    check("normal walk", perturbed_walks(m7, "normal_walk.controller.json",
                                         "normal_walk.keyframes.json", flat_terrain{}, log));
  }
  SECTION("Fig. 5c 16-link walk") {
    const planar_model m16 = sharon2005_human16();
    check("16-link walk", perturbed_walks(m16, "human16_walk.controller.json",
                                          "human16_walk.keyframes.json", flat_terrain{}, log));
  }
  SECTION("Fig. 6a high knee") {
    check("high knee", perturbed_walks(m7, "high_knee.controller.json", "high_knee.keyframes.json",
                                       flat_terrain{}, log));
  }
  SECTION("Fig. 6c back swing") {
    check("back swing", perturbed_walks(m7, "backswing.controller.json", "backswing.keyframes.json",
                                        flat_terrain{}, log));
  }
  SECTION("Fig. 7 uphill") {
    check("uphill", perturbed_walks(m7, "uphill.controller.json", "uphill.keyframes.json",
                                    slope_terrain(10.0 * std::numbers::pi / 180.0), log));
  }
  SECTION("Fig. 8a-c changed bodies") {
    for (int i = 0; i < 3; ++i) {
      const planar_model mb = sharon2005_human7(sharon_scenarios::figure8_bodies()[i].params);
      check(i == 0   ? "Fig. 8a"
            : i == 1 ? "Fig. 8b"
                     : "Fig. 8c",
            perturbed_walks(mb, "normal_walk.controller.json", "normal_walk.keyframes.json",
                            flat_terrain{}, log, &nominal, true));
    }
  }
  SECTION("Fig. 8d bumpy terrain") {
    check("Fig. 8d",
          perturbed_walks(m7, "normal_walk.controller.json", "normal_walk.keyframes.json",
                          sharon_scenarios::bumpy_terrain(), log, nullptr, true));
  }
}
