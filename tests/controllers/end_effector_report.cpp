// Wu & Popovic 2010's offline-optimization hooks of planned_walk (controllers/end_effector/):
// the per-step report Sec. 8.1's cost reads (frame-tracking errors with Sec. 8.3's weights, the
// half-cycle and its COM target), the report's absence for controllers without the hook, and
// Sec. 8.2's helper force: h_max as the optional last parameter with Sec. 8.3's bounds, nothing
// applied for h_max <= 0 (the rollout is the helper-off controller's, bit for bit), for h_max > 0
// clip(b - A f) applied as the upper body's external wrench, a changed motion.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/standing_balance.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wu2010_search_space.hpp"

using namespace gaitsynth;

static_assert(controller_with_report<planned_walk<>>);
static_assert(controller_with_external_wrenches<planned_walk<>, floating_root>);
static_assert(!controller_with_report<standing_balance<>>);
static_assert(!controller_with_external_wrenches<standing_balance<>, floating_root>);

namespace {

const floating_model& biped() {
  static const floating_model m = wu2010_biped();
  return m;
}

rollout_options walk_options(const floating_model& m, double duration) {
  rollout_options o;
  o.duration = duration;
  o.detect_falls = false;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  return o;
}

/// Per step: the report, checked against the controller's frame states, and the helper force.
struct report_log {
  std::size_t steps = 0, report_size = 0;
  double max_track_mismatch = 0.0;  ///< |report - hand-computed squared position error|
  double max_helper = 0.0;          ///< largest |entry| of the state's helper force
  double max_reported_helper = 0.0;
  double max_helper_mismatch = 0.0;  ///< |state's helper - clip(b - A f)|
  double max_wrench_mismatch = 0.0;  ///< |upper body's external wrench - the helper's|
  double max_com_target_mismatch = 0.0;
  double half_cycle = -1.0;
  helper_scope scope = helper_scope::all;  ///< the rows the helper acts on (expected)
  std::vector<double> q_final;
  template <class Ob>
  void observe(const Ob& ob) {
    ++steps;
    report_size = ob.controller_report.size();
    if constexpr (controller_with_report<std::remove_cvref_t<decltype(*ob.controller_ptr)>>) {
      const auto& c = *ob.controller_ptr;
      const auto& st = *ob.controller_state_ptr;
      const auto& L = c.report_layout();
      const auto r = ob.controller_report;
      // Sec. 8.3's weights (kp = kr = ko = 1, b = 0): the errors themselves.
      const frame_states &cur = st.lower.current, &des = st.lower.desired;
      auto mismatch = [&](std::size_t i, double expected) {
        max_track_mismatch =
            std::max(max_track_mismatch, std::abs(r[L.tracking_begin + i] - expected));
      };
      mismatch(0, (des.reaction_position - cur.reaction_position).squaredNorm());
      vec3 tau = vec3::Zero();
      for (int j = 0; j < 3; ++j)
        tau += cur.reaction_rotation.col(j).cross(des.reaction_rotation.col(j) -
                                                  cur.reaction_rotation.col(j));
      mismatch(1, tau.squaredNorm());
      for (int j = 0; j < c.layout().num_action(); ++j) {
        const auto& a = c.layout().action[static_cast<std::size_t>(j)];
        const vec3 e = a.type == frame_type::linear_relative
                           ? vec3(des.relative[j] - cur.relative[j])
                           : vec3(des.position[j] - cur.position[j]);
        mismatch(2 + static_cast<std::size_t>(j), e.squaredNorm());
      }
      max_helper = std::max(max_helper, st.helper.cwiseAbs().maxCoeff());
      if (c.h_max() > 0.0) {
        // Sec. 8.2: clip(b - A f) with the pinned frames' rows zero, from the tick's QP.
        Eigen::VectorXd h = st.lower.qp.b - st.lower.qp.A * st.lower.qp.f;
        for (int j = 0; j < c.layout().num_action(); ++j)
          if (st.lower.pinned[static_cast<std::size_t>(j)]) h.segment<3>(action_row(j)).setZero();
        h = h.cwiseMax(-c.h_max()).cwiseMin(c.h_max());
        const Eigen::Index n = h.size();
        if (scope == helper_scope::feet) {
          h.head<3>().setZero();
          h.tail<3>().setZero();
        }
        if (scope != helper_scope::all && scope != helper_scope::feet) {
          h.segment(3, n - 6).setZero();
          if (scope == helper_scope::upper_body_force) h.tail<3>().setZero();
          if (scope == helper_scope::upper_body_torque) h.head<3>().setZero();
        }
        max_helper_mismatch = std::max(max_helper_mismatch, (h - st.helper).cwiseAbs().maxCoeff());
        // The upper body touches nothing: its external wrench is the helper's alone, the force
        // at the LA frame plus the torque rows.
        const int ub = c.layout().link_body[0];
        const vec3 p_la = ob.body_position[ub] + ob.body_rotation[ub] * c.layout().reaction_point;
        const vec3 f = h.head<3>();
        const vec3 torque = (p_la - ob.body_position[ub]).cross(f) + vec3(h.tail<3>());
        vec6 expected;
        expected << torque, f;
        max_wrench_mismatch = std::max(max_wrench_mismatch,
                                       (ob.external_wrench[ub] - expected).cwiseAbs().maxCoeff());
      }
      max_reported_helper = std::max(max_reported_helper, r[L.helper_max]);
      if (r[L.half_cycle] != half_cycle) {  // a new plan: c_k = c^_{k-1} + 0.65 x
        max_com_target_mismatch =
            std::max({max_com_target_mismatch, std::abs(r[L.com_target] - (ob.com.x() + 0.65)),
                      std::abs(r[L.com_target + 1] - ob.com.y())});
        half_cycle = r[L.half_cycle];
      }
    }
    q_final.assign(ob.q().data(), ob.q().data() + ob.q().size());
  }
};

template <class C, class O>
rollout_result run(const C& c, const std::vector<double>& p, const O& obj, report_log& log,
                   double duration = 0.6) {
  const floating_model& m = biped();
  auto scratch = make_rollout_scratch(m);
  return rollout(m, torque_actuator{}, c, obj, flat_terrain{}, semi_implicit_euler(), p,
                 walk_options(m, duration), scratch, log);
}

}  // namespace

TEST_CASE("planned_walk reports Sec. 8.1's tracking errors, half-cycle and COM target",
          "[end_effector][wu2010_cost]") {
  const floating_model& m = biped();
  const planned_walk<> c(m);
  const auto& L = c.report_layout();
  CHECK(L.tracking_count == 10);  // upper body force and torque, 8 action frames
  CHECK(c.report_names().size() == L.size);
  CHECK(c.report_names()[0] == "track.ub_force");
  CHECK(c.report_names()[L.h_max] == "h_max");
  report_log log;
  const auto r = run(c, c.default_parameters(), distance_objective(), log);
  CHECK_FALSE(r.diverged());
  CHECK(log.report_size == L.size);
  CHECK(log.max_track_mismatch < 1e-12);
  CHECK(log.max_com_target_mismatch < 1e-12);
  CHECK(log.half_cycle == 1.0);  // 0.6 s: half-cycles 0 and 1
  CHECK(log.max_helper == 0.0);
  CHECK(log.max_reported_helper == 0.0);
}

TEST_CASE("a controller without the report hook leaves the view's report empty",
          "[end_effector][wu2010_cost]") {
  const floating_model& m = biped();
  standing_balance<> c(m);
  report_log log;
  const auto p = c.gains().to_array();
  auto scratch = make_rollout_scratch(m);
  const auto r = rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                         semi_implicit_euler(), p, walk_options(m, 0.01), scratch, log);
  CHECK(r.steps == 24);
  CHECK(log.steps == 24);
  CHECK(log.report_size == 0);
}

TEST_CASE("planned_walk's helper force: h_max parameter, bounds, off for h_max <= 0, clipped",
          "[end_effector][wu2010_cost]") {
  const floating_model& m = biped();
  const planned_walk<> off(m);
  planned_walk_options o;
  o.helper_force = true;
  const planned_walk<> on(m, flat_terrain{}, o);
  REQUIRE(on.num_parameters() == off.num_parameters() + 1);
  CHECK(on.num_parameters() == 50);  // Sec. 8.3's 46 = 25 + 2 x 10 + h_max; ours adds 2 x 2
  CHECK(on.parameter_names().back() == "h_max");
  CHECK(on.helper_offset() == 49);
  const auto space = wu2010_search_space(on, on.default_parameters());
  REQUIRE(space.size() == 50);
  CHECK(space[49].name == "h_max");
  CHECK(space[49].lower == -200.0);
  CHECK(space[49].upper == 1000.0);
  CHECK(wu2010_search_space(off, off.default_parameters()).size() == 49);

  auto with_h = [&](double h) {
    std::vector<double> p = on.default_parameters();
    p.back() = h;
    return p;
  };
  const auto obj = wu2010_objective(on.report_layout());
  report_log log_off, log_zero, log_neg;
  const auto r_off = run(off, off.default_parameters(), obj, log_off);
  const auto r_zero = run(on, with_h(0.0), obj, log_zero);
  const auto r_neg = run(on, with_h(-150.0), obj, log_neg);
  // h_max <= 0: no helper force, the same rollout bit for bit, no penalty.
  CHECK(log_zero.q_final == log_off.q_final);
  CHECK(log_neg.q_final == log_off.q_final);
  CHECK(r_zero.cost == r_off.cost);
  CHECK(r_neg.cost == r_off.cost);
  CHECK(log_neg.max_helper == 0.0);

  // h_max > 0: the motion changes, the force stays within the clip, the penalty is w_h L h_max.
  const double h = 50.0;
  rollout_policy_states<torque_actuator, planned_walk<>, wu2010_objective_type> states;
  report_log log_on;
  const floating_model& mm = biped();
  auto scratch = make_rollout_scratch(mm);
  planned_walk<> ctrl = on;
  semi_implicit_euler integ;
  const std::vector<double> p_on = with_h(h);
  const auto r_on =
      rollout(mm, torque_actuator{}, ctrl, obj, flat_terrain{}, integ,
              std::span<const double>(p_on), walk_options(mm, 0.6), scratch, states, log_on);
  CHECK_FALSE(r_on.diverged());
  CHECK(log_on.q_final != log_off.q_final);
  CHECK(log_on.max_helper > 0.0);
  CHECK(log_on.max_helper <= h);
  CHECK(log_on.max_reported_helper == log_on.max_helper);
  CHECK(log_on.max_helper_mismatch < 1e-9);
  CHECK(log_on.max_wrench_mismatch < 1e-9);
  const auto& acc = *states.objective;
  // L counts eq. 6's 1/64 s timesteps (objectives/wu2010/common.hpp): steps x (1/2400) x 64.
  CHECK(std::get<wu2010_term::helper>(acc).sum ==
        Approx(5e-3 * static_cast<double>(r_on.steps) * (64.0 / 2400.0) * h));
  CHECK(std::get<wu2010_term::helper>(acc).sum > 0.0);
}

TEST_CASE("planned_walk's helper force on a subset of eq. 4's rows (helper_rows, diagnosis)",
          "[end_effector][wu2010_cost]") {
  const floating_model& m = biped();
  const auto obj = wu2010_objective(planned_walk<>(m).report_layout());
  std::vector<double> q_final;
  for (const helper_scope scope :
       {helper_scope::all, helper_scope::upper_body, helper_scope::upper_body_force,
        helper_scope::upper_body_torque, helper_scope::feet}) {
    planned_walk_options o;
    o.helper_force = true;
    o.helper_rows = scope;
    const planned_walk<> c(m, flat_terrain{}, o);
    std::vector<double> p = c.default_parameters();
    p.back() = 50.0;
    report_log log;
    log.scope = scope;
    const auto r = run(c, p, obj, log);
    INFO("scope " << static_cast<int>(scope));
    CHECK_FALSE(r.diverged());
    CHECK(log.max_helper > 0.0);
    CHECK(log.max_helper <= 50.0);
    // The state's helper is clip(b - A f) on the scope's rows and zero elsewhere, and the upper
    // body's external wrench is what the scope leaves on its rows (zero for the feet).
    CHECK(log.max_helper_mismatch < 1e-9);
    CHECK(log.max_wrench_mismatch < 1e-9);
    CHECK(log.q_final != q_final);  // each scope moves the walker differently
    q_final = log.q_final;
  }
}
