// The composition test of the 3D biped controllers (controllers/fsm/): each controller with each
// integrator and terrain under the whole Wang 2009 objective, and each objective term of
// objectives/wang2009/ alone, run a short rollout of the Wang 2009 humanoid through
// mixed_pd_actuator, the actuator both controllers command.
#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
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
