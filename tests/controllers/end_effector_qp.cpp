// Wu & Popovic 2010, eq. 5 and Sec. 6.3 (controllers/end_effector/force_qp.hpp): the QP solved
// per tick satisfies its KKT conditions, gives the same forces as eq. 5 written as the paper
// does (3K unknowns, Z^T f = 0), agrees with Eigen's least squares when no bound is active,
// drops exactly the pinned frames' rows, appendix B's canceling QP leaves only the part of the
// knee torque that J^T f cannot produce, and the null-space spring-damper accelerates only null(J).
#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/qp/kkt.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

namespace {

struct fixture {
  floating_model m = wu2010_biped();
  end_effector_layout L = biped_end_effector_layout(m);
  lower_level_workspace<floating_root> ws = make_lower_level_workspace(m, L);
  force_qp_options opt;
  Eigen::VectorXd q, v;

  /// A bent-knee pose with random velocities, random ideal wrenches in b.
  void setup(std::mt19937& rng, double wrench_scale) {
    q = Eigen::VectorXd::Zero(m.nq());
    q[3] = 1.0;
    q.tail(17) = gaitsynth::testing::random_vector(rng, 17, 0.3);
    q[7 + m.dof_index("lknee")] = 0.5;
    q[7 + m.dof_index("rknee")] = 0.7;
    v = gaitsynth::testing::random_vector(rng, m.nv(), 0.5);
    forward_kinematics(m, ws.dyn, q, v);
    read_frame_states(m, ws.dyn, L, ws.current);
    pair_jacobian(m, ws.dyn, q, L, ws.J);
    factor_pair_jacobian(ws.J, opt, ws.qp);
    ws.ideal.reaction_force = gaitsynth::testing::random_vec3(rng, wrench_scale);
    ws.ideal.reaction_torque = gaitsynth::testing::random_vec3(rng, wrench_scale);
    for (vec3& f : ws.ideal.action_force) f = gaitsynth::testing::random_vec3(rng, wrench_scale);
    assemble_eq4(L, ws.current, ws.ideal, ws.qp.A, ws.qp.b);
    ws.qp.w.setOnes();
    ws.qp.w.head(3).setConstant(5.0);
    ws.qp.w.tail(3).setConstant(5.0);
  }
};

/// Eq. 5 as the paper writes it: unknowns f (3K), equality rows Z^T f = 0, bounds on f and J^T f,
/// with the same regularization lambda ||f||^2 as force_qp.hpp.
dense_qp paper_program(const force_qp_workspace& w, std::span<const unsigned char> pinned,
                       const Eigen::MatrixXd& J, const Eigen::VectorXd& tau_max, double f_max,
                       double lambda) {
  const Eigen::Index K3 = w.K3, nz = K3 - w.rank;
  Eigen::MatrixXd Wsqrt_A(0, K3);
  Eigen::VectorXd Wsqrt_b(0);
  for (Eigen::Index i = 0; i < w.rows_full; ++i) {
    const Eigen::Index frame = i >= 3 && i < w.rows_full - 3 ? (i - 3) / 3 : -1;
    if (frame >= 0 && pinned[static_cast<std::size_t>(frame)]) continue;
    Wsqrt_A.conservativeResize(Wsqrt_A.rows() + 1, K3);
    Wsqrt_b.conservativeResize(Wsqrt_b.size() + 1);
    Wsqrt_A.bottomRows(1) = std::sqrt(w.w[i]) * w.A.row(i);
    Wsqrt_b[Wsqrt_b.size() - 1] = std::sqrt(w.w[i]) * w.b[i];
  }
  dense_qp qp = make_dense_qp(K3, nz, J.cols());
  qp.H = Wsqrt_A.transpose() * Wsqrt_A + lambda * Eigen::MatrixXd::Identity(K3, K3);
  qp.g = -Wsqrt_A.transpose() * Wsqrt_b;
  qp.A = w.Q.rightCols(nz).transpose();  // Z^T f = 0
  qp.C = J.transpose();
  qp.c_lower = -tau_max;
  qp.c_upper = tau_max;
  qp.x_lower.setConstant(-f_max);
  qp.x_upper.setConstant(f_max);
  return qp;
}

}  // namespace

TEST_CASE("eq. 5 in range(J)'s coordinates equals eq. 5 with Z^T f = 0, and is optimal (KKT)",
          "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(5);
  for (int trial = 0; trial < 6; ++trial) {
    // Large wrenches make bounds active on some trials (f_max and the joint torque limits).
    fx.setup(rng, trial < 3 ? 200.0 : 3000.0);
    std::vector<unsigned char> pinned(8, 0);
    if (trial % 2) pinned = {1, 1, 0, 1, 0, 0, 1, 0};
    REQUIRE(fx.ws.qp.rank == 12);
    const qp_status st = solve_force_qp(pinned, fx.ws.tau_max, fx.opt, fx.ws.qp);
    REQUIRE(st == qp_status::optimal);
    const qp_result& r = fx.ws.qp.qp_ws.result;
    const qp_kkt_residuals k = kkt_residuals(fx.ws.qp.qp, r.x, r.y, r.lambda_c, r.lambda_x);
    INFO("trial " << trial << ", active " << r.active_constraints);
    CHECK(k.max() < 1e-7 * std::max(1.0, fx.ws.qp.qp.g.cwiseAbs().maxCoeff()));
    // The regularization the solver added: H's diagonal minus the unregularized one.
    const Eigen::MatrixXd AU = fx.ws.qp.AU.topRows(fx.ws.qp.rows);
    const double lambda = (fx.ws.qp.qp.H - AU.transpose() * AU).diagonal()[0];
    const dense_qp paper =
        paper_program(fx.ws.qp, pinned, fx.ws.J, fx.ws.tau_max, fx.opt.f_max, lambda);
    qp_workspace pws(paper.num_variables(), paper.num_equalities(), paper.num_inequalities());
    const qp_result& pr = solve_qp(paper, pws);
    REQUIRE(pr.status == qp_status::optimal);
    CHECK_THAT(fx.ws.qp.f, is_approx(pr.x, 1e-7, 1e-6));
    CHECK((fx.ws.J.transpose() * fx.ws.qp.f - fx.ws.qp.tau).norm() < 1e-8 * fx.ws.qp.f.norm());
    // Sec. 6.2's bounds hold.
    CHECK(fx.ws.qp.f.cwiseAbs().maxCoeff() <= fx.opt.f_max * (1 + 1e-9));
    CHECK(((fx.ws.qp.tau.cwiseAbs() - fx.ws.tau_max).array() <= 1e-6).all());
  }
}

TEST_CASE("with no bound active, eq. 5 is Eigen's regularized least squares over range(J)",
          "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(17);
  fx.setup(rng, 50.0);
  const std::vector<unsigned char> pinned(8, 0);
  REQUIRE(solve_force_qp(pinned, fx.ws.tau_max, fx.opt, fx.ws.qp) == qp_status::optimal);
  REQUIRE(fx.ws.qp.qp_ws.result.active_constraints == 0);
  // Independent: an SVD of J for range(J) (not the solver's QR) and Eigen's least squares of
  // [W^1/2 A U; sqrt(lambda) I] c = [W^1/2 b; 0].
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(fx.ws.J, Eigen::ComputeThinU);
  const Eigen::MatrixXd U = svd.matrixU().leftCols(12);
  const Eigen::MatrixXd Ws = fx.ws.qp.w.cwiseSqrt().asDiagonal();
  const Eigen::MatrixXd AU = Ws * fx.ws.qp.A * U;
  const double lambda =
      fx.opt.regularization * std::max((AU.transpose() * AU).diagonal().maxCoeff(), 1.0);
  Eigen::MatrixXd M(AU.rows() + 12, 12);
  M << AU, std::sqrt(lambda) * Eigen::MatrixXd::Identity(12, 12);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(M.rows());
  rhs.head(AU.rows()) = Ws * fx.ws.qp.b;
  const Eigen::VectorXd c = M.colPivHouseholderQr().solve(rhs);
  CHECK_THAT(fx.ws.qp.f, is_approx(U * c, 1e-8, 1e-8));
  // And the regularization is small: the plain least-squares answer differs by < 1e-3.
  const Eigen::VectorXd c0 = AU.colPivHouseholderQr().solve(Ws * fx.ws.qp.b);
  CHECK((fx.ws.qp.f - U * c0).norm() < 1e-3 * (U * c0).norm());
}

TEST_CASE("Sec. 6.3: a pinned frame's rows leave A and b", "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(63);
  fx.setup(rng, 100.0);
  const std::vector<unsigned char> pinned = {0, 1, 1, 0, 1, 0, 0, 0};
  REQUIRE(solve_force_qp(pinned, fx.ws.tau_max, fx.opt, fx.ws.qp) == qp_status::optimal);
  CHECK(fx.ws.qp.rows == 30 - 3 * 3);
  // The kept rows, in order: the upper body's force, frames 0, 3, 5, 6, 7, the upper body's torque.
  const int kept[] = {0, 3, 12, 18, 21, 24, 27};
  for (int blk = 0; blk < 7; ++blk)
    for (int i = 0; i < 3; ++i)
      CHECK(fx.ws.qp.Ar.row(3 * blk + i) == fx.ws.qp.A.row(kept[blk] + i));
  const Eigen::VectorXd f = fx.ws.qp.f;
  // Changing a pinned frame's ideal force changes nothing; an unpinned one's does.
  fx.ws.qp.b.segment<3>(action_row(1)) += vec3(500, -300, 800);
  solve_force_qp(pinned, fx.ws.tau_max, fx.opt, fx.ws.qp);
  CHECK(fx.ws.qp.f == f);
  fx.ws.qp.b.segment<3>(action_row(0)) += vec3(50, 0, 0);
  solve_force_qp(pinned, fx.ws.tau_max, fx.opt, fx.ws.qp);
  CHECK((fx.ws.qp.f - f).norm() > 1.0);
}

TEST_CASE("Sec. 6.3: pinned_frames' contact test, the frame's own geometry or its foot's",
          "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(64);
  fx.setup(rng, 100.0);
  const end_effector_layout& L = fx.L;
  // Every frame at its target, the targets still: only the contact test decides.
  frame_states desired = fx.ws.current;
  for (vec3& v : desired.velocity) v.setZero();
  // The left foot stands on its toe box alone (rolled onto its toes); the right foot is in the air.
  std::vector<unsigned char> touching(fx.m.contact_points.size(), 0);
  int lheel = -1, ltoe = -1;
  for (int j = 0; j < L.num_action(); ++j) {
    const action_frame& a = L.action[static_cast<std::size_t>(j)];
    if (a.name == "lheel") lheel = j;
    if (a.name == "ltoe_front_lat") ltoe = j;
  }
  REQUIRE(lheel >= 0);
  REQUIRE(ltoe >= 0);
  for (const int c : L.action[static_cast<std::size_t>(ltoe)].contacts)
    touching[static_cast<std::size_t>(c)] = 1;
  std::vector<unsigned char> pinned(L.action.size(), 2);
  lower_level_options opt;
  REQUIRE(opt.pin_by == pin_contact::frame_geometry);  // the default, as before the option
  pinned_frames(L, fx.ws.current, desired, touching, opt, pinned);
  for (int j = 0; j < L.num_action(); ++j) {
    const action_frame& a = L.action[static_cast<std::size_t>(j)];
    INFO(a.name);
    // Own geometry: the heel frame (heel box) is free, the toe and ankle frames (whose boxes
    // include the toe box) are pinned; nothing on the right foot.
    CHECK(pinned[static_cast<std::size_t>(j)] == (a.link == 1 && a.name != "lheel"));
  }
  opt.pin_by = pin_contact::link;
  pinned_frames(L, fx.ws.current, desired, touching, opt, pinned);
  for (int j = 0; j < L.num_action(); ++j) {
    INFO(L.action[static_cast<std::size_t>(j)].name);
    CHECK(pinned[static_cast<std::size_t>(j)] == (L.action[static_cast<std::size_t>(j)].link == 1));
  }
  // The other two tests still apply to every frame: the heel's target past eps_p, or moving.
  desired.position[static_cast<std::size_t>(lheel)].z() += 1.01 * opt.eps_p;
  pinned_frames(L, fx.ws.current, desired, touching, opt, pinned);
  CHECK(pinned[static_cast<std::size_t>(lheel)] == 0);
  CHECK(pinned[static_cast<std::size_t>(ltoe)] == 1);
  desired.position[static_cast<std::size_t>(lheel)] =
      fx.ws.current.position[static_cast<std::size_t>(lheel)];
  desired.velocity[static_cast<std::size_t>(lheel)] = vec3(0.0, 1.01 * opt.eps_pdot, 0.0);
  pinned_frames(L, fx.ws.current, desired, touching, opt, pinned);
  CHECK(pinned[static_cast<std::size_t>(lheel)] == 0);
  CHECK(pinned[static_cast<std::size_t>(ltoe)] == 1);
}

TEST_CASE("appendix B: the canceling QP removes what J^T f can produce (eq. 12)",
          "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(12);
  fx.setup(rng, 100.0);
  Eigen::VectorXd tau_theta = Eigen::VectorXd::Zero(17);
  tau_theta[fx.m.dof_index("lknee")] = 40.0;
  tau_theta[fx.m.dof_index("lhip_z")] = -25.0;  // a swivel torque: partly in null(J)
  REQUIRE(solve_canceling_qp(tau_theta, fx.opt, fx.ws.qp) == qp_status::optimal);
  const Eigen::VectorXd& extra = fx.ws.qp.tau_extra;
  // Normal equations of min ||tau + J^T f||: J (tau + J^T f) = 0 (to the regularization).
  CHECK((fx.ws.J * extra).norm() < 1e-4 * tau_theta.norm());
  // What is left is the projection of tau_theta on null(J), computed independently by an SVD.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(fx.ws.J, Eigen::ComputeFullV);
  const Eigen::MatrixXd N = svd.matrixV().rightCols(5);
  // (to 1e-3 of its size: lambda / sigma_min(J)^2 of the regularization)
  CHECK_THAT(extra, is_approx(N * (N.transpose() * tau_theta), 1e-3));
  CHECK(extra.norm() > 1.0);  // the swivel part survives
  // Zero tau_theta: nothing to cancel.
  REQUIRE(solve_canceling_qp(Eigen::VectorXd::Zero(17), fx.opt, fx.ws.qp) == qp_status::optimal);
  CHECK(fx.ws.qp.tau_extra.isZero(0.0));
}

TEST_CASE("the null-space spring-damper accelerates only null(J), as a unit mass",
          "[controllers][end_effector][qp]") {
  fixture fx;
  std::mt19937 rng(13);
  fx.setup(rng, 100.0);
  const Eigen::MatrixXd M = crba(fx.m, fx.ws.dyn, fx.q);
  const double kp = 900.0, kd = 60.0;
  // Joint accelerations of a torque alone (gravity and velocity terms aside): M a = [0; tau],
  // solved by an LDLT of the whole M, not by the Schur complement the damper uses.
  auto joint_accel = [&](const Eigen::VectorXd& q_j, const Eigen::VectorXd& v_j) {
    const Eigen::VectorXd& tau = null_space_spring_damper(fx.ws.qp.JtU.leftCols(fx.ws.qp.rank), M,
                                                          q_j, v_j, kp, kd, fx.ws.null_space);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(fx.m.nv());
    rhs.tail(17) = tau;
    return Eigen::VectorXd(M.ldlt().solve(rhs).tail(17));
  };
  const Eigen::VectorXd q_j = fx.q.tail(17), v_j = fx.v.tail(17);
  const Eigen::VectorXd a = joint_accel(q_j, v_j);
  // null(J) from an SVD (independent of the damper's QR).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(fx.ws.J, Eigen::ComputeFullV);
  const Eigen::MatrixXd N = svd.matrixV().rightCols(5);
  CHECK(fx.ws.qp.rank == 12);
  CHECK_THAT(a, is_approx(Eigen::VectorXd(N * (N.transpose() * (-kp * q_j - kd * v_j))), 1e-9));
  CHECK(a.norm() > 10.0);
  CHECK((fx.ws.J * a).norm() < 1e-9 * a.norm());  // moves no frame
  // As a function of v it is -kd N N^T: every null-space mode a unit mass with damping kd, so
  // the explicit step is stable for h kd < 2 whatever the inertia. The torque -kd N N^T v without
  // the inertia (an earlier design, null_space_damper.hpp) would, at this state, accelerate the
  // foot's roll by ~5800 rad/s^2 per rad/s of roll rate: h times that is above 2 at 2400 Hz,
  // where the explicit step reverses the roll rate every step and grows.
  Eigen::MatrixXd G(17, 17);
  for (int i = 0; i < 17; ++i) G.col(i) = joint_accel(q_j, v_j + Eigen::VectorXd::Unit(17, i)) - a;
  CHECK_THAT(G, is_approx(Eigen::MatrixXd(-kd * N * N.transpose()), 1e-8));
  const Eigen::Index roll = fx.m.dof_index("lankle_x");
  const Eigen::MatrixXd Minv_jj = M.inverse().bottomRightCorner(17, 17);
  const Eigen::VectorXd euclidean = Minv_jj * (-kd * N * N.transpose()).col(roll);
  const double h = 1.0 / 2400.0;
  CHECK(h * std::abs(euclidean[roll]) > 2.0);  // measured 2.4
  CHECK(h * std::abs(G(roll, roll)) < 0.01);   // measured 0.0023
  // Bad sizes throw, naming them.
  CHECK_THROWS_WITH(null_space_spring_damper(fx.ws.qp.JtU.leftCols(12), M, q_j.head(16), v_j, kp,
                                             kd, fx.ws.null_space),
                    Catch::Contains("16"));
}
