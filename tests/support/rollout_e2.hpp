#pragma once
// Test helpers of the rollout (helper E2): the characters the composition test runs, standing
// poses and PD gains that hold them, and a recording controller.
#include <Eigen/Core>
#include <string>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace gaitsynth::test_e2 {

/// Hip, knee, ankle and back servos stiff enough to hold a standing pose (ankle stiffness above
/// the m g h = 600 N m/rad that a toppling body needs), arms and neck soft, toes 20 N m/rad
/// (Wang et al. 2009 Table 2), kd = 0.1 kp, then capped for the timestep (pd_actuator::capped).
template <root_joint Root>
pd_actuator standing_pd(const model<Root>& m, double dt, double scale = 1.0) {
  Eigen::VectorXd kp(m.num_joint_dofs());
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const std::string& n = m.dofs[j].name;
    auto has = [&](const char* s) { return n.find(s) != std::string::npos; };
    kp[j] = has("toe")                                                   ? 20.0
            : (has("hip") || has("knee") || has("ankle") || has("back")) ? 1000.0
                                                                         : 100.0;
  }
  kp *= scale;
  return pd_actuator::capped(m, kp, 0.1 * kp, dt);
}

/// Joint angles of a standing pose. The 7-link human's ankle sits at the heel end of its foot
/// (sharon2005.hpp), so upright its COM is 7 mm in front of the heel and it topples backwards;
/// dorsiflexing the ankles by 0.1 rad leans it forward over the middle of the foot.
template <root_joint Root>
Eigen::VectorXd standing_pose(const model<Root>& m) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(m.num_joint_dofs());
  if (m.name.rfind("sharon2005_human7", 0) == 0) {
    p[m.dof_index("lankle")] = -0.1;
    p[m.dof_index("rankle")] = -0.1;
  }
  return p;
}

/// Characters of the composition test: each a tag with build().
struct planar_human7 {
  using root = planar_root;
  static planar_model build() { return sharon2005_human7(); }
};
struct humanoid3d {
  using root = floating_root;
  static floating_model build() { return wang2009_humanoid(); }
};

}  // namespace gaitsynth::test_e2
