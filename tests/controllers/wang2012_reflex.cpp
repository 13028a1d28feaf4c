// The reflex controller of Wang et al. 2012 Sec. 4 (controllers/reflex/): the leg state machine
// on scripted inputs, the parameter vector (122 named values, refused by name when bad), the
// stance laws in a muscle-driven rollout against the sensed values they read, the start state of
// the parameters, and Sec. 4.4's control as an exact mirror image when the other leg stands.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
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
  CHECK(c.num_parameters() == 122);
  CHECK_THAT(c.leg_length(), WithinAbs(0.4274 + 0.4457, 1e-3));
  const auto names = wang2012_reflex_controller::parameter_names();
  REQUIRE(names.size() == 122);
  CHECK(std::set<std::string>(names.begin(), names.end()).size() == 122);
  CHECK(names[58 + cd_coronal] == "cd_coronal");
  CHECK(names[58 + 31 + 7 + 1] == "start.q.lknee");
  auto bad = wang2012_reflex_controller::initial_parameters(m);
  bad[G_GAS] = std::nan("");
  CHECK_THROWS_WITH(c.bind(bad), Contains("G_GAS") && Contains("not finite"));
  bad[G_GAS] = 1.0;
  bad[58 + elbow_target] = INFINITY;
  CHECK_THROWS_WITH(c.bind(bad), Contains("elbow_target") && Contains("inf"));
  bad[58 + elbow_target] = 0.0;
  bad[58 + 31 + 3] = std::nan("");
  CHECK_THROWS_WITH(c.bind(bad), Contains("start.root_vx") && Contains("not finite"));
  bad.pop_back();
  CHECK_THROWS_WITH(c.bind(bad), Contains("expected 122") && Contains("121"));
}

TEST_CASE("the start-state parameters: Geyer & Herr's pose and speed, the stance sole on z = 0",
          "[controllers][reflex]") {
  const auto m = wang2012_humanoid();
  const wang2012_reflex_controller c(m);  // bound to the initial parameters
  sim_state s;
  c.initial_state(m, s);
  constexpr double deg = M_PI / 180.0;
  auto q = [&](const char* n) { return s.q[7 + m.dof_index(n)]; };
  // Their angles (hip, knee 180 straight; ankle 90 square), ours by the maps of the header.
  CHECK_THAT(180.0 + q("rhip_y") / deg, WithinAbs(175.0, 1e-9));
  CHECK_THAT(180.0 - q("rknee") / deg, WithinAbs(175.0, 1e-9));
  CHECK_THAT(90.0 + q("rankle_y") / deg, WithinAbs(85.0, 1e-9));
  CHECK_THAT(180.0 + q("lhip_y") / deg, WithinAbs(140.0, 1e-9));
  CHECK_THAT(90.0 + q("lankle_y") / deg, WithinAbs(90.0, 1e-9));
  CHECK(s.v[0] == 1.3);
  CHECK_THAT(lowest_foot_point(m, s.q), WithinAbs(0.0, 1e-12));
  CHECK_THAT(Eigen::Vector4d(s.q.segment<4>(3)).norm(), WithinAbs(1.0, 1e-15));
  // With start_from_parameters off, the rollout's own start stays.
  const wang2012_reflex_controller off(m, {.start_from_parameters = false});
  sim_state kept;
  kept.q = Eigen::VectorXd::Constant(m.nq(), 0.5);
  off.initial_state(m, kept);
  CHECK(kept.q[10] == 0.5);
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
  wang2012_reflex_controller ctrl(m, {.start_from_parameters = false});  // the default start
  const auto p = reflex_initial_parameters();
  rollout_options opt;
  opt.duration = 0.2;
  opt.detect_falls = false;
  auto scratch = make_rollout_scratch(m);
  first_step rec;
  const std::vector<double> params = wang2012_reflex_controller::initial_parameters(m);
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

namespace {

/// The mirror image of a floating-base state across the sagittal (x-z) plane.
sim_state mirrored(const floating_model& m, const sim_state& s) {
  sim_state out = s;
  out.q[1] = -s.q[1];
  out.q[4] = -s.q[4], out.q[6] = -s.q[6];  // (w, x, y, z) -> (w, -x, y, -z)
  out.v[1] = -s.v[1], out.v[3] = -s.v[3], out.v[5] = -s.v[5];
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const int k = m.mirror_dof[j];
    out.q[7 + k] = m.mirror_sign[j] * s.q[7 + j];
    out.v[6 + k] = m.mirror_sign[j] * s.v[6 + j];
  }
  return out;
}

}  // namespace

TEST_CASE("Sec. 4.4 control: the left leg standing commands the mirror image of the right",
          "[controllers][reflex][rollout]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units, 0.05);
  wang2012_reflex_controller ctrl(m, {.start_from_parameters = false});
  // Every coronal and transverse target away from 0, and a start that is not symmetric, so that
  // a sign error anywhere in the mirrored state shows.
  auto params = wang2012_reflex_controller::initial_parameters(m);
  const std::size_t u = 58;
  params[u + pelvis_coronal] = 0.03, params[u + swing_hip_coronal] = -0.05;
  params[u + stance_foot_coronal] = 0.02, params[u + swing_foot_coronal] = -0.04;
  params[u + torso_coronal] = 0.06, params[u + back_z_target] = 0.07;
  params[u + back_y_target] = 0.1, params[u + elbow_target] = -0.4;
  ctrl.bind(params);
  sim_state right;
  wang2012_reflex_controller(m).initial_state(m,
                                              right);  // Geyer & Herr's start: the right leg stands
  right.q[7 + m.dof_index("rhip_x")] = 0.04;
  right.q[7 + m.dof_index("lhip_z")] = -0.1;
  right.v[1] = 0.1;  // sideways
  right.v[3] = 0.2;  // roll rate
  right.q[7 + m.dof_index("back_x")] = 0.05;
  right.q[7 + m.dof_index("lshoulder_y")] = 0.3;
  right.q[7 + m.dof_index("lankle_x")] = 0.1;
  right.q[2] -= lowest_foot_point(m, right.q);
  auto first_command = [&](const sim_state& start) {
    rollout_options opt;
    opt.duration = 0.01;
    opt.detect_falls = false;
    opt.initial_state = start;
    auto scratch = make_rollout_scratch(m);
    first_step rec;
    rollout(m, act, ctrl, distance_objective(), flat_terrain(), semi_implicit_euler(),
            std::span<const double>(params), opt, scratch, rec);
    return rec.command;
  };
  const Eigen::VectorXd a = first_command(right), b = first_command(mirrored(m, right));
  const int nj = m.num_joint_dofs();
  REQUIRE(a.size() == 16 + 4 * nj);
  for (int i = 0; i < 16; ++i) {
    INFO("MTU " << i);
    CHECK_THAT(b[(i + 8) % 16], WithinAbs(a[i], 1e-9));
  }
  const biped_layout B = biped_layout::of(m);
  for (int j = 0; j < nj; ++j) {
    const int k = m.mirror_dof[j];
    const double sg = m.mirror_sign[j];
    INFO(m.dofs[j].name);
    CHECK_THAT(b[16 + k], WithinAbs(sg * a[16 + j], 1e-9));                    // target
    CHECK_THAT(b[16 + nj + k], WithinAbs(a[16 + nj + j], 1e-9));               // kp
    CHECK_THAT(b[16 + 2 * nj + k], WithinAbs(a[16 + 2 * nj + j], 1e-9));       // kd
    CHECK_THAT(b[16 + 3 * nj + k], WithinAbs(sg * a[16 + 3 * nj + j], 1e-7));  // feed-forward
  }
  // The laws themselves, on the right-standing side: the elbow and the shoulders follow Sec. 4.4,
  // the stance hip_x holds the pelvis with a torque (no local stiffness), the muscle DOFs are limp.
  const double el = params[u + elbow_target];
  CHECK(a[16 + B.arm[0].elbow_y] == el);
  const double hip_diff = right.q[7 + B.leg[1].hip_y] - right.q[7 + B.leg[0].hip_y];
  CHECK_THAT(a[16 + B.arm[0].shoulder_y],
             WithinAbs(params[u + alpha_arm] * hip_diff + shoulder_beta * el, 1e-12));
  CHECK_THAT(a[16 + B.arm[0].shoulder_z], WithinAbs(shoulder_gamma * el, 1e-12));
  CHECK(a[16 + nj + B.leg[1].hip_x] == 0.0);
  CHECK(a[16 + 3 * nj + B.leg[1].hip_x] != 0.0);
  CHECK(a[16 + B.back_y] == params[u + back_y_target]);
  for (int j : {B.leg[0].knee, B.leg[1].hip_y, B.leg[0].ankle_y})
    CHECK(a[16 + nj + j] + a[16 + 2 * nj + j] + a[16 + 3 * nj + j] == 0.0);
}
