// Muscle-driven rollouts (Wang et al. 2012, issue 13 "Speed"): 10 s of the Wang 2012 humanoid
// holding a pose with its 16 Hill-type MTUs at a constant excitation plus PD servos on every DOF
// (musculotendon_actuator, scored by the metabolic effort w_e J_effort), next to the same body,
// controller and servos without muscles (mixed_pd_actuator, distance objective): the difference
// is what the muscles cost. BM_Rollout_Wang2012_Walk10s_Muscles walks the saved muscle walker
// (data/wang2012/walkers/nwalk.controller.json: the reflex controller, 16 MTUs, the whole Sec. 5
// objective): one evaluation of a Wang 2012 optimization near its optimum, to set beside
// BM_Rollout_Humanoid3D_Walk10s (rollout.cpp, the torque-driven Wang 2009 walker) in one run.
// BM_Musculotendon_Step16 times the actuator alone per physics step (torques, then activation
// and fiber dynamics for 16 MTUs). Counters as in rollout.cpp.
#include <benchmark/benchmark.h>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/wang2012/effort_terms.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#if __has_include(<nlohmann/json.hpp>)
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#endif

namespace {

using namespace gaitsynth;
constexpr double dt = 1.0 / 2400.0;

template <class Actuator, class Objective>
void bench_stand(benchmark::State& state, const floating_model& m, const Actuator& act,
                 const pose_hold& ctrl_in, const Objective& obj) {
  pose_hold ctrl = ctrl_in;
  const flat_terrain ground;
  semi_implicit_euler integ;
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 10.0;
  // The Wang 2012 body balances on its heel and ball cylinders only in a narrow band of ankle
  // angles under stiff PD (docs/performance.md); 0.02 rad of dorsiflexion holds it with PD alone.
  // Falls are not detected, so every iteration simulates 10 s whatever happens; the counter
  // com_height_end shows whether it still stood.
  opt.detect_falls = false;
  Eigen::VectorXd params = Eigen::VectorXd::Zero(m.num_joint_dofs());
  for (const char* d : {"lankle_y", "rankle_y"}) params[m.dof_index(d)] = -0.02;
  opt.initial_state = make_state(m);
  opt.initial_state.q.tail(m.num_joint_dofs()) = params;
  place_on_terrain(m, ground, opt.initial_state.q);
  auto scr = make_rollout_scratch(m);
  std::int64_t steps = 0;
  double com_end = 0.0;
  for (auto _ : state) {
    const rollout_result r = rollout(m, act, ctrl, obj, ground, integ, params, opt, scr);
    steps += r.steps;
    com_end = r.com_final.z();
    benchmark::DoNotOptimize(r.cost);
  }
  state.counters["com_height_end"] = com_end;
  state.counters["real_time_factor"] = benchmark::Counter(
      10.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["us_per_step"] = benchmark::Counter(
      1e-6 * static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

pose_hold hold(const floating_model& m, command_kind out, int num_units) {
  const pd_actuator g = standing_pd(m, dt);
  return pose_hold(
      m, {.output = out, .kp = g.kp, .kd = g.kd, .num_excitations = num_units, .excitation = 0.0});
}

void BM_Rollout_Wang2012_Stand10s_MixedPD(benchmark::State& state) {
  const auto m = wang2012_humanoid();
  bench_stand(state, m, mixed_pd_actuator{}, hold(m, command_kind::mixed, 0), distance_objective());
}
BENCHMARK(BM_Rollout_Wang2012_Stand10s_MixedPD)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_Rollout_Wang2012_Stand10s_Muscles(benchmark::State& state) {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units);
  bench_stand(state, m, act, hold(m, command_kind::excitation, act.num_units()),
              wang2012::effort(m.total_mass(), units, wang2012::metabolic_energy(units)));
}
BENCHMARK(BM_Rollout_Wang2012_Stand10s_Muscles)->Unit(benchmark::kMillisecond)->MinTime(2.0);

#if __has_include(<nlohmann/json.hpp>)
void BM_Rollout_Wang2012_Walk10s_Muscles(benchmark::State& state) {
  const std::string path =
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2012/walkers/nwalk.controller.json";
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units);
  const wang2012_saved_controller saved = load_wang2012_controller(path);
  const wang2012_reflex_controller ctrl(m);
  const auto obj = wang2012::objective(m, units, wang2012::metabolic_energy(units),
                                       {.target_speed = saved.target_speed});
  const rollout_options opt = wang2009_rollout_options(m);  // as examples/wang2012_walk.cpp
  auto scr = make_rollout_scratch(m);
  semi_implicit_euler integ;
  std::int64_t steps = 0;
  for (auto _ : state) {
    const rollout_result r = rollout(m, act, ctrl, obj, flat_terrain{}, integ,
                                     std::span<const double>(saved.parameters), opt, scr);
    if (r.reason != stop_reason::horizon) state.SkipWithError("the walker did not walk 10 s");
    steps += r.steps;
    benchmark::DoNotOptimize(r.cost);
  }
  state.counters["real_time_factor"] = benchmark::Counter(
      10.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["us_per_step"] = benchmark::Counter(
      1e-6 * static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rollout_Wang2012_Walk10s_Muscles)->Unit(benchmark::kMillisecond)->MinTime(2.0);
#endif

/// The actuator's share of a physics step: torques, then advance (activation, backward-Euler
/// fiber step) of 16 MTUs, at a pose that changes every call so no result is reused.
void BM_Musculotendon_Step16(benchmark::State& state) {
  const auto m = wang2012_humanoid();
  const musculotendon_actuator act(musculotendon::geyer_herr_leg_muscles(m));
  auto st = act.make_state(m);
  sim_state s = make_state(m);
  act.start(m, s, st);
  Eigen::VectorXd cmd = Eigen::VectorXd::Zero(act.command_size(m));
  cmd.head(act.num_units()).setConstant(0.3);
  Eigen::VectorXd tau(m.num_joint_dofs());
  const int knee = floating_root::nq + m.dof_index("lknee");
  std::int64_t k = 0;
  for (auto _ : state) {
    s.q[knee] = 0.3 + 0.2 * std::sin(1e-3 * static_cast<double>(k++));
    act.torques(m, s, cmd, st, tau);
    act.advance(m, s, cmd, st, dt);
    benchmark::DoNotOptimize(tau.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_Musculotendon_Step16)->Unit(benchmark::kMicrosecond);

}  // namespace
