// The composition test of the 3D biped controllers (controllers/fsm/, controllers/reflex/): each
// controller with each integrator and terrain under the whole Wang 2009 objective, and each
// objective term of objectives/wang2009/ alone, run a short rollout of the Wang 2009 humanoid
// through mixed_pd_actuator, the actuator both FSM controllers command; the muscle-reflex
// controller through the musculotendon actuator under the Wang 2012 objective, the Wang 2009 one
// and each term alone; and the FSM controller on the Wang 2012 body under the Wang 2012 task and
// torque terms (every objective it accepts: the metabolic term needs muscles).
#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

struct wang2009_case {
  static auto make(const floating_model& m, std::vector<double>& p, rollout_options&) {
    wang2009_controller c(m);
    p = wang2009_table2_parameters(m, c);
    return c;
  }
};
struct simbicon_case {
  static auto make(const floating_model& m, std::vector<double>& p, rollout_options& o) {
    const auto [kp, kd] = simbicon_walk_gains(m);
    p = simbicon_walk_parameters();
    o.initial_state = simbicon_start_state(m);
    return simbicon_controller(m, kp, kd);
  }
};

template <class Case, class Integrator, class Terrain, class Objective>
rollout_result run(const floating_model& m, const Terrain& ground, const Objective& obj) {
  std::vector<double> p;
  rollout_options o;
  o.duration = 0.05;
  o.contact.mu = 10.0;
  auto c = Case::make(m, p, o);
  auto scratch = make_rollout_scratch(m);
  return rollout(m, mixed_pd_actuator{}, c, obj, ground, Integrator{}, std::span<const double>(p),
                 o, scratch);
}

using cases = std::tuple<std::tuple<wang2009_case, semi_implicit_euler, flat_terrain>,
                         std::tuple<wang2009_case, odeint_rk4, slope_terrain>,
                         std::tuple<simbicon_case, semi_implicit_euler, slope_terrain>,
                         std::tuple<simbicon_case, odeint_rk4, flat_terrain>>;

template <class T>
T terrain_of() {
  if constexpr (std::is_same_v<T, slope_terrain>)
    return slope_terrain(0.05);
  else
    return T{};
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("3D biped controllers compose with integrators, terrains and eq. 16",
                        "[rollout][compose][wang2009]", cases) {
  using Case = std::tuple_element_t<0, TestType>;
  using Integrator = std::tuple_element_t<1, TestType>;
  using Terrain = std::tuple_element_t<2, TestType>;
  const auto m = wang2009_humanoid();
  const rollout_result r = run<Case, Integrator>(m, terrain_of<Terrain>(), wang2009_objective(m));
  CHECK(r.reason == stop_reason::horizon);
  CHECK(std::isfinite(r.cost));
  CHECK(r.cost > 0.0);  // 0.05 s of a 10 s horizon: E_fail charges the unsimulated rest
}

TEST_CASE("every Wang 2009 term is an objective on its own", "[rollout][compose][wang2009]") {
  const auto m = wang2009_humanoid();
  const flat_terrain g;
  const auto check = [&](const auto& obj) {
    const rollout_result r = run<wang2009_case, semi_implicit_euler>(m, g, obj);
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
  };
  check(wang2009::user_gait(m, {.target_speed = 1.0, .target_step_length = 0.6}));
  check(wang2009::velocity());
  check(wang2009::landing(m, {}));
  check(wang2009::failure());
  check(wang2009::symmetry{});
  check(wang2009::angular_momentum(m, {}));
  check(wang2009::head(m));
  check(wang2009::power({.cost_of_transport = true}));
  check(wang2009::power_ratio(m));
}

namespace {

/// The reflex controller from its start state, driving the 16 leg MTUs, for 0.05 s.
template <class Integrator, class Terrain, class Objective>
rollout_result run_muscles(const floating_model& m, const Terrain& ground, const Objective& obj) {
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m));
  const wang2012_reflex_controller c(m);
  const std::vector<double> p = wang2012_reflex_controller::initial_parameters(m);
  rollout_options o;
  o.duration = 0.05;
  auto scratch = make_rollout_scratch(m);
  return rollout(m, act, c, obj, ground, Integrator{}, std::span<const double>(p), o, scratch);
}

}  // namespace

TEST_CASE("the muscle-reflex controller composes with integrators, terrains and objectives",
          "[rollout][compose][wang2012]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const auto obj = wang2012::objective(m, units, wang2012::metabolic_energy(units));
  const auto check = [&](const rollout_result& r) {
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
  };
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, obj));
  check(run_muscles<semi_implicit_euler>(m, slope_terrain(0.05), obj));
  check(run_muscles<odeint_rk4>(m, flat_terrain{}, obj));
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2009_objective(m)));
  // Each Wang 2012 term alone.
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2012::metabolic_energy(units)));
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2012::other_joint_torque(units)));
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2012::joint_limit_torque(units)));
  check(
      run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2012::sagittal_joint_torque(units)));
  check(run_muscles<semi_implicit_euler>(m, flat_terrain{}, wang2012::mean_squared_activation{}));
}

TEST_CASE("the torque-driven FSM controller on the Wang 2012 body under the Wang 2012 terms",
          "[rollout][compose][wang2012]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const auto check = [&](const auto& obj) {
    const rollout_result r = run<wang2009_case, semi_implicit_euler>(m, flat_terrain{}, obj);
    CHECK(r.reason == stop_reason::horizon);
    CHECK(std::isfinite(r.cost));
  };
  // The task terms and the torque efforts: J_R, J_L and the min_torque ablation's J_M.
  const wang2012::effort_weights w;
  const double we = w.effort_per_kg / m.total_mass();
  check(weighted_sum<wang2009::user_gait, wang2009::failure, wang2012::mean_squared_joint_torque,
                     wang2012::mean_squared_joint_torque, wang2012::mean_squared_joint_torque>(
      {100.0, 120000.0, we * 5.0, we * w.other_torque, we * w.limit_torque},
      wang2009::user_gait(m, {.target_speed = 1.25}), wang2009::failure(),
      wang2012::sagittal_joint_torque(units), wang2012::other_joint_torque(units),
      wang2012::joint_limit_torque(units)));
}
