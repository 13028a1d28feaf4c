#pragma once
/// \file options.hpp
/// html_player_options: what the HTML player (viz/html_player.hpp) shows at first and which frames
/// it keeps. A file of its own because both the page writer and the data it embeds
/// (player/data.hpp) read it; include viz/html_player.hpp to use it.
#include <string>
#include <vector>

#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

struct html_player_options {
  std::string title;             ///< page title; empty: "<model> - gaitsynth player"
  double max_frame_rate = 60.0;  ///< frames kept per second of motion (the nearest recorded ones)
  double force_scale = 0.0;      ///< arrow length per force, m/N; 0: 0.5 m per body weight
  bool autoplay = true;
  double speed = 1.0;                    ///< initial playback speed
  std::vector<std::string> plot_joints;  ///< joints shown at first; empty: sagittal hip/knee/ankle
  gait_cycle_options cycles;  ///< heel-strike detection for the gait-cycle plot (side, foot)
};

}  // namespace gaitsynth
