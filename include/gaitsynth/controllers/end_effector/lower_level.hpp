#pragma once
/// \file controllers/end_effector/lower_level.hpp
/// One tick of the lower level of Wu & Popovic 2010 (Sec. 5, 6 and appendix B): from the state
/// (q, v), the contacts and the end-effector links' targets to joint torques,
///
///   frames (Sec. 5) -> ideal PD wrenches (eqs. 1-3) -> J (Sec. 6.1) -> pinned frames (Sec. 6.3)
///   -> eq. 5's QP -> tau = J^T f + (tau_theta + J^T f_theta) (appendix B, eq. 12)
///   + S N N^T (-kp q - kd v) (ours: null_space_damper.hpp).
///
/// The workspace is sized once (make_lower_level_workspace); a tick allocates nothing. The planner
/// (Sec. 4, later) and the standing controller (standing_balance.hpp) call it with their targets.
#include <Eigen/Core>
#include <cmath>
#include <span>
#include <vector>

#include "gaitsynth/controllers/end_effector/force_qp.hpp"
#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/controllers/end_effector/generalized_forces.hpp"
#include "gaitsynth/controllers/end_effector/null_space_damper.hpp"
#include "gaitsynth/controllers/end_effector/null_space_knee.hpp"
#include "gaitsynth/controllers/end_effector/pd_forces.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// Sec. 6.3's contact test for pinning: "the geometry to which a stationary action frame is
/// attached is in contact with the ground". Which geometry that is the paper leaves open.
enum class pin_contact {
  /// The frame's own geometry (action_frame::contacts: the toe box for a toe frame, the heel box
  /// for the heel frame, both for the ankle frame): a stance foot rolled onto its toes unpins its
  /// heel frame, whose ideal force then competes with the upper body's (the default, as before).
  frame_geometry,
  /// The whole link (the foot: any of its frames' geometry): every stationary frame of a foot
  /// that touches anywhere is pinned, so a rolling stance foot keeps out of eq. 5's objective.
  link
};

struct lower_level_options {
  force_qp_options qp{};
  pin_contact pin_by = pin_contact::frame_geometry;  ///< Sec. 6.3's contact test
  double eps_p = 0.2;        ///< Sec. 6.3: pinned only within this distance of the target (m)
  double eps_pdot = 0.05;    ///< Sec. 6.3: and when the target moves slower than this (m/s)
  bool knee_control = true;  ///< appendix B
  /// Ours, not the paper's: a spring and damper toward the zero joint angles on the joint motions
  /// that move no frame, null(J) (null_space_damper.hpp): it holds the 5 of the Table 3 biped's 17
  /// joint DOFs that eq. 5 does not reach. As accelerations, 1/s^2 and 1/s: each null-space mode
  /// is a unit mass, here critically damped at 30 rad/s (h kd = 0.025 at 2400 Hz, 0.94 at 64 Hz,
  /// below the explicit step's limit of 2). 0 and 0 switch it off.
  double null_space_kp = 900.0;
  double null_space_kd = 60.0;
};

template <root_joint Root>
struct lower_level_workspace {
  workspace<Root> dyn;                ///< own kinematics (the rollout's workspace is read-only)
  frame_states current, desired;      ///< hatted and desired frame states
  ideal_wrenches ideal;               ///< eqs. 1-3
  Eigen::MatrixXd J;                  ///< 3K x nj, Sec. 6.1
  std::vector<unsigned char> pinned;  ///< per action frame (Sec. 6.3)
  Eigen::VectorXd tau_max;            ///< nj, the model's torque limits (Table 3)
  Eigen::VectorXd tau_theta;          ///< nj, appendix B's knee torques
  Eigen::VectorXd tau;                ///< nj, the output
  force_qp_workspace qp;
  null_space_workspace null_space;
};

template <root_joint Root>
lower_level_workspace<Root> make_lower_level_workspace(const model<Root>& m,
                                                       const end_effector_layout& L) {
  check_argument(L.num_links() >= 2 && L.num_action() >= 1,
                 "make_lower_level_workspace: the layout needs an upper body, a foot and an "
                 "action frame, has ",
                 L.num_links(), " links and ", L.num_action(), " action frames");
  const int nj = m.num_joint_dofs();
  lower_level_workspace<Root> ws;
  ws.dyn = make_workspace(m);
  ws.current = make_frame_states(L);
  ws.desired = make_frame_states(L);
  ws.ideal.action_force.assign(L.action.size(), vec3::Zero());
  ws.J.setZero(3 * L.num_pairs(), nj);
  ws.pinned.assign(L.action.size(), 0);
  ws.tau_max.resize(nj);
  for (int j = 0; j < nj; ++j) {
    const double t = m.dofs[j].torque_limit;
    check_argument(t > 0.0, "make_lower_level_workspace: DOF '", m.dofs[j].name,
                   "' needs a finite torque limit > 0 for eq. 5c, has ", t);
    ws.tau_max[j] = std::isfinite(t) ? t : 1e12;
  }
  ws.tau_theta.setZero(nj);
  ws.tau.setZero(nj);
  ws.qp = force_qp_workspace(L.num_pairs(), L.num_action(), nj);
  ws.null_space = null_space_workspace(nj, Root::nv, ws.qp.n);
  return ws;
}

/// Throws std::invalid_argument naming the link and the value unless every target is finite.
inline void check_link_targets(const std::vector<link_target>& targets) {
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const link_target& t = targets[i];
    auto finite = [](const auto& x) { return x.allFinite(); };
    check_argument(finite(t.position), "lower level: link ", i, " target position is not finite (",
                   t.position.transpose(), ")");
    check_argument(finite(t.rotation), "lower level: link ", i, " target rotation is not finite");
    check_argument(finite(t.velocity), "lower level: link ", i, " target velocity is not finite (",
                   t.velocity.transpose(), ")");
    check_argument(finite(t.angular_velocity), "lower level: link ", i,
                   " target angular velocity is not finite (", t.angular_velocity.transpose(), ")");
  }
}

/// Sec. 6.3: action frame j is pinned when a contact point of its geometry (options.pin_by: its
/// own, or any frame's on its link) touches, its position is within eps_p of its target and its
/// target moves slower than eps_pdot.
inline void pinned_frames(const end_effector_layout& L, const frame_states& current,
                          const frame_states& desired, std::span<const unsigned char> touching,
                          const lower_level_options& opt, std::span<unsigned char> pinned) {
  const auto touches = [&](int j) {
    if (opt.pin_by == pin_contact::frame_geometry) return frame_touches(L.action[j], touching);
    for (const action_frame& a : L.action)
      if (a.link == L.action[j].link && frame_touches(a, touching)) return true;
    return false;
  };
  for (int j = 0; j < L.num_action(); ++j) {
    pinned[j] = touches(j) && (desired.position[j] - current.position[j]).norm() < opt.eps_p &&
                desired.velocity[j].norm() < opt.eps_pdot;
  }
}

/// One tick. `touching` has one flag per contact point of the model (sensors::contact_active).
/// Returns ws.tau (nj): J^T f plus eq. 12's null-space knee term plus the null-space spring-damper.
/// When the QP fails (a status in ws.qp.status, never NaN) J^T f is zero.
template <root_joint Root>
const Eigen::VectorXd& lower_level_torques(
    const model<Root>& m, const end_effector_layout& L, const end_effector_gains& g,
    const lower_level_options& opt, const Eigen::Ref<const Eigen::VectorXd>& q,
    const Eigen::Ref<const Eigen::VectorXd>& v, const std::vector<link_target>& targets,
    std::span<const unsigned char> touching, lower_level_workspace<Root>& ws) {
  check_link_targets(targets);
  forward_kinematics(m, ws.dyn, q, v);
  read_frame_states(m, ws.dyn, L, ws.current);
  desired_frame_states(m, L, targets, ws.desired);
  compute_ideal_wrenches(L, g, ws.current, ws.desired, ws.ideal);
  pinned_frames(L, ws.current, ws.desired, touching, opt, ws.pinned);
  pair_jacobian(m, ws.dyn, q, L, ws.J);
  factor_pair_jacobian(ws.J, opt.qp, ws.qp);
  assemble_eq4(L, ws.current, ws.ideal, ws.qp.A, ws.qp.b);
  // W: the upper body's force and torque rows share one weight, the feet's are 1 (Sec. 6.2).
  ws.qp.w.setOnes();
  ws.qp.w.head(3).setConstant(g.upper_body_weight);
  ws.qp.w.tail(3).setConstant(g.upper_body_weight);
  solve_force_qp(ws.pinned, ws.tau_max, opt.qp, ws.qp);
  ws.tau = ws.qp.tau;
  ws.tau_theta.setZero();
  if (opt.knee_control && g.rho > 0.0)
    knee_bending_torques(m, ws.dyn, q, L, ws.current, ws.desired, g.rho, ws.tau_theta);
  solve_canceling_qp(ws.tau_theta, opt.qp, ws.qp);  // eq. 12's bracket
  ws.tau += ws.qp.tau_extra;
  const int nj = m.num_joint_dofs();
  if (opt.null_space_kp > 0.0 || opt.null_space_kd > 0.0)
    ws.tau +=
        null_space_spring_damper(ws.qp.JtU.leftCols(ws.qp.rank), crba(m, ws.dyn, q), q.tail(nj),
                                 v.tail(nj), opt.null_space_kp, opt.null_space_kd, ws.null_space);
  return ws.tau;
}

}  // namespace gaitsynth
