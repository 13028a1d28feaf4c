#pragma once
// Test support for the 3D biped controllers (controllers/fsm/): sensors built by hand from a state,
// and the left/right mirror image of a state, for symmetry tests.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "gaitsynth/gaitsynth.hpp"

namespace gaitsynth::testing {

/// Sensors of (q, v) for m, with kinematics computed into ws and contact counts from `counts`.
struct sensed {
  workspace<floating_root> ws;
  sim_state s;
  std::vector<int> counts;
  sensors<floating_root> sen;
  sensed(const floating_model& m, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
         std::vector<int> c)
      : ws(make_workspace(m)), counts(std::move(c)) {
    s.q = q;
    s.v = v;
    forward_kinematics(m, ws, s.q, s.v);
    sen.model_ptr = &m;
    sen.dt = 1.0 / 2400.0;
    sen.q_ptr = &s.q;
    sen.v_ptr = &s.v;
    sen.body_rotation = ws.body_rotation;
    sen.body_position = ws.body_position;
    sen.body_angular_velocity = ws.body_angular_velocity;
    sen.body_linear_velocity = ws.body_linear_velocity;
    sen.contact_count = counts;
    sen.com = center_of_mass(m, ws);
    sen.com_velocity = com_velocity(m, ws);
  }
};

/// The mirror image of (q, v) across the sagittal plane (x-z).
inline std::pair<Eigen::VectorXd, Eigen::VectorXd> mirrored(const floating_model& m,
                                                            const Eigen::VectorXd& q,
                                                            const Eigen::VectorXd& v) {
  Eigen::VectorXd qm = q, vm = v;
  qm[1] = -q[1];
  qm[4] = -q[4];  // quaternion (w, x, y, z): x and z flip
  qm[6] = -q[6];
  vm[1] = -v[1];
  vm[3] = -v[3];  // angular velocity (pelvis frame): x and z flip
  vm[5] = -v[5];
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    qm[7 + m.mirror_dof[j]] = m.mirror_sign[j] * q[7 + j];
    vm[6 + m.mirror_dof[j]] = m.mirror_sign[j] * v[6 + j];
  }
  return {qm, vm};
}

}  // namespace gaitsynth::testing
