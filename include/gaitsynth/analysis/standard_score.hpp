#pragma once
/// \file analysis/standard_score.hpp
/// How far a simulated gait curve lies from human data, in standard deviations (Wang et al. 2012
/// Sec. 6 compare their walkers' joint angles and torques with Winter's data; issue 13 asks for a
/// number): the mean over n points of the cycle of |sim(p) - mean(p)| / sd(p),
///
///   const normative_gait human = load_normative_gait(".../falisse2019_subject1_walking.csv");
///   const gait_cycle_data g = gait_cycles(m, tr, {.channels = human_sagittal_channels("l")});
///   double z = standard_score(g.percent, g.mean[1], human.curve("knee_flexion_angle"));
///
/// Points p_i = 100 i / (n - 1), i = 0..n-1 (n = 100: the grid of data/normative_gait/), both
/// curves linearly interpolated there. 0 means the simulation follows the human mean; about 0.8
/// is the mean |z| of a normal sample drawn from the data.
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

namespace detail {
/// y(x) by linear interpolation on strictly increasing xs (clamped at the ends).
inline double interpolate_curve(std::span<const double> xs, std::span<const double> ys, double x) {
  if (x <= xs.front()) return ys.front();
  if (x >= xs.back()) return ys.back();
  std::size_t k = 1;
  while (xs[k] < x) ++k;
  const double u = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + u * (ys[k] - ys[k - 1]);
}
}  // namespace detail

/// Mean over n points of |sim - mean| / sd (file comment). sim_percent: strictly increasing
/// percents of the gait cycle covering [0, 100], sim: the simulated curve there, in the data's
/// unit. \throws std::invalid_argument for mismatched or non-finite input, a grid that does not
/// cover the cycle, n < 2, or a point where the data's s.d. is 0 (naming the variable and the
/// percent).
inline double standard_score(std::span<const double> sim_percent, std::span<const double> sim,
                             const normative_curve& human, int n = 100) {
  check_argument(n >= 2, "standard_score: n must be >= 2, got ", n);
  check_size(static_cast<std::ptrdiff_t>(sim.size()),
             static_cast<std::ptrdiff_t>(sim_percent.size()), "standard_score: sim");
  check_argument(
      sim_percent.size() >= 2 && sim_percent.front() <= 0.0 && sim_percent.back() >= 100.0,
      "standard_score: the simulated curve must cover 0-100 % of the cycle");
  for (std::size_t i = 0; i < sim.size(); ++i) {
    check_argument(std::isfinite(sim[i]) && std::isfinite(sim_percent[i]),
                   "standard_score: simulated value ", i, " is not finite (", sim[i], " at ",
                   sim_percent[i], " %)");
    check_argument(i == 0 || sim_percent[i] > sim_percent[i - 1],
                   "standard_score: simulated percents must increase (", sim_percent[i], " at ", i,
                   ")");
  }
  check_argument(human.percent.size() >= 2, "standard_score: '", human.variable,
                 "' has fewer than 2 samples");
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double p = 100.0 * i / (n - 1);
    const double sd = detail::interpolate_curve(human.percent, human.sd, p);
    check_argument(sd > 0.0, "standard_score: '", human.variable, "' has s.d. ", sd, " at ", p,
                   " % of the cycle");
    const double mean = detail::interpolate_curve(human.percent, human.mean, p);
    sum += std::abs(detail::interpolate_curve(sim_percent, sim, p) - mean) / sd;
  }
  return sum / n;
}

/// The sagittal hip, knee and ankle angles of side "l" or "r" of the 30-DOF humanoids in the
/// conventions of data/normative_gait/ (degrees; hip flexion, knee flexion, ankle dorsiflexion
/// positive): -hip_y, knee, -ankle_y. Labelled with the data's variable names.
inline std::vector<gait_channel> human_sagittal_channels(const std::string& side) {
  constexpr double deg = 180.0 / 3.14159265358979323846;
  using kind = gait_channel::kind;
  return {{.type = kind::joint_angle,
           .label = "hip_flexion_angle",
           .name = side + "hip_y",
           .scale = -deg},
          {.type = kind::joint_angle,
           .label = "knee_flexion_angle",
           .name = side + "knee",
           .scale = deg},
          {.type = kind::joint_angle,
           .label = "ankle_dorsiflexion_angle",
           .name = side + "ankle_y",
           .scale = -deg}};
}

/// The sagittal hip, knee and ankle actuator torques of side "l" or "r" per kg of body mass, as
/// the internal joint moments of data/normative_gait/ (N m/kg; flexor and dorsiflexor positive):
/// -tau_hip_y, tau_knee, -tau_ankle_y over mass. Labelled with the data's variable names.
inline std::vector<gait_channel> human_sagittal_moment_channels(const std::string& side,
                                                                double body_mass) {
  check_positive(body_mass, "human_sagittal_moment_channels: body_mass (kg)");
  using kind = gait_channel::kind;
  const double s = 1.0 / body_mass;
  return {{.type = kind::joint_torque,
           .label = "hip_flexion_moment_per_kg",
           .name = side + "hip_y",
           .scale = -s,
           .unit = "N*m/kg"},
          {.type = kind::joint_torque,
           .label = "knee_flexion_moment_per_kg",
           .name = side + "knee",
           .scale = s,
           .unit = "N*m/kg"},
          {.type = kind::joint_torque,
           .label = "ankle_dorsiflexion_moment_per_kg",
           .name = side + "ankle_y",
           .scale = -s,
           .unit = "N*m/kg"}};
}

}  // namespace gaitsynth
