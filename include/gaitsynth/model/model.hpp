#pragma once
/// \file model.hpp
/// The immutable kinematic-tree model (Pinocchio's "Model"): topology, inertial parameters, joint
/// DOFs with limits, contact points, visual shapes and the left/right mirror map. Built and validated
/// by model_builder (model_builder.hpp); never modified by an algorithm, so threads share one model
/// and each owns a workspace (dynamics/workspace.hpp).
///
/// Layout of the generalized coordinates (docs/dynamics.md):
///   q = [q_root (Root::nq), q_joints (num_joint_dofs)],  v = [v_root (Root::nv), v_joints].
/// Joint DOF j has q index Root::nq + j and v index Root::nv + j. Bodies are stored in topological
/// order (parent index < child index); body 0 is the root body, attached to the world by Root.
///
/// A body may carry several revolute DOFs (an anatomical hip has lhip_x, lhip_y, lhip_z). They are
/// composed intrinsically in their listed order, all about the body's origin:
///   R_parent_body = R(a_1, q_1) * R(a_2, q_2) * ... with each axis a_k constant in the body frame.
/// This is exactly MuJoCo's rule for several hinge joints in one <body>.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/model/root.hpp"

namespace gaitsynth {

/// How soft joint-position limits push back (both are passive torques added to the actuator's).
enum class limit_model {
  none,           ///< no limit torque (limits still validated and used by controllers)
  spring_damper,  ///< tau = -k (q - bound) - d qdot when past the bound (Wang 2009 / ODE style)
  exponential     ///< tau = -k (exp(s (q - bound)) - 1) - d qdot past the bound (Sharon 2005)
};

struct joint_limit {
  double lower = -1e9;       ///< rad
  double upper = 1e9;        ///< rad
  double stiffness = 0.0;    ///< N m / rad (spring_damper) or N m (exponential amplitude)
  double damping = 0.0;      ///< N m s / rad
  double sharpness = 20.0;   ///< 1/rad, exponent scale s of the exponential spring
  limit_model model = limit_model::none;
};

/// One revolute degree of freedom.
struct joint_dof {
  std::string name;               ///< e.g. "lhip_x"
  int body = -1;                  ///< body this DOF moves (relative to its parent)
  Eigen::Vector3d axis{0, 1, 0};  ///< unit axis in the body frame
  joint_limit limit;              ///< position limit (rad) and its soft model
  double torque_limit = 1e9;      ///< |tau| <= torque_limit, N m
};

/// Visual / collision-free geometry of a body (viewer, MJCF export). Not used by the dynamics.
struct shape {
  enum class kind { box, capsule, sphere } type = kind::box;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< body frame, m
  Eigen::Vector3d half_extents{0.05, 0.05, 0.05};    ///< box half sizes, m
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero();      ///< capsule end points (body frame), m
  Eigen::Vector3d p1 = Eigen::Vector3d::Zero();
  double radius = 0.03;                              ///< capsule / sphere radius, m
};

struct body {
  std::string name;
  int parent = -1;                                    ///< -1 for the root body
  Eigen::Vector3d joint_offset = Eigen::Vector3d::Zero();  ///< body origin in the parent frame at q = 0, m
  double mass = 0.0;                                  ///< kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();      ///< centre of mass in the body frame, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the COM, body-frame axes, kg m^2
  int first_dof = 0;                                  ///< index of its first joint DOF
  int num_dofs = 0;                                   ///< 0 for the root body
  std::vector<shape> shapes;
  double length = 0.0;  ///< nominal segment length, m (mass-distance metrics, docs)
  Eigen::Vector3d segment_end = Eigen::Vector3d::Zero();  ///< distal end point of the segment (body frame)
};

/// A point on a body that can touch the terrain (penalty contact).
struct contact_point {
  enum class kind { sole, toe, toe_top, other };
  std::string name;
  int body = -1;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< body frame, m
  kind role = kind::sole;
};

template <root_joint Root>
struct model {
  using root_type = Root;
  std::string name;
  std::vector<body> bodies;
  std::vector<joint_dof> dofs;  ///< internal (non-root) DOFs, in q/v order
  std::vector<contact_point> contact_points;
  /// mirror_dof[j]: the joint DOF that is j's left/right mirror (j itself for central DOFs);
  /// mirror_sign[j]: +1 or -1, the sign relating the two (lateral rotations flip sign).
  std::vector<int> mirror_dof;
  std::vector<double> mirror_sign;
  std::vector<int> mirror_body;
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};  ///< m/s^2

  int num_bodies() const { return static_cast<int>(bodies.size()); }
  int num_joint_dofs() const { return static_cast<int>(dofs.size()); }
  int nq() const { return Root::nq + num_joint_dofs(); }
  int nv() const { return Root::nv + num_joint_dofs(); }
  static constexpr int nq_root = Root::nq;
  static constexpr int nv_root = Root::nv;

  double total_mass() const {
    double m = 0;
    for (const auto& b : bodies) m += b.mass;
    return m;
  }
  /// Index of the body called `name`, or -1.
  int find_body(std::string_view n) const {
    for (int i = 0; i < num_bodies(); ++i)
      if (bodies[i].name == n) return i;
    return -1;
  }
  /// Index of the joint DOF called `name` (into `dofs`), or -1.
  int find_dof(std::string_view n) const {
    for (int i = 0; i < num_joint_dofs(); ++i)
      if (dofs[i].name == n) return i;
    return -1;
  }
  /// Like find_body / find_dof but throws std::invalid_argument naming the missing name.
  int body_index(std::string_view n) const;
  int dof_index(std::string_view n) const;
};

using planar_model = model<planar_root>;
using floating_model = model<floating_root>;
using fixed_model = model<fixed_root>;

}  // namespace gaitsynth

#include "gaitsynth/error.hpp"

namespace gaitsynth {
template <root_joint Root>
int model<Root>::body_index(std::string_view n) const {
  const int i = find_body(n);
  check_argument(i >= 0, "model '", name, "': no body named '", n, "'");
  return i;
}
template <root_joint Root>
int model<Root>::dof_index(std::string_view n) const {
  const int i = find_dof(n);
  check_argument(i >= 0, "model '", name, "': no joint DOF named '", n, "'");
  return i;
}
}  // namespace gaitsynth
