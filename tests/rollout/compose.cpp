// The composition test: every combination of the policies that exist compiles and runs a short
// rollout. To add a policy, append its type to the axis list below and, if it needs more than
// default construction, specialize make<> (or make_controller<>) for it.
#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "support/rollout_e2.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_e2;

namespace {

constexpr double dt = 1.0 / 2400.0;

// ---- the axes ---------------------------------------------------------------------------------
template <class... Ts>
struct type_list {};

using characters = type_list<planar_human7, humanoid3d>;
using actuators =
    type_list<pd_actuator, torque_actuator, mixed_pd_actuator, musculotendon_actuator>;
using controllers = type_list<pose_hold>;
using objectives = type_list<decltype(distance_objective())>;
using terrains = type_list<flat_terrain, slope_terrain>;
using integrators = type_list<semi_implicit_euler, odeint_rk4>;

template <class Character, class Actuator, class Controller, class Objective, class Terrain,
          class Integrator>
struct combination {
  using character = Character;
  using actuator_type = Actuator;
  using controller_type = Controller;
  using objective_type = Objective;
  using terrain_type = Terrain;
  using integrator_type = Integrator;
};

// ---- Cartesian product of type lists -> std::tuple<combination<...>...> -------------------------
template <class A, class B>
struct concat;
template <class... A, class... B>
struct concat<type_list<A...>, type_list<B...>> {
  using type = type_list<A..., B...>;
};
template <class... Ls>
struct concat_all {
  using type = type_list<>;
};
template <class L, class... Ls>
struct concat_all<L, Ls...> {
  using type = typename concat<L, typename concat_all<Ls...>::type>::type;
};
// Prepends T to each tuple (a type_list) of the list P.
template <class T, class P>
struct prepend_each;
template <class T, class... Tuples>
struct prepend_each<T, type_list<Tuples...>> {
  using type = type_list<typename concat<type_list<T>, Tuples>::type...>;
};
template <class... Axes>
struct product {
  using type = type_list<type_list<>>;
};
template <class... Ts, class... Axes>
struct product<type_list<Ts...>, Axes...> {
  using rest = typename product<Axes...>::type;
  using type = typename concat_all<typename prepend_each<Ts, rest>::type...>::type;
};
template <class L>
struct to_combinations;
template <class... Tuples>
struct to_combinations<type_list<Tuples...>> {
  template <class T>
  struct one;
  template <class... Ps>
  struct one<type_list<Ps...>> {
    using type = combination<Ps...>;
  };
  using type = std::tuple<typename one<Tuples>::type...>;
};
using all_combinations =
    typename to_combinations<typename product<characters, actuators, controllers, objectives,
                                              terrains, integrators>::type>::type;
static_assert(std::tuple_size_v<all_combinations> == 2 * 4 * 1 * 1 * 2 * 2);

// ---- factories ----------------------------------------------------------------------------------
template <class T>
struct make {
  template <class Model>
  static T from(const Model&) {
    return T{};
  }
};
template <>
struct make<pd_actuator> {
  template <class Model>
  static pd_actuator from(const Model& m) {
    return standing_pd(m, dt);
  }
};
/// The 16 leg MTUs of Wang et al. 2012 on the 3D humanoid (its DOF names are the Wang 2012
/// model's); the planar human has no such legs, so it gets none (the mixed block alone).
template <>
struct make<musculotendon_actuator> {
  template <class Model>
  static musculotendon_actuator from(const Model& m) {
    if constexpr (std::is_same_v<typename Model::root_type, floating_root>)
      return musculotendon_actuator(musculotendon::geyer_herr_leg_muscles(m));
    else
      return musculotendon_actuator({});
  }
};
template <>
struct make<slope_terrain> {
  template <class Model>
  static slope_terrain from(const Model&) {
    return slope_terrain(0.05);  // 2.9 degrees uphill along +x
  }
};
template <>
struct make<decltype(distance_objective())> {
  template <class Model>
  static auto from(const Model&) {
    return distance_objective();
  }
};

/// Controllers may depend on the actuator they drive (what a command means).
template <class Controller>
struct make_controller;
template <>
struct make_controller<pose_hold> {
  template <class Model, class Actuator>
  static pose_hold from(const Model& m, const Actuator& a) {
    if (a.input_kind() == command_kind::joint_target) return pose_hold(m);
    // Torque actuation: the controller servos itself with the same gains; mixed actuation: it
    // sends those gains with its targets.
    const pd_actuator g = standing_pd(m, dt);
    if constexpr (std::is_same_v<Actuator, musculotendon_actuator>)  // low tone in every MTU
      return pose_hold(m, {.output = command_kind::excitation,
                           .kp = g.kp,
                           .kd = g.kd,
                           .num_excitations = a.num_units(),
                           .excitation = 0.05});
    const command_kind out =
        a.input_kind() == command_kind::mixed ? command_kind::mixed : command_kind::joint_torque;
    return pose_hold(m, {.output = out, .kp = g.kp, .kd = g.kd});
  }
};

}  // namespace

TEMPLATE_LIST_TEST_CASE("every combination of policies composes and runs a standing rollout",
                        "[rollout][compose]", all_combinations) {
  using C = TestType;
  const auto m = C::character::build();
  const auto act = make<typename C::actuator_type>::from(m);
  auto ctrl = make_controller<typename C::controller_type>::from(m, act);
  const auto obj = make<typename C::objective_type>::from(m);
  const auto ground = make<typename C::terrain_type>::from(m);
  auto integ = make<typename C::integrator_type>::from(m);

  const Eigen::VectorXd params = standing_pose(m);
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 0.1;
  opt.initial_state = make_state(m);
  opt.initial_state.q.tail(m.num_joint_dofs()) = params;
  place_on_terrain(m, ground, opt.initial_state.q);
  auto scratch = make_rollout_scratch(m);

  const rollout_result r = rollout(m, act, ctrl, obj, ground, integ, params, opt, scratch);
  INFO(m.name << ": stopped by " << to_string(r.reason) << " at t = " << r.time);
  REQUIRE(r.reason == stop_reason::horizon);
  CHECK(r.steps == 240);
  CHECK(r.time == Approx(0.1));
  CHECK(r.controller_calls == 240);
  CHECK(std::isfinite(r.cost));
  CHECK(scratch.state.q.allFinite());
  CHECK(scratch.state.t == Approx(0.1));
  // Standing: the COM neither fell nor was launched in a tenth of a second.
  CHECK(std::abs(r.com_final.z() - r.com_initial.z()) < 0.02);
  // A standing character travels (almost) nowhere: distance cost ~ 0, no fall penalty.
  CHECK(std::abs(r.cost) < 0.02);
}
