// weighted_sum (objectives/weighted_sum.hpp): the weighted cost, early stop, the parts' recorded
// terms (names forwarded, repeats made unique) and the in-place accumulator reset.
#include <catch2/catch.hpp>

#include <array>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"
#include "gaitsynth/rollout/problem.hpp"

using namespace gaitsynth;

namespace {

/// Counts steps and sums the joint power: two terms, and a reset hook that is observable.
struct work_counter {
  struct accumulator_type {
    std::vector<double> per_step;  // owns memory, as a real accumulator might
    double work = 0.0;
    int steps = 0;
    int resets = 0;
  };
  int stop_after = -1;
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {std::vector<double>(4, 0.0)};
  }
  template <root_joint Root>
  void reset_accumulator(const model<Root>&, accumulator_type& a) const {
    a.work = 0.0;
    a.steps = 0;
    ++a.resets;
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    for (int j = 0; j < v.model().num_joint_dofs(); ++j) a.work += v.joint_power(j) * v.dt;
    ++a.steps;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.work; }
  bool done(const accumulator_type& a) const { return stop_after >= 0 && a.steps >= stop_after; }
  static std::array<std::string_view, 2> term_names() { return {"work_J", "steps"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.work;
    out[1] = a.steps;
  }
};

}  // namespace

TEST_CASE("weighted_sum adds the weighted costs and stops when a part is done",
          "[objectives][weighted_sum]") {
  const planar_model m = sharon2005_human7();
  rollout_options ro;
  ro.duration = 0.2;
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(m.num_joint_dofs(), 0.05);
  auto problem = [&](auto objective) {
    return rollout_problem{m,         standing_pd(m, ro.dt), pose_hold(m),
                           objective, flat_terrain{},        semi_implicit_euler{},
                           ro};
  };
  const double d = problem(distance_travelled{}).cost(x, 0.2);
  const double w = problem(work_counter{}).cost(x, 0.2);
  REQUIRE(w != 0.0);
  const auto both = weighted_sum<distance_travelled, work_counter>(
      {2.0, -0.5}, distance_travelled{}, work_counter{});
  CHECK(problem(both).cost(x, 0.2) == Approx(2.0 * d - 0.5 * w).epsilon(1e-14));
  const auto early = weighted_sum<distance_travelled, work_counter>(
      {1.0, 1.0}, distance_travelled{}, work_counter{.stop_after = 10});
  const rollout_result r = problem(early).evaluate(x, 0.2);
  CHECK(r.reason == stop_reason::objective);
  CHECK(r.steps == 9);  // done after the 10th accumulate (step 9), before integrating it
}

TEST_CASE("weighted_sum forwards its parts' term names and values", "[objectives][weighted_sum]") {
  const auto o = weighted_sum<distance_travelled, time_to_fall, work_counter, work_counter>(
      {1.0, 1.0, 1.0, 1.0}, distance_travelled{}, time_to_fall{}, work_counter{}, work_counter{});
  static_assert(objective_with_terms<decltype(o)>);
  const std::vector<std::string> expected = {"distance_m", "work_J", "steps", "work_J#3",
                                             "steps#3"};
  CHECK(o.term_names() == expected);
  const planar_model m = sharon2005_human7();
  auto acc = o.make_accumulator(m);
  std::get<2>(acc).work = 1.5;
  std::get<2>(acc).steps = 7;
  std::get<3>(acc).work = -2.0;
  std::get<3>(acc).steps = 3;
  std::array<double, 5> out{};
  out.fill(99.0);
  o.terms(acc, std::span<double>(out));
  CHECK(out == std::array<double, 5>{0.0, 1.5, 7.0, -2.0, 3.0});

  // Recorded per frame by the rollout, one column per term.
  rollout_options ro;
  ro.duration = 0.05;
  trajectory tr;
  const rollout_problem prob{
      m, standing_pd(m, ro.dt), pose_hold(m), o, flat_terrain{}, semi_implicit_euler{}, ro};
  prob.evaluate(Eigen::VectorXd::Zero(m.num_joint_dofs()), 0.05, &tr, 10);
  REQUIRE(tr.objective_term_names == expected);
  REQUIRE(tr.frames.size() >= 2);
  CHECK(tr.frames.back().objective_terms[2] == 120.0);  // steps counted by part 2: all 120
}

TEST_CASE("weighted_sum resets its parts' accumulators in place", "[objectives][weighted_sum]") {
  const planar_model m = sharon2005_human7();
  const auto o = weighted_sum<distance_travelled, work_counter>({1.0, 1.0}, distance_travelled{},
                                                                work_counter{});
  auto acc = o.make_accumulator(m);
  std::get<0>(acc).started = true;
  std::get<1>(acc).work = 3.0;
  std::get<1>(acc).steps = 5;
  const double* memory = std::get<1>(acc).per_step.data();
  o.reset_accumulator(m, acc);
  CHECK_FALSE(std::get<0>(acc).started);  // no hook: made anew
  CHECK(std::get<1>(acc).work == 0.0);    // hook: reset in place, memory kept
  CHECK(std::get<1>(acc).steps == 0);
  CHECK(std::get<1>(acc).resets == 1);
  CHECK(std::get<1>(acc).per_step.data() == memory);
}
