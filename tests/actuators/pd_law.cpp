// The PD law written once (actuators/pd_law.hpp): hand values, the inverse's round trip, the
// vector form against the scalar one, the clamp; and that the actuators and pose_hold apply
// exactly this law.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/models/sharon2005.hpp"

using namespace gaitsynth;

// Usable in constant expressions.
static_assert(pd_torque(2.0, 0.5, 1.0, 0.25, 3.0) == 2.0 * 0.75 - 1.5);
static_assert(pd_target_for_torque(2.0, 0.5, 0.0, 0.25, 0.0) == 0.25);
static_assert(clamp_torque(5.0, 2.0) == 2.0 && clamp_torque(-5.0, 2.0) == -2.0);

TEST_CASE("pd_torque is kp (target - q) - kd qdot", "[actuators][pd_law]") {
  // 300 (0.5 - 0.2) - 30 (-1) = 90 + 30
  CHECK(pd_torque(300.0, 30.0, 0.5, 0.2, -1.0) == Approx(120.0).epsilon(1e-15));
  // 100 (0 - 0.25) - 10 (2) = -25 - 20: values exact in binary, so exact.
  CHECK(pd_torque(100.0, 10.0, 0.0, 0.25, 2.0) == -45.0);
  CHECK(pd_torque(0.0, 0.0, 1.0, 2.0, 3.0) == 0.0);  // no gains, no torque
  CHECK(pd_torque(50.0, 0.0, 0.125, 0.125, 7.0) == 0.0);
  // The exact expression, operation for operation (the saved controllers rely on it).
  const double kp = 612.3, kd = 61.7, target = 0.3127, q = -0.0719, qd = 1.337;
  CHECK(pd_torque(kp, kd, target, q, qd) == kp * (target - q) - kd * qd);
}

TEST_CASE("pd_target_for_torque inverts pd_torque in the target", "[actuators][pd_law]") {
  // q + (tau + kd qdot) / kp = 0.25 + (10 + 10 * 2) / 100 = 0.55
  CHECK(pd_target_for_torque(100.0, 10.0, 10.0, 0.25, 2.0) == Approx(0.55).epsilon(1e-15));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  // Gains, angles and torques of the Sharon 2005 servos (kp 600, kd 60, |tau| <= 370 N m).
  for (int trial = 0; trial < 1000; ++trial) {
    const double kp = 100 + 900 * (0.5 + 0.5 * U(rng)), kd = 100 * (0.5 + 0.5 * U(rng));
    const double tau = 370 * U(rng), q = U(rng), qd = 5 * U(rng);
    const double target = pd_target_for_torque(kp, kd, tau, q, qd);
    INFO("kp " << kp << " kd " << kd << " tau " << tau << " q " << q << " qdot " << qd);
    CHECK(std::abs(pd_torque(kp, kd, target, q, qd) - tau) <= 1e-12);
  }
}

TEST_CASE("the vector pd_torque is the scalar law per coefficient", "[actuators][pd_law]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const int n = 9;
  Eigen::VectorXd kp(n), kd(n), target(n), q(n + 3), qd(n + 3);
  for (int i = 0; i < n; ++i) {
    kp[i] = 500 * (1 + U(rng));
    kd[i] = 50 * (1 + U(rng));
    target[i] = U(rng);
  }
  for (int i = 0; i < n + 3; ++i) {
    q[i] = U(rng);
    qd[i] = 5 * U(rng);
  }
  // Operands as the controllers pass them: plain vectors and tails (blocks) of q and v.
  const Eigen::VectorXd tau = pd_torque(kp, kd, target, q.tail(n), qd.tail(n));
  for (int i = 0; i < n; ++i)
    CHECK(tau[i] == pd_torque(kp[i], kd[i], target[i], q[3 + i], qd[3 + i]));
  const Eigen::VectorXd old_form =
      kp.cwiseProduct(target - q.tail(n)) - kd.cwiseProduct(qd.tail(n));
  CHECK(tau == old_form);
}

TEST_CASE("clamp_torque clamps to +-limit and keeps NaN", "[actuators][pd_law]") {
  CHECK(clamp_torque(3.0, 10.0) == 3.0);
  CHECK(clamp_torque(10.0, 10.0) == 10.0);
  CHECK(clamp_torque(10.5, 10.0) == 10.0);
  CHECK(clamp_torque(-11.0, 10.0) == -10.0);
  CHECK(clamp_torque(1e300, std::numeric_limits<double>::infinity()) == 1e300);
  CHECK(std::isnan(clamp_torque(std::numeric_limits<double>::quiet_NaN(), 10.0)));
}

TEST_CASE("pd_actuator and pose_hold apply pd_torque bit for bit", "[actuators][pd_law]") {
  const planar_model m = sharon2005_human7();
  const int nj = m.num_joint_dofs();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Eigen::VectorXd kp(nj), kd(nj);
  for (int j = 0; j < nj; ++j) {
    kp[j] = 300 + 200 * U(rng);
    kd[j] = 30 + 20 * U(rng);
  }
  sim_state s = make_state(m);
  for (int i = 0; i < m.nq(); ++i) s.q[i] = 0.5 * U(rng);
  for (int i = 0; i < m.nv(); ++i) s.v[i] = 3 * U(rng);
  Eigen::VectorXd target(nj);
  for (int j = 0; j < nj; ++j) target[j] = 0.5 * U(rng);

  const pd_actuator pd(kp, kd);
  Eigen::VectorXd tau(nj);
  auto pd_state = pd.make_state(m);
  pd.torques(m, s, target, pd_state, tau);
  for (int j = 0; j < nj; ++j)
    CHECK(tau[j] == clamp_torque(pd_torque(kp[j], kd[j], target[j], s.q[3 + j], s.v[3 + j]),
                                 m.dofs[j].torque_limit));

  pose_hold ph(m, {.output = command_kind::joint_torque, .kp = kp, .kd = kd});
  ph.bind(std::span<const double>(target.data(), static_cast<std::size_t>(nj)));
  sensors<planar_root> sen;
  sen.model_ptr = &m;
  sen.q_ptr = &s.q;
  sen.v_ptr = &s.v;
  auto st = ph.make_state(m);
  Eigen::VectorXd cmd(nj);
  ph.command(sen, st, cmd);
  for (int j = 0; j < nj; ++j)
    CHECK(cmd[j] == pd_torque(kp[j], kd[j], target[j], s.q[3 + j], s.v[3 + j]));
}
