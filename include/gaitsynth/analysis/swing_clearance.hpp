#pragma once
/// \file analysis/swing_clearance.hpp
/// How high a foot is lifted over the terrain in each swing of a recorded walk. Wu & Popovic 2010
/// (Sec. 1, 9): "terrain-aware control eliminates the need of using unnaturally high clearance
/// during the swing phase on uneven terrain, a typical strategy that terrain-blind controllers
/// use"; comparing a controller with and without terrain sampling needs this number.
///
/// A swing is a maximal run of recorded frames in which no sole or toe contact point of the foot
/// touches, with a touching frame on both sides (complete swings only). The foot's clearance in a
/// frame is the height of its lowest sole or toe point over the terrain under that point,
/// min_i (z_i - height(x_i, y_i)); a swing's peak clearance is the largest over its frames. A
/// foot that scuffs the ground mid-swing ends one swing and starts another, which shows up as
/// more, shorter swings with low peaks.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

struct foot_swing {
  double t_begin = 0.0, t_end = 0.0;  ///< s: first and last frame off the ground
  double peak_clearance = 0.0;        ///< m, the lowest point's largest height over the terrain
};

struct swing_clearance_report {
  std::vector<foot_swing> swings;  ///< complete swings, in time order
  double median_peak_clearance = std::numeric_limits<double>::quiet_NaN();  ///< m; NaN if none
  double max_peak_clearance = std::numeric_limits<double>::quiet_NaN();     ///< m; NaN if none
};

/// The swings of body `foot` (name) in trajectory tr of model m over `ground`, the terrain the
/// walk was simulated on. Throws std::invalid_argument naming an unknown body, a body without sole
/// or toe points, or a frame that does not fit the model.
template <root_joint Root, terrain Terrain>
swing_clearance_report swing_clearance(const model<Root>& m, const trajectory& tr,
                                       const Terrain& ground, const std::string& foot) {
  const int body = m.body_index(foot);
  check_argument(body >= 0, "swing_clearance: no body named '", foot, "' in model '", m.name, "'");
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < m.contact_points.size(); ++i) {
    const contact_point& cp = m.contact_points[i];
    if (cp.body == body &&
        (cp.role == contact_point::kind::sole || cp.role == contact_point::kind::toe))
      points.push_back(i);
  }
  check_argument(!points.empty(), "swing_clearance: body '", foot, "' has no sole or toe points");
  const std::size_t n = tr.frames.size();
  std::vector<unsigned char> down(n, 0);
  for (std::size_t f = 0; f < n; ++f) {
    const trajectory_frame& fr = tr.frames[f];
    check_argument(fr.contact_active.size() == m.contact_points.size() &&
                       fr.contact_position.size() == m.contact_points.size(),
                   "swing_clearance: frame ", f, " does not fit model '", m.name, "' (",
                   fr.contact_active.size(), " contact flags, ", fr.contact_position.size(),
                   " contact positions, ", m.contact_points.size(), " contact points)");
    for (const std::size_t i : points) down[f] |= fr.contact_active[i];
  }
  swing_clearance_report out;
  std::size_t f = 0;
  while (f < n && !down[f]) ++f;  // a swing under way at the start is not complete
  while (f < n) {
    while (f < n && down[f]) ++f;
    const std::size_t b = f;
    while (f < n && !down[f]) ++f;
    if (f >= n) break;  // runs to the end
    foot_swing s;
    s.t_begin = tr.frames[b].t;
    s.t_end = tr.frames[f - 1].t;
    s.peak_clearance = -std::numeric_limits<double>::infinity();
    for (std::size_t k = b; k < f; ++k) {
      double lowest = std::numeric_limits<double>::infinity();
      for (const std::size_t i : points) {
        const Eigen::Vector3d& p = tr.frames[k].contact_position[i];
        lowest = std::min(lowest, p.z() - ground.height(p.x(), p.y()));
      }
      s.peak_clearance = std::max(s.peak_clearance, lowest);
    }
    out.swings.push_back(s);
  }
  if (out.swings.empty()) return out;
  std::vector<double> peaks;
  for (const foot_swing& s : out.swings) peaks.push_back(s.peak_clearance);
  std::sort(peaks.begin(), peaks.end());
  const std::size_t h = peaks.size() / 2;
  out.median_peak_clearance = peaks.size() % 2 ? peaks[h] : 0.5 * (peaks[h - 1] + peaks[h]);
  out.max_peak_clearance = peaks.back();
  return out;
}

}  // namespace gaitsynth
