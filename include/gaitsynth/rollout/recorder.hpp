#pragma once
/// \file recorder.hpp
/// Optional recording of a rollout into a gaitsynth::trajectory (rollout/trajectory.hpp), every
/// `every` physics steps. All memory is reserved at set-up (start): each frame's vectors are sized
/// once, and the step loop only writes into them, so a recording rollout does not allocate in its
/// step loop either. finish() trims unused frames and samples the terrain for the viewers (after
/// the loop).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// Names of the generalized coordinates / velocities of m (root first), e.g. "root_qw", "lknee".
template <root_joint Root>
std::vector<std::string> q_coordinate_names(const model<Root>& m) {
  std::vector<std::string> n;
  if constexpr (Root::nq == 7) {
    n = {"root_x", "root_y", "root_z", "root_qw", "root_qx", "root_qy", "root_qz"};
  } else {
    for (auto d : Root::dof_names) n.emplace_back(d);
  }
  for (const auto& d : m.dofs) n.push_back(d.name);
  return n;
}
template <root_joint Root>
std::vector<std::string> v_coordinate_names(const model<Root>& m) {
  std::vector<std::string> n;
  for (auto d : Root::dof_names) n.emplace_back(d);
  for (const auto& d : m.dofs) n.push_back(d.name);
  return n;
}

class trajectory_recorder {
 public:
  /// Prepares `tr` (may be null: recording off) for at most max_frames frames of model m.
  template <root_joint Root, class Names>
  void start(trajectory* tr, const model<Root>& m, int every, std::int64_t max_frames,
             const Names& objective_term_names, std::size_t max_pushes) {
    tr_ = tr;
    count_ = 0;
    if (tr_ == nullptr) return;
    check_argument(every >= 1, "rollout_options::record_every must be >= 1, got ", every);
    every_ = every;
    tr_->model_name = m.name;
    tr_->planar = std::is_same_v<Root, planar_root>;
    tr_->q_names = q_coordinate_names(m);
    tr_->v_names = v_coordinate_names(m);
    tr_->body_names.clear();
    tr_->body_parents.clear();
    for (const auto& b : m.bodies) {
      tr_->body_names.push_back(b.name);
      tr_->body_parents.push_back(b.parent);
    }
    tr_->contact_names.clear();
    tr_->contact_bodies.clear();
    for (const auto& c : m.contact_points) {
      tr_->contact_names.push_back(c.name);
      tr_->contact_bodies.push_back(c.body);
    }
    tr_->objective_term_names.clear();
    for (const auto& n : objective_term_names) tr_->objective_term_names.emplace_back(n);
    const auto nb = static_cast<std::size_t>(m.num_bodies());
    const auto nc = m.contact_points.size();
    trajectory_frame proto;
    proto.q = Eigen::VectorXd::Zero(m.nq());
    proto.v = Eigen::VectorXd::Zero(m.nv());
    proto.tau = Eigen::VectorXd::Zero(m.nv());
    proto.body_position.assign(nb, Eigen::Vector3d::Zero());
    proto.body_orientation.assign(nb, Eigen::Quaterniond::Identity());
    proto.contact_position.assign(nc, Eigen::Vector3d::Zero());
    proto.contact_force.assign(nc, Eigen::Vector3d::Zero());
    proto.contact_active.assign(nc, 0);
    proto.pushes.reserve(max_pushes);
    proto.objective_terms.assign(tr_->objective_term_names.size(), 0.0);
    tr_->frames.assign(static_cast<std::size_t>(std::max<std::int64_t>(max_frames, 0)), proto);
    // assign() copy-constructs, which does not carry the pushes' capacity over: reserve each.
    for (auto& f : tr_->frames) f.pushes.reserve(max_pushes);
  }

  bool enabled() const { return tr_ != nullptr; }
  /// Whether physics step k is recorded.
  bool due(std::int64_t k) const {
    return tr_ != nullptr && k % every_ == 0 && count_ < tr_->frames.size();
  }
  bool has_room() const { return tr_ != nullptr && count_ < tr_->frames.size(); }
  /// The next frame to fill (call only when due()).
  trajectory_frame& next() { return tr_->frames[count_++]; }

  /// Drops unused frames and samples the terrain around the recorded motion (after the loop).
  template <terrain T>
  void finish(const T& ground) {
    if (tr_ == nullptr) return;
    tr_->frames.resize(count_);
    double x0 = -2, x1 = 2, y0 = -2, y1 = 2;
    for (const auto& f : tr_->frames) {
      x0 = std::min(x0, f.com.x() - 2);
      x1 = std::max(x1, f.com.x() + 2);
      y0 = std::min(y0, f.com.y() - 2);
      y1 = std::max(y1, f.com.y() + 2);
    }
    auto& ts = tr_->terrain;
    ts.dx = ts.dy = 0.1;
    ts.x0 = x0;
    ts.y0 = tr_->planar ? -0.5 : y0;
    ts.nx = std::min(2001, static_cast<int>(std::ceil((x1 - x0) / ts.dx)) + 1);
    ts.ny = tr_->planar ? 2 : std::min(2001, static_cast<int>(std::ceil((y1 - y0) / ts.dy)) + 1);
    ts.dy = tr_->planar ? 1.0 : ts.dy;
    ts.height.resize(static_cast<std::size_t>(ts.nx) * ts.ny);
    for (int iy = 0; iy < ts.ny; ++iy)
      for (int ix = 0; ix < ts.nx; ++ix)
        ts.height[static_cast<std::size_t>(iy) * ts.nx + ix] =
            ground.height(ts.x0 + ix * ts.dx, ts.y0 + iy * ts.dy);
  }

 private:
  trajectory* tr_ = nullptr;
  int every_ = 1;
  std::size_t count_ = 0;
};

}  // namespace gaitsynth
