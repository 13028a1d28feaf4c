// Wu & Popovic 2010, Sec. 5 and 6.1 (controllers/end_effector/frames.hpp, generalized_forces.hpp):
// the frames sit where Sec. 5 puts them, J = dx/dtheta with the upper body held still matches
// central differences of x(theta), and J^T f equals the joint forces of the pair forces applied
// as external wrenches (RNEA), whose root forces vanish (the pairs are in equilibrium).
#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/controllers/end_effector/generalized_forces.hpp"
#include "gaitsynth/dynamics/rnea.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;

namespace {

/// A random configuration: root anywhere, joint angles within +-0.6 rad, knees bent.
Eigen::VectorXd random_q(const floating_model& m, std::mt19937& rng) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq());
  q.head<3>() = gaitsynth::testing::random_vec3(rng, 1.0);
  q.segment<4>(3) = Eigen::Quaterniond::UnitRandom().coeffs();  // Eigen order x y z w
  const Eigen::Quaterniond r = Eigen::Quaterniond(q[6], q[3], q[4], q[5]).normalized();
  q[3] = r.w();
  q[4] = r.x();
  q[5] = r.y();
  q[6] = r.z();
  q.tail(m.num_joint_dofs()) = gaitsynth::testing::random_vector(rng, m.num_joint_dofs(), 0.6);
  for (const char* k : {"lknee", "rknee"}) q[7 + m.dof_index(k)] = 0.3 + 0.5 * std::abs(q[7]);
  return q;
}

/// x(theta) with the upper body held still: the pair vectors p_j - p_i, expressed in the upper
/// body's frame and rotated back with the unperturbed upper body's rotation R0.
Eigen::VectorXd pair_vector(const floating_model& m, workspace<floating_root>& ws,
                            const end_effector_layout& L, const Eigen::VectorXd& q,
                            const mat3& R0) {
  forward_kinematics(m, ws, q);
  const int ub = L.link_body[0];
  const vec3 pi = point_position(m, ws, ub, L.reaction_point);
  Eigen::VectorXd x(3 * L.num_pairs());
  for (int k = 0; k < L.num_pairs(); ++k) {
    const action_frame& a = L.action[k];
    const vec3 pj = point_position(m, ws, L.link_body[a.link], a.point);
    x.segment<3>(3 * k) = R0 * (ws.body_rotation[ub].transpose() * (pj - pi));
  }
  return x;
}

}  // namespace

TEST_CASE("Sec. 5's frames on the Table 3 biped", "[controllers][end_effector]") {
  const floating_model m = wu2010_biped();
  const end_effector_layout L = biped_end_effector_layout(m);
  REQUIRE(L.num_links() == 3);
  REQUIRE(L.num_action() == 8);  // N = 8: per foot an L frame and three LR frames
  CHECK(L.num_pairs() == 8);     // K = 8
  CHECK(L.link_body[0] == m.body_index("upper_body"));
  CHECK(L.reaction_point.isApprox(m.bodies[m.body_index("upper_body")].com));
  int l = 0, lr = 0;
  for (const action_frame& a : L.action) {
    l += a.type == frame_type::linear;
    lr += a.type == frame_type::linear_relative;
    CHECK(!a.contacts.empty());
  }
  CHECK(l == 2);
  CHECK(lr == 6);
  // Left foot: ankle at the foot origin, toes at the front corners, heel at the back's middle.
  CHECK(L.action[0].point.isZero());
  CHECK(L.action[1].point.x() == Approx(0.19));
  CHECK(L.action[2].point.x() == Approx(0.19));
  CHECK(L.action[1].point.y() == Approx(-L.action[2].point.y()));
  CHECK(L.action[3].point.x() == Approx(-0.06));
  CHECK(L.action[3].point.y() == Approx(0.0).margin(1e-15));
  CHECK(L.action[3].point.z() == Approx(-0.06));
  REQUIRE(L.legs.size() == 2);
  CHECK(L.legs[0].knee_dof == m.dof_index("lknee"));
  CHECK(L.legs[1].ankle_frame == 4);
}

TEST_CASE("J = dx/dtheta (Sec. 6.1) matches central differences with the upper body held still",
          "[controllers][end_effector]") {
  const floating_model m = wu2010_biped();
  const end_effector_layout L = biped_end_effector_layout(m);
  auto ws = make_workspace(m);
  auto ws_fd = make_workspace(m);
  frame_states s = make_frame_states(L);
  Eigen::MatrixXd J(24, 17), J_fd(24, 17);
  std::mt19937 rng(2010);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = random_q(m, rng);
    const Eigen::VectorXd v = Eigen::VectorXd::Zero(m.nv());
    forward_kinematics(m, ws, q, v);
    read_frame_states(m, ws, L, s);
    pair_jacobian(m, ws, q, L, J);
    const mat3 R0 = ws.body_rotation[L.link_body[0]];
    constexpr double h = 1e-6;
    for (int j = 0; j < 17; ++j) {
      Eigen::VectorXd qp = q, qm = q;
      qp[7 + j] += h;
      qm[7 + j] -= h;
      J_fd.col(j) = (pair_vector(m, ws_fd, L, qp, R0) - pair_vector(m, ws_fd, L, qm, R0)) / (2 * h);
    }
    INFO("trial " << trial);
    CHECK_THAT(J, is_approx(J_fd, 1e-8, 1e-8));
    // Rank 12: each foot has 6 DOF relative to the upper body; 5 joint DOFs move no frame.
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
    qr.setThreshold(1e-10);
    CHECK(qr.rank() == 12);
  }
}

TEST_CASE("J^T f is the joint force of the pair forces applied as external wrenches",
          "[controllers][end_effector]") {
  const floating_model m = wu2010_biped();
  const end_effector_layout L = biped_end_effector_layout(m);
  auto ws = make_workspace(m);
  frame_states s = make_frame_states(L);
  Eigen::MatrixXd J(24, 17);
  std::mt19937 rng(64);
  const int ub = L.link_body[0];
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = random_q(m, rng);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(m.nv());
    forward_kinematics(m, ws, q, zero);
    read_frame_states(m, ws, L, s);
    pair_jacobian(m, ws, q, L, J);
    const Eigen::VectorXd f = gaitsynth::testing::random_vector(rng, 24, 500.0);
    // Sec. 6.1: f_k at action frame k's origin on its link; -f_k on the reaction frame at p_i
    // with Sec. 6.2's torque (p_k - p_i) x -f_k. f_ext holds [torque about the body origin; force].
    for (auto& w : ws.f_ext) w.setZero();
    for (int k = 0; k < 8; ++k) {
      const int b = L.link_body[L.action[k].link];
      const vec3 fk = f.segment<3>(3 * k);
      ws.f_ext[b].head<3>() += (s.position[k] - ws.body_position[b]).cross(fk);
      ws.f_ext[b].tail<3>() += fk;
      ws.f_ext[ub].head<3>() += (s.reaction_position - ws.body_position[ub]).cross(-fk) +
                                (s.position[k] - s.reaction_position).cross(-fk);
      ws.f_ext[ub].tail<3>() -= fk;
    }
    const Eigen::VectorXd with = rnea_with_external(m, ws, q, zero, zero);
    const Eigen::VectorXd without = rnea(m, ws, q, zero, zero);
    const Eigen::VectorXd generalized = without - with;  // rnea_with_external = ... - J^T f_ext
    INFO("trial " << trial);
    CHECK(generalized.head<6>().norm() < 1e-9 * f.norm());  // the pairs are in equilibrium
    CHECK_THAT(generalized.tail(17), is_approx(J.transpose() * f, 1e-10, 1e-9));
  }
}
