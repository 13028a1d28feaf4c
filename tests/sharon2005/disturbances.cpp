// The saved 7-link walkers under disturbances that no figure of Sharon & van de Panne 2005 shows
// and that no optimization saw (synthesis/sharon2005_disturbances.hpp): slopes of -5 and +3
// degrees, friction 0.5, 50 N pushes forward and backward every 4 s, torso mass -/+20 %. The
// hardening issue found the high-knee and back-swing walks stalling or falling under some of them;
// their controllers were re-optimized with other disturbances in the cost
// (--disturbance-training). Re-simulation only; `sharon2005_robustness --disturbances` prints the
// same rollouts.
#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <string>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/synthesis/sharon2005_disturbances.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

using namespace gaitsynth;
using sharon_scenarios::disturbance;

namespace {

std::string data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

/// The 70 s test of a saved 7-link controller under d, from its keyframes' first state placed on
/// d's ground.
walk_check walk_under(const disturbance& d, const std::string& style) {
  const planar_model nominal = sharon2005_human7();
  const auto target = load_keyframes(nominal, data(style + ".keyframes.json"));
  const auto ctrl = load_nearest_neighbor(nominal, data(style + ".controller.json"));
  const planar_model m = sharon2005_human7(d.body());
  rollout_options ro = d.apply(rollout_options{}, 70.0);
  ro.initial_state = sharon_scenarios::start_state_for(m, target, d.ground());
  const rollout_problem prob{
      m,          torque_actuator{},     ctrl, mass_distance<planar_root>(m, target),
      d.ground(), semi_implicit_euler{}, ro};
  const auto p = ctrl.parameters();
  return check_walk(
      prob, Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())), 70.0,
      nullptr, 40, sharon2005_walk_criteria);
}

}  // namespace

TEST_CASE("disturbances: the test and training sets are what their documentation says",
          "[sharon2005][disturbances]") {
  CHECK(sharon2005_human7().body_index("torso") == 0);  // apply() pushes body 0
  const auto test = sharon_scenarios::test_disturbances();
  REQUIRE(test.size() == 7);
  // Pushes: 50 N for 0.4 s every 4 s from 2 s, so 18 of them start within 70 s.
  const rollout_options o = test[3].apply(rollout_options{}, 70.0);
  REQUIRE(o.pushes.size() == 18);
  CHECK(o.pushes.front().force.x() == 50.0);
  CHECK(o.pushes.back().start == Approx(2.0 + 17 * 4.0));
  CHECK(o.pushes.back().duration == 0.4);
  CHECK(test[2].apply(rollout_options{}, 70.0).contact.mu == 0.5);
  CHECK(test[2].apply(rollout_options{}, 70.0).pushes.empty());
  CHECK(test[6].body().torso_mass == 48.0);
  CHECK(test[6].body().torso_inertia > sharon2005_human7_parameters{}.torso_inertia);
  CHECK_THROWS_WITH(test[0].apply(rollout_options{}, -1.0), Catch::Contains("got -1"));
  // No training condition repeats a test magnitude.
  std::set<double> slopes, frictions, forces, masses;
  for (const disturbance& d : test)
    slopes.insert(d.slope_deg), frictions.insert(d.friction), forces.insert(d.push_force),
        masses.insert(d.torso_mass);
  for (const disturbance& d : sharon_scenarios::training_disturbances()) {
    INFO(d.name);
    CHECK((d.slope_deg == 0.0 || !slopes.count(d.slope_deg)));
    CHECK((d.friction == 1.0 || !frictions.count(d.friction)));
    CHECK((d.push_force == 0.0 || !forces.count(d.push_force)));
    CHECK((d.torso_mass == 40.0 || !masses.count(d.torso_mass)));
  }
}

TEST_CASE("disturbances: each saved 7-link walk walks 70 s under the conditions its page claims",
          "[sharon2005][claims][disturbances]") {
  // docs/reproductions/sharon2005.md, "Disturbances": the conditions each walk is claimed to walk,
  // those it walks in this build, with clang and with FMA contraction; the others are reported
  // (documented there), not required. The high knee on the -5 degree slope and the back swing on
  // the +3 degree slope walk 70 s here and with clang but fall after 13 s with FMA: not claimed.
  const std::map<std::string, std::set<std::string>> claimed = {
      {"normal_walk",
       {"slope_-5deg", "slope_+3deg", "friction_0.5", "push_+50N", "push_-50N", "torso_32kg",
        "torso_48kg"}},
      {"high_knee", {"slope_+3deg", "friction_0.5", "push_-50N", "torso_32kg", "torso_48kg"}},
      {"backswing", {"friction_0.5", "torso_32kg", "torso_48kg"}},
  };
  for (const auto& [style, walks] : claimed)
    for (const disturbance& d : sharon_scenarios::test_disturbances()) {
      const walk_check w = walk_under(d, style);
      INFO(style << ", " << d.description << ": " << verdict(w) << " after " << w.seconds << " s, "
                 << w.distance << " m");
      if (walks.count(d.name))
        CHECK(w.walked);
      else
        WARN(style << " under " << d.name << " (not claimed): " << verdict(w) << " after "
                   << w.seconds << " s");
    }
}
