// Actuators: the PD law of Wang et al. 2009 Eq. 1 and torque passthrough, computed by hand for
// every DOF, clamped at each DOF's own torque limit; validation of gains; concept conformance.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/model/model_builder.hpp"

using namespace gaitsynth;

namespace {

/// A planar chain with three joints of different torque limits (10, 20, 1e9 N m).
planar_model three_joint_chain() {
  model_builder<planar_root> b("chain3");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "base", .mass = 5, .inertia = I});
  b.add_body({.name = "a",
              .parent = "base",
              .mass = 1,
              .inertia = I,
              .dofs = {{.name = "ja", .torque_limit = 10}}});
  b.add_body({.name = "b",
              .parent = "a",
              .mass = 1,
              .inertia = I,
              .dofs = {{.name = "jb", .torque_limit = 20}}});
  b.add_body({.name = "c", .parent = "b", .mass = 1, .inertia = I, .dofs = {{.name = "jc"}}});
  return b.build();
}

double clamp_ref(double x, double lim) {
  return std::max(-lim, std::min(lim, x));
}

}  // namespace

static_assert(actuator<pd_actuator, planar_root>);
static_assert(actuator<pd_actuator, floating_root>);
static_assert(actuator<torque_actuator, planar_root>);
static_assert(actuator<torque_actuator, floating_root>);
static_assert(!actuator_with_advance<pd_actuator, planar_root>);
static_assert(!actuator_with_derivative<torque_actuator, planar_root>);

TEST_CASE("pd_actuator computes kp (target - q) - kd qdot per DOF, clamped to its limit",
          "[actuators][pd]") {
  const auto m = three_joint_chain();
  const Eigen::Vector3d kp(300, 50, 1000), kd(30, 5, 0);
  const pd_actuator pd(kp, kd);
  const auto st = pd.make_state(m);
  REQUIRE(pd.command_size(m) == 3);
  REQUIRE(pd.input_kind() == command_kind::joint_target);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    sim_state s = make_state(m);
    for (int i = 0; i < m.nq(); ++i) s.q[i] = U(rng);
    for (int i = 0; i < m.nv(); ++i) s.v[i] = 3 * U(rng);
    const Eigen::Vector3d target(U(rng), U(rng), U(rng));
    Eigen::Vector3d tau;
    pd.torques(m, s, target, st, tau);
    const double limits[3] = {10, 20, 1e9};
    for (int j = 0; j < 3; ++j) {
      const double raw = kp[j] * (target[j] - s.q[3 + j]) - kd[j] * s.v[3 + j];
      CHECK(tau[j] == Approx(clamp_ref(raw, limits[j])).margin(1e-12));
      CHECK(std::abs(tau[j]) <= limits[j]);
    }
  }
}

TEST_CASE("pd_actuator: the limit is reached exactly and only beyond it", "[actuators][pd]") {
  const auto m = three_joint_chain();
  const pd_actuator pd = pd_actuator::uniform(m, 100.0, 0.0);
  const auto st = pd.make_state(m);
  sim_state s = make_state(m);
  Eigen::Vector3d tau;
  // 100 * 0.05 = 5 N m: inside every limit.
  pd.torques(m, s, Eigen::Vector3d(0.05, 0.05, 0.05), st, tau);
  CHECK(tau.isApprox(Eigen::Vector3d(5, 5, 5)));
  // 100 * 0.5 = 50 N m: clamped to 10 and 20, the third joint (1e9) passes.
  pd.torques(m, s, Eigen::Vector3d(0.5, -0.5, 0.5), st, tau);
  CHECK(tau[0] == 10.0);
  CHECK(tau[1] == -20.0);
  CHECK(tau[2] == Approx(50.0));
}

TEST_CASE("pd_actuator with feed-forward adds the second half of the command before clamping",
          "[actuators][pd]") {
  const auto m = three_joint_chain();
  const pd_actuator pd = pd_actuator::uniform(m, 10.0, 1.0, /*feedforward=*/true);
  const auto st = pd.make_state(m);
  REQUIRE(pd.command_size(m) == 6);
  sim_state s = make_state(m);
  s.q.tail(3) << 0.1, 0.2, 0.3;
  s.v.tail(3) << 1, -1, 2;
  Eigen::VectorXd cmd(6);
  cmd << 0, 0, 0, 3, 30, -4;
  Eigen::Vector3d tau;
  pd.torques(m, s, cmd, st, tau);
  CHECK(tau[0] == Approx(10 * -0.1 - 1 + 3));  // 1
  CHECK(tau[1] == Approx(20.0));               // -2 + 1 + 30 = 29 -> limit 20
  CHECK(tau[2] == Approx(10 * -0.3 - 2 - 4));  // -9
}

TEST_CASE("torque_actuator passes the command through, clamped, and NaN stays NaN",
          "[actuators][torque]") {
  const auto m = three_joint_chain();
  const torque_actuator ta;
  const auto st = ta.make_state(m);
  REQUIRE(ta.command_size(m) == 3);
  REQUIRE(ta.input_kind() == command_kind::joint_torque);
  sim_state s = make_state(m);
  Eigen::Vector3d tau;
  ta.torques(m, s, Eigen::Vector3d(5, -25, 1e6), st, tau);
  CHECK(tau[0] == 5.0);
  CHECK(tau[1] == -20.0);
  CHECK(tau[2] == 1e6);
  // A NaN command must not be hidden by the clamp: the rollout reports the divergence instead.
  ta.torques(m, s, Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0), st, tau);
  CHECK(std::isnan(tau[0]));
}

TEST_CASE("pd_actuator rejects gains that do not fit the model", "[actuators][pd][bad_input]") {
  const auto m = three_joint_chain();
  CHECK_THROWS_WITH(pd_actuator(Eigen::Vector2d(1, 1), Eigen::Vector3d(1, 1, 1)).make_state(m),
                    Catch::Contains("expected 3, got 2"));
  CHECK_THROWS_WITH(pd_actuator(Eigen::Vector3d(1, -2, 1), Eigen::Vector3d(1, 1, 1)).make_state(m),
                    Catch::Contains("'jb'") && Catch::Contains("-2"));
  CHECK_THROWS_AS(pd_actuator(Eigen::Vector3d(1, 1, 1),
                              Eigen::Vector3d(1, std::numeric_limits<double>::quiet_NaN(), 1))
                      .make_state(m),
                  std::invalid_argument);
}

#include <Eigen/Eigenvalues>

#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace {
/// lambda_max(M^-1 (Kp dt^2 + 2 Kd dt)) at the neutral configuration: the explicit-PD stability
/// measure (< 4 stable) that pd_actuator::capped bounds by 2 margin.
template <root_joint Root>
double pd_step_rate(const model<Root>& m, const pd_actuator& pd, double dt) {
  auto ws = make_workspace(m);
  const Eigen::MatrixXd M = crba(m, ws, neutral_configuration(m));
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m.nv(), m.nv());
  K.diagonal().tail(m.num_joint_dofs()) = pd.kp * dt * dt + 2.0 * dt * pd.kd;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}
}  // namespace

TEST_CASE("joint_effective_inertia is 1 / diag(M^-1) at the neutral configuration",
          "[actuators][pd][capped]") {
  const auto m = three_joint_chain();
  const Eigen::VectorXd I = joint_effective_inertia(m);
  auto ws = make_workspace(m);
  const Eigen::MatrixXd M = crba(m, ws, neutral_configuration(m));
  const Eigen::MatrixXd Minv = M.inverse();
  for (int j = 0; j < 3; ++j) CHECK(I[j] == Approx(1.0 / Minv(3 + j, 3 + j)).epsilon(1e-12));
  // A floating joint drives less than the locked subtree inertia M_jj.
  for (int j = 0; j < 3; ++j) CHECK(I[j] <= M(3 + j, 3 + j) * (1 + 1e-12));
}

TEST_CASE("pd_actuator::capped keeps explicit PD stable and leaves stable gains alone",
          "[actuators][pd][capped]") {
  const auto m = wang2009_humanoid();
  const double dt = 1.0 / 2400.0;
  // Wang et al. 2009 Table 2 style gains, kd = 0.1 kp: unstable at 2400 Hz (lambda > 4).
  const pd_actuator raw = pd_actuator::uniform(m, 300.0, 30.0);
  CHECK(pd_step_rate(m, raw, dt) > 4.0);
  const pd_actuator capped = pd_actuator::capped(m, raw.kp, raw.kd, dt);
  CHECK(pd_step_rate(m, capped, dt) <= 2.0 * (1 + 1e-9));
  CHECK(pd_step_rate(m, capped, dt) >= 1.9);  // the bisection found the largest c
  // Only lowered, never raised; the heavy hips keep their stiffness.
  CHECK((capped.kp.array() <= raw.kp.array()).all());
  CHECK((capped.kd.array() <= raw.kd.array()).all());
  CHECK(capped.kp[m.dof_index("lhip_y")] == 300.0);
  CHECK(capped.kd[m.dof_index("ltoe")] < raw.kd[m.dof_index("ltoe")]);
  // Gains that are already stable come back unchanged.
  const pd_actuator soft = pd_actuator::uniform(m, 1.0, 0.01);
  const pd_actuator same = pd_actuator::capped(m, soft.kp, soft.kd, dt);
  CHECK(same.kp == soft.kp);
  CHECK(same.kd == soft.kd);
  // Bad input.
  CHECK_THROWS_WITH(pd_actuator::capped(m, raw.kp, raw.kd, 0.0), Catch::Contains("dt"));
  CHECK_THROWS_WITH(pd_actuator::capped(m, Eigen::VectorXd::Ones(3), raw.kd, dt),
                    Catch::Contains("expected 30, got 3"));
}
