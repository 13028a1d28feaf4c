#pragma once
/// \file scene.hpp
/// What every viewer and exporter in viz/ and io/ needs from a recorded trajectory: body poses per
/// frame (recorded, or recomputed from q when a hand-made trajectory left them out), the world
/// geometry of the model's shapes, terrain heights between the recorded samples, and which side
/// (left / right / centre) a body is on, for colours. docs/viewer.md.
///
/// `fill_missing_kinematics(model, traj)` completes a trajectory built by hand (tests, docs, data
/// converted from elsewhere): names, body poses, COM and contact-point positions are filled where
/// they are empty, from q, with the kinematics stated in model.hpp (a body's DOFs composed
/// intrinsically in order at the body origin, body frames aligned with their parent at q = 0).
/// Recorded trajectories (rollout/recorder.hpp) already hold all of it; nothing is overwritten.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/recorder.hpp"  // q_coordinate_names, v_coordinate_names
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// World poses of every body for the configuration q (size nq), by the rule of model.hpp:
/// R_i = R_parent * R(a_1, q_1) * ... (the body's DOFs in order), p_i = p_parent + R_parent *
/// offset. The root pose comes from the root joint (planar: (x, 0, z) and pitch about +y; floating:
/// position and unit quaternion w, x, y, z; fixed: the root body's joint_offset, no rotation).
template <root_joint Root>
void compute_body_poses(const model<Root>& m, const Eigen::VectorXd& q,
                        std::vector<Eigen::Vector3d>& position,
                        std::vector<Eigen::Quaterniond>& orientation) {
  check_size(q.size(), m.nq(), "compute_body_poses: q");
  const int nb = m.num_bodies();
  position.assign(nb, Eigen::Vector3d::Zero());
  orientation.assign(nb, Eigen::Quaterniond::Identity());
  if (nb == 0) return;
  if constexpr (Root::nq == 3) {
    position[0] = m.bodies[0].joint_offset + Eigen::Vector3d(q[0], 0.0, q[1]);
    orientation[0] = Eigen::Quaterniond(Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitY()));
  } else if constexpr (Root::nq == 7) {
    position[0] = m.bodies[0].joint_offset + q.head<3>();
    Eigen::Quaterniond r(q[3], q[4], q[5], q[6]);
    check_argument(r.norm() > 1e-12, "compute_body_poses: root quaternion is zero");
    orientation[0] = r.normalized();
  } else {
    position[0] = m.bodies[0].joint_offset;
  }
  for (int i = 1; i < nb; ++i) {
    const body& b = m.bodies[i];
    const Eigen::Quaterniond& rp = orientation[b.parent];
    position[i] = position[b.parent] + rp * b.joint_offset;
    Eigen::Quaterniond r = rp;
    for (int k = 0; k < b.num_dofs; ++k) {
      const int j = b.first_dof + k;
      r = r * Eigen::Quaterniond(Eigen::AngleAxisd(q[Root::nq + j], m.dofs[j].axis));
    }
    orientation[i] = r.normalized();
  }
}

/// Completes a hand-made trajectory from q (see the file comment). Throws std::invalid_argument
/// naming the frame when a frame's q has the wrong size or names disagree with the model.
template <root_joint Root>
void fill_missing_kinematics(const model<Root>& m, trajectory& traj) {
  const int nb = m.num_bodies();
  const int nc = static_cast<int>(m.contact_points.size());
  if (traj.model_name.empty()) traj.model_name = m.name;
  if constexpr (Root::nq == 3) traj.planar = true;
  if (traj.q_names.empty()) traj.q_names = q_coordinate_names(m);
  if (traj.v_names.empty()) traj.v_names = v_coordinate_names(m);
  if (traj.body_names.empty()) {
    for (const auto& b : m.bodies) {
      traj.body_names.push_back(b.name);
      traj.body_parents.push_back(b.parent);
    }
  }
  if (traj.contact_names.empty()) {
    for (const auto& c : m.contact_points) {
      traj.contact_names.push_back(c.name);
      traj.contact_bodies.push_back(c.body);
    }
  }
  check_size(static_cast<std::ptrdiff_t>(traj.q_names.size()), m.nq(),
             "fill_missing_kinematics: trajectory.q_names");
  check_size(static_cast<std::ptrdiff_t>(traj.body_names.size()), nb,
             "fill_missing_kinematics: trajectory.body_names");
  check_size(static_cast<std::ptrdiff_t>(traj.contact_names.size()), nc,
             "fill_missing_kinematics: trajectory.contact_names");
  const double mass = m.total_mass();
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Quaterniond> r;
  for (std::size_t f = 0; f < traj.frames.size(); ++f) {
    trajectory_frame& fr = traj.frames[f];
    check_argument(fr.q.size() == m.nq(), "fill_missing_kinematics: frame ", f, ": q has size ",
                   fr.q.size(), ", model '", m.name, "' has nq = ", m.nq());
    compute_body_poses(m, fr.q, p, r);
    const bool had_poses = static_cast<int>(fr.body_position.size()) == nb &&
                           static_cast<int>(fr.body_orientation.size()) == nb;
    if (!had_poses) {
      fr.body_position = p;
      fr.body_orientation = r;
    }
    if (fr.v.size() == 0) fr.v = Eigen::VectorXd::Zero(m.nv());
    if (fr.tau.size() == 0) fr.tau = Eigen::VectorXd::Zero(m.nv());
    if (fr.com.isZero(0.0) && mass > 0) {  // a recorded COM is never exactly 0
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int i = 0; i < nb; ++i)
        c += m.bodies[i].mass * (fr.body_position[i] + fr.body_orientation[i] * m.bodies[i].com);
      fr.com = c / mass;
    }
    if (static_cast<int>(fr.contact_position.size()) != nc) {
      fr.contact_position.resize(nc);
      for (int k = 0; k < nc; ++k) {
        const contact_point& cp = m.contact_points[k];
        fr.contact_position[k] =
            fr.body_position[cp.body] + fr.body_orientation[cp.body] * cp.position;
      }
    }
    if (static_cast<int>(fr.contact_force.size()) != nc)
      fr.contact_force.assign(nc, Eigen::Vector3d::Zero());
    if (static_cast<int>(fr.contact_active.size()) != nc) {
      fr.contact_active.assign(nc, 0);
      for (int k = 0; k < nc; ++k) fr.contact_active[k] = fr.contact_force[k].norm() > 0 ? 1 : 0;
    }
  }
}

/// Which side of the character a body is on, for colours (left drawn behind in side views).
enum class body_side { left, centre, right };

/// A body that mirrors to another body is left or right by its name ("l..."/"left..." is left,
/// "r..."/"right..." is right); a body that mirrors to itself is central.
template <root_joint Root>
body_side side_of_body(const model<Root>& m, int i) {
  const bool paired =
      static_cast<int>(m.mirror_body.size()) == m.num_bodies() && m.mirror_body[i] != i;
  if (!paired) return body_side::centre;
  const std::string& n = m.bodies[i].name;
  if (!n.empty() && (n[0] == 'r' || n[0] == 'R')) return body_side::right;
  return body_side::left;
}

/// Terrain height at (x, y) from the recorded samples: bilinear between grid points, clamped to the
/// grid's edge outside it; 0 for flat ground (nx == 0 or ny == 0).
inline double terrain_height(const terrain_samples& ts, double x, double y) {
  if (ts.nx <= 0 || ts.ny <= 0 ||
      ts.height.size() < static_cast<std::size_t>(ts.nx) * static_cast<std::size_t>(ts.ny))
    return 0.0;
  auto cell = [](double u, int n, double& w) {
    if (n == 1 || !(u > 0)) {
      w = 0;
      return 0;
    }
    if (u >= n - 1) {
      w = 1;
      return n - 2;
    }
    const int i = static_cast<int>(std::floor(u));
    w = u - i;
    return i;
  };
  double wx = 0, wy = 0;
  const int ix = cell((x - ts.x0) / ts.dx, ts.nx, wx);
  const int iy = cell((y - ts.y0) / ts.dy, ts.ny, wy);
  auto h = [&](int i, int j) {
    i = std::clamp(i, 0, ts.nx - 1);
    j = std::clamp(j, 0, ts.ny - 1);
    return ts.height[static_cast<std::size_t>(j) * ts.nx + i];
  };
  return (1 - wy) * ((1 - wx) * h(ix, iy) + wx * h(ix + 1, iy)) +
         wy * ((1 - wx) * h(ix, iy + 1) + wx * h(ix + 1, iy + 1));
}

namespace viz_detail {

/// Body poses of frame f: the recorded ones, or recomputed from q when the frame has none.
template <root_joint Root>
void frame_body_poses(const model<Root>& m, const trajectory_frame& fr,
                      std::vector<Eigen::Vector3d>& p, std::vector<Eigen::Quaterniond>& r) {
  const int nb = m.num_bodies();
  if (static_cast<int>(fr.body_position.size()) == nb &&
      static_cast<int>(fr.body_orientation.size()) == nb) {
    p = fr.body_position;
    r = fr.body_orientation;
    for (auto& x : r) x.normalize();
  } else {
    compute_body_poses(m, fr.q, p, r);
  }
}

/// Index of the frame whose time is closest to t (frames sorted by time); -1 when empty.
inline int nearest_frame(const trajectory& traj, double t) {
  const auto& fr = traj.frames;
  if (fr.empty()) return -1;
  auto it = std::lower_bound(fr.begin(), fr.end(), t,
                             [](const trajectory_frame& a, double tt) { return a.t < tt; });
  if (it == fr.end()) return static_cast<int>(fr.size()) - 1;
  int i = static_cast<int>(it - fr.begin());
  if (i > 0 && std::abs(fr[i - 1].t - t) <= std::abs(fr[i].t - t)) --i;
  return i;
}

/// Checks that a trajectory is usable by a viewer for model m: frames in non-decreasing time, each
/// q of size nq with finite values. Throws std::invalid_argument naming the first bad frame.
template <root_joint Root>
void check_trajectory(const model<Root>& m, const trajectory& traj, const char* who) {
  for (std::size_t f = 0; f < traj.frames.size(); ++f) {
    const trajectory_frame& fr = traj.frames[f];
    check_argument(std::isfinite(fr.t), who, ": frame ", f, ": time is not finite");
    check_argument(f == 0 || fr.t >= traj.frames[f - 1].t, who, ": frame ", f, ": time ", fr.t,
                   " s is before the previous frame's ", traj.frames[f - 1].t, " s");
    check_argument(fr.q.size() == m.nq(), who, ": frame ", f, ": q has size ", fr.q.size(),
                   ", model '", m.name, "' has nq = ", m.nq());
    check_argument(fr.q.allFinite(), who, ": frame ", f, " (t = ", fr.t, " s): q is not finite");
  }
}

/// Contact point indices on body `b` and its descendants (a foot and its toes).
inline std::vector<int> contacts_on_subtree(const trajectory& traj, int b) {
  std::vector<int> out;
  for (std::size_t k = 0; k < traj.contact_bodies.size(); ++k) {
    int x = traj.contact_bodies[k];
    while (x >= 0 && x != b)
      x = (static_cast<std::size_t>(x) < traj.body_parents.size()) ? traj.body_parents[x] : -1;
    if (x == b) out.push_back(static_cast<int>(k));
  }
  return out;
}

/// Points of a body's drawing in its frame (bounding boxes): shape corners / ends / centres, or the
/// origin, segment_end and the children's origins for a body without shapes.
template <root_joint Root>
void body_points(const model<Root>& m, int i, std::vector<Eigen::Vector3d>& local) {
  local.clear();
  const body& b = m.bodies[i];
  for (const shape& s : b.shapes) {
    if (s.type == shape::kind::box) {
      for (int c = 0; c < 8; ++c)
        local.push_back(s.center +
                        Eigen::Vector3d((c & 1) ? s.half_extents.x() : -s.half_extents.x(),
                                        (c & 2) ? s.half_extents.y() : -s.half_extents.y(),
                                        (c & 4) ? s.half_extents.z() : -s.half_extents.z()));
    } else if (s.type == shape::kind::capsule) {
      local.push_back(s.p0);
      local.push_back(s.p1);
    } else {
      local.push_back(s.center);
    }
  }
  if (b.shapes.empty()) {
    local.push_back(Eigen::Vector3d::Zero());
    if (!b.segment_end.isZero()) local.push_back(b.segment_end);
    for (int c = i + 1; c < m.num_bodies(); ++c)
      if (m.bodies[c].parent == i) local.push_back(m.bodies[c].joint_offset);
  }
}

}  // namespace viz_detail
}  // namespace gaitsynth
