// problem_with_constraint (rollout/problem_with_constraint.hpp): Deb's feasibility rules as one
// cost (feasible candidates keep theirs, every infeasible one ranks below them, infeasible ones by
// violation), CMA-ES finding a constrained minimum through it, and the violation read from the
// main rollout's own context when variants surround it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/problem_with_constraint.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/rollout/walk_check.hpp"

using namespace gaitsynth;

namespace {

/// (x0 - 2)^2 + x1^2; its context keeps the last x0, as a rollout's keeps its accumulator.
struct toy_problem {
  struct context_type {
    double last_x0 = 0.0;
  };
  context_type make_context() const { return {}; }
  std::size_t num_parameters() const { return 2; }
  double cost(const Eigen::VectorXd& x, double, context_type& ctx) const {
    ctx.last_x0 = x[0];
    return (x[0] - 2.0) * (x[0] - 2.0) + x[1] * x[1];
  }
};

/// x0 <= 1.
struct x0_at_most_1 {
  double operator()(const toy_problem::context_type& ctx) const {
    return std::max(0.0, ctx.last_x0 - 1.0);
  }
};

Eigen::VectorXd point(double a, double b) {
  return Eigen::Vector2d(a, b);
}

}  // namespace

TEST_CASE("problem_with_constraint ranks by Deb's feasibility rules", "[rollout][problem]") {
  const auto prob = make_problem_with_constraint(toy_problem{}, x0_at_most_1{});
  // Feasible: the main cost, unchanged.
  CHECK(prob.cost(point(1.0, 0.0), 1.0) == 1.0);
  CHECK(prob.cost(point(-3.0, 40.0), 1.0) == 25.0 + 1600.0);
  // Infeasible: below every feasible candidate, however good its own cost (x0 = 2 is the
  // unconstrained minimum, cost 0), and ordered by violation alone.
  const double near = prob.cost(point(1.01, 0.0), 1.0), far = prob.cost(point(2.0, 0.0), 1.0);
  CHECK(near == 1e15 * 1.01);
  CHECK(far == 1e15 * 2.0);
  CHECK(near > prob.cost(point(-3.0, 40.0), 1.0));
  CHECK(far > near);
  CHECK(prob.cost(point(1.01, 9.0), 1.0) == near);  // (x1 does not matter when infeasible)
  CHECK(std::isfinite(far));
}

TEST_CASE("problem_with_constraint: bad violations and offsets are errors, NaN is worst",
          "[rollout][problem]") {
  auto nan_violation = [](const toy_problem::context_type&) { return std::nan(""); };
  CHECK(make_problem_with_constraint(toy_problem{}, nan_violation).cost(point(0, 0), 1.0) ==
        std::numeric_limits<double>::infinity());
  auto negative = [](const toy_problem::context_type&) { return -0.5; };
  CHECK_THROWS_WITH(make_problem_with_constraint(toy_problem{}, negative).cost(point(0, 0), 1.0),
                    Catch::Contains("-0.5"));
  // A feasible cost at or above the offset would rank among the infeasible ones: refused.
  const auto low = make_problem_with_constraint(toy_problem{}, x0_at_most_1{}, 100.0);
  CHECK(low.cost(point(-7.0, 0.0), 1.0) == 81.0);
  CHECK_THROWS_WITH(low.cost(point(-8.0, 0.0), 1.0), Catch::Contains("raise infeasible_cost"));
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")})
    CHECK_THROWS_WITH(make_problem_with_constraint(toy_problem{}, x0_at_most_1{}, bad),
                      Catch::Contains("infeasible_cost"));
}

TEST_CASE("CMA-ES finds the constrained minimum through problem_with_constraint",
          "[rollout][problem][optimizers]") {
  // min (x0 - 2)^2 + x1^2 subject to x0 <= 1: the minimum is on the boundary, (1, 0); started
  // from a feasible point, CMA-ES must press against the constraint, not step over it.
  const auto prob = make_problem_with_constraint(toy_problem{}, x0_at_most_1{});
  parameter_space space;
  space.add({"x0", -5.0, 5.0, -2.0, 1.0});
  space.add({"x1", -5.0, 5.0, 3.0, 1.0});
  cmaes_options co;
  co.sigma0 = 0.2;
  co.seed = 3;
  co.stop.max_iterations = 300;
  serial_evaluator serial;
  problem_contexts ctx(prob, 1);
  const optimization_result r = minimize(cmaes(space, co), problem_cost(prob, 1.0, ctx), serial);
  CHECK(r.x[0] <= 1.0);
  CHECK(r.x[0] == Approx(1.0).margin(1e-4));
  CHECK(r.x[1] == Approx(0.0).margin(1e-3));
  CHECK(r.value == Approx(1.0).margin(1e-3));
}

namespace {

std::string sharon_data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

/// The saved normal walk on body m scored by the distance walked (cost: minus it).
auto distance_problem(const planar_model& m, const planar_model& nominal) {
  const auto target = load_keyframes(nominal, sharon_data("normal_walk.keyframes.json"));
  const auto ctrl = load_nearest_neighbor(nominal, sharon_data("normal_walk.controller.json"));
  rollout_options ro;
  ro.initial_state = target.initial_state();
  return rollout_problem{
      m, torque_actuator{}, ctrl, distance_travelled{}, flat_terrain{}, semi_implicit_euler{}, ro};
}

}  // namespace

TEST_CASE("problem_with_constraint judges the main rollout, not the variants around it",
          "[rollout][problem]") {
  const planar_model m = sharon2005_human7();
  sharon2005_human7_parameters heavy;
  heavy.torso_mass = 48.0;
  const planar_model mh = sharon2005_human7(heavy.with_rod_inertias());
  const auto main = distance_problem(m, m);
  const auto variant = distance_problem(mh, m);
  const Eigen::VectorXd x = main.initial_parameters();
  const double horizon = 1.0;
  const double main_cost = main.cost(x, horizon), variant_cost = variant.cost(x, horizon);
  const double walked = -main_cost, walked_heavy = -variant_cost;  // m, along +x
  REQUIRE(walked > 0.0);
  REQUIRE(std::abs(walked - walked_heavy) > 1e-4);  // (d between them tells them apart)
  // "Walk at least d": read from the accumulator the rollout left in the main context.
  auto at_least = [](double d) {
    return [d](const auto& ctx) {
      const auto& a = *ctx.states.objective;
      return std::max(0.0, d - (a.com_last - a.com_start).x());
    };
  };
  const double between = 0.5 * (walked + walked_heavy);
  const double d_ok = walked > walked_heavy ? between : walked - 0.01;   // main feasible
  const double d_not = walked > walked_heavy ? walked + 0.01 : between;  // main infeasible
  for (double d : {d_ok, d_not}) {
    const auto prob = make_problem_with_variants(make_problem_with_constraint(main, at_least(d)),
                                                 std::vector{variant}, 0.5);
    auto ctx = prob.make_context();
    const double c = prob.cost(x, horizon, ctx);
    const double v = std::max(
        0.0, d - (ctx.main.states.objective->com_last - ctx.main.states.objective->com_start).x());
    INFO("d = " << d << ", main walked " << walked << " m, the heavy variant " << walked_heavy);
    if (d == d_ok) {
      CHECK(v == 0.0);
      CHECK(c == main_cost + 0.5 * variant_cost);
    } else {
      CHECK(v > 0.0);
      CHECK(c == 1e15 * (1.0 + v) + 0.5 * variant_cost);
    }
    // The walk check follows the main problem through both adapters.
    CHECK(check_walk(prob, x, horizon).distance == Approx(walked).epsilon(1e-12));
  }
}
