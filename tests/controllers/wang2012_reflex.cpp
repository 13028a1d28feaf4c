// The reflex controller of Wang et al. 2012 Sec. 4 (controllers/reflex/): the leg state machine
// on scripted inputs, the parameter vector (58 named values, refused by name when bad), and the
// stance laws in a muscle-driven rollout against the sensed values they read.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/reflex/leg_phase.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;
using namespace gaitsynth::reflex;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

static_assert(controller<wang2012_reflex_controller, floating_root,
                         sensors_with<floating_root, musculotendon_state>>);
static_assert(command_kinds_compatible<wang2012_reflex_controller, musculotendon_actuator>);

TEST_CASE("leg phases: stance, swing initiation, swing, stance preparation",
          "[controllers][reflex]") {
  leg_state left, right;  // both start in stance at t = 0
  const double d_si = 0.2, d_sp = -0.15;
  left.update(true, right, 0.1, d_si, d_sp, 0.0);
  CHECK(left.phase == leg_phase::stance);
  left.update(true, right, 0.25, d_si, d_sp, 0.1);  // the COM passed d_SI
  CHECK(left.phase == leg_phase::swing_initiation);
  left.update(false, right, 0.3, d_si, d_sp, 0.2);  // lift-off
  CHECK(left.phase == leg_phase::swing);
  CHECK(left.phase_start == 0.2);
  left.update(false, right, -0.1, d_si, d_sp, 0.3);  // not yet far enough ahead
  CHECK(left.phase == leg_phase::swing);
  left.update(false, right, -0.2, d_si, d_sp, 0.4);
  CHECK(left.phase == leg_phase::stance_preparation);
  left.update(true, right, -0.2, d_si, d_sp, 0.5);  // touch-down
  CHECK(left.phase == leg_phase::stance);
  CHECK(left.phase_start == 0.5);
  // The right leg, in stance since 0, trails: the left landing later starts its swing initiation.
  right.update(true, left, 0.05, d_si, d_sp, 0.5);
  CHECK(right.phase == leg_phase::swing_initiation);
  // The left leg, which landed later, does not: it leads.
  left.update(true, right, 0.05, d_si, d_sp, 0.51);
  CHECK(left.phase == leg_phase::stance);
}

TEST_CASE("the reflex parameters: 30 stance, 26 swing, 2 balance gains, refused by name",
          "[controllers][reflex][bad_input]") {
  const auto p = reflex_initial_parameters();
  CHECK(p.size() == 58);
  CHECK(reflex_parameter_names[G_SOL] == "G_SOL");
  CHECK(reflex_parameter_names[d_SP] == "d_SP");
  CHECK(p[G_SOL] == 1.2);  // Geyer & Herr 2010
  CHECK(p[H_TA] == Approx(0.72));
  const auto m = wang2012_humanoid();
  wang2012_reflex_controller c(m);
  CHECK(c.num_parameters() == 58);
  CHECK_THAT(c.leg_length(), WithinAbs(0.4274 + 0.4457, 1e-3));
  std::vector<double> bad(p.begin(), p.end());
  bad[G_GAS] = std::nan("");
  CHECK_THROWS_WITH(c.bind(bad), Contains("G_GAS") && Contains("not finite"));
  bad.pop_back();
  CHECK_THROWS_WITH(c.bind(bad), Contains("expected 58") && Contains("57"));
}

namespace {

/// Records step 0's command and the actuator's sensed values it was computed from.
struct first_step {
  Eigen::VectorXd command, force, length;
  int phase = -1;
  template <class Ob>
  void observe(const Ob& ob) {
    if (ob.step != 0) return;
    command = ob.command();
    const auto& st = ob.actuator_state();
    force = st.force;
    length = st.fiber_length;
    phase = ob.controller_phase;
  }
};

}  // namespace

TEST_CASE("in double stance at the start, the stance laws read the sensed muscle state",
          "[controllers][reflex][rollout]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units, 0.05);
  wang2012_reflex_controller ctrl(m);
  const auto p = reflex_initial_parameters();
  rollout_options opt;
  opt.duration = 0.2;
  opt.detect_falls = false;
  auto scratch = make_rollout_scratch(m);
  first_step rec;
  const std::vector<double> params(p.begin(), p.end());
  const rollout_result r =
      rollout(m, act, ctrl, distance_objective(), flat_terrain(), semi_implicit_euler(),
              std::span<const double>(params), opt, scratch, rec);
  REQUIRE(r.steps == 480);
  CHECK(rec.phase == 0);  // both legs in stance (4 x stance + stance)
  // The history is filled "as if still" before t0, so every delayed value is the start's.
  for (int k = 0; k < 2; ++k) {
    const int b = 8 * k;
    auto F = [&](int i) { return rec.force[b + i] / units[b + i].parameters.max_isometric_force; };
    auto L = [&](int i) {
      return rec.length[b + i] / units[b + i].parameters.optimal_fiber_length;
    };
    INFO("leg " << k);
    CHECK_THAT(rec.command[b + 4], WithinAbs(p[p_SOL] + p[G_SOL] * F(4), 1e-12));  // SOL
    CHECK_THAT(rec.command[b + 7], WithinAbs(p[p_GAS] + p[G_GAS] * F(7), 1e-12));  // GAS
    CHECK_THAT(
        rec.command[b + 3],  // TA
        WithinAbs(p[p_TA] + std::max(p[G_TA] * (L(3) - p[H_TA]), 0.0) - p[G_SOL_TA] * F(4), 1e-12));
    CHECK_THAT(rec.command[b + 2], WithinAbs(p[p_VAS] + p[G_VAS] * F(2), 1e-12));  // VAS
    CHECK(rec.command[b + 6] == p[p_RF]);                                          // RF
  }
  // Upright (lean 0 < 6 deg): the leading leg's HFL pulls the trunk forward, K (6 deg - 0).
  CHECK_THAT(rec.command[1], WithinAbs(p[p_HFL] + p[K_HFL_lean] * p[lean_HFL], 1e-3));
  CHECK(rec.command[9] == p[p_HFL]);  // the right leg does not lead (a tie goes left)
  // Muscle DOFs are limp in the mixed block; the toes are springs.
  const int nj = m.num_joint_dofs();
  CHECK(rec.command[16 + nj + m.dof_index("lknee")] == 0.0);
  CHECK(rec.command[16 + nj + m.dof_index("ltoe")] == wang2012_passive::toe_stiffness);
}
