// The offline-optimization cost terms of Wu & Popovic 2010, Sec. 8.1 and 8.2
// (objectives/wu2010/) against hand-computed values on synthetic step views whose controller
// report is filled by hand, and the terms' refusal of a view without the report.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"

using namespace gaitsynth;
namespace w10 = gaitsynth::wu2010;

namespace {

/// A step view with a hand-written report in planned_walk's layout (8 action frames).
struct synthetic {
  const floating_model& m;
  planned_walk_report_layout layout = planned_walk_report_layout::for_action_frames(8);
  std::vector<double> report;
  Eigen::VectorXd q, v, tau, tau_passive;
  step_view<floating_root> view;

  explicit synthetic(const floating_model& model)
      : m(model),
        report(layout.size, 0.0),
        q(neutral_configuration(model)),
        v(Eigen::VectorXd::Zero(model.nv())),
        tau(Eigen::VectorXd::Zero(model.nv())),
        tau_passive(Eigen::VectorXd::Zero(model.nv())) {
    view.model_ptr = &m;
    view.dt = 1.0 / 64.0;  // one of eq. 6's timesteps (the paper's): each step weighs 1
    view.q_ptr = &q;
    view.v_ptr = &v;
    view.tau_ptr = &tau;
    view.tau_passive_ptr = &tau_passive;
    view.controller_report = report;
    report[layout.half_cycle] = -1.0;
  }
  /// A frame whose position error is e m: its squared "force" with unit weight is e^2.
  void set_frame_error(std::size_t frame, double e) {
    report[layout.tracking_begin + frame] = e * e;
  }
};

const floating_model& biped() {
  static const floating_model m = wu2010_biped();
  return m;
}

}  // namespace

TEST_CASE("wu2010 tracking error charges squared frame errors above eps_track",
          "[objectives][wu2010]") {
  synthetic s(biped());
  const w10::tracking_error obj(s.layout);
  auto acc = obj.make_accumulator(s.m);
  // 0.04 m: 1.6e-3 m^2 < eps_track = 2.5e-3: free.
  s.set_frame_error(2, 0.04);
  obj.accumulate(acc, s.view);
  CHECK(acc.sum == 0.0);
  // 0.1 m on an ankle (1e-2 - 2.5e-3 = 7.5e-3) and the LA torque entry at 5e-3 (2.5e-3).
  s.set_frame_error(2, 0.1);
  s.report[s.layout.tracking_begin + 1] = 5e-3;
  obj.accumulate(acc, s.view);
  CHECK(acc.last == Approx(7.5e-3 + 2.5e-3));
  // Per timestep: a second identical step doubles it (eq. 6 sums over timesteps).
  obj.accumulate(acc, s.view);
  CHECK(obj.finish(acc, {}) == Approx(2.0 * 1e-2));
  // Every frame at 0.1 m: 10 entries (upper body force and torque, 8 action frames).
  for (std::size_t i = 0; i < s.layout.tracking_count; ++i) s.set_frame_error(i, 0.1);
  auto acc2 = obj.make_accumulator(s.m);
  obj.accumulate(acc2, s.view);
  CHECK(acc2.sum == Approx(10 * 7.5e-3));
  // The tolerance is an option.
  const w10::tracking_error strict(s.layout, {.eps_track = 0.0});
  auto acc3 = strict.make_accumulator(s.m);
  strict.accumulate(acc3, s.view);
  CHECK(acc3.sum == Approx(10 * 1e-2));
  CHECK_THROWS_AS(w10::tracking_error(s.layout, {.eps_track = -1.0}), std::invalid_argument);
}

TEST_CASE("wu2010 COM deviation charges each finished half-cycle's horizontal miss",
          "[objectives][wu2010]") {
  synthetic s(biped());
  const w10::com_deviation obj(s.layout);
  auto acc = obj.make_accumulator(s.m);
  auto step = [&](double k, const vec3& com, double tx, double ty) {
    s.report[s.layout.half_cycle] = k;
    s.report[s.layout.com_target] = tx;
    s.report[s.layout.com_target + 1] = ty;
    s.view.com = com;
    obj.accumulate(acc, s.view);
  };
  step(-1, vec3(0, 0, 1), 0, 0);          // before the first command: nothing
  step(0, vec3(0, 0, 1), 0.65, 0.0);      // half-cycle 0 planned from c^_{-1} = 0
  step(0, vec3(0.3, 0.1, 1), 0.65, 0.0);  // mid half-cycle: not charged
  CHECK(acc.sum == 0.0);
  // Half-cycle 0 ends at (0.55, 0.05, 0.9): miss (-0.1, 0.05), 100 x 0.0125 = 1.25; z is free.
  step(1, vec3(0.55, 0.05, 0.9), 1.2, 0.05);
  CHECK(acc.sum == Approx(1.25));
  CHECK(acc.charged == 1);
  // Half-cycle 1 ends exactly on target: + 0.
  step(1, vec3(0.9, 0.0, 1), 1.2, 0.05);
  step(2, vec3(1.2, 0.05, 1.3), 1.85, 0.05);
  CHECK(acc.sum == Approx(1.25));
  CHECK(acc.charged == 2);
  // Half-cycle 2 never ends: finish charges nothing more.
  step(2, vec3(5, 5, 1), 1.85, 0.05);
  CHECK(obj.finish(acc, {}) == Approx(1.25));
  // W_c scales it.
  const w10::com_deviation unit(s.layout, {.weight = 1.0});
  auto a1 = unit.make_accumulator(s.m);
  s.report[s.layout.half_cycle] = 0;
  s.report[s.layout.com_target] = 1.0;
  s.report[s.layout.com_target + 1] = 0.0;
  unit.accumulate(a1, s.view);
  s.report[s.layout.half_cycle] = 1;
  s.view.com = vec3(1.0, 2.0, 0.0);
  unit.accumulate(a1, s.view);
  CHECK(a1.sum == Approx(4.0));
}

TEST_CASE("wu2010 energy weights squared torques by the inverse squared torque limits",
          "[objectives][wu2010]") {
  synthetic s(biped());
  const w10::energy obj;
  auto acc = obj.make_accumulator(s.m);
  const int nj = s.m.num_joint_dofs();
  REQUIRE(acc.weight.size() == nj);
  // tau_j = tau_max,j / 2 on every DOF with a limit: each contributes 8e-2 / 4 = 0.02.
  int limited = 0;
  for (int j = 0; j < nj; ++j) {
    const double t = s.m.dofs[j].torque_limit;
    if (std::isfinite(t) && t > 0) {
      s.tau[floating_root::nv + j] = 0.5 * t;
      ++limited;
    }
  }
  REQUIRE(limited > 0);
  s.tau.head(floating_root::nv).setConstant(1e6);  // root entries are not joint torques
  obj.accumulate(acc, s.view);
  CHECK(acc.last == Approx(0.02 * limited));
  obj.accumulate(acc, s.view);
  CHECK(obj.finish(acc, {}) == Approx(0.04 * limited));
  // One DOF alone, 10 N m against its limit: 8e-2 x 100 / tau_max^2.
  s.tau.setZero();
  s.tau[floating_root::nv + 0] = 10.0;
  const double t0 = s.m.dofs[0].torque_limit;
  auto a1 = obj.make_accumulator(s.m);
  obj.accumulate(a1, s.view);
  CHECK(a1.sum == Approx(8e-2 * 100.0 / (t0 * t0)));
  obj.reset_accumulator(s.m, a1);
  CHECK(a1.sum == 0.0);
  CHECK(a1.weight.size() == nj);
}

TEST_CASE("wu2010 helper penalty totals w_h L {h_max}+", "[objectives][wu2010]") {
  synthetic s(biped());
  const w10::helper_penalty obj(s.layout);
  auto acc = obj.make_accumulator(s.m);
  s.report[s.layout.h_max] = 400.0;
  for (int j = 0; j < 7; ++j) obj.accumulate(acc, s.view);
  CHECK(obj.finish(acc, {}) == Approx(5e-3 * 7 * 400.0));
  auto a2 = obj.make_accumulator(s.m);
  s.report[s.layout.h_max] = -150.0;  // {h_max}+ = 0
  for (int j = 0; j < 7; ++j) obj.accumulate(a2, s.view);
  CHECK(a2.sum == 0.0);
}

TEST_CASE("wu2010 objective sums eq. 6 and eq. 7's penalty; terms need the report",
          "[objectives][wu2010]") {
  synthetic s(biped());
  const auto obj = wu2010_objective(s.layout);
  static_assert(objective<wu2010_objective_type, floating_root>);
  static_assert(objective<w10::energy, floating_root>);
  auto acc = obj.make_accumulator(s.m);
  s.set_frame_error(3, 0.1);          // 7.5e-3
  s.report[s.layout.h_max] = 100.0;   // 0.5
  s.tau[floating_root::nv] = 10.0;    // energy of DOF 0
  s.report[s.layout.half_cycle] = 0;  // COM: target 0.65 ahead of 0
  s.report[s.layout.com_target] = 0.65;
  obj.accumulate(acc, s.view);
  s.report[s.layout.half_cycle] = 1;
  s.view.com = vec3(0.55, 0.0, 1.0);  // miss 0.1: 100 x 0.01 = 1
  obj.accumulate(acc, s.view);
  const double t0 = s.m.dofs[0].torque_limit;
  const double e_tau = 2 * 8e-2 * 100.0 / (t0 * t0);
  CHECK(obj.finish(acc, {}) == Approx(2 * 7.5e-3 + 1.0 + e_tau + 2 * 0.5));
  CHECK(obj.term_names().size() == 7);

  // A view without a report (a controller without the hook) is a wiring error, named.
  synthetic bare(biped());
  bare.view.controller_report = {};
  auto a2 = obj.make_accumulator(bare.m);
  CHECK_THROWS_WITH(obj.accumulate(a2, bare.view),
                    Catch::Contains("wu2010::tracking_error") && Catch::Contains("report"));
  // Energy alone reads no report.
  const w10::energy e;
  auto a3 = e.make_accumulator(bare.m);
  CHECK_NOTHROW(e.accumulate(a3, bare.view));
}

TEST_CASE("wu2010 per-timestep terms weigh a physics step by dt / timestep",
          "[objectives][wu2010]") {
  // Eq. 6's j runs over the paper's 1/64 s timesteps (objectives/wu2010/common.hpp); at 2400 Hz
  // a physics step is 64 / 2400 of one. The COM term is per half-cycle and does not change.
  synthetic s(biped());
  const double w = 64.0 / 2400.0;
  s.set_frame_error(3, 0.1);         // 7.5e-3 per timestep
  s.report[s.layout.h_max] = 100.0;  // 0.5 per timestep
  s.tau[floating_root::nv] = 10.0;   // DOF 0
  const double t0 = s.m.dofs[0].torque_limit;
  const double e_tau = 8e-2 * 100.0 / (t0 * t0);
  auto total = [&](double dt, int steps, const wu2010_objective_options& o) {
    const auto obj = wu2010_objective(s.layout, o);
    auto acc = obj.make_accumulator(s.m);
    s.view.dt = dt;
    for (int j = 0; j < steps; ++j) obj.accumulate(acc, s.view);
    return obj.finish(acc, {});
  };
  const double per_timestep = 7.5e-3 + e_tau + 0.5;
  // 2400 steps at 2400 Hz are 64 timesteps: 64 x, and the same from 4800 steps at 4800 Hz.
  CHECK(total(1.0 / 2400.0, 2400, {}) == Approx(64.0 * per_timestep));
  CHECK(total(1.0 / 4800.0, 4800, {}) == Approx(64.0 * per_timestep));
  // timestep = 0: each physics step counts once (the runs f1, f2), 37.5 times the above.
  wu2010_objective_options per_step;
  per_step.timestep = 0.0;
  CHECK(total(1.0 / 2400.0, 2400, per_step) == Approx(2400.0 * per_timestep));
  // Each term alone, one 2400 Hz step.
  s.view.dt = 1.0 / 2400.0;
  const w10::tracking_error track(s.layout);
  auto a1 = track.make_accumulator(s.m);
  track.accumulate(a1, s.view);
  CHECK(a1.sum == Approx(w * 7.5e-3));
  CHECK(a1.last == Approx(7.5e-3));  // the per-step value is unweighted
  const w10::helper_penalty helper(s.layout, {.w_h = 5e-3, .timestep = 0.01});
  auto a2 = helper.make_accumulator(s.m);
  helper.accumulate(a2, s.view);
  CHECK(a2.sum == Approx(5e-3 * 100.0 / 24.0));  // dt / 0.01 = 1 / 24
  const w10::energy energy;
  auto a3 = energy.make_accumulator(s.m);
  energy.accumulate(a3, s.view);
  CHECK(a3.sum == Approx(w * e_tau));
  // A negative or NaN timestep is refused, named.
  CHECK_THROWS_WITH(
      w10::energy({.scale = 8e-2, .timestep = -1.0}),
      Catch::Contains("wu2010::energy") && Catch::Contains("timestep") && Catch::Contains("-1"));
  wu2010_objective_options bad;
  bad.timestep = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(wu2010_objective(s.layout, bad), Catch::Contains("timestep"));
}
