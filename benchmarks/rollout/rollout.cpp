// Rollout benchmarks (issue 2, "Performance"): one full physics step with contacts, and 10 s
// rollouts at 2400 Hz of the 3D humanoid (Wang et al. 2009) holding a standing pose on flat ground
// with all its foot and toe contact points, and of the 7-link planar human (Sharon & van de Panne
// 2005). Counters: real_time_factor (simulated seconds per wall second) and us_per_step.
// When MuJoCo is found (GAITSYNTH_HAVE_MUJOCO), this binary also registers the MuJoCo peer cases
// (BM_MuJoCo_*, benchmarks/mujoco_peer/mujoco_peer.hpp: mj_step on the exported MJCF of the same
// characters at the same timestep), so the gaitsynth / mj_step ratio comes from one run.
#include <benchmark/benchmark.h>

#include "mujoco_peer/mujoco_peer.hpp"

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#if __has_include(<nlohmann/json.hpp>)
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#endif
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

namespace {

using namespace gaitsynth;
constexpr double dt = 1.0 / 2400.0;

template <class Model>
rollout_options standing(const Model& m, double duration) {
  rollout_options o;
  o.dt = dt;
  o.duration = duration;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain(), o.initial_state.q);
  return o;
}

/// real_time_factor (simulated seconds per wall second) and us_per_step of rollouts of `seconds`
/// each that took `steps` physics steps in all.
void set_rollout_counters(benchmark::State& state, double seconds, std::int64_t steps) {
  state.counters["real_time_factor"] = benchmark::Counter(
      seconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["us_per_step"] = benchmark::Counter(
      1e-6 * static_cast<double>(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// A 10 s standing rollout per iteration.
template <class Model, class Integrator>
void bench_rollout(benchmark::State& state, const Model& m) {
  const pd_actuator pd = standing_pd(m, dt);
  pose_hold ctrl(m);
  const auto obj = distance_objective();
  const flat_terrain ground;
  Integrator integ;
  const auto opt = standing(m, 10.0);
  const Eigen::VectorXd params = Eigen::VectorXd::Zero(m.num_joint_dofs());
  auto scr = make_rollout_scratch(m);
  std::int64_t steps = 0;
  for (auto _ : state) {
    const rollout_result r = rollout(m, pd, ctrl, obj, ground, integ, params, opt, scr);
    if (r.reason != stop_reason::horizon) state.SkipWithError("the character did not stand 10 s");
    steps += r.steps;
    benchmark::DoNotOptimize(r.cost);
  }
  set_rollout_counters(state, 10.0, steps);
  state.counters["contact_points"] = static_cast<double>(m.contact_points.size());
}

void BM_Rollout_Humanoid3D_Stand10s(benchmark::State& state) {
  bench_rollout<floating_model, semi_implicit_euler>(state, wang2009_humanoid());
}
BENCHMARK(BM_Rollout_Humanoid3D_Stand10s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_Rollout_Human7_Stand10s(benchmark::State& state) {
  bench_rollout<planar_model, semi_implicit_euler>(state, sharon2005_human7());
}
BENCHMARK(BM_Rollout_Human7_Stand10s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_Rollout_Humanoid3D_Stand10s_RK4(benchmark::State& state) {
  bench_rollout<floating_model, odeint_rk4>(state, wang2009_humanoid());
}
BENCHMARK(BM_Rollout_Humanoid3D_Stand10s_RK4)->Unit(benchmark::kMillisecond)->MinTime(2.0);

/// A 10 s walk per iteration: SIMBICON (controllers/fsm/simbicon.hpp) on the 3D humanoid through
/// mixed_pd_actuator, scored by the whole objective of Wang et al. 2009 (eq. 16), mu = 10: what
/// one evaluation of a Wang 2009 optimization costs (the optimized controller adds a few world
/// servos of the same kind).
void BM_Rollout_Humanoid3D_SimbiconWalk10s(benchmark::State& state) {
  const floating_model m = wang2009_humanoid();
  const auto [kp, kd] = simbicon_walk_gains(m);
  simbicon_controller ctrl(m, kp, kd);
  const std::vector<double> p = simbicon_walk_parameters();
  const auto obj = wang2009_objective(m);
  rollout_options opt;
  opt.contact.mu = 10.0;
  opt.initial_state = simbicon_start_state(m);
  auto scr = make_rollout_scratch(m);
  rollout_policy_states<mixed_pd_actuator, simbicon_controller, wang2009_objective_type> states;
  semi_implicit_euler integ;
  std::int64_t steps = 0;
  for (auto _ : state) {
    const rollout_result r = rollout(m, mixed_pd_actuator{}, ctrl, obj, flat_terrain{}, integ,
                                     std::span<const double>(p), opt, scr, states);
    if (r.reason != stop_reason::horizon) state.SkipWithError("SIMBICON did not walk 10 s");
    steps += r.steps;
    benchmark::DoNotOptimize(r.cost);
  }
  set_rollout_counters(state, 10.0, steps);
}
BENCHMARK(BM_Rollout_Humanoid3D_SimbiconWalk10s)->Unit(benchmark::kMillisecond)->MinTime(2.0);

#if __has_include(<nlohmann/json.hpp>)
/// A 10 s walk per iteration of the optimized Wang 2009 walker (data/wang2009/walkers/, the
/// stocky walker from Table 2) with the whole objective of eq. 16 and the settings of its
/// optimization (synthesis/wang2009_simulation.hpp: mu = 10, implicit joint dampers): one
/// evaluation of a Wang 2009 optimization near its optimum.
template <class Terrain>
void bench_wang2009_walk(benchmark::State& state, bool aba_by_joint = false) {
  const std::string path =
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/walkers/stocky_table2.controller.json";
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  wang2009_controller ctrl(m);
  const std::vector<double> p = load_wang2009_controller(path, ctrl).parameters;
  ctrl.bind(p);
  const auto obj = wang2009_objective(m);
  const rollout_options opt = wang2009_rollout_options(m);
  auto scr = make_rollout_scratch(m);
  // ABA by joints (dynamics/aba_by_joint.hpp, opt-in): the peer of the default node passes.
  if (aba_by_joint) enable_aba_by_joint(scr.ws);
  rollout_policy_states<mixed_pd_actuator, wang2009_controller, wang2009_objective_type> states;
  semi_implicit_euler integ;
  std::int64_t steps = 0;
  for (auto _ : state) {
    const rollout_result r = rollout(m, mixed_pd_actuator{}, ctrl, obj, Terrain{}, integ,
                                     std::span<const double>(p), opt, scr, states);
    if (r.reason != stop_reason::horizon) state.SkipWithError("the walker did not walk 10 s");
    steps += r.steps;
    benchmark::DoNotOptimize(r.cost);
  }
  set_rollout_counters(state, 10.0, steps);
}

/// Flat ground that gives no height bound: the contact broad phase (contact/penalty_contact.hpp)
/// then computes all 63 points every step, the peer that shows what the broad phase saves.
struct flat_without_height_bound {
  double height(double, double) const { return 0.0; }
  vec3 normal(double, double) const { return vec3::UnitZ(); }
};

void BM_Rollout_Humanoid3D_Walk10s(benchmark::State& state) {
  bench_wang2009_walk<flat_terrain>(state);
}
BENCHMARK(BM_Rollout_Humanoid3D_Walk10s)->Unit(benchmark::kMillisecond)->MinTime(2.0);
void BM_Rollout_Humanoid3D_Walk10s_AbaByJoint(benchmark::State& state) {
  bench_wang2009_walk<flat_terrain>(state, true);
}
BENCHMARK(BM_Rollout_Humanoid3D_Walk10s_AbaByJoint)->Unit(benchmark::kMillisecond)->MinTime(2.0);
void BM_Rollout_Humanoid3D_Walk10s_NoBroadPhase(benchmark::State& state) {
  bench_wang2009_walk<flat_without_height_bound>(state);
}
BENCHMARK(BM_Rollout_Humanoid3D_Walk10s_NoBroadPhase)->Unit(benchmark::kMillisecond)->MinTime(2.0);
#endif

/// One full step of the rollout's order, written out with the public algorithms: kinematics, COM,
/// penalty contact at all points (16 sole points touching while standing), PD torques, passive
/// limits, ABA, semi-implicit Euler. The character stands, so the state stays representative.
template <class Model>
void bench_step(benchmark::State& state, const Model& m) {
  const pd_actuator pd = standing_pd(m, dt);
  auto pd_state = pd.make_state(m);
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  const contact_parameters cp;
  const flat_terrain ground;
  semi_implicit_euler integ(m);
  sim_state s = standing(m, 0.0).initial_state;
  const Eigen::VectorXd target = Eigen::VectorXd::Zero(m.num_joint_dofs());
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv()), tau_passive = tau, tau_total = tau;
  const int nj = m.num_joint_dofs();
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double, Eigen::VectorXd& a) {
    a = aba(m, ws, q, v, tau_total);
  };
  auto step = [&] {
    forward_kinematics(m, ws, s.q, s.v);
    benchmark::DoNotOptimize(center_of_mass(m, ws));
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, ground, cp, cs, dt);
    pd.torques(m, s, target, pd_state, tau.tail(nj));
    tau_passive.setZero();
    joint_limit_torques(m, s.q, s.v, tau_passive);
    tau_total = tau + tau_passive;
    integ.step(m, s, dt, sys);
  };
  for (int i = 0; i < 2400; ++i) step();  // settle onto the contact springs (1 s)
  for (auto _ : state) {
    step();
    benchmark::ClobberMemory();
  }
  state.counters["points_touching"] = cs.total_points_touching;
  state.counters["real_time_factor"] =
      benchmark::Counter(dt * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_Step_Humanoid3D_FullStepWithContacts(benchmark::State& state) {
  bench_step(state, wang2009_humanoid());
}
BENCHMARK(BM_Step_Humanoid3D_FullStepWithContacts)->Unit(benchmark::kMicrosecond);

void BM_Step_Human7_FullStepWithContacts(benchmark::State& state) {
  bench_step(state, sharon2005_human7());
}
BENCHMARK(BM_Step_Human7_FullStepWithContacts)->Unit(benchmark::kMicrosecond);

}  // namespace
