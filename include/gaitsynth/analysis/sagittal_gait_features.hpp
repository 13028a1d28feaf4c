#pragma once
/// \file analysis/sagittal_gait_features.hpp
/// The four numbers Wang et al. 2012 Sec. 6.2 compare its walkers by, from the mean gait cycle of
/// human_sagittal_channels (degrees; knee flexion and ankle dorsiflexion positive), over the
/// windows of analysis/cycle_window.hpp:
///   knee flexion in mid stance, its minimum ("a minimum knee flexion angle of 2 deg ... the same
///     angle for nwalk is 9 deg", HAM weakness) and mean ("a mild crouch", GAS/SOL weakness,
///     min_act);
///   knee flexion in swing, its maximum ("too much knee flexion during the swing phase",
///   min_torque); ankle dorsiflexion in terminal swing, its mean ("too much dorsiflexion before
///   heel-strike").
///
///   const gait_cycle_data g = gait_cycles(m, tr, {.channels = human_sagittal_channels("l")});
///   const sagittal_gait_features f = sagittal_gait_features_of(g);
#include <cstddef>
#include <string>

#include "gaitsynth/analysis/cycle_window.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

struct sagittal_gait_features {
  double knee_flexion_mid_stance_min = 0.0;             ///< deg
  double knee_flexion_mid_stance_mean = 0.0;            ///< deg
  double knee_flexion_swing_max = 0.0;                  ///< deg
  double ankle_dorsiflexion_terminal_swing_mean = 0.0;  ///< deg
};

/// The features of g's mean cycle; its channels must include "knee_flexion_angle" and
/// "ankle_dorsiflexion_angle" (human_sagittal_channels' labels). Throws std::invalid_argument
/// naming a missing channel, or when g has no complete cycle.
inline sagittal_gait_features sagittal_gait_features_of(const gait_cycle_data& g) {
  check_argument(g.num_cycles() >= 1, "sagittal_gait_features_of: no complete gait cycle");
  auto curve = [&](const char* label) -> const std::vector<double>& {
    for (std::size_t k = 0; k < g.channels.size(); ++k)
      if (g.channels[k].label == label) return g.mean.at(k);
    check_argument(false, "sagittal_gait_features_of: no channel '", label,
                   "' (use human_sagittal_channels)");
    return g.mean.front();  // not reached
  };
  const std::vector<double>& knee = curve("knee_flexion_angle");
  const std::vector<double>& ankle = curve("ankle_dorsiflexion_angle");
  const cycle_window_stats stance = cycle_window(g.percent, knee, gait_windows::mid_stance);
  return {.knee_flexion_mid_stance_min = stance.min,
          .knee_flexion_mid_stance_mean = stance.mean,
          .knee_flexion_swing_max = cycle_window(g.percent, knee, gait_windows::swing).max,
          .ankle_dorsiflexion_terminal_swing_mean =
              cycle_window(g.percent, ankle, gait_windows::terminal_swing).mean};
}

}  // namespace gaitsynth
