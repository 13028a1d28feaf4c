// Implicit joint damping (rollout_options::implicit_joint_damping): the joint dampers of the
// actuator and of the soft joint limits taken by backward Euler through an armature dt kd in ABA.
// The regression it guards: the Wang 2009 controller's rollouts diverged near the gimbal lock of
// the 3-DOF Euler hips (hip_y = -pi/2, where the hip_x and hip_z axes align and the joint-space
// inertia has a mode of vanishing inertia, so any explicit damper on those DOFs is unstable at
// 2400 Hz, whatever its cap at the neutral pose).
#include <Eigen/Cholesky>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/synthesis/wang2009_search_space.hpp"

using namespace gaitsynth;

namespace {

/// The largest joint rate seen over a rollout (rad/s).
struct max_joint_rate {
  double value = 0.0;
  template <class Observation>
  void observe(const Observation& ob) {
    const auto v = ob.joint_velocities();
    for (Eigen::Index j = 0; j < v.size(); ++j) value = std::max(value, std::abs(v[j]));
  }
};

/// Each observed step: q, v and the applied torques.
struct step_log {
  std::vector<Eigen::VectorXd> q, v, tau, tau_passive;
  template <class Observation>
  void observe(const Observation& ob) {
    q.push_back(ob.q());
    v.push_back(ob.v());
    tau.push_back(ob.tau());
    tau_passive.push_back(ob.tau_passive());
  }
};

}  // namespace

TEST_CASE("aba with an armature solves (M + diag(0, a)) ddq = tau - C", "[dynamics][aba]") {
  const floating_model m = wang2009_humanoid();
  auto ws = make_workspace(m);
  std::mt19937 rng(7);
  std::mt19937_64 configuration_rng(7);  // random_configuration takes the portable engine
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd q = random_configuration(m, configuration_rng);
  Eigen::VectorXd v(m.nv()), tau(m.nv()), a(m.num_joint_dofs());
  for (int i = 0; i < m.nv(); ++i) {
    v[i] = 2.0 * u(rng);
    tau[i] = 20.0 * u(rng);
  }
  for (int j = 0; j < a.size(); ++j) a[j] = 0.05 * (u(rng) + 1.0);
  clear_external_wrenches(ws);
  const Eigen::VectorXd ddq = aba(m, ws, q, v, tau, a);
  Eigen::MatrixXd M = crba(m, ws, q);
  const Eigen::VectorXd h = nonlinear_effects(m, ws, q, v);
  M.diagonal().tail(a.size()) += a;
  const Eigen::VectorXd expected = M.llt().solve(tau - h);
  CHECK((ddq - expected).norm() <= 1e-9 * (1.0 + expected.norm()));
  // A zero armature is plain ABA.
  const Eigen::VectorXd plain = aba(m, ws, q, v, tau);
  CHECK((aba(m, ws, q, v, tau, Eigen::VectorXd::Zero(a.size())) - plain).norm() == 0.0);
  Eigen::VectorXd bad = a;
  bad[3] = -1.0;
  CHECK_THROWS_AS(aba(m, ws, q, v, tau, bad), std::invalid_argument);
}

TEST_CASE("mixed_pd_actuator::joint_damping gives each DOF's kd", "[actuators][mixed]") {
  const floating_model m = wang2009_humanoid();
  const int nj = m.num_joint_dofs();
  Eigen::VectorXd cmd = Eigen::VectorXd::Zero(4 * nj), c(nj);
  mixed_command out(cmd);
  out.set_target(0, 0.3, 100.0, 10.0);
  out.set_target(1, 0.0, 1e6, 5.0);   // its torque is clamped; the damper still counts
  out.set_target(2, 0.0, 0.0, -3.0);  // negative gains are not dampers
  out.set_torque(3, 50.0);
  const sim_state s = make_state(m);
  mixed_pd_actuator{}.joint_damping(m, s, cmd, {}, c);
  CHECK(c[0] == 10.0);
  CHECK(c[1] == 5.0);
  CHECK(c[2] == 0.0);
  CHECK(c[3] == 0.0);
}

TEST_CASE("explicit dampers diverge at the hip's gimbal lock; implicit ones do not",
          "[rollout][implicit_damping]") {
  // The humanoid stands holding its left thigh at hip_y = -1.55 (flexed 89 degrees) with
  // standing_pd's capped gains (kd 100 at hip_x, 16 at hip_z, stable at the neutral pose).
  const floating_model m = wang2009_humanoid();
  const double dt = 1.0 / 2400.0;
  const pd_actuator g = standing_pd(m, dt);
  const int hx = m.dof_index("lhip_x"), hy = m.dof_index("lhip_y");
  pose_hold::options po;
  po.output = command_kind::mixed;
  po.kp = g.kp;
  po.kd = g.kd;
  std::vector<double> target(static_cast<std::size_t>(m.num_joint_dofs()), 0.0);
  target[static_cast<std::size_t>(hy)] = -1.55;
  rollout_options opt;
  opt.duration = 1.0;
  opt.detect_falls = false;
  sim_state s0 = make_state(m);
  s0.q[floating_root::nq + hy] = -1.55;
  s0.v[floating_root::nv + hx] = 1.0;
  place_on_terrain(m, flat_terrain{}, s0.q);
  opt.initial_state = s0;
  auto scratch = make_rollout_scratch(m);
  auto run = [&](bool implicit, max_joint_rate& ob) {
    rollout_options o = opt;
    o.implicit_joint_damping = implicit;
    return rollout(m, mixed_pd_actuator{}, pose_hold(m, po), distance_objective(), flat_terrain{},
                   semi_implicit_euler{}, std::span<const double>(target), o, scratch, ob);
  };
  max_joint_rate explicit_rate, implicit_rate;
  const rollout_result e = run(false, explicit_rate);
  CHECK(e.reason == stop_reason::non_finite);
  CHECK(e.time < 0.01);
  const rollout_result i = run(true, implicit_rate);
  CHECK(i.reason == stop_reason::horizon);
  CHECK(implicit_rate.value < 5.0);
}

TEST_CASE("implicit damping: the observed torques are the applied ones",
          "[rollout][implicit_damping]") {
  // In the air (no contact): M(q_k) (v_k+1 - v_k) / dt + C(q_k, v_k) = tau_k + tau_passive_k, with
  // the torques the observer sees, joint limits past their bounds included.
  const floating_model m = wang2009_humanoid();
  const int nj = m.num_joint_dofs();
  pose_hold::options po;
  po.output = command_kind::mixed;
  po.kp = Eigen::VectorXd::Constant(nj, 300.0);
  po.kd = Eigen::VectorXd::Constant(nj, 30.0);  // uncapped: explicit would diverge at the toes
  std::vector<double> target(static_cast<std::size_t>(nj), 0.4);
  rollout_options opt;
  opt.duration = 40 * opt.dt;
  opt.detect_falls = false;
  opt.implicit_joint_damping = true;
  sim_state s0 = make_state(m);
  s0.q[2] = 3.0;
  s0.q[floating_root::nq + m.dof_index("lknee")] = -0.2;  // past the knee's stop
  for (int j = 0; j < nj; ++j) s0.v[floating_root::nv + j] = 0.5 * std::sin(j + 1.0);
  opt.initial_state = s0;
  auto scratch = make_rollout_scratch(m);
  step_log log;
  const rollout_result r =
      rollout(m, mixed_pd_actuator{}, pose_hold(m, po), distance_objective(), flat_terrain{},
              semi_implicit_euler{}, std::span<const double>(target), opt, scratch, log);
  REQUIRE(r.reason == stop_reason::horizon);
  REQUIRE(log.q.size() >= 40);
  auto ws = make_workspace(m);
  double passive = 0.0;
  for (std::size_t k = 0; k + 1 < log.q.size(); ++k) {
    const Eigen::MatrixXd M = crba(m, ws, log.q[k]);
    const Eigen::VectorXd h = nonlinear_effects(m, ws, log.q[k], log.v[k]);
    const Eigen::VectorXd lhs = M * ((log.v[k + 1] - log.v[k]) / opt.dt) + h;
    const Eigen::VectorXd rhs = log.tau[k] + log.tau_passive[k];
    CAPTURE(k);
    CHECK((lhs - rhs).norm() <= 1e-6 * (1.0 + rhs.norm()));
    passive += log.tau_passive[k].norm();
  }
  CHECK(passive > 0.0);  // the knee's stop acted
}

TEST_CASE("Table 2 neighbours never diverge with implicit joint damping",
          "[controllers][wang2009][implicit_damping]") {
  // Candidates as CMA-ES draws them around Table 2 (normalized sigma 0.005). With explicit
  // dampers about half of them blow up while falling (joint rates of 1e3..1e100 rad/s, most
  // stopped by the fall test before q or v overflow); with implicit damping none does.
  const floating_model m = wang2009_humanoid();
  wang2009_controller ctrl(m);
  const std::vector<double> x0 = wang2009_table2_parameters(m, ctrl);
  const parameter_space space = wang2009_search_space(m, ctrl, x0);
  const Eigen::VectorXd u0 =
      space.to_normalized(Eigen::Map<const Eigen::VectorXd>(x0.data(), std::ssize(x0)));
  const auto obj = wang2009_objective(m, {});
  rollout_options opt;
  opt.contact.mu = 10.0;
  opt.fall_height = 0.7;
  opt.implicit_joint_damping = true;
  auto scratch = make_rollout_scratch(m);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n01;
  int fast = 0, nonfinite = 0;
  for (int c = 0; c < 40; ++c) {
    Eigen::VectorXd u = u0;
    for (Eigen::Index k = 0; k < u.size(); ++k) u[k] += 0.005 * n01(rng);
    const Eigen::VectorXd x = space.to_user(u);
    max_joint_rate ob;
    const rollout_result r = rollout(
        m, mixed_pd_actuator{}, ctrl, obj, flat_terrain{}, semi_implicit_euler{},
        std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), opt, scratch, ob);
    nonfinite += r.reason == stop_reason::non_finite;
    fast += ob.value > 1000.0;
  }
  CHECK(nonfinite == 0);
  CHECK(fast == 0);
}

TEST_CASE("implicit joint damping needs the general path", "[rollout][implicit_damping]") {
  const planar_model m = sharon2005_human7();
  rollout_options opt;
  opt.duration = 0.01;
  opt.implicit_joint_damping = true;
  auto scratch = make_rollout_scratch(m);
  std::vector<double> target(static_cast<std::size_t>(m.num_joint_dofs()), 0.0);
  auto run = [&] {
    return rollout(m, standing_pd(m, opt.dt), pose_hold(m), distance_objective(), flat_terrain{},
                   semi_implicit_euler{}, std::span<const double>(target), opt, scratch);
  };
  CHECK_THROWS_AS(run(), std::invalid_argument);
  disable_planar_path(scratch.ws);
  CHECK(run().reason != stop_reason::non_finite);
}
