// Recorded gait channels (viz/gait_cycles.hpp, gait_channel::kind::recorded) on series known in
// closed form, and the muscle recorder (analysis/muscle_recording.hpp) on a short rollout of the
// Wang 2012 muscle model: it lines up with the trajectory recorded at the same spacing and holds
// the actuator's state at the recorded steps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/analysis/muscle_recording.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

TEST_CASE("gait_cycles: a recorded channel interpolates its series at the frames' times",
          "[analysis][gait]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 3.0, 0.01, 1.0);
  gait_cycle_options o;
  o.cycle_starts = {0.5, 1.5, 2.5};
  o.samples = 11;
  // raw = t on an uneven grid (linear, so interpolation is exact), value = 2 raw + 1; and
  // sin(2 pi t) on a fine grid; and raw = t known only on [1, 2], held beyond.
  gait_channel linear{.type = gait_channel::kind::recorded,
                      .label = "line",
                      .scale = 2.0,
                      .offset = 1.0,
                      .unit = "",
                      .series_time = {0.0, 0.37, 1.2, 3.0},
                      .series_value = {0.0, 0.37, 1.2, 3.0}};
  gait_channel wave{.type = gait_channel::kind::recorded, .name = "wave", .scale = 1.0};
  for (int i = 0; i <= 3000; ++i) {
    wave.series_time.push_back(0.001 * i);
    wave.series_value.push_back(std::sin(2 * std::numbers::pi * 0.001 * i));
  }
  gait_channel held{.type = gait_channel::kind::recorded,
                    .label = "held",
                    .scale = 1.0,
                    .series_time = {1.0, 2.0},
                    .series_value = {1.0, 2.0}};
  o.channels = {linear, wave, held};
  const gait_cycle_data d = gait_cycles(m, traj, o);
  REQUIRE(d.num_cycles() == 2);
  CHECK(d.channels[1].label == "wave");  // empty label -> name
  for (std::size_t s = 0; s < d.percent.size(); ++s) {
    INFO("sample " << s);
    for (int k = 0; k < 2; ++k) {
      const double t = 0.5 + k + d.percent[s] / 100.0;
      CHECK(d.curves[0][k][s] == Approx(2.0 * t + 1.0).margin(1e-12));
      CHECK(d.curves[1][k][s] == Approx(std::sin(2 * std::numbers::pi * t)).margin(1e-4));
      CHECK(d.curves[2][k][s] == Approx(std::clamp(t, 1.0, 2.0)).margin(1e-12));
    }
    CHECK(d.stddev[1][s] < 1e-4);  // periodic
  }

  gait_channel bad = linear;
  bad.series_value.pop_back();
  o.channels = {bad};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o),
                    Contains("'line'") && Contains("4 series times but 3 series values"));
  bad = wave;
  bad.series_time[7] = bad.series_time[6];
  o.channels = {bad};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Contains("'wave'") && Contains("increase strictly"));
  bad.series_time = {};
  bad.series_value = {};
  o.channels = {bad};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Contains("'wave'") && Contains("empty"));
  bad.series_time = {NAN};
  bad.series_value = {0.0};
  o.channels = {bad};
  CHECK_THROWS_WITH(gait_cycles(m, traj, o), Contains("'wave'") && Contains("finite"));
}

namespace {

/// The actuator state at step `at` and at the end, captured independently of the recorder.
struct state_at_step {
  std::int64_t at = 0;
  musculotendon_state seen, last;
  double t_seen = -1, t_last = -1;
  template <class Observation>
  void observe(const Observation& ob) {
    if (ob.step == at) {
      seen = ob.actuator_state();
      t_seen = ob.t;
    }
  }
  template <class Observation>
  void finish(const Observation& ob, const rollout_result&) {
    last = ob.actuator_state();
    t_last = ob.t;
  }
};

}  // namespace

TEST_CASE("musculotendon_recorder: samples line up with the trajectory and hold the state",
          "[analysis][rollout]") {
  const floating_model m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units);
  const wang2012_reflex_controller ctrl(m);
  const std::vector<double> params = wang2012_reflex_controller::initial_parameters(m);
  rollout_options opt = wang2009_rollout_options(m);
  opt.duration = 0.25;
  constexpr int every = 40;
  trajectory tr;
  opt.record = &tr;
  opt.record_every = every;
  auto scratch = make_rollout_scratch(m);
  muscle_recording mr;
  const rollout_result r = rollout(m, act, ctrl, distance_objective(), flat_terrain(),
                                   semi_implicit_euler(), std::span<const double>(params), opt,
                                   scratch, musculotendon_recorder(act, &mr, every));
  REQUIRE(r.reason == stop_reason::horizon);
  REQUIRE(r.steps == 600);  // 2400 Hz
  const int M = act.num_units();
  REQUIRE(mr.names.size() == units.size());
  CHECK(mr.names[7] == units[7].name);
  const int n = mr.num_samples();
  REQUIRE(n == static_cast<int>(tr.frames.size()));
  CHECK(n == r.steps / every + 1);  // the steps 0, 40, ... and the end (a multiple here)
  for (int k = 0; k < n; ++k) CHECK(mr.time[k] == tr.frames[k].t);
  for (const auto* series :
       {&mr.excitation, &mr.activation, &mr.normalized_force, &mr.normalized_fiber_length}) {
    REQUIRE(series->size() == units.size());
    for (const auto& s : *series) {
      REQUIRE(s.size() == static_cast<std::size_t>(n));
      for (double x : s) CHECK(std::isfinite(x));
    }
  }
  for (int i = 0; i < M; ++i)
    for (int k = 0; k < n; ++k) {
      CHECK(mr.activation[i][k] >= 0.0);
      CHECK(mr.activation[i][k] <= 1.0);
    }

  // The first sample: the initial activation, every fiber in isometric equilibrium at the start.
  const Eigen::VectorXd qj = tr.frames[0].q.tail(m.num_joint_dofs());
  for (int i = 0; i < M; ++i) {
    const auto& p = units[i].parameters;
    const double l_mtu = units[i].length(qj);
    const double l_ce = musculotendon::isometric_fiber_length(p, act.initial_activation(), l_mtu);
    INFO(units[i].name);
    CHECK(mr.activation[i][0] == act.initial_activation());
    CHECK(mr.excitation[i][0] == act.initial_activation());
    CHECK(mr.normalized_fiber_length[i][0] == Approx(l_ce / p.optimal_fiber_length).margin(1e-12));
    CHECK(mr.normalized_force[i][0] ==
          Approx(musculotendon::forces_at(p, l_mtu, l_ce).tendon / p.max_isometric_force)
              .margin(1e-12));
  }

  // A middle sample and the last one against the state seen by another observer of the same
  // (deterministic) rollout.
  opt.record = nullptr;
  state_at_step probe{.at = 3 * every};
  const rollout_result r2 =
      rollout(m, act, ctrl, distance_objective(), flat_terrain(), semi_implicit_euler(),
              std::span<const double>(params), opt, scratch, probe);
  REQUIRE(r2.steps == r.steps);
  REQUIRE(probe.seen.activation.size() == M);
  CHECK(mr.time[3] == probe.t_seen);
  CHECK(mr.time[n - 1] == probe.t_last);
  for (int i = 0; i < M; ++i) {
    INFO(units[i].name);
    CHECK(mr.activation[i][3] == probe.seen.activation[i]);
    CHECK(mr.excitation[i][3] == probe.seen.excitation[i]);
    CHECK(mr.activation[i][n - 1] == probe.last.activation[i]);
    CHECK(mr.normalized_force[i][n - 1] ==
          probe.last.force[i] / units[i].parameters.max_isometric_force);
    CHECK(mr.normalized_fiber_length[i][n - 1] ==
          probe.last.fiber_length[i] / units[i].parameters.optimal_fiber_length);
  }
  // Something happened: the reflexes moved some activation away from its start.
  double moved = 0.0;
  for (int i = 0; i < M; ++i)
    moved = std::max(moved, std::abs(mr.activation[i][n - 1] - act.initial_activation()));
  CHECK(moved > 0.01);

  // Channels for the gait plot (Figure 5's GAS); an unknown MTU is named with the known ones.
  const std::vector<gait_channel> ch = muscle_gait_channels(mr, "lGAS");
  REQUIRE(ch.size() == 4);
  CHECK(ch[1].label == "lGAS activation");
  CHECK(ch[2].unit == "F_max");
  CHECK(ch[3].unit == "l_opt");
  const int gas = mr.index_of("lGAS");
  REQUIRE(gas >= 0);
  CHECK(ch[1].series_value == mr.activation[gas]);
  gait_cycle_options o;
  o.channels = ch;
  o.cycle_starts = {0.0, tr.frames.back().t};
  o.samples = n;
  const gait_cycle_data d = gait_cycles(m, tr, o);
  REQUIRE(d.num_cycles() == 1);
  for (int k = 0; k < n; ++k)  // the cycle's samples fall on the frames
    CHECK(d.curves[3][0][k] == Approx(mr.normalized_fiber_length[gas][k]).margin(1e-12));
  CHECK_THROWS_WITH(muscle_gait_channels(mr, "lGASTRO"),
                    Contains("'lGASTRO'") && Contains("lGAS") && Contains("rSOL"));
}

TEST_CASE("mean_activation: each MTU's activation averaged over the samples from t_from",
          "[analysis]") {
  muscle_recording r;
  r.names = {"lTA", "lVAS"};
  r.time = {0.0, 1.0, 2.0, 3.0};
  r.activation = {{0.9, 0.1, 0.2, 0.4}, {0.5, 0.5, 0.0, 1.0}};
  const std::vector<double> all = mean_activation(r, 0.0);
  REQUIRE(all.size() == 2);
  CHECK(all[0] == Approx(0.4));  // (0.9 + 0.1 + 0.2 + 0.4) / 4
  CHECK(all[1] == Approx(0.5));
  const std::vector<double> late = mean_activation(r, 1.5);  // the samples at 2 and 3 s
  CHECK(late[0] == Approx(0.3));
  CHECK(late[1] == Approx(0.5));
  CHECK(mean_activation(r, 3.0)[0] == Approx(0.4));  // t_from itself counts
  try {
    (void)mean_activation(r, 3.5);
    FAIL("a t_from after the last sample must throw");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("t_from = 3.5") && Catch::Contains("ends at 3 s"));
  }
  r.activation.pop_back();  // a series short
  CHECK_THROWS_AS(mean_activation(r, 0.0), std::invalid_argument);
}
