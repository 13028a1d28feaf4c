// Composition of the Sharon 2005 policies with the rest of the library: the nearest-neighbor
// controller and the mass-distance objective with every character (7-link, 16-link, 3D humanoid),
// both actuators (pd, torque), next to E2's pose_hold controller and distance objective
// (tests/rollout/compose.cpp is E2's; this is the same idea for the new policies), plus the
// mass-distance objective inside CMA-ES.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "support/rollout_e2.hpp"

using namespace gaitsynth;

namespace {

constexpr double dt = 1.0 / 2400.0;

struct human7 {
  using root = planar_root;
  static planar_model build() { return sharon2005_human7(); }
  static nearest_neighbor_options nn() { return {}; }
};
struct human16 {
  using root = planar_root;
  static planar_model build() { return sharon2005_human16(); }
  // Section VI.A: only the hips, knees and ankles are optimized; the upper body follows the target.
  static nearest_neighbor_options nn() {
    nearest_neighbor_options o;
    o.free_dofs = {"lhip", "lknee", "lankle", "rhip", "rknee", "rankle"};
    return o;
  }
};
struct humanoid3d {
  using root = floating_root;
  static floating_model build() { return wang2009_humanoid(); }
  // The stance hip's flexion DOF drives the pelvis (the root) to the target pitch.
  static nearest_neighbor_options nn() {
    nearest_neighbor_options o;
    o.left_hip = "lhip_y";
    o.right_hip = "rhip_y";
    o.torso_body = "pelvis";
    return o;
  }
};

struct nn_tag {};
struct pose_hold_tag {};
struct mass_distance_tag {};
struct distance_tag {};

/// A symmetric target for any character: standing, then the right hip flexed by 0.2 rad and the
/// right knee bent by 0.3 rad (the left leg the mirror image half a cycle later). Joint names are
/// looked up, so the same recipe serves the planar and the 3D characters.
template <root_joint Root>
keyframe_motion<Root> sway_target(const model<Root>& m) {
  Eigen::VectorXd q0 = neutral_configuration(m);
  place_on_terrain(m, flat_terrain{}, q0);
  Eigen::VectorXd q1 = q0;
  const int hip = m.find_dof("rhip") >= 0 ? m.find_dof("rhip") : m.dof_index("rhip_y");
  const int knee = m.dof_index("rknee");
  q1[Root::nq + hip] = -0.2;  // flexion is negative about +y in both conventions
  q1[Root::nq + knee] = 0.3;
  return keyframe_motion<Root>(m, {{0.0, q0}, {0.3, q1}}, 0.6, true, {}, stance_side::left);
}

template <class Character, class Actuator, class Controller, class Objective>
struct combination {
  using character = Character;
  using actuator_type = Actuator;
  using controller_tag = Controller;
  using objective_tag = Objective;
};

template <class... Ts>
using L = std::tuple<Ts...>;
#define GS_COMBOS(CH)                                                     \
  combination<CH, pd_actuator, nn_tag, mass_distance_tag>,                \
      combination<CH, pd_actuator, nn_tag, distance_tag>,                 \
      combination<CH, pd_actuator, pose_hold_tag, mass_distance_tag>,     \
      combination<CH, pd_actuator, pose_hold_tag, distance_tag>,          \
      combination<CH, torque_actuator, nn_tag, mass_distance_tag>,        \
      combination<CH, torque_actuator, nn_tag, distance_tag>,             \
      combination<CH, torque_actuator, pose_hold_tag, mass_distance_tag>, \
      combination<CH, torque_actuator, pose_hold_tag, distance_tag>
using all_combinations = L<GS_COMBOS(human7), GS_COMBOS(human16), GS_COMBOS(humanoid3d)>;
#undef GS_COMBOS
static_assert(std::tuple_size_v<all_combinations> == 3 * 2 * 2 * 2);

template <class A>
struct make_actuator;
template <>
struct make_actuator<pd_actuator> {
  template <class M>
  static pd_actuator from(const M& m) {
    return test_e2::standing_pd(m, dt);
  }
};
template <>
struct make_actuator<torque_actuator> {
  template <class M>
  static torque_actuator from(const M&) {
    return {};
  }
};

// The NN controller's servo gains are the standing PD gains, in both modes (with pd_actuator they
// must equal the actuator's for the torso servo's equivalent target).
template <class Character, class M, class A>
nearest_neighbor_controller<typename Character::root> make_nn(
    const M& m, const A& act, const keyframe_motion<typename Character::root>& target) {
  nearest_neighbor_options o = Character::nn();
  const pd_actuator g = test_e2::standing_pd(m, dt);
  o.kp.assign(g.kp.data(), g.kp.data() + g.kp.size());
  o.kd.assign(g.kd.data(), g.kd.data() + g.kd.size());
  o.output = act.input_kind();
  return nearest_neighbor_controller<typename Character::root>(m, target, o);
}

template <class M, class A>
pose_hold make_pose_hold(const M& m, const A& act) {
  if (act.input_kind() == command_kind::joint_target) return pose_hold(m);
  const pd_actuator g = test_e2::standing_pd(m, dt);
  return pose_hold(m, {.output = command_kind::joint_torque, .kp = g.kp, .kd = g.kd});
}

template <class C, class M, class Ctrl, class Obj, class A>
rollout_result run_one(const M& m, const A& act, Ctrl ctrl, const Obj& obj,
                       const Eigen::VectorXd& params, const sim_state& start) {
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.1;
  opt.initial_state = start;
  auto scratch = make_rollout_scratch(m);
  return rollout(m, act, ctrl, obj, flat_terrain{}, semi_implicit_euler{}, params, opt, scratch);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE(
    "nearest-neighbor controller and mass-distance objective compose with "
    "every character and actuator",
    "[controllers][compose]", all_combinations) {
  using C = TestType;
  using Root = typename C::character::root;
  const auto m = C::character::build();
  const auto act = make_actuator<typename C::actuator_type>::from(m);
  const keyframe_motion<Root> target = sway_target(m);
  const sim_state start = target.initial_state();

  auto go = [&](auto ctrl, const Eigen::VectorXd& params) {
    if constexpr (std::is_same_v<typename C::objective_tag, mass_distance_tag>)
      return run_one<C>(m, act, ctrl, mass_distance<Root>(m, target), params, start);
    else
      return run_one<C>(m, act, ctrl, distance_objective(), params, start);
  };
  rollout_result r;
  if constexpr (std::is_same_v<typename C::controller_tag, nn_tag>) {
    const auto ctrl = make_nn<typename C::character>(m, act, target);
    const std::vector<double> p = ctrl.parameters();
    r = go(ctrl, Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())));
    CHECK(ctrl.num_free_nodes() == 6);
  } else {
    r = go(make_pose_hold(m, act), test_e2::standing_pose(m));
  }
  INFO(m.name << ": stopped by " << to_string(r.reason) << " at t = " << r.time);
  REQUIRE(r.reason == stop_reason::horizon);
  CHECK(r.steps == 240);
  CHECK(std::isfinite(r.cost));
  // Nothing fell or was launched in a tenth of a second.
  CHECK(std::abs(r.com_final.z() - r.com_initial.z()) < 0.05);
  if constexpr (std::is_same_v<typename C::objective_tag, mass_distance_tag>) {
    CHECK(r.cost >= 0.0);
    // The character started on the target; in 0.1 s it cannot stray further than its whole mass
    // moved by 10 cm on average (delta <= M (0.1 m)^2 at every instant).
    CHECK(r.cost <= m.total_mass() * 0.01 * 0.1);
  }
}

TEST_CASE("mass-distance objective inside CMA-ES (nearest-neighbor controller, 7-link human)",
          "[controllers][compose][cmaes]") {
  const planar_model m = sharon2005_human7();
  const auto target = load_keyframes(
      m, std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/normal_walk.keyframes.json");
  rollout_options ro;
  ro.initial_state = target.initial_state();
  const nearest_neighbor_controller<planar_root> c0(m, target, {});
  const rollout_problem prob{m,
                             torque_actuator{},
                             c0,
                             mass_distance<planar_root>(m, target),
                             flat_terrain{},
                             semi_implicit_euler{},
                             ro};
  const Eigen::VectorXd x0 = prob.initial_parameters();
  REQUIRE(x0.size() == 72);
  const double f0 = prob.cost(x0, 0.2);
  REQUIRE(std::isfinite(f0));
  parameter_space space;
  for (Eigen::Index i = 0; i < x0.size(); ++i)
    space.add({std::string("p").append(std::to_string(i)),  // not "p" + ...: GCC 12 -Wrestrict
               x0[i] - 1.0, x0[i] + 1.0, x0[i], 1.0});      // false positive (PR 105329)
  cmaes_options co;
  co.sigma0 = 0.02;
  co.seed = 5;
  co.stop.max_iterations = 2;
  cmaes es(space, co);
  thread_pool_evaluator pool(2);
  const optimization_result r = minimize(
      es, [&](const Eigen::VectorXd& x) { return prob.cost(x, 0.2); }, pool);
  CHECK(r.iterations == 2);
  CHECK(r.evaluations == 2 * (4 + static_cast<int>(std::floor(3 * std::log(72.0)))));
  CHECK(r.non_finite == 0);
  CHECK(std::isfinite(r.value));
  CHECK(r.value > 0.0);
  // The best of 34 samples is a real cost of that point, reproducible by a fresh evaluation.
  CHECK(prob.cost(r.x, 0.2) == r.value);
}

TEST_CASE("a problem with variants adds the variants' costs, on other terrain types",
          "[controllers][synthesis][variants]") {
  const planar_model m = sharon2005_human7();
  const auto target = load_keyframes(
      m, std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/normal_walk.keyframes.json");
  rollout_options ro;
  ro.initial_state = target.initial_state();
  const nearest_neighbor_controller<planar_root> c0(m, target, {});
  const rollout_problem flat{m,
                             torque_actuator{},
                             c0,
                             mass_distance<planar_root>(m, target),
                             flat_terrain{},
                             semi_implicit_euler{},
                             ro};
  // Variants: the same controller on a 5 degree slope, and on flat ground from a faster start.
  const slope_terrain hill(5.0 * std::numbers::pi / 180.0);
  rollout_options rh = ro;
  rh.initial_state = target_start_states(m, target, hill, {0.0}).front();
  using hill_problem = nn_problem<planar_root, torque_actuator, mass_distance<planar_root>,
                                  slope_terrain, semi_implicit_euler>;
  std::vector<hill_problem> variants{hill_problem{m, torque_actuator{}, c0,
                                                  mass_distance<planar_root>(m, target), hill,
                                                  semi_implicit_euler{}, rh}};
  const auto combined = make_problem_with_variants(flat, variants, 0.5);
  const Eigen::VectorXd x = flat.initial_parameters();
  const double c_flat = flat.cost(x, 0.3), c_hill = variants[0].cost(x, 0.3);
  REQUIRE(std::isfinite(c_flat));
  REQUIRE(std::isfinite(c_hill));
  CHECK(c_hill != c_flat);  // the slope changes the motion
  CHECK(combined.cost(x, 0.3) == c_flat + 0.5 * c_hill);
  // Everything else is the main problem's: the 70 s check runs on flat ground.
  CHECK(combined.evaluate(x, 0.3).cost == flat.evaluate(x, 0.3).cost);
  CHECK(combined.initial_parameters() == x);

  CHECK_THROWS_WITH(make_problem_with_variants(flat, variants, -1.0),
                    Catch::Contains("variant_weight") && Catch::Contains("-1"));
  nearest_neighbor_options o24;
  o24.num_nodes = 24;
  std::vector<hill_problem> wrong{
      hill_problem{m, torque_actuator{}, nearest_neighbor_controller<planar_root>(m, target, o24),
                   mass_distance<planar_root>(m, target), hill, semi_implicit_euler{}, rh}};
  CHECK_THROWS_WITH(make_problem_with_variants(flat, wrong),
                    Catch::Contains("144") && Catch::Contains("72"));
}
