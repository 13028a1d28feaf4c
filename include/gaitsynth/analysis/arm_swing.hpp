#pragma once
/// \file analysis/arm_swing.hpp
/// Arm swing against the legs in a recorded walk. In human walking each arm swings with the
/// opposite leg (the left arm forward as the right thigh swings forward), which cancels much of
/// the legs' angular momentum about the vertical; Wang et al. 2009 (Fig. 4) find that E_ang
/// gives this "in-phase" swing and that without it "the arms are in-phase with the wrong legs".
///
/// Measured here as Pearson correlations, over the frames from t_begin on, between the world
/// sagittal angle of each upper arm and that of each thigh (spatial/world_angles.hpp, Sec. 3's
/// world-frame angles): opposite-leg
/// correlation near +1 is the human pattern, near -1 the arm swings with its own leg.
/// Segment pitches need no joint sign convention, so any model with these four bodies works.
#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

namespace gaitsynth {

struct arm_swing_report {
  double opposite_leg_correlation = 0.0;  ///< mean of corr(left arm, right thigh), (right, left)
  double same_leg_correlation = 0.0;      ///< mean of corr(left arm, left thigh), (right, right)
  double arm_pitch_amplitude = 0.0;       ///< rad: mean over the arms of sqrt(2) x the pitch s.d.
  int frames = 0;                         ///< frames used
};

/// Names of the segments compared (the Wang 2009 humanoid's by default).
struct arm_swing_bodies {
  std::string left_arm = "lupper_arm", right_arm = "rupper_arm";
  std::string left_thigh = "lthigh", right_thigh = "rthigh";
};

namespace analysis_detail {

/// Pearson correlation of two equally long series; 0 when either is constant.
inline double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= n;
  mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

inline double standard_deviation(const std::vector<double>& a) {
  double m = 0, s = 0;
  for (const double x : a) m += x;
  m /= static_cast<double>(a.size());
  for (const double x : a) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(a.size()));
}

}  // namespace analysis_detail

/// The arm swing of trajectory tr (recorded with body poses) of model m, from t_begin (s) on.
/// Throws std::invalid_argument naming an unknown body, a trajectory without body poses, or fewer
/// than 3 frames after t_begin.
template <root_joint Root>
arm_swing_report arm_swing(const model<Root>& m, const trajectory& tr, double t_begin = 0.0,
                           const arm_swing_bodies& names = {}) {
  const int la = m.body_index(names.left_arm), ra = m.body_index(names.right_arm);
  const int lt = m.body_index(names.left_thigh), rt = m.body_index(names.right_thigh);
  const std::size_t nb = static_cast<std::size_t>(m.num_bodies());
  std::vector<double> pla, pra, plt, prt;
  auto pitch = [](const Eigen::Quaterniond& q) {
    return body_world_angles(q.normalized().toRotationMatrix()).sagittal;
  };
  for (const trajectory_frame& f : tr.frames) {
    if (f.t < t_begin) continue;
    check_argument(f.body_orientation.size() == nb, "arm_swing: the frame at t = ", f.t, " has ",
                   f.body_orientation.size(), " body orientations, model '", m.name, "' has ", nb,
                   " bodies (record body poses)");
    pla.push_back(pitch(f.body_orientation[static_cast<std::size_t>(la)]));
    pra.push_back(pitch(f.body_orientation[static_cast<std::size_t>(ra)]));
    plt.push_back(pitch(f.body_orientation[static_cast<std::size_t>(lt)]));
    prt.push_back(pitch(f.body_orientation[static_cast<std::size_t>(rt)]));
  }
  check_argument(pla.size() >= 3, "arm_swing: ", pla.size(), " frames from t = ", t_begin,
                 " s on, need at least 3");
  using analysis_detail::correlation;
  arm_swing_report r;
  r.frames = static_cast<int>(pla.size());
  r.opposite_leg_correlation = 0.5 * (correlation(pla, prt) + correlation(pra, plt));
  r.same_leg_correlation = 0.5 * (correlation(pla, plt) + correlation(pra, prt));
  r.arm_pitch_amplitude =
      std::sqrt(2.0) * 0.5 *
      (analysis_detail::standard_deviation(pla) + analysis_detail::standard_deviation(pra));
  return r;
}

}  // namespace gaitsynth
