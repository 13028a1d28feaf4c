// rollout_problem (rollout/problem.hpp): per-worker contexts reused across evaluations give the
// values of fresh ones, a scratch reused for another body is rebuilt, parameters are named in
// errors, and an optimization's values do not depend on the thread count.
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/optimizers/sds.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"

using namespace gaitsynth;

namespace {

std::string data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

/// The saved normal walk as a problem on body m (the controller was optimized for the nominal
/// body; the start is the keyframes' first state).
auto normal_walk_problem(const planar_model& m, const planar_model& nominal) {
  const auto target = load_keyframes(nominal, data("normal_walk.keyframes.json"));
  const auto ctrl = load_nearest_neighbor(nominal, data("normal_walk.controller.json"));
  rollout_options ro;
  ro.initial_state = target.initial_state();
  return rollout_problem{m,
                         torque_actuator{},
                         ctrl,
                         mass_distance<planar_root>(m, target),
                         flat_terrain{},
                         semi_implicit_euler{},
                         ro};
}

void require_same(const rollout_result& a, const rollout_result& b) {
  CHECK(a.cost == b.cost);
  CHECK(a.steps == b.steps);
  CHECK(a.reason == b.reason);
  CHECK(a.com_final == b.com_final);
}

}  // namespace

TEST_CASE("a reused context gives the values of a fresh one", "[rollout][problem]") {
  SECTION("7-link walker, nearest-neighbor controller, mass-distance cost") {
    const planar_model m = sharon2005_human7();
    const auto prob = normal_walk_problem(m, m);
    const Eigen::VectorXd x = prob.initial_parameters();
    Eigen::VectorXd y = x;
    y.array() += 0.05;  // another candidate: a different trajectory through the same context
    const rollout_result fresh = prob.evaluate(x, 1.0);
    auto ctx = prob.make_context();
    const rollout_result ry = prob.evaluate(y, 1.0, ctx);
    const rollout_result again = prob.evaluate(x, 1.0, ctx);
    REQUIRE(ry.cost != fresh.cost);  // the detour really changed the context's contents
    require_same(again, fresh);
    CHECK(prob.cost(x, 1.0, ctx) == fresh.cost);
  }
  SECTION("3D humanoid, PD pose hold, a push, RK4") {
    const floating_model m = wang2009_humanoid();
    const double dt = 1.0 / 2400.0;
    rollout_options ro;
    ro.duration = 0.3;
    ro.pushes = {push{0, vec3(120, 40, 0), 0.05, 0.15}};
    const rollout_problem prob{
        m, standing_pd(m, dt), pose_hold(m), distance_objective(), flat_terrain{}, odeint_rk4{},
        ro};
    const Eigen::VectorXd x = Eigen::VectorXd::Zero(m.num_joint_dofs());
    const Eigen::VectorXd y = Eigen::VectorXd::Constant(m.num_joint_dofs(), 0.1);
    const rollout_result fresh = prob.evaluate(x, 0.3);
    auto ctx = prob.make_context();
    prob.evaluate(y, 0.3, ctx);
    require_same(prob.evaluate(x, 0.3, ctx), fresh);
  }
}

TEST_CASE("pushes changed between evaluations reach a context made before", "[rollout][problem]") {
  // Between optimizer iterations a program may redraw the pushes (wang2012_walk --push-phase
  // random): the context's copy of the options must not keep the old ones.
  const floating_model m = wang2009_humanoid();
  rollout_options ro;
  ro.duration = 0.3;
  ro.pushes = {push{0, vec3(120, 40, 0), 0.05, 0.15}};
  rollout_problem prob{m,
                       standing_pd(m, 1.0 / 2400.0),
                       pose_hold(m),
                       distance_objective(),
                       flat_terrain{},
                       semi_implicit_euler{},
                       ro};
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(m.num_joint_dofs());
  auto ctx = prob.make_context();
  const rollout_result first = prob.evaluate(x, 0.3, ctx);
  prob.options.pushes = {push{0, vec3(-200, 0, 0), 0.1, 0.1}, push{0, vec3(0, 90, 0), 0.2, 0.05}};
  const rollout_result moved = prob.evaluate(x, 0.3, ctx);
  CHECK(moved.com_final != first.com_final);
  require_same(moved, prob.evaluate(x, 0.3));  // a fresh context: the same pushes, the same walk
  prob.options.pushes.clear();
  require_same(prob.evaluate(x, 0.3, ctx), prob.evaluate(x, 0.3));
}

TEST_CASE("a scratch reused for another body of the same size is rebuilt", "[rollout][problem]") {
  // Fig. 8a's body has the sizes of the nominal one; only the torso mass (40 -> 28 kg) and its
  // inertia differ. contact_state caches per-body inverse masses and the planar workspace per-body
  // masses: a scratch kept from the nominal body would simulate with stale ones. The bodies are
  // built into the same storage, so even the model's address does not change.
  const planar_model nominal = sharon2005_human7();
  sharon2005_human7_parameters light;
  light.torso_mass = 28.0;
  light = light.with_rod_inertias();
  const auto target = load_keyframes(nominal, data("normal_walk.keyframes.json"));
  const auto ctrl = load_nearest_neighbor(nominal, data("normal_walk.controller.json"));
  const auto p = ctrl.parameters();
  rollout_options ro;
  ro.initial_state = target.initial_state();
  ro.duration = 1.0;
  auto run = [&](const planar_model& m, rollout_scratch<planar_root>& scr) {
    auto c = ctrl;
    return rollout(m, torque_actuator{}, c, mass_distance<planar_root>(m, target), flat_terrain{},
                   semi_implicit_euler{}, std::span<const double>(p), ro, scr);
  };
  std::optional<planar_model> slot;
  slot.emplace(nominal);
  const planar_model* address = &*slot;
  rollout_scratch<planar_root> reused;
  run(*slot, reused);
  slot.reset();
  slot.emplace(sharon2005_human7(light));
  REQUIRE(&*slot == address);
  REQUIRE(model_fingerprint(*slot) != model_fingerprint(nominal));
  rollout_scratch<planar_root> fresh;
  const rollout_result expected = run(*slot, fresh);
  const rollout_result got = run(*slot, reused);
  require_same(got, expected);
  const int torso = slot->body_index("torso");
  CHECK(reused.contacts.inv_mass[static_cast<std::size_t>(torso)] == 1.0 / 28.0);
  // Equal content at another address keeps the scratch (nothing to rebuild) and the values.
  const planar_model copy = *slot;
  const auto* before = reused.contacts.inv_mass.data();
  require_same(run(copy, reused), expected);
  CHECK(reused.contacts.inv_mass.data() == before);
}

TEST_CASE("a problem names the bad parameter", "[rollout][problem]") {
  const planar_model m = sharon2005_human7();
  const auto prob = normal_walk_problem(m, m);
  Eigen::VectorXd x = prob.initial_parameters();
  const std::vector<std::string> names = prob.parameter_names();
  REQUIRE(names.size() == static_cast<std::size_t>(x.size()));
  x[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(prob.cost(x, 0.1), Catch::Contains("parameter 3 '" + names[3] + "'") &&
                                           Catch::Contains("not finite"));
  CHECK_THROWS_WITH(prob.cost(Eigen::VectorXd::Zero(2), 0.1), Catch::Contains("parameter vector"));
  // Controllers without names get p0, p1, ...
  const floating_model h = wang2009_humanoid();
  const rollout_problem ph{h,
                           standing_pd(h, 1.0 / 2400.0),
                           pose_hold(h),
                           distance_objective(),
                           flat_terrain{},
                           semi_implicit_euler{},
                           rollout_options{}};
  CHECK(ph.parameter_names().at(2) == "p2");
}

TEST_CASE("problem costs on worker contexts do not depend on the thread count",
          "[rollout][problem][evaluators]") {
  const planar_model m = sharon2005_human7();
  const auto main = normal_walk_problem(m, m);
  sharon2005_human7_parameters heavy;
  heavy.torso_mass = 48.0;
  const planar_model mh = sharon2005_human7(heavy.with_rod_inertias());
  const auto prob = make_problem_with_variants(main, std::vector{normal_walk_problem(mh, m)}, 0.5);
  const Eigen::VectorXd x0 = prob.initial_parameters();
  std::vector<Eigen::VectorXd> xs;
  for (int k = 0; k < 7; ++k) {
    Eigen::VectorXd x = x0;
    x[k % x.size()] += 0.02 * (k - 3);
    xs.push_back(x);
  }
  std::vector<double> ref;
  for (const auto& x : xs) ref.push_back(prob.cost(x, 0.4));  // fresh contexts
  for (unsigned threads : {1u, 2u, 3u}) {
    thread_pool_evaluator pool(threads);
    problem_contexts ctx(prob, pool.thread_count());
    std::vector<double> out(xs.size());
    for (int rep = 0; rep < 2; ++rep) {
      problem_cost f(prob, 0.4, ctx);
      pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
      INFO(threads << " threads, batch " << rep);
      CHECK(out == ref);
    }
  }
}

TEST_CASE("CMA-ES and SDS minimize a problem through worker contexts, on any thread count",
          "[rollout][problem][optimizers]") {
  const planar_model m = sharon2005_human7();
  const auto prob = normal_walk_problem(m, m);
  const Eigen::VectorXd x0 = prob.initial_parameters();
  const std::vector<std::string> names = prob.parameter_names();
  parameter_space space;
  for (Eigen::Index i = 0; i < x0.size(); ++i)
    space.add({names[static_cast<std::size_t>(i)], x0[i] - 1.0, x0[i] + 1.0, x0[i], 1.0});
  auto run = [&](unsigned threads, bool use_sds) {
    thread_pool_evaluator pool(threads);
    problem_contexts ctx(prob, pool.thread_count());
    problem_cost f(prob, 0.2, ctx);
    if (use_sds) {
      sds_options so;
      so.x0 = x0;
      so.stop.max_evaluations = 40;
      sds opt(space, so);
      return minimize(opt, f, pool);
    }
    cmaes_options co;
    co.sigma0 = 0.02;
    co.seed = 5;
    co.stop.max_iterations = 2;
    cmaes opt(space, co);
    return minimize(opt, f, pool);
  };
  for (bool use_sds : {false, true}) {
    INFO((use_sds ? "SDS" : "CMA-ES"));
    const optimization_result one = run(1, use_sds), two = run(2, use_sds);
    CHECK(one.x == two.x);
    CHECK(one.value == two.value);
    CHECK(one.evaluations == two.evaluations);
    CHECK(std::isfinite(one.value));
    CHECK(prob.cost(one.x, 0.2) == one.value);  // a fresh context gives the logged value
  }
}
