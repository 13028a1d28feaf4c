#pragma once
// A small biped and a hand-made (kinematic, not simulated) walking trajectory for the viewer and
// exporter tests: legs swing sinusoidally with period `period`, the root is lowered so that the
// lowest contact point touches z = 0, and the points within 1 mm of the ground are "active" and
// carry the body weight. Each foot therefore lands once per period: heel strikes are known.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace viz_test {

using namespace gaitsynth;

inline Eigen::Matrix3d box_inertia(double m, double x, double y, double z) {
  return Eigen::Vector3d(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12,
                         m * (x * x + y * y) / 12)
      .asDiagonal();
}

constexpr double thigh_len = 0.45, shin_len = 0.45;

/// Pelvis (box) - torso (no shape: drawn as a segment) - head (sphere); thighs and shins
/// (capsules), feet (boxes) with heel and toe contact points. Sagittal DOFs about +y; the
/// floating version adds a lateral hip DOF (lhip_x) to exercise several DOFs per body.
template <root_joint Root>
model<Root> make_biped() {
  model_builder<Root> b("test_biped");
  shape pelvis_box;
  pelvis_box.type = shape::kind::box;
  pelvis_box.half_extents = {0.08, 0.14, 0.07};
  b.add_body({.name = "pelvis",
              .mass = 10,
              .inertia = box_inertia(10, 0.16, 0.28, 0.14),
              .shapes = {pelvis_box}});
  b.add_body({.name = "torso",
              .parent = "pelvis",
              .joint_offset = {0, 0, 0.08},
              .mass = 25,
              .com = {0, 0, 0.25},
              .inertia = box_inertia(25, 0.2, 0.3, 0.5),
              .dofs = {{.name = "back"}},
              .length = 0.5,
              .segment_end = {0, 0, 0.5}});
  shape head;
  head.type = shape::kind::sphere;
  head.center = {0, 0, 0.1};
  head.radius = 0.1;
  b.add_body({.name = "head",
              .parent = "torso",
              .joint_offset = {0, 0, 0.5},
              .mass = 5,
              .com = {0, 0, 0.1},
              .inertia = box_inertia(5, 0.2, 0.2, 0.2),
              .dofs = {{.name = "neck"}},
              .shapes = {head}});
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    const double y = p == "l" ? 0.1 : -0.1;
    shape thigh;
    thigh.type = shape::kind::capsule;
    thigh.p1 = {0, 0, -thigh_len};
    thigh.radius = 0.06;
    std::vector<dof_spec> hip{{.name = p + "hip"}};
    if constexpr (Root::nq == 7)
      hip.insert(hip.begin(), dof_spec{.name = p + "hip_x", .axis = {1, 0, 0}});
    b.add_body({.name = p + "thigh",
                .parent = "pelvis",
                .joint_offset = {0, y, -0.07},
                .mass = 7,
                .com = {0, 0, -0.2},
                .inertia = box_inertia(7, 0.1, 0.1, thigh_len),
                .dofs = hip,
                .shapes = {thigh},
                .length = thigh_len,
                .segment_end = {0, 0, -thigh_len}});
    shape shin = thigh;
    shin.p1 = {0, 0, -shin_len};
    shin.radius = 0.05;
    b.add_body({.name = p + "shin",
                .parent = p + "thigh",
                .joint_offset = {0, 0, -thigh_len},
                .mass = 4,
                .com = {0, 0, -0.2},
                .inertia = box_inertia(4, 0.08, 0.08, shin_len),
                .dofs = {{.name = p + "knee"}},
                .shapes = {shin},
                .length = shin_len,
                .segment_end = {0, 0, -shin_len}});
    shape foot;
    foot.type = shape::kind::box;
    foot.center = {0.05, 0, -0.03};
    foot.half_extents = {0.11, 0.05, 0.03};
    b.add_body({.name = p + "foot",
                .parent = p + "shin",
                .joint_offset = {0, 0, -shin_len},
                .mass = 1,
                .com = {0.05, 0, -0.03},
                .inertia = box_inertia(1, 0.22, 0.1, 0.06),
                .dofs = {{.name = p + "ankle"}},
                .shapes = {foot}});
    b.add_contact_point({.name = p + "heel", .body = p + "foot", .position = {-0.06, 0, -0.06}});
    b.add_contact_point({.name = p + "toe", .body = p + "foot", .position = {0.16, 0, -0.06}});
  }
  return b.build();
}

/// Joint angles of the synthetic walk at phase ph (radians of the gait cycle), by DOF name.
inline double walk_angle(const std::string& n, double ph) {
  const double s = n[0] == 'l' ? 1.0 : -1.0;  // legs in antiphase
  const double p = n[0] == 'r' ? ph + std::numbers::pi : ph;
  if (n.find("hip_x") != std::string::npos) return 0.05 * s * std::sin(p);
  if (n.find("hip") != std::string::npos) return -0.45 * std::sin(p);
  if (n.find("knee") != std::string::npos) return 0.7 * std::max(0.0, std::sin(p + 0.6));
  if (n.find("ankle") != std::string::npos) return -0.15 * std::sin(p);
  if (n == "back") return 0.05 * std::sin(2 * ph);
  return 0.0;
}

/// The synthetic walk (see the file comment): frames every dt over [0, duration].
template <root_joint Root>
trajectory make_walk(const model<Root>& m, double duration = 2.5, double dt = 0.01,
                     double period = 1.0, double speed = 0.9) {
  trajectory traj;
  traj.objective_term_names = {"distance", "effort"};
  const int n = static_cast<int>(std::lround(duration / dt)) + 1;
  const double g = m.total_mass() * 9.81;
  double effort = 0;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Quaterniond> r;
  for (int k = 0; k < n; ++k) {
    trajectory_frame fr;
    fr.t = k * dt;
    const double ph = 2 * std::numbers::pi * fr.t / period;
    Eigen::VectorXd q = neutral_configuration(m);
    q[0] = speed * fr.t;
    for (int j = 0; j < m.num_joint_dofs(); ++j) q[Root::nq + j] = walk_angle(m.dofs[j].name, ph);
    if constexpr (Root::nq == 3) q[2] = 0.04 * std::sin(2 * ph);
    if constexpr (Root::nq == 7) {
      const Eigen::Quaterniond yaw(
          Eigen::AngleAxisd(0.03 * std::sin(ph), Eigen::Vector3d::UnitZ()));
      q.segment<4>(3) << yaw.w(), yaw.x(), yaw.y(), yaw.z();
    }
    // Lower the root until the lowest contact point is on the ground.
    compute_body_poses(m, q, p, r);
    double zmin = 1e9;
    for (const auto& c : m.contact_points)
      zmin = std::min(zmin, (p[c.body] + r[c.body] * c.position).z());
    q[Root::nq == 3 ? 1 : 2] -= zmin;
    fr.q = q;
    fr.v = Eigen::VectorXd::Zero(m.nv());
    fr.v[0] = speed;
    fr.tau = Eigen::VectorXd::Zero(m.nv());
    for (int j = 0; j < m.num_joint_dofs(); ++j) fr.tau[Root::nv + j] = 20 * std::cos(ph + j);
    compute_body_poses(m, q, p, r);
    const int nc = static_cast<int>(m.contact_points.size());
    fr.contact_position.resize(nc);
    fr.contact_force.assign(nc, Eigen::Vector3d::Zero());
    fr.contact_active.assign(nc, 0);
    int active = 0;
    for (int c = 0; c < nc; ++c) {
      const auto& cp = m.contact_points[c];
      fr.contact_position[c] = p[cp.body] + r[cp.body] * cp.position;
      if (fr.contact_position[c].z() < 1e-3) {
        fr.contact_active[c] = 1;
        ++active;
      }
    }
    for (int c = 0; c < nc; ++c)
      if (fr.contact_active[c])
        fr.contact_force[c] = Eigen::Vector3d(-0.1 * g / active, 0, g / active);
    if (fr.t >= 1.0 && fr.t < 1.2) fr.pushes.emplace_back(0, Eigen::Vector3d(0, 150, 0));
    effort += fr.tau.squaredNorm() * dt;
    fr.objective_terms = {q[0], effort};
    fr.controller_state = static_cast<int>(std::floor(2 * fr.t / period)) % 4;
    traj.frames.push_back(std::move(fr));
  }
  fill_missing_kinematics(m, traj);
  return traj;
}

}  // namespace viz_test
