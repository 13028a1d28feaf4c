// walk_script (controllers/end_effector/walk_script.hpp): planned_walk controllers chained per
// half-cycle at run time. One controller scripted alone is planned_walk itself, bit for bit; a
// script runs each half-cycle with its controller's goal and Omega; its parameters are the free
// controller's; what cannot be chained is refused, naming the entry or controller.
#include "gaitsynth/controllers/end_effector/walk_script.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

static_assert(controller<walk_script<>, floating_root>);

namespace {

/// Each half-cycle's plan as it is made: k, goal, and the planned upper-body height.
struct plan_log {
  struct entry {
    std::int64_t half_cycle = -1;
    task_goal goal;
    double upper_body_z = 0.0;
  };
  std::vector<entry> plans;
  std::int64_t seen = 0;
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    if (st.plans_made == seen) return;
    seen = st.plans_made;
    if (plans.size() < plans.capacity())
      plans.push_back({st.half_cycle, st.plan()->goal, st.plan()->upper_body_target.z()});
  }
};

template <class C>
rollout_result run(const floating_model& m, C c, double duration, plan_log& log,
                   std::vector<double> p = {}) {
  rollout_options o;
  o.duration = duration;
  o.detect_falls = false;  // the schedule runs on the clock whatever the biped does
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  log.plans.reserve(16);
  if (p.empty()) p = c.default_parameters();
  return rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                 semi_implicit_euler(), p, o, scratch, log);
}

planned_walk<> forward(const floating_model& m) {
  return planned_walk<>(m);
}

/// A second controller: another goal (a 0.2 rad turn, shorter steps) and a lower upper body.
planned_walk<> turning(const floating_model& m) {
  planned_walk_options o;
  o.goal = {0.2, 0.2, 0.3};
  o.planner.z_ub = 1.30;
  return planned_walk<>(m, flat_terrain{}, o);
}

}  // namespace

TEST_CASE("walk_script: one controller scripted alone is that planned_walk, bit for bit",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  const double t_h = forward(m).half_cycle_duration();
  plan_log a, b;
  const rollout_result direct = run(m, forward(m), 2.5 * t_h, a);
  const rollout_result scripted = run(m, walk_script<>({forward(m)}, {{0, 0}}), 2.5 * t_h, b, {});
  CHECK(scripted.time == direct.time);
  CHECK(scripted.com_final == direct.com_final);  // exact: the same arithmetic
  REQUIRE(a.plans.size() == 3);
  REQUIRE(b.plans.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) CHECK(a.plans[k].upper_body_z == b.plans[k].upper_body_z);
}

TEST_CASE("walk_script: each half-cycle plans with its scripted controller",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  const walk_script<> s({forward(m), turning(m)}, {{0, 0}, {1, 1}, {2, 0}});
  CHECK(s.controller_of(0) == 0);
  CHECK(s.controller_of(1) == 1);
  CHECK(s.controller_of(2) == 0);
  CHECK(s.controller_of(100) == 0);
  CHECK(walk_script<>({forward(m), turning(m)}, {{0, 1}, {5, 0}}).controller_of(4) == 1);
  CHECK(s.num_parameters() == 0);
  const double t_h = s.half_cycle_duration();
  plan_log log;
  // The default parameters fall; with falls not detected this script's walk diverged at 1.39 s
  // (measured), in the third half-cycle, so the test stops before that.
  const rollout_result r = run(m, s, 2.5 * t_h, log);
  INFO("stopped at " << r.time << " s");
  REQUIRE(log.plans.size() == 3);
  const int expected[] = {0, 1, 0};
  for (std::size_t k = 0; k < 3; ++k) {
    INFO("half-cycle " << k);
    const planned_walk<>& c = s.controllers()[static_cast<std::size_t>(expected[k])];
    CHECK(log.plans[k].half_cycle == static_cast<std::int64_t>(k));
    CHECK(log.plans[k].goal.facing == c.opts().goal.facing);
    CHECK(log.plans[k].goal.step_length == c.opts().goal.step_length);
  }
  // Eq. 9's height: the lower foot plus z_ub, 1.40 m (forward) or 1.30 m (turning). The feet
  // stay within millimetres of the ground in these first steps, so the planned heights differ by
  // about the 0.1 m between the controllers' z_ub.
  CHECK(log.plans[1].upper_body_z - log.plans[0].upper_body_z == Approx(-0.1).margin(0.01));
  CHECK(log.plans[2].upper_body_z - log.plans[1].upper_body_z == Approx(0.1).margin(0.01));
}

TEST_CASE("walk_script: its parameters are the free controller's",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  walk_script<> s({forward(m), turning(m)}, {{0, 0}, {1, 1}}, 1);
  CHECK(s.num_parameters() == turning(m).num_parameters());
  CHECK(s.parameter_names() == turning(m).parameter_names());
  std::vector<double> p = s.default_parameters();
  const std::size_t z_ub = 11;  // omega0.z_ub
  REQUIRE(s.parameter_names()[z_ub] == "omega0.z_ub");
  CHECK(p[z_ub] == 1.30);
  p[z_ub] = 1.20;
  s.bind(p);
  CHECK(s.controllers()[1].planner(0).z_ub == 1.20);
  CHECK(s.controllers()[0].planner(0).z_ub == 1.40);  // the other keeps its own
  p[z_ub] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(s.bind(p), Catch::Contains("z_ub") && Catch::Contains("not finite"));
  walk_script<> none({forward(m)}, {{0, 0}});
  const double one = 1.0;
  CHECK_THROWS_WITH(none.bind(std::span<const double>(&one, 1)),
                    Catch::Contains("no free controller") && Catch::Contains("1"));
}

TEST_CASE("walk_script refuses what cannot be chained, naming it",
          "[controllers][end_effector][walk]") {
  const floating_model m = wu2010_biped();
  using S = walk_script<>;
  CHECK_THROWS_WITH(S({}, {{0, 0}}), Catch::Contains("no controllers"));
  CHECK_THROWS_WITH(S({forward(m)}, {{1, 0}}),
                    Catch::Contains("start at half-cycle 0") && Catch::Contains("got 1"));
  CHECK_THROWS_WITH(S({forward(m)}, {}), Catch::Contains("no entries"));
  CHECK_THROWS_WITH(S({forward(m), turning(m)}, {{0, 0}, {2, 1}, {2, 0}}),
                    Catch::Contains("entry 2") && Catch::Contains("got 2"));
  CHECK_THROWS_WITH(S({forward(m)}, {{0, 0}, {1, 3}}),
                    Catch::Contains("entry 1") && Catch::Contains("controller 3 of 1"));
  CHECK_THROWS_WITH(S({forward(m)}, {{0, 0}}, 1),
                    Catch::Contains("free_controller") && Catch::Contains("got 1"));
  planned_walk_options o;
  o.setup.t_h = 0.5;
  CHECK_THROWS_WITH(S({forward(m), planned_walk<>(m, flat_terrain{}, o)}, {{0, 0}}),
                    Catch::Contains("controller 1's t_h (0.5 s)"));
  o = {};
  o.first_stance = stance_side::right;
  CHECK_THROWS_WITH(S({forward(m), planned_walk<>(m, flat_terrain{}, o)}, {{0, 0}}),
                    Catch::Contains("controller 1's first stance"));
  o = {};
  o.period = 1.0 / 600.0;
  CHECK_THROWS_WITH(S({forward(m), planned_walk<>(m, flat_terrain{}, o)}, {{0, 0}}),
                    Catch::Contains("controller 1's period"));
  o = {};
  o.timing = half_cycle_end::touchdown;  // the script runs on the clock
  CHECK_THROWS_WITH(S({forward(m), planned_walk<>(m, flat_terrain{}, o)}, {{0, 0}}),
                    Catch::Contains("controller 1 ends its half-cycles on touchdown"));
}
