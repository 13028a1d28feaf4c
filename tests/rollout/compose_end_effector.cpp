// The composition test of Wu & Popovic 2010's lower level (controllers/end_effector/): the
// standing controller (and once the cyclical controller, planned_walk) on the Table 3 biped,
// through the torque actuator it commands, with each integrator and terrain, under the distance
// objective and the Wang 2009 terms that need no particular body (they read the step view: COM,
// torques, momentum), each alone and summed, and planned_walk under the offline-optimization cost
// of Wu & Popovic 2010 (objectives/wu2010/: its terms read the controller's report), with and
// without the helper force; walk_script (planned_walks chained per half-cycle) the same way.
#include <catch2/catch.hpp>

#include <cmath>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/standing_balance.hpp"
#include "gaitsynth/controllers/end_effector/walk_script.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/wang2009/angular_momentum.hpp"
#include "gaitsynth/objectives/wang2009/failure.hpp"
#include "gaitsynth/objectives/wang2009/power.hpp"
#include "gaitsynth/objectives/wang2009/velocity.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

/// `duration` seconds from the neutral pose standing on `ground` (feet on the ground below).
template <class Terrain>
rollout_options on_ground(const floating_model& m, const Terrain& ground, double duration) {
  rollout_options o;
  o.duration = duration;
  o.initial_state = make_state(m);
  place_on_terrain(m, ground, o.initial_state.q);
  return o;
}

template <class Integrator, class Terrain, class Objective>
rollout_result stand(const floating_model& m, const Terrain& ground, const Objective& obj) {
  standing_balance<> c(m);
  const rollout_options o = on_ground(m, ground, 0.05);
  auto scratch = make_rollout_scratch(m);
  const auto p = c.gains().to_array();
  return rollout(m, torque_actuator{}, c, obj, ground, Integrator{}, p, o, scratch);
}

/// The cyclical controller (planned_walk.hpp) holds its own copy of the terrain it plans on.
template <class Integrator, class Terrain, class Objective>
rollout_result walk(const floating_model& m, const Terrain& ground, const Objective& obj) {
  const planned_walk<Terrain> c(m, ground);
  const rollout_options o = on_ground(m, ground, 0.05);
  auto scratch = make_rollout_scratch(m);
  return rollout(m, torque_actuator{}, c, obj, ground, Integrator{}, c.default_parameters(), o,
                 scratch);
}

/// planned_walk under the Wu 2010 cost terms, which are made from its report layout.
template <class Integrator, class Terrain, class MakeObjective>
rollout_result walk_wu2010(const floating_model& m, const Terrain& ground, MakeObjective make,
                           double h_max = -1.0) {
  planned_walk_options po;
  po.helper_force = h_max >= 0.0;
  const planned_walk<Terrain> c(m, ground, po);
  std::vector<double> p = c.default_parameters();
  if (po.helper_force) p[c.helper_offset()] = h_max;
  const rollout_options o = on_ground(m, ground, 0.05);
  auto scratch = make_rollout_scratch(m);
  return rollout(m, torque_actuator{}, c, make(c.report_layout()), ground, Integrator{}, p, o,
                 scratch);
}

/// walk_script: two planned_walks on `ground` (the second standing, r = 0), switching at the
/// first half-cycle boundary of the 0.6 s rollout; the first one free, with the helper force.
template <class Integrator, class Terrain, class Objective>
rollout_result scripted(const floating_model& m, const Terrain& ground, const Objective& obj) {
  planned_walk_options po;
  po.helper_force = true;
  po.h_max = 100.0;
  planned_walk_options stand;
  stand.goal = {0.0, 0.0, 0.0};
  const walk_script<Terrain> c(
      {planned_walk<Terrain>(m, ground, po), planned_walk<Terrain>(m, ground, stand)},
      {{0, 0}, {1, 1}}, 0);
  const rollout_options o = on_ground(m, ground, 0.6);
  auto scratch = make_rollout_scratch(m);
  return rollout(m, torque_actuator{}, c, obj, ground, Integrator{}, c.default_parameters(), o,
                 scratch);
}

}  // namespace

TEST_CASE(
    "the end-effector standing controller composes with integrators, terrains and "
    "objectives",
    "[rollout][compose][end_effector]") {
  const floating_model m = wu2010_biped();
  const auto check = [](const rollout_result& r) {
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
  };
  check(stand<semi_implicit_euler>(m, flat_terrain{}, distance_objective()));
  check(stand<semi_implicit_euler>(m, slope_terrain(0.05), distance_objective()));
  check(stand<odeint_rk4>(m, flat_terrain{}, distance_objective()));
  check(stand<semi_implicit_euler>(m, flat_terrain{}, wang2009::velocity()));
  check(stand<semi_implicit_euler>(m, flat_terrain{}, wang2009::failure()));
  check(stand<semi_implicit_euler>(m, flat_terrain{}, wang2009::power()));
  check(stand<semi_implicit_euler>(m, flat_terrain{}, wang2009::angular_momentum(m)));
  check(walk<odeint_rk4>(m, slope_terrain(0.05), wang2009::failure()));
  check(stand<odeint_rk4>(
      m, slope_terrain(0.05),
      weighted_sum<wang2009::velocity, wang2009::failure, wang2009::power>(
          {1.0, 100.0, 0.01}, wang2009::velocity(), wang2009::failure(), wang2009::power())));
}

TEST_CASE("planned_walk composes with the Wu 2010 cost terms and the helper force",
          "[rollout][compose][end_effector][wu2010_cost]") {
  const floating_model m = wu2010_biped();
  const auto check = [](const rollout_result& r) {
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
    CHECK(r.cost >= 0.0);
  };
  using L = planned_walk_report_layout;
  check(walk_wu2010<semi_implicit_euler>(m, flat_terrain{},
                                         [](const L& l) { return wu2010::tracking_error(l); }));
  check(walk_wu2010<semi_implicit_euler>(m, slope_terrain(0.05),
                                         [](const L& l) { return wu2010::com_deviation(l); }));
  check(walk_wu2010<odeint_rk4>(m, flat_terrain{}, [](const L&) { return wu2010::energy(); }));
  check(walk_wu2010<semi_implicit_euler>(
      m, flat_terrain{}, [](const L& l) { return wu2010::helper_penalty(l); }, 100.0));
  check(walk_wu2010<odeint_rk4>(
      m, slope_terrain(0.05), [](const L& l) { return wu2010_objective(l); }, 300.0));
  // The helper penalty over L timesteps is w_h L {h_max}+ exactly; L counts the paper's 1/64 s
  // timesteps (objectives/wu2010/common.hpp): steps x dt x 64, dt the rollout's default 1/2400 s.
  const auto r = walk_wu2010<semi_implicit_euler>(
      m, flat_terrain{}, [](const L& l) { return wu2010::helper_penalty(l); }, 100.0);
  CHECK(r.cost ==
        Approx(5e-3 * static_cast<double>(r.steps) * (rollout_options{}.dt * 64.0) * 100.0));
  // Mixed with a term that reads no report.
  check(walk_wu2010<semi_implicit_euler>(m, flat_terrain{}, [](const L& l) {
    return weighted_sum<wu2010_objective_type, wang2009::failure>({1.0, 1.0}, wu2010_objective(l),
                                                                  wang2009::failure());
  }));
}

TEST_CASE("walk_script composes with integrators, terrains and objectives",
          "[rollout][compose][end_effector][walk_script]") {
  const floating_model m = wu2010_biped();
  const auto check = [](const rollout_result& r) {
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
  };
  const auto wu = wu2010_objective(planned_walk_report_layout::for_action_frames(8));
  check(scripted<semi_implicit_euler>(m, flat_terrain{}, wu));
  check(scripted<semi_implicit_euler>(m, slope_terrain(0.05), distance_objective()));
  check(scripted<odeint_rk4>(m, flat_terrain{}, wang2009::power()));
}
