#pragma once
// The viewer flags every example offers, parsed in one place into gaitsynth::viz_outputs
// (io/viewer_outputs.hpp writes the files; docs/viewer.md):
//
//   --html FILE        self-contained HTML player (viz/html_player.hpp)
//   --filmstrip FILE   SVG strobe filmstrip (viz/filmstrip_svg.hpp), side view
//   --filmstrip-front FILE   the same seen from the front
//   --gait-svg FILE    SVG gait-cycle plot (viz/gait_plot_svg.hpp)
//   --bvh FILE         BVH motion (io/bvh.hpp)
//   --csv FILE         trajectory CSV (io/trajectory_csv.hpp)
//   --mjcf-replay FILE MJCF model with one keyframe per frame (io/mjcf_replay.hpp)
//
// Both "--html FILE" and "--html=FILE" are accepted.
//
//   int main(int argc, char** argv) {
//     gaitsynth::viz_outputs out = viewer_flags::extract(argc, argv);  // removes them
//     ... parse the remaining flags, run, record `traj` ...
//     gaitsynth::write_viz_outputs(model, traj, out, &std::cout);
//   }
#include <stdexcept>
#include <string>
#include <string_view>

#include "gaitsynth/io/viewer_outputs.hpp"

namespace viewer_flags {

/// One line per flag, for an example's --help.
inline const char* help() {
  return "  --html FILE         write a self-contained HTML player of the motion\n"
         "  --filmstrip FILE    write an SVG strobe filmstrip (side view)\n"
         "  --filmstrip-front FILE  write an SVG strobe filmstrip seen from the front\n"
         "  --gait-svg FILE     write SVG gait-cycle plots (hip, knee, ankle)\n"
         "  --bvh FILE          write the motion as BVH (centimetres, Y up)\n"
         "  --csv FILE          write the recorded trajectory as CSV\n"
         "  --mjcf-replay FILE  write an MJCF model with one keyframe per frame\n";
}

/// If argv[i] is one of the flags, stores its value, advances i past it and returns true.
/// Throws std::invalid_argument when the flag has no value.
inline bool parse_flag(int argc, char** argv, int& i, gaitsynth::viz_outputs& out) {
  using gaitsynth::viz_outputs;
  const std::string_view a = argv[i];
  struct flag {
    std::string_view name;
    std::string viz_outputs::*field;
  };
  static const flag flags[] = {{"--html", &viz_outputs::html},
                               {"--filmstrip", &viz_outputs::filmstrip_svg},
                               {"--filmstrip-front", &viz_outputs::filmstrip_front_svg},
                               {"--gait-svg", &viz_outputs::gait_svg},
                               {"--bvh", &viz_outputs::bvh},
                               {"--csv", &viz_outputs::trajectory_csv},
                               {"--mjcf-replay", &viz_outputs::mjcf_replay}};
  for (const flag& f : flags) {
    if (a == f.name) {
      if (i + 1 >= argc || argv[i + 1][0] == '\0' ||
          (argv[i + 1][0] == '-' && argv[i + 1][1] == '-'))
        throw std::invalid_argument(std::string(f.name) + " needs a file name");
      out.*(f.field) = argv[i + 1];
      i += 2;
      return true;
    }
    if (a.size() > f.name.size() + 1 && a.substr(0, f.name.size()) == f.name &&
        a[f.name.size()] == '=') {
      out.*(f.field) = std::string(a.substr(f.name.size() + 1));
      i += 1;
      return true;
    }
  }
  return false;
}

/// Removes every viewer flag and its value from argv, updating argc; returns what they ask for.
inline gaitsynth::viz_outputs extract(int& argc, char** argv) {
  gaitsynth::viz_outputs out;
  int w = 1;
  for (int i = 1; i < argc;) {
    if (parse_flag(argc, argv, i, out)) continue;
    argv[w++] = argv[i++];
  }
  argc = w;
  if (w >= 0) argv[w] = nullptr;  // argv[argc] is a null pointer, as for main's
  return out;
}

}  // namespace viewer_flags
