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

#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/observer.hpp"
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

/// Records a trajectory (an observer, rollout/observer.hpp): every `every` physics steps, plus
/// the state the rollout stopped in, then samples the terrain around the motion for the viewers.
/// All memory is reserved in start(); observe() only writes into it. A null trajectory records
/// nothing (rollout_options::record's default).
class trajectory_observer {
 public:
  explicit trajectory_observer(trajectory* tr = nullptr, int every = 1) : tr_(tr), every_(every) {}

  bool enabled() const { return tr_ != nullptr; }

  /// Prepares the trajectory for at most horizon_steps / every + 1 frames of model m.
  template <root_joint Root>
  void start(const model<Root>& m, const observer_setup& su) {
    count_ = 0;
    last_ = -1;
    if (tr_ == nullptr) return;
    check_argument(every_ >= 1, "rollout_options::record_every must be >= 1, got ", every_);
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
    tr_->objective_term_names = su.objective_term_names;
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
    proto.objective_terms.assign(tr_->objective_term_names.size(), 0.0);
    const std::int64_t frames = su.horizon_steps / every_ + 1;
    tr_->frames.assign(static_cast<std::size_t>(std::max<std::int64_t>(frames, 0)), proto);
    // assign() copy-constructs, which does not carry the pushes' capacity over: reserve each.
    for (auto& f : tr_->frames) f.pushes.reserve(su.max_pushes);
  }

  template <class Observation>
  void observe(const Observation& ob) {
    if (tr_ != nullptr && ob.step % every_ == 0 && count_ < tr_->frames.size()) fill(ob);
  }

  /// The state it stopped in (unless already recorded), then trims the unused frames and
  /// samples the terrain.
  template <class Observation>
  void finish(const Observation& ob, const rollout_result&) {
    if (tr_ == nullptr) return;
    if (ob.final_state_valid && count_ < tr_->frames.size() && last_ != ob.step) fill(ob);
    tr_->frames.resize(count_);
    sample_terrain(ob.terrain());
  }

 private:
  template <class Observation>
  void fill(const Observation& ob) {
    const auto& m = ob.model();
    last_ = ob.step;
    trajectory_frame& f = tr_->frames[count_++];
    f.t = ob.t;
    f.q = ob.q();
    f.v = ob.v();
    f.tau = ob.tau();
    for (int b = 0; b < m.num_bodies(); ++b) {
      f.body_position[b] = ob.body_position[b];
      f.body_orientation[b] = Eigen::Quaterniond(ob.body_rotation[b]);
    }
    f.com = ob.com;
    for (std::size_t c = 0; c < m.contact_points.size(); ++c) {
      const auto& cp = m.contact_points[c];
      f.contact_position[c] = point_position(m, ob.workspace(), cp.body, cp.position);
      f.contact_force[c] = ob.contact_force[c];
      f.contact_active[c] = ob.contact_active[c];
    }
    f.pushes.clear();
    for (const push& p : ob.pushes)
      if (p.active(ob.t)) f.pushes.emplace_back(p.body, p.force);
    ob.objective_terms(std::span<double>(f.objective_terms));
    f.controller_state = ob.controller_state();
  }

  template <terrain T>
  void sample_terrain(const T& ground) {
    double x0 = -2, x1 = 2, y0 = -2, y1 = 2;
    for (const auto& f : tr_->frames) {
      // A diverged rollout's last frames may hold huge or non-finite COMs: they do not size the
      // grid (a cell count from them would overflow int).
      if (!f.com.allFinite() || std::abs(f.com.x()) > 1e4 || std::abs(f.com.y()) > 1e4) continue;
      x0 = std::min(x0, f.com.x() - 2);
      x1 = std::max(x1, f.com.x() + 2);
      y0 = std::min(y0, f.com.y() - 2);
      y1 = std::max(y1, f.com.y() + 2);
    }
    auto& ts = tr_->terrain;
    ts.dx = ts.dy = 0.1;
    ts.x0 = x0;
    ts.y0 = tr_->planar ? -0.5 : y0;
    ts.nx = static_cast<int>(std::min(2001.0, std::ceil((x1 - x0) / ts.dx) + 1));
    ts.ny = tr_->planar ? 2 : static_cast<int>(std::min(2001.0, std::ceil((y1 - y0) / ts.dy) + 1));
    ts.dy = tr_->planar ? 1.0 : ts.dy;
    ts.height.resize(static_cast<std::size_t>(ts.nx) * ts.ny);
    for (int iy = 0; iy < ts.ny; ++iy)
      for (int ix = 0; ix < ts.nx; ++ix)
        ts.height[static_cast<std::size_t>(iy) * ts.nx + ix] =
            ground.height(ts.x0 + ix * ts.dx, ts.y0 + iy * ts.dy);
  }

  trajectory* tr_ = nullptr;
  int every_ = 1;
  std::size_t count_ = 0;
  std::int64_t last_ = -1;
};

}  // namespace gaitsynth
