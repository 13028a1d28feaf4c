// Observers (rollout/observer.hpp): they see every step in order and the stop state, change
// nothing, and the trajectory recorder is one of them (options.record is its shorthand).
#include <catch2/catch.hpp>

#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/recorder.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

constexpr double dt = 1.0 / 2400.0;

/// Logs what it sees (memory reserved in start, so observing does not allocate).
struct logging_observer {
  std::vector<std::int64_t> steps;
  std::vector<double> times, com_x, distance_terms;
  observer_setup setup;
  std::int64_t final_step = -1;
  double final_cost = 0.0;
  int starts = 0;
  template <class Model>
  void start(const Model&, const observer_setup& su) {
    setup = su;
    ++starts;
    steps.reserve(static_cast<std::size_t>(su.horizon_steps));
  }
  template <class Observation>
  void observe(const Observation& ob) {
    steps.push_back(ob.step);
    times.push_back(ob.t);
    com_x.push_back(ob.com.x());
    double term[1] = {0.0};
    ob.objective_terms(std::span<double>(term));
    distance_terms.push_back(term[0]);
  }
  template <class Observation>
  void finish(const Observation& ob, const rollout_result& r) {
    final_step = ob.step;
    final_cost = r.cost;
  }
};

rollout_options options_for(const planar_model& m) {
  rollout_options o;
  o.duration = 0.1;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain(), o.initial_state.q);
  o.pushes = {push{0, vec3(60, 0, 0), 0.02, 0.06}};
  return o;
}

}  // namespace

TEST_CASE("an observer sees every step in order and the stop state, and changes nothing",
          "[rollout][observer]") {
  const planar_model m = sharon2005_human7();
  const rollout_options o = options_for(m);
  const Eigen::VectorXd p = Eigen::VectorXd::Constant(m.num_joint_dofs(), 0.05);
  auto scr = make_rollout_scratch(m);
  const rollout_result plain = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(),
                                       flat_terrain(), semi_implicit_euler(), p, o, scr);
  logging_observer log;
  const rollout_result seen = rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(),
                                      flat_terrain(), semi_implicit_euler(), p, o, scr, log);
  CHECK(seen.cost == plain.cost);
  CHECK(seen.com_final == plain.com_final);
  REQUIRE(seen.steps == 240);
  CHECK(log.starts == 1);
  CHECK(log.setup.horizon_steps == 240);
  CHECK(log.setup.dt == dt);
  CHECK(log.setup.objective_term_names == std::vector<std::string>{"distance_m"});
  REQUIRE(log.steps.size() == 240);
  for (std::size_t k = 0; k < log.steps.size(); ++k) {
    REQUIRE(log.steps[k] == static_cast<std::int64_t>(k));
    REQUIRE(log.times[k] == static_cast<double>(k) * dt);
  }
  CHECK(log.final_step == 240);
  CHECK(log.final_cost == seen.cost);
  CHECK(log.distance_terms.back() != 0.0);  // the COM moved: the terms are live
  CHECK(log.com_x.back() != log.com_x.front());
}

TEST_CASE("the trajectory recorder is an observer, options.record is its shorthand",
          "[rollout][observer][recorder]") {
  const planar_model m = sharon2005_human7();
  rollout_options o = options_for(m);
  const Eigen::VectorXd p = Eigen::VectorXd::Zero(m.num_joint_dofs());
  auto scr = make_rollout_scratch(m);
  trajectory by_option, by_observer, both_option;
  o.record = &by_option;
  o.record_every = 8;
  rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
          semi_implicit_euler(), p, o, scr);
  o.record = nullptr;
  rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
          semi_implicit_euler(), p, o, scr, trajectory_observer(&by_observer, 8));
  // With a user observer as well, the option still records.
  o.record = &both_option;
  logging_observer log;
  rollout(m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain(),
          semi_implicit_euler(), p, o, scr, log);
  REQUIRE(by_option.frames.size() == 31);  // 240 / 8 + the stop state
  for (const trajectory* t : {&by_observer, &both_option}) {
    REQUIRE(t->frames.size() == by_option.frames.size());
    CHECK(t->objective_term_names == by_option.objective_term_names);
    CHECK(t->terrain.height == by_option.terrain.height);
    for (std::size_t i = 0; i < t->frames.size(); ++i) {
      const auto& a = t->frames[i];
      const auto& b = by_option.frames[i];
      REQUIRE(a.t == b.t);
      REQUIRE(a.q == b.q);
      REQUIRE(a.contact_force == b.contact_force);
      REQUIRE(a.objective_terms == b.objective_terms);
      REQUIRE(a.pushes.size() == b.pushes.size());
    }
  }
  CHECK(log.steps.size() == 240);
  CHECK(by_option.frames[8].pushes.size() == 1);  // t = 64 steps = 26.7 ms: inside the push
  CHECK(by_option.frames[2].pushes.empty());      // t = 16 steps = 6.7 ms: before it
}

TEST_CASE("a problem's evaluation takes an observer", "[rollout][observer][problem]") {
  const planar_model m = sharon2005_human7();
  const rollout_problem prob{m,
                             standing_pd(m, dt),
                             pose_hold(m),
                             distance_objective(),
                             flat_terrain(),
                             semi_implicit_euler(),
                             options_for(m)};
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(m.num_joint_dofs());
  auto ctx = prob.make_context();
  logging_observer log;
  const rollout_result r = prob.evaluate(x, 0.05, ctx, log);
  CHECK(r.cost == prob.evaluate(x, 0.05).cost);
  CHECK(log.steps.size() == 120);
  CHECK(log.final_step == 120);
}
