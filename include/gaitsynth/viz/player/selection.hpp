#pragma once
/// \file selection.hpp
/// What the HTML player shows, decided from the model, the trajectory and html_player_options
/// before anything is written: the frames kept, the gait cycles of the cycle plot (and the foot
/// they come from), the joints plotted at first, the character's size (the camera distance) and
/// the force-arrow scale. player/data.hpp puts the results into the page's JSON.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace gaitsynth::viz_detail {

/// Recorded frames kept for a clock of `max_frame_rate` ticks per second: the one nearest to each
/// tick (each once, in order), and always the last one, so the page ends where the motion does.
inline std::vector<int> player_frames(const trajectory& traj, double max_frame_rate) {
  std::vector<int> keep;
  const double t0 = traj.frames.front().t, t1 = traj.frames.back().t;
  for (long k = 0; k <= 100000000; ++k) {
    const double t = t0 + k / max_frame_rate;
    if (t > t1 + 1e-9) break;
    const int f = nearest_frame(traj, t);
    if (keep.empty() || f > keep.back()) keep.push_back(f);
  }
  if (keep.back() != static_cast<int>(traj.frames.size()) - 1)
    keep.push_back(static_cast<int>(traj.frames.size()) - 1);
  return keep;
}

/// The foot whose heel strikes delimit the plotted gait cycles (-1: none) and the cycle start
/// times: opt.cycle_starts when given, else the strikes detected over all recorded frames. A
/// hand-made trajectory may lack the names heel_strike_times needs; the model supplies them.
template <root_joint Root>
std::vector<double> player_cycles(const model<Root>& m, const trajectory& traj,
                                  const gait_cycle_options& opt, int& foot) {
  const int nb = m.num_bodies();
  const int nc = static_cast<int>(m.contact_points.size());
  trajectory names_only;  // names and contact flags only: copying whole frames would be wasteful
  names_only.body_names = traj.body_names;
  names_only.body_parents = traj.body_parents;
  names_only.contact_bodies = traj.contact_bodies;
  if (names_only.body_parents.size() != static_cast<std::size_t>(nb)) {
    names_only.body_names.clear();
    names_only.body_parents.clear();
    for (const auto& b : m.bodies) {
      names_only.body_names.push_back(b.name);
      names_only.body_parents.push_back(b.parent);
    }
  }
  if (names_only.contact_bodies.size() != static_cast<std::size_t>(nc)) {
    names_only.contact_bodies.clear();
    for (const auto& c : m.contact_points) names_only.contact_bodies.push_back(c.body);
  }
  foot = !opt.foot.empty() ? m.body_index(opt.foot) : default_foot_body(m, opt.side);
  std::vector<double> cycles = opt.cycle_starts;
  if (cycles.empty() && foot >= 0) {
    names_only.frames.reserve(traj.frames.size());
    for (const auto& fr : traj.frames) {
      trajectory_frame lite;
      lite.t = fr.t;
      lite.contact_active = fr.contact_active;
      names_only.frames.push_back(std::move(lite));
    }
    cycles = heel_strike_times(names_only, foot, opt.min_cycle_duration);
  }
  return cycles;
}

/// DOF indices of the joints plotted at first: `names`, else the sagittal hip, knee and ankle of
/// both sides (default_gait_channels), else the first four joint DOFs of a model without them.
/// Throws std::invalid_argument for a name the model does not have.
template <root_joint Root>
std::vector<int> player_plot_joints(const model<Root>& m, const std::vector<std::string>& names) {
  std::vector<int> plot;
  for (const auto& n : names) plot.push_back(m.dof_index(n));
  if (names.empty()) {
    for (const char* side : {"l", "r"}) {
      try {
        for (const auto& c : default_gait_channels(m, side)) plot.push_back(m.dof_index(c.name));
      } catch (const std::invalid_argument&) {  // no such side: the other one, or the fallback
      }
    }
    if (plot.empty())
      for (int j = 0; j < std::min(m.num_joint_dofs(), 4); ++j) plot.push_back(j);
  }
  return plot;
}

/// Size of the character in frame `fr` (largest extent of its drawing's bounding box, at least
/// 0.3 m so that a tiny model is still seen from a sensible distance), m.
template <root_joint Root>
double character_size(const model<Root>& m, const trajectory_frame& fr) {
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Quaterniond> R;
  frame_body_poses(m, fr, P, R);
  Eigen::Vector3d lo = P[0], hi = P[0];
  std::vector<Eigen::Vector3d> local;
  for (int i = 0; i < m.num_bodies(); ++i) {
    body_points(m, i, local);
    for (const auto& l : local) {
      const Eigen::Vector3d w = P[i] + R[i] * l;
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    }
  }
  return std::max(0.3, (hi - lo).maxCoeff());
}

/// Force-arrow length per newton: `requested` when > 0, else 0.5 m per body weight (1 mm/N for a
/// weightless model).
template <root_joint Root>
double player_force_scale(const model<Root>& m, double requested) {
  if (requested > 0) return requested;
  const double weight = m.total_mass() * m.gravity.norm();
  return weight > 0 ? 0.5 / weight : 0.001;
}

}  // namespace gaitsynth::viz_detail
