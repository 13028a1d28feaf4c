#pragma once
/// \file controllers/end_effector/null_space_knee.hpp
/// Appendix B of Wu & Popovic 2010: null-space knee control. A fully extended knee is a singular
/// configuration (J loses rank): a force pulling the ankle toward the hip then makes no knee
/// torque. When the current distance d^ between the ankle and the upper body, measured along the
/// direction from the ankle to the hip joint, exceeds the planned distance d, the knee gets the
/// bending torque
///
///   tau_theta,knee = rho cos(theta_knee) {d^ - d}+            (theta_knee = 0: fully extended)
///
/// (every other entry of tau_theta is 0), and eq. 12 adds tau_theta + J^T f_theta with f_theta from
/// the canceling QP (force_qp.hpp, solve_canceling_qp), so that the end-effector dynamics are left
/// as the frames' forces set them [Khatib 1987]. Planned distance: the desired upper-body and
/// ankle frame positions, projected on the same (current) ankle-to-hip direction.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "gaitsynth/controllers/end_effector/frames.hpp"

namespace gaitsynth {

/// tau_theta (nj) of appendix B for every leg of the layout. `ws` holds the poses of q.
template <root_joint Root>
void knee_bending_torques(const model<Root>& m, const workspace<Root>& ws,
                          const Eigen::Ref<const Eigen::VectorXd>& q, const end_effector_layout& L,
                          const frame_states& current, const frame_states& desired, double rho,
                          Eigen::Ref<Eigen::VectorXd> tau_theta) {
  (void)m;
  tau_theta.setZero();
  for (const knee_leg& leg : L.legs) {
    const vec3 ankle = current.position[leg.ankle_frame];
    const vec3 axis = ws.body_position[leg.hip_body] - ankle;
    const double len = axis.norm();
    if (!(len > 0.0)) continue;
    const vec3 u = axis / len;
    const double d_hat = (current.reaction_position - ankle).dot(u);
    const double d = (desired.reaction_position - desired.position[leg.ankle_frame]).dot(u);
    const double theta = q[Root::nq + leg.knee_dof];
    tau_theta[leg.knee_dof] = leg.bend_sign * rho * std::cos(theta) * std::max(d_hat - d, 0.0);
  }
}

}  // namespace gaitsynth
