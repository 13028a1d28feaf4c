#pragma once
/// \file bvh.hpp
/// Biovision Hierarchy (BVH) export of a recorded trajectory, for Blender and other animation
/// tools.
///
/// Hierarchy: one BVH joint per body, named like the body, nested as the model's tree (children in
/// body index order); the root body is the ROOT. OFFSET of a joint = the body's joint_offset (its
/// origin in the parent frame at q = 0, where gaitsynth body frames are aligned with their parent,
/// so BVH's rest pose is the model's q = 0 pose). Leaves get an "End Site" at the body's
/// segment_end (or the farthest shape point, or a zero offset).
///
/// Channels: ROOT "Xposition Yposition Zposition Zrotation Xrotation Yrotation", every other
/// joint "Zrotation Xrotation Yrotation". Rotations are the body-relative rotations
/// R_local = R_parent^T R_body (root: R_world_root) as ZXY Euler angles in degrees, meaning
/// R = Rz(z) Rx(x) Ry(y), the usual BVH reading (Blender's importer uses it). Angles are made
/// continuous from frame to frame (the equivalent solution closest to the previous frame, no 360
/// degree jumps), so curves in an editor do not flip.
///
/// Units and axes (bvh_options): lengths are multiplied by `scale`, 100 by default, so the file is
/// in centimetres as most BVH tools expect (use 1 to keep metres; Blender's importer has its own
/// scale option). With `y_up` (default) gaitsynth's z-up world is turned into the Y-up convention
/// of BVH: (x, y, z) -> (x, z, -y), a proper rotation, so the walk along +x stays along +X and up
/// is +Y; rotations are conjugated by the same change of axes. With y_up = false the axes are kept.
///
/// Frames: BVH needs a fixed frame time. `frame_time` 0 uses the median spacing of the recorded
/// frames; frames are then taken as the recorded frame nearest to t0 + k * frame_time (an exact
/// copy when the recording is uniform, no interpolation).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace gaitsynth {

struct bvh_options {
  double scale = 100.0;   ///< length multiplier: 100 writes centimetres, 1 metres
  bool y_up = true;       ///< convert z-up to BVH's Y-up: (x, y, z) -> (x, z, -y)
  double frame_time = 0;  ///< s; 0: median spacing of the recorded frames
  int precision = 6;      ///< significant digits of the motion values
};

/// ZXY Euler angles (radians) of a rotation matrix: R = Rz(z) Rx(x) Ry(y). Returns (z, x, y) with
/// x in [-pi/2, pi/2]; at gimbal lock (|x| = pi/2) y is set to 0.
inline Eigen::Vector3d euler_zxy(const Eigen::Matrix3d& R) {
  const double sx = std::clamp(R(2, 1), -1.0, 1.0);
  const double x = std::asin(sx);
  double z, y;
  if (std::abs(sx) < 1.0 - 1e-12) {
    z = std::atan2(-R(0, 1), R(1, 1));
    y = std::atan2(-R(2, 0), R(2, 2));
  } else {
    y = 0.0;
    z = std::atan2(R(1, 0), R(0, 0));
  }
  return {z, x, y};
}

/// The rotation R = Rz(a[0]) Rx(a[1]) Ry(a[2]) (inverse of euler_zxy).
inline Eigen::Matrix3d rotation_zxy(const Eigen::Vector3d& a) {
  return (Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

namespace detail::bvh {

/// The ZXY triple representing R that is closest to `prev`: of the two equivalent solutions
/// (z, x, y) and (z + pi, pi - x, y + pi), each shifted by multiples of 2 pi.
inline Eigen::Vector3d continuous_zxy(const Eigen::Matrix3d& R, const Eigen::Vector3d* prev) {
  Eigen::Vector3d a = euler_zxy(R);
  if (!prev) return a;
  constexpr double pi = std::numbers::pi;
  auto near = [&](Eigen::Vector3d c) {
    for (int k = 0; k < 3; ++k) c[k] -= 2 * pi * std::round((c[k] - (*prev)[k]) / (2 * pi));
    return c;
  };
  const Eigen::Vector3d c1 = near(a);
  const Eigen::Vector3d c2 = near(Eigen::Vector3d(a[0] + pi, pi - a[1], a[2] + pi));
  return (c1 - *prev).squaredNorm() <= (c2 - *prev).squaredNorm() ? c1 : c2;
}

inline std::string num(double x, int precision) {
  if (std::abs(x) < 1e-12) return "0";
  std::ostringstream s;
  s.precision(precision);
  s << x;
  return s.str();
}

}  // namespace detail::bvh

/// Writes the BVH file (see the file comment). Throws std::invalid_argument when the trajectory
/// does not fit the model, has no frames, or the options are invalid.
template <root_joint Root>
void write_bvh(const model<Root>& m, const trajectory& traj, std::ostream& os,
               const bvh_options& opt = {}) {
  using detail::bvh::num;
  viz_detail::check_trajectory(m, traj, "write_bvh");
  check_argument(!traj.frames.empty(), "write_bvh: the trajectory has no frames");
  check_positive(opt.scale, "write_bvh: scale");
  check_argument(std::isfinite(opt.frame_time) && opt.frame_time >= 0,
                 "write_bvh: frame_time must be finite and >= 0, got ", opt.frame_time);
  check_argument(opt.precision >= 3 && opt.precision <= 17,
                 "write_bvh: precision must be in [3, 17], got ", opt.precision);
  for (const auto& b : m.bodies)
    check_argument(!b.name.empty() && b.name.find_first_of(" \t\r\n{}") == std::string::npos,
                   "write_bvh: body name '", b.name,
                   "' cannot be a BVH joint name (spaces or braces)");
  const int nb = m.num_bodies();
  // Change of axes C: world -> BVH.
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  if (opt.y_up) C << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  const auto& fr = traj.frames;
  double ft = opt.frame_time;
  if (ft == 0) {
    std::vector<double> dts;
    for (std::size_t i = 1; i < fr.size(); ++i)
      if (fr[i].t > fr[i - 1].t) dts.push_back(fr[i].t - fr[i - 1].t);
    if (dts.empty()) {
      ft = 1.0 / 30.0;
    } else {
      std::nth_element(dts.begin(), dts.begin() + dts.size() / 2, dts.end());
      ft = dts[dts.size() / 2];
    }
  }
  std::vector<int> picks;
  const double t0 = fr.front().t, t1 = fr.back().t;
  for (long k = 0;; ++k) {
    const double t = t0 + k * ft;
    if (t > t1 + 1e-9 * std::max(1.0, std::abs(t1)) || k > 10000000) break;
    picks.push_back(viz_detail::nearest_frame(traj, t));
  }
  // Depth-first order of the hierarchy (children in index order).
  std::vector<std::vector<int>> children(nb);
  for (int i = 1; i < nb; ++i) children[m.bodies[i].parent].push_back(i);
  std::vector<int> order;
  std::string h = "HIERARCHY\n";
  auto write_joint = [&](auto&& self, int i, int depth) -> void {
    order.push_back(i);
    const std::string ind(2 * depth, ' ');
    const body& b = m.bodies[i];
    if (i == 0) {
      h += "ROOT " + b.name +
           "\n{\n  OFFSET 0 0 0\n"
           "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
    } else {
      const Eigen::Vector3d o = opt.scale * (C * b.joint_offset);
      h += ind + "JOINT " + b.name + "\n" + ind + "{\n" + ind + "  OFFSET " + num(o.x(), 9) + " " +
           num(o.y(), 9) + " " + num(o.z(), 9) + "\n" + ind +
           "  CHANNELS 3 Zrotation Xrotation Yrotation\n";
    }
    for (int c : children[i]) self(self, c, depth + 1);
    if (children[i].empty()) {
      Eigen::Vector3d e = b.segment_end;
      if (e.isZero()) {
        std::vector<Eigen::Vector3d> pts;
        for (const shape& s : b.shapes) {
          if (s.type == shape::kind::capsule) {
            pts.push_back(s.p0);
            pts.push_back(s.p1);
          } else {
            pts.push_back(s.center);
          }
        }
        for (const auto& p : pts)
          if (p.norm() > e.norm()) e = p;
      }
      const Eigen::Vector3d o = opt.scale * (C * e);
      h += ind + "  End Site\n" + ind + "  {\n" + ind + "    OFFSET " + num(o.x(), 9) + " " +
           num(o.y(), 9) + " " + num(o.z(), 9) + "\n" + ind + "  }\n";
    }
    h += ind + "}\n";
  };
  write_joint(write_joint, 0, 0);
  os << h;
  os << "MOTION\nFrames: " << picks.size() << "\nFrame Time: " << num(ft, 9) << "\n";
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Quaterniond> R;
  std::vector<Eigen::Vector3d> prev(nb);
  constexpr double deg = 180.0 / std::numbers::pi;
  std::string line;
  for (std::size_t k = 0; k < picks.size(); ++k) {
    viz_detail::frame_body_poses(m, fr[picks[k]], P, R);
    line.clear();
    const Eigen::Vector3d p = opt.scale * (C * P[0]);
    line += num(p.x(), opt.precision) + " " + num(p.y(), opt.precision) + " " +
            num(p.z(), opt.precision);
    for (int i : order) {
      const Eigen::Matrix3d Rw = R[i].toRotationMatrix();
      const Eigen::Matrix3d Rl =
          i == 0 ? Rw : Eigen::Matrix3d(R[m.bodies[i].parent].toRotationMatrix().transpose() * Rw);
      const Eigen::Vector3d a =
          detail::bvh::continuous_zxy(C * Rl * C.transpose(), k == 0 ? nullptr : &prev[i]);
      prev[i] = a;
      for (int c = 0; c < 3; ++c) {
        line += ' ';
        line += num(a[c] * deg, opt.precision);
      }
    }
    line += '\n';
    os << line;
  }
}

/// Writes the BVH file to `path` (nothing when the arguments are invalid); std::runtime_error when
/// the file cannot be written.
template <root_joint Root>
void save_bvh(const model<Root>& m, const trajectory& traj, const std::string& path,
              const bvh_options& opt = {}) {
  std::ostringstream s;
  write_bvh(m, traj, s, opt);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("save_bvh: cannot open '" + path + "' for writing");
  f << s.str();
  f.close();
  if (!f) throw std::runtime_error("save_bvh: failed writing '" + path + "'");
}

}  // namespace gaitsynth
