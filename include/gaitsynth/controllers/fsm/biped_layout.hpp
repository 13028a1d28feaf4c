#pragma once
/// \file controllers/fsm/biped_layout.hpp
/// Where a SIMBICON-style controller finds its joints: the DOF and body indices of a 30-DOF
/// humanoid (models/wang2009.hpp, models/wang2012.hpp), looked up by name once at construction, so
/// the step loop indexes arrays. Side 0 is the left, 1 the right. Also where the feet are.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

struct biped_leg {
  int hip_x = -1, hip_y = -1, hip_z = -1, knee = -1, ankle_x = -1, ankle_y = -1,
      toe = -1;                                     ///< DOFs
  int thigh = -1, shin = -1, foot = -1, toes = -1;  ///< bodies
};

struct biped_arm {
  int shoulder_x = -1, shoulder_y = -1, shoulder_z = -1, elbow_y = -1, elbow_z = -1;  ///< DOFs
};

struct biped_layout {
  std::array<biped_leg, 2> leg;  ///< [left, right]
  std::array<biped_arm, 2> arm;  ///< [left, right]
  int back_x = -1, back_y = -1, back_z = -1, neck_x = -1, neck_y = -1, neck_z = -1;  ///< DOFs
  int pelvis = -1, torso = -1, head = -1;                                            ///< bodies

  /// The layout of m. \throws std::invalid_argument naming the first missing DOF or body.
  template <root_joint Root>
  static biped_layout of(const model<Root>& m) {
    biped_layout L;
    for (int side = 0; side < 2; ++side) {
      const std::string s = side == 0 ? "l" : "r";
      biped_leg& g = L.leg[side];
      g.hip_x = m.dof_index(s + "hip_x");
      g.hip_y = m.dof_index(s + "hip_y");
      g.hip_z = m.dof_index(s + "hip_z");
      g.knee = m.dof_index(s + "knee");
      g.ankle_x = m.dof_index(s + "ankle_x");
      g.ankle_y = m.dof_index(s + "ankle_y");
      g.toe = m.dof_index(s + "toe");
      g.thigh = m.body_index(s + "thigh");
      g.shin = m.body_index(s + "shin");
      g.foot = m.body_index(s + "foot");
      g.toes = m.body_index(s + "toes");
      biped_arm& a = L.arm[side];
      a.shoulder_x = m.dof_index(s + "shoulder_x");
      a.shoulder_y = m.dof_index(s + "shoulder_y");
      a.shoulder_z = m.dof_index(s + "shoulder_z");
      a.elbow_y = m.dof_index(s + "elbow_y");
      a.elbow_z = m.dof_index(s + "elbow_z");
    }
    L.back_x = m.dof_index("back_x");
    L.back_y = m.dof_index("back_y");
    L.back_z = m.dof_index("back_z");
    L.neck_x = m.dof_index("neck_x");
    L.neck_y = m.dof_index("neck_y");
    L.neck_z = m.dof_index("neck_z");
    L.pelvis = m.body_index("pelvis");
    L.torso = m.body_index("torso");
    L.head = m.body_index("head");
    return L;
  }
};

/// Height (m) of the lowest sole or toe contact point of m in configuration q: subtracting it from
/// the root height stands the character on z = 0. Set-up helper (allocates a workspace).
template <root_joint Root>
double lowest_foot_point(const model<Root>& m, const Eigen::VectorXd& q) {
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, q);
  double lowest = std::numeric_limits<double>::infinity();
  for (const contact_point& cp : m.contact_points)
    if (cp.role == contact_point::kind::sole || cp.role == contact_point::kind::toe)
      lowest = std::min(lowest, point_position(m, ws, cp.body, cp.position).z());
  return lowest;
}

}  // namespace gaitsynth
