// One 64 Hz tick of Wu & Popovic 2010's lower level (controllers/end_effector/lower_level.hpp) on
// the Table 3 biped: frames, ideal PD forces (eqs. 1-3), J (Sec. 6.1) and its QR, eq. 5's QP and
// appendix B's canceling QP. Issue 12's goal: the controller below 20 us per tick.
//
//   bench_controllers                      every case
//   BM_LowerLevelTick/pinned:1             double stance: the 8 foot frames pinned (Sec. 6.3)
//   BM_LowerLevelTick/pinned:0             nothing touches: every frame's rows in the objective
//   BM_PairJacobianAndQR                   J and its QR alone
//   BM_PlanHalfCycle                       the planner (Sec. 4, appendix A), once per half-cycle,
//                                          on a seeded random height field
//   BM_PlanQuery                           the plan's link targets at one time, once per tick
//   BM_PlannedWalkRollout/offline:0        1.1 s (two half-cycles) of the cyclical controller
//                                          (Sec. 7) at 2400 Hz with the lower level every step,
//                                          physics and contact included: what a check rollout costs
//   BM_PlannedWalkRollout/offline:1        the same as the optimization runs it (Sec. 8): the
//                                          tracking report, eq. 6's objective, the helper force
// GCC 12 with -march=native warns falsely inside avx512fintrin.h (see benchmarks/qp/qp.cpp).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include <gaitsynth/actuators/torque.hpp>
#include <gaitsynth/contact/height_field_terrain.hpp>
#include <gaitsynth/controllers/end_effector/half_cycle_plan.hpp>
#include <gaitsynth/controllers/end_effector/lower_level.hpp>
#include <gaitsynth/controllers/end_effector/planned_walk.hpp>
#include <gaitsynth/detail/uniform01.hpp>
#include <gaitsynth/integrators/semi_implicit_euler.hpp>
#include <gaitsynth/models/wu2010.hpp>
#include <gaitsynth/objectives/distance.hpp>
#include <gaitsynth/objectives/wu2010/wu2010_objective.hpp>
#include <gaitsynth/rollout/rollout.hpp>

using namespace gaitsynth;

namespace {

/// A standing pose with bent knees, small velocities, targets a few cm off.
struct tick_fixture {
  floating_model m = wu2010_biped();
  end_effector_layout L = biped_end_effector_layout(m);
  lower_level_workspace<floating_root> ws = make_lower_level_workspace(m, L);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq()), v = Eigen::VectorXd::Zero(m.nv());
  std::vector<link_target> targets{3};
  std::vector<unsigned char> touching;
  tick_fixture(bool touch) : touching(m.contact_points.size(), touch ? 1 : 0) {
    q[2] = 1.08;
    q[3] = 1.0;
    for (const char* S : {"l", "r"}) {
      const std::string s = S;
      q[7 + m.dof_index(s + "hip_y")] = -0.2;
      q[7 + m.dof_index(s + "knee")] = 0.4;
      q[7 + m.dof_index(s + "ankle_y")] = -0.2;
    }
    for (int i = 0; i < m.nv(); ++i) v[i] = 0.05 * std::sin(i);
    auto fk = make_workspace(m);
    forward_kinematics(m, fk, q);
    for (int i = 0; i < 3; ++i)
      targets[i] = {fk.body_position[L.link_body[i]] + vec3(0.01, -0.01, 0.02 * (i == 0)),
                    fk.body_rotation[L.link_body[i]], vec3::Zero(), vec3::Zero()};
  }
};

void BM_LowerLevelTick(benchmark::State& state) {
  tick_fixture fx(state.range(0) != 0);
  const end_effector_gains g;
  const lower_level_options opt;
  for (auto _ : state) {
    const Eigen::VectorXd& tau =
        lower_level_torques(fx.m, fx.L, g, opt, fx.q, fx.v, fx.targets, fx.touching, fx.ws);
    benchmark::DoNotOptimize(tau.data());
  }
  if (fx.ws.qp.status != qp_status::optimal) state.SkipWithError("QP not optimal");
  int pinned = 0;
  for (const unsigned char p : fx.ws.pinned) pinned += p;
  state.counters["pinned"] = pinned;
  state.counters["rank"] = static_cast<double>(fx.ws.qp.rank);
  state.counters["active"] = fx.ws.qp.qp_ws.result.active_constraints;
}

void BM_PairJacobianAndQR(benchmark::State& state) {
  tick_fixture fx(true);
  const force_qp_options opt;
  forward_kinematics(fx.m, fx.ws.dyn, fx.q, fx.v);
  read_frame_states(fx.m, fx.ws.dyn, fx.L, fx.ws.current);
  for (auto _ : state) {
    pair_jacobian(fx.m, fx.ws.dyn, fx.q, fx.L, fx.ws.J);
    factor_pair_jacobian(fx.ws.J, opt, fx.ws.qp);
    benchmark::DoNotOptimize(fx.ws.qp.U.data());
  }
}

/// A 4 m x 4 m height field at 5 cm with seeded heights of 0-5 cm around the walk, the inputs
/// of a forward step, and a first plan (the second uses it for the upper body's deviation).
struct plan_fixture {
  height_field_terrain ground = [] {
    std::mt19937_64 rng(2010);
    Eigen::MatrixXd h(81, 81);
    for (Eigen::Index j = 0; j < h.cols(); ++j)
      for (Eigen::Index i = 0; i < h.rows(); ++i) h(i, j) = 0.05 * detail::uniform01(rng);
    return height_field_terrain(Eigen::Vector2d(-2.0, -2.0), 0.05, h);
  }();
  planner_setup setup;
  planner_parameters omega;
  planner_input in;
  task_goal goal{0.0, 0.0, 0.65};
  half_cycle_plan first;
  plan_fixture() {
    in.stance_foot.position = vec3(0.0, 0.1, 0.11);
    in.swing_foot.position = vec3(-0.3, -0.1, 0.11);
    in.upper_body.position = vec3(-0.15, 0.0, 1.5);
    first = plan_half_cycle(goal, omega, setup, in, ground);
  }
};

void BM_PlanHalfCycle(benchmark::State& state) {
  plan_fixture fx;
  for (auto _ : state) {
    const half_cycle_plan p =
        plan_half_cycle(fx.goal, fx.omega, fx.setup, fx.in, fx.ground, &fx.first);
    benchmark::DoNotOptimize(&p);
  }
}

void BM_PlanQuery(benchmark::State& state) {
  plan_fixture fx;
  std::array<link_target, 3> links;
  double t = 0.0;
  for (auto _ : state) {
    fx.first.link_targets(t, links);
    benchmark::DoNotOptimize(links.data());
    t = t < 0.5 ? t + 1.0 / 64.0 : 0.0;
  }
}

}  // namespace

void BM_PlannedWalkRollout(benchmark::State& state) {
  const bool offline = state.range(0) != 0;
  const floating_model m = wu2010_biped();
  planned_walk_options po;
  po.helper_force = offline;
  po.h_max = 200.0;  // N: the helper acts (eq. 7's bound inside Sec. 8.3's [-200, 1000])
  const planned_walk<> c(m, flat_terrain{}, po);
  rollout_options o;
  o.duration = 2 * 0.55;  // the default parameters stand that long (docs/reproductions/wu2010.md)
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> p = c.default_parameters();
  const auto run = [&](const auto& obj) {
    for (auto _ : state) {
      const rollout_result r = rollout(m, torque_actuator{}, c, obj, flat_terrain{},
                                       semi_implicit_euler{}, p, o, scratch);
      benchmark::DoNotOptimize(r.cost);
    }
  };
  if (offline)
    run(wu2010_objective(c.report_layout()));
  else
    run(distance_objective());
  // items: physics steps, so items_per_second is the simulation rate in steps per second.
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(std::llround(o.duration / o.dt)));
}

BENCHMARK(BM_PlanHalfCycle);
BENCHMARK(BM_PlanQuery);
BENCHMARK(BM_LowerLevelTick)->ArgName("pinned")->Arg(1)->Arg(0);
BENCHMARK(BM_PairJacobianAndQR);
BENCHMARK(BM_PlannedWalkRollout)
    ->ArgName("offline")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);
