#pragma once
// Test helpers of the rollout (helper E2): the characters the composition test runs, standing
// poses and PD gains that hold them, and a recording controller.
#include <Eigen/Core>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace gaitsynth::test_e2 {

using gaitsynth::standing_pd;  // actuators/pd.hpp

/// Joint angles of a standing pose: upright (all zero). Both characters' standing COM lies well
/// inside their feet (models/, docs/models.md), so the upright pose is statically stable.
template <root_joint Root>
Eigen::VectorXd standing_pose(const model<Root>& m) {
  return Eigen::VectorXd::Zero(m.num_joint_dofs());
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
