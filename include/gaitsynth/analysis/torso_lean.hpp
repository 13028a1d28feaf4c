#pragma once
/// \file analysis/torso_lean.hpp
/// The posture of a recorded walk: the mean world sagittal angle of the torso (spatial/
/// world_angles.hpp, Sec. 3's world-frame angles; positive leaning forward) and the largest tilt
/// of its up vector from the vertical (objectives/wang2009/torso_posture.hpp's measure), over the
/// frames from t_begin on. Adults walk with the trunk within a few degrees of the vertical.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

namespace gaitsynth {

struct torso_lean_report {
  double mean_pitch = 0.0;  ///< rad, mean world sagittal angle, positive forward
  double max_tilt = 0.0;    ///< rad, largest angle of the up vector from the vertical
  int frames = 0;           ///< frames used
};

/// The torso lean of trajectory tr (recorded with body poses) of model m, from t_begin (s) on.
/// Throws std::invalid_argument naming an unknown body, a frame without body poses, or no frame
/// after t_begin.
template <root_joint Root>
torso_lean_report torso_lean(const model<Root>& m, const trajectory& tr, double t_begin = 0.0,
                             const std::string& torso = "torso") {
  const auto b = static_cast<std::size_t>(m.body_index(torso));
  const std::size_t nb = static_cast<std::size_t>(m.num_bodies());
  torso_lean_report r;
  double sum = 0.0;
  for (const trajectory_frame& f : tr.frames) {
    if (f.t < t_begin) continue;
    check_argument(f.body_orientation.size() == nb, "torso_lean: the frame at t = ", f.t, " has ",
                   f.body_orientation.size(), " body orientations, model '", m.name, "' has ", nb,
                   " bodies (record body poses)");
    const mat3 R = f.body_orientation[b].normalized().toRotationMatrix();
    sum += body_world_angles(R).sagittal;
    r.max_tilt = std::max(r.max_tilt, tilt_from_vertical(R.col(2)));
    ++r.frames;
  }
  check_argument(r.frames > 0, "torso_lean: no frame from t = ", t_begin, " s on");
  r.mean_pitch = sum / r.frames;
  return r;
}

}  // namespace gaitsynth
