#pragma once
/// \file gait_cycles.hpp
/// Gait-cycle analysis of a recorded trajectory: heel strikes (a foot's contact points going from
/// none touching to at least one touching), sagittal angle channels (a joint angle, a segment's
/// pitch in the world, or the pitch between two segments) and their curves against percent of the
/// gait cycle, averaged over cycles with their spread, as in Wang et al. 2009, Figure 6; and joint
/// torque channels for torque curves (Wang et al. 2012, Figure 7); and recorded channels, a series
/// the caller recorded beside the trajectory (a muscle's activation: Wang et al. 2012, Figure 5;
/// analysis/muscle_recording.hpp records them), interpolated at the frames' times.
/// gait_plot_svg.hpp draws them; the HTML player uses the heel strikes for its cycle plots.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace gaitsynth {

/// One curve of a gait plot: value = scale * raw + offset, raw an angle in radians, a torque in
/// N m, or a recorded value. scale defaults to degrees: set it (to 1) for the other kinds.
struct gait_channel {
  enum class kind {
    joint_angle,     ///< the joint DOF `name` (its q value)
    segment_pitch,   ///< pitch of body `name` about world +y: atan2(R(0,2), R(2,2)) of R_world_body
    relative_pitch,  ///< pitch of body `name` relative to body `reference`: same on R_ref^T R_body
    joint_torque,    ///< the actuator's torque on joint DOF `name` (frame tau), N m
    recorded         ///< series_value at series_time, linearly interpolated (held beyond the ends)
  };
  kind type = kind::joint_angle;
  std::string label;      ///< panel title ("hip"); empty: `name`
  std::string name;       ///< DOF name (joint_angle) or body name
  std::string reference;  ///< relative_pitch only: the body the angle is measured from
  double scale = 180.0 / std::numbers::pi;  ///< default: degrees
  double offset = 0.0;
  std::string unit = "deg";
  std::vector<double> series_time;   ///< recorded only: s, strictly increasing
  std::vector<double> series_value;  ///< recorded only: raw values at series_time
};

struct gait_cycle_options {
  /// Channels to analyse; empty: default_gait_channels(model, side).
  std::vector<gait_channel> channels;
  /// Prefix of the analysed side's names (builder's mirror prefix, "l" by default).
  std::string side = "l";
  /// Body whose contact points (and its descendants', e.g. toes) define heel strike; empty: the
  /// first body with sole or toe points whose name starts with `side` (else the first with any).
  std::string foot;
  /// Cycle start times (s) to use instead of detected heel strikes (ascending).
  std::vector<double> cycle_starts;
  /// Heel strikes closer than this to the previous one are contact chatter and ignored, s.
  double min_cycle_duration = 0.25;
  /// Samples per cycle (0 % .. 100 %, inclusive).
  int samples = 101;
};

/// Curves of every channel over every complete gait cycle, their mean and standard deviation.
struct gait_cycle_data {
  std::vector<gait_channel> channels;
  std::string foot;                  ///< body whose strikes define the cycles ("" if given)
  std::vector<double> cycle_starts;  ///< s; cycle k spans [cycle_starts[k], cycle_starts[k+1]]
  std::vector<double> percent;       ///< 0 .. 100
  std::vector<std::vector<std::vector<double>>> curves;  ///< [channel][cycle][sample]
  std::vector<std::vector<double>> mean;                 ///< [channel][sample]
  std::vector<std::vector<double>> stddev;  ///< [channel][sample], sample s.d. (n - 1), 0 if n = 1
  int num_cycles() const {
    return cycle_starts.size() < 2 ? 0 : static_cast<int>(cycle_starts.size()) - 1;
  }
};

/// Sagittal hip, knee and ankle joint angles of one side: for each keyword ("hip", "knee",
/// "ankle") the DOF whose name starts with `side` and contains it, preferring the axis closest to
/// +-y (the sagittal one). Keywords with no DOF are left out. Throws std::invalid_argument when
/// none is found (pass explicit channels then).
template <root_joint Root>
std::vector<gait_channel> default_gait_channels(const model<Root>& m, const std::string& side) {
  std::vector<gait_channel> out;
  for (const char* key : {"hip", "knee", "ankle"}) {
    int best = -1;
    double best_y = -1;
    for (int j = 0; j < m.num_joint_dofs(); ++j) {
      const std::string& n = m.dofs[j].name;
      if (n.rfind(side, 0) != 0 || n.find(key) == std::string::npos) continue;
      const double ay = std::abs(m.dofs[j].axis.y());
      if (ay > best_y + 1e-12) {
        best = j;
        best_y = ay;
      }
    }
    if (best >= 0) {
      gait_channel c;
      c.type = gait_channel::kind::joint_angle;
      c.label = key;
      c.name = m.dofs[best].name;
      out.push_back(c);
    }
  }
  check_argument(!out.empty(), "default_gait_channels: model '", m.name,
                 "' has no DOF starting with '", side,
                 "' named like hip/knee/ankle; give gait_cycle_options::channels");
  return out;
}

/// The default foot of `side` (see gait_cycle_options::foot); -1 when no body has contacts.
inline int default_foot_body(const trajectory& traj, const std::string& side) {
  int any = -1;
  for (std::size_t b = 0; b < traj.body_names.size(); ++b) {
    bool has = false;
    for (int cb : traj.contact_bodies) has = has || cb == static_cast<int>(b);
    if (!has) continue;
    if (any < 0) any = static_cast<int>(b);
    if (traj.body_names[b].rfind(side, 0) == 0) return static_cast<int>(b);
  }
  return any;
}

/// The default foot of `side` for model m: the first body with sole or toe contact points whose
/// name starts with `side` (else the first with any). Points of other kinds do not make a foot:
/// the 3D humanoids also carry points on knees, hands and pelvis, for falls.
template <root_joint Root>
int default_foot_body(const model<Root>& m, const std::string& side) {
  int any = -1;
  for (int b = 0; b < m.num_bodies(); ++b) {
    bool has = false;
    for (const contact_point& cp : m.contact_points)
      has = has || (cp.body == b &&
                    (cp.role == contact_point::kind::sole || cp.role == contact_point::kind::toe));
    if (!has) continue;
    if (any < 0) any = b;
    if (m.bodies[static_cast<std::size_t>(b)].name.rfind(side, 0) == 0) return b;
  }
  return any;
}

/// Times (s) of the heel strikes of body `foot`: frames where the number of touching contact
/// points on the foot and its descendants goes from 0 to > 0, at least `min_interval` s after the
/// previous strike. A strike at the very first frame is not counted (nothing before it).
inline std::vector<double> heel_strike_times(const trajectory& traj, int foot,
                                             double min_interval = 0.25) {
  std::vector<double> out;
  if (foot < 0) return out;
  const std::vector<int> pts = viz_detail::contacts_on_subtree(traj, foot);
  if (pts.empty()) return out;
  auto touching = [&](const trajectory_frame& fr) {
    int n = 0;
    for (int k : pts)
      if (static_cast<std::size_t>(k) < fr.contact_active.size() && fr.contact_active[k]) ++n;
    return n;
  };
  int prev = -1;
  for (const auto& fr : traj.frames) {
    const int n = touching(fr);
    if (prev == 0 && n > 0 && (out.empty() || fr.t - out.back() >= min_interval))
      out.push_back(fr.t);
    prev = n;
  }
  return out;
}

namespace viz_detail {

/// Sagittal pitch of rotation r: the angle about +y, atan2(R(0,2), R(2,2)).
inline double sagittal_pitch(const Eigen::Quaterniond& r) {
  const Eigen::Matrix3d R = r.toRotationMatrix();
  return std::atan2(R(0, 2), R(2, 2));
}

/// Removes 2 pi jumps from a sampled angle (numpy.unwrap).
inline void unwrap(std::vector<double>& a) {
  for (std::size_t i = 1; i < a.size(); ++i) {
    if (!std::isfinite(a[i]) || !std::isfinite(a[i - 1])) continue;
    const double d = a[i] - a[i - 1];
    a[i] -= 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
  }
}

/// Piecewise-linear y(t) through the points (t[i], y[i]) at x, held constant beyond the ends.
inline double interpolate_series(const std::vector<double>& t, const std::vector<double>& y,
                                 double x) {
  if (!(x > t.front())) return y.front();  // (a NaN x gives the first value)
  if (x >= t.back()) return y.back();
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
  const double w = (x - t[i - 1]) / (t[i] - t[i - 1]);
  return (1 - w) * y[i - 1] + w * y[i];
}

/// Throws std::invalid_argument naming channel c unless its recorded series is usable.
inline void check_recorded_series(const gait_channel& c) {
  const std::string& who = c.label.empty() ? c.name : c.label;
  check_argument(c.series_time.size() == c.series_value.size(), "gait channel '", who,
                 "': ", c.series_time.size(), " series times but ", c.series_value.size(),
                 " series values");
  check_argument(!c.series_time.empty(), "gait channel '", who, "': the recorded series is empty");
  for (std::size_t i = 1; i < c.series_time.size(); ++i)
    check_argument(c.series_time[i] > c.series_time[i - 1], "gait channel '", who,
                   "': series times must increase strictly, got ", c.series_time[i - 1], " then ",
                   c.series_time[i], " s at sample ", i);
  check_argument(std::isfinite(c.series_time.front()) && std::isfinite(c.series_time.back()),
                 "gait channel '", who, "': series times must be finite");
}

/// Value of channel c (in its units) at every frame.
template <root_joint Root>
std::vector<double> channel_series(const model<Root>& m, const trajectory& traj,
                                   const gait_channel& c) {
  std::vector<double> out(traj.frames.size());
  if (c.type == gait_channel::kind::recorded) {
    check_recorded_series(c);
    for (std::size_t f = 0; f < traj.frames.size(); ++f)
      out[f] = interpolate_series(c.series_time, c.series_value, traj.frames[f].t);
  } else if (c.type == gait_channel::kind::joint_angle) {
    const int j = m.dof_index(c.name);
    for (std::size_t f = 0; f < traj.frames.size(); ++f) out[f] = traj.frames[f].q[Root::nq + j];
  } else if (c.type == gait_channel::kind::joint_torque) {
    const int j = m.dof_index(c.name);
    for (std::size_t f = 0; f < traj.frames.size(); ++f) {
      const Eigen::VectorXd& tau = traj.frames[f].tau;
      check_argument(tau.size() == m.nv(), "gait channel '", c.name, "': frame ", f,
                     " has no recorded torques");
      out[f] = tau[Root::nv + j];
    }
  } else {
    const int b = m.body_index(c.name);
    const int r = c.type == gait_channel::kind::relative_pitch ? m.body_index(c.reference) : -1;
    std::vector<Eigen::Vector3d> p;
    std::vector<Eigen::Quaterniond> R;
    for (std::size_t f = 0; f < traj.frames.size(); ++f) {
      frame_body_poses(m, traj.frames[f], p, R);
      out[f] = sagittal_pitch(r >= 0 ? Eigen::Quaterniond(R[r].conjugate() * R[b]) : R[b]);
    }
    unwrap(out);
  }
  for (double& x : out) x = c.scale * x + c.offset;
  return out;
}

/// Linear interpolation of series y (at the frames' times) at time t.
inline double interpolate_at(const trajectory& traj, const std::vector<double>& y, double t) {
  const auto& fr = traj.frames;
  auto it = std::lower_bound(fr.begin(), fr.end(), t,
                             [](const trajectory_frame& a, double tt) { return a.t < tt; });
  if (it == fr.begin()) return y.front();
  if (it == fr.end()) return y.back();
  const std::size_t i = static_cast<std::size_t>(it - fr.begin());
  const double t0 = fr[i - 1].t, t1 = fr[i].t;
  if (t1 <= t0) return y[i];
  const double w = (t - t0) / (t1 - t0);
  return (1 - w) * y[i - 1] + w * y[i];
}

}  // namespace viz_detail

/// Gait-cycle curves of the trajectory (see gait_cycle_data). Throws std::invalid_argument for an
/// unknown DOF / body / foot name, a bad recorded series or bad options; a trajectory with fewer
/// than two heel strikes gives num_cycles() == 0 (not an error: a fall is worth plotting too).
template <root_joint Root>
gait_cycle_data gait_cycles(const model<Root>& m, const trajectory& traj,
                            const gait_cycle_options& opt = {}) {
  viz_detail::check_trajectory(m, traj, "gait_cycles");
  check_argument(opt.samples >= 2, "gait_cycles: samples must be >= 2, got ", opt.samples);
  check_argument(std::isfinite(opt.min_cycle_duration) && opt.min_cycle_duration >= 0,
                 "gait_cycles: min_cycle_duration must be finite and >= 0, got ",
                 opt.min_cycle_duration);
  gait_cycle_data d;
  d.channels = opt.channels.empty() ? default_gait_channels(m, opt.side) : opt.channels;
  for (auto& c : d.channels)
    if (c.label.empty()) c.label = c.name;
  if (!opt.cycle_starts.empty()) {
    for (std::size_t k = 1; k < opt.cycle_starts.size(); ++k)
      check_argument(opt.cycle_starts[k] > opt.cycle_starts[k - 1],
                     "gait_cycles: cycle_starts must increase, got ", opt.cycle_starts[k - 1],
                     " then ", opt.cycle_starts[k]);
    d.cycle_starts = opt.cycle_starts;
  } else {
    int foot = -1;
    if (!opt.foot.empty()) {
      foot = m.body_index(opt.foot);
    } else {
      foot = default_foot_body(m, opt.side);
    }
    if (foot >= 0) d.foot = m.bodies[foot].name;
    d.cycle_starts = heel_strike_times(traj, foot, opt.min_cycle_duration);
  }
  for (int s = 0; s < opt.samples; ++s) d.percent.push_back(100.0 * s / (opt.samples - 1));
  const int nc = d.num_cycles();
  for (const auto& c : d.channels) {
    const std::vector<double> y = viz_detail::channel_series(m, traj, c);
    std::vector<std::vector<double>> curves;
    for (int k = 0; k < nc && !traj.frames.empty(); ++k) {
      const double t0 = d.cycle_starts[k], t1 = d.cycle_starts[k + 1];
      std::vector<double> curve(opt.samples);
      for (int s = 0; s < opt.samples; ++s)
        curve[s] = viz_detail::interpolate_at(traj, y, t0 + (t1 - t0) * d.percent[s] / 100.0);
      curves.push_back(std::move(curve));
    }
    std::vector<double> mean(opt.samples, 0.0), sd(opt.samples, 0.0);
    const int n = static_cast<int>(curves.size());
    for (int s = 0; s < opt.samples && n > 0; ++s) {
      double sum = 0;
      for (const auto& cv : curves) sum += cv[s];
      mean[s] = sum / n;
      double ss = 0;
      for (const auto& cv : curves) ss += (cv[s] - mean[s]) * (cv[s] - mean[s]);
      sd[s] = n > 1 ? std::sqrt(ss / (n - 1)) : 0.0;
    }
    d.curves.push_back(std::move(curves));
    d.mean.push_back(std::move(mean));
    d.stddev.push_back(std::move(sd));
  }
  return d;
}

}  // namespace gaitsynth
