// Wu & Popovic 2010's cyclical controller (controllers/end_effector/planned_walk.hpp) allocates
// nothing after set-up: a rollout with a command every physics step, counted from the objective's
// first accumulate (after step 0's command, which made the first plan) to its last, runs 2880
// lower-level ticks and two more plans (t = t_h and 2 t_h) inside the counted region. Also with
// Sec. 8.1's report read by the wu2010 objective, Sec. 8.2's helper force applied (h_max > 0) and
// the stance foot re-targeted at touchdown (planned_walk_options::stance_target).
#include "support/counting_allocations.hpp"  // first: it configures Eigen

#include <catch2/catch.hpp>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/walk_script.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "support/counting_objective.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_alloc;

namespace {

/// Counts the plans the controller made (read through the observer's view of its state).
struct plan_counter {
  std::int64_t plans = 0;
  template <class Ob>
  void observe(const Ob& ob) {
    plans = ob.controller_state_ptr->plans_made;
  }
};

/// What 1.2 s of `c` on flat ground (plans at 0, 0.55 and 1.1 s; falls not detected: the default
/// parameters fall near 1.2 s, keep ticking regardless) allocated between its first and last
/// objective view, with the plans it made.
struct counted_walk {
  rollout_result result;
  region r;
  std::int64_t plans = 0;
};

template <class C, class Objective>
counted_walk count_walk(const floating_model& m, const C& c, const Objective& inner,
                        const std::vector<double>& p) {
  rollout_options o;
  o.duration = 1.2;
  o.detect_falls = false;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  counted_walk out;
  const counting_objective<Objective> obj{inner, &out.r};
  plan_counter plans;
  out.result = rollout(m, torque_actuator{}, c, obj, flat_terrain{}, semi_implicit_euler(), p, o,
                       scratch, plans);
  out.plans = plans.plans;
  return out;
}

}  // namespace

TEST_CASE("planned_walk ticks and plans without allocating", "[end_effector][allocation]") {
  CHECK(counters_see_allocations());
  const floating_model m = wu2010_biped();
  const planned_walk<> c(m);
  const counted_walk w = count_walk(m, c, distance_objective(), c.default_parameters());
  CHECK_FALSE(w.result.diverged());
  CHECK(w.r.views == 2880);
  CHECK(w.plans == 3);
  CHECK(w.r.news_at_end - w.r.news_at_start == 0);
  CHECK(w.r.eigen_at_end - w.r.eigen_at_start == 0);
}

TEST_CASE(
    "planned_walk with its report, the wu2010 objective, the helper force and touchdown stance "
    "targets allocates nothing",
    "[end_effector][allocation][wu2010_cost]") {
  CHECK(counters_see_allocations());
  const floating_model m = wu2010_biped();
  planned_walk_options po;
  po.helper_force = true;
  po.stance_target = stance_foot_target::touchdown;
  const planned_walk<> c(m, flat_terrain{}, po);
  std::vector<double> p = c.default_parameters();
  p[c.helper_offset()] = 200.0;
  const counted_walk w = count_walk(m, c, wu2010_objective(c.report_layout()), p);
  CHECK_FALSE(w.result.diverged());
  CHECK(std::isfinite(w.result.cost));
  CHECK(w.r.views == 2880);
  CHECK(w.plans == 3);
  CHECK(w.r.news_at_end - w.r.news_at_start == 0);
  CHECK(w.r.eigen_at_end - w.r.eigen_at_start == 0);
}

TEST_CASE(
    "walk_script switching controllers, with goal changes and the helper force, allocates "
    "nothing",
    "[end_effector][allocation][walk_script]") {
  CHECK(counters_see_allocations());
  const floating_model m = wu2010_biped();
  planned_walk_options po;
  po.helper_force = true;
  po.h_max = 200.0;
  po.goal_schedule = {{1, {0.1, 0.1, 0.5}}};
  planned_walk_options stand;
  stand.goal = {0.0, 0.0, 0.0};
  const walk_script<> c(
      {planned_walk<>(m, flat_terrain{}, po), planned_walk<>(m, flat_terrain{}, stand)},
      {{0, 0}, {2, 1}}, 0);
  const counted_walk w =
      count_walk(m, c, wu2010_objective(c.report_layout()), c.default_parameters());
  CHECK_FALSE(w.result.diverged());
  CHECK(w.r.views == 2880);
  CHECK(w.plans == 3);
  CHECK(w.r.news_at_end - w.r.news_at_start == 0);
  CHECK(w.r.eigen_at_end - w.r.eigen_at_start == 0);
}
