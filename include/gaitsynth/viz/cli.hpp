#pragma once
/// \file cli.hpp
/// The output flags every example offers, parsed and acted on in one place:
///
///   --html FILE        self-contained HTML player (viz/html_player.hpp)
///   --filmstrip FILE   SVG strobe filmstrip (viz/filmstrip_svg.hpp)
///   --gait-svg FILE    SVG gait-cycle plot (viz/gait_plot_svg.hpp)
///   --bvh FILE         BVH motion (io/bvh.hpp)
///   --csv FILE         trajectory CSV (io/trajectory_csv.hpp)
///   --mjcf-replay FILE MJCF model with one keyframe per frame (io/mjcf_replay.hpp)
///
/// Both "--html FILE" and "--html=FILE" are accepted.
///
///   int main(int argc, char** argv) {
///     gaitsynth::viz_outputs out = gaitsynth::extract_viz_flags(argc, argv);  // removes them
///     ... parse the remaining flags, run, record `traj` ...
///     gaitsynth::write_viz_outputs(model, traj, out, &std::cout);
///   }
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "gaitsynth/io/bvh.hpp"
#include "gaitsynth/io/mjcf_replay.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"
#include "gaitsynth/viz/gait_plot_svg.hpp"
#include "gaitsynth/viz/html_player.hpp"

namespace gaitsynth {

/// Files requested on the command line (empty: not requested), with the writers' options.
struct viz_outputs {
  std::string html, filmstrip_svg, gait_svg, bvh, trajectory_csv, mjcf_replay;
  html_player_options html_options;
  filmstrip_options filmstrip;
  gait_plot_options gait;
  bvh_options bvh_opts;
  mjcf_replay_options mjcf;
  bool any() const {
    return !(html.empty() && filmstrip_svg.empty() && gait_svg.empty() && bvh.empty() &&
             trajectory_csv.empty() && mjcf_replay.empty());
  }
};

/// One line per flag, for an example's --help.
inline const char* viz_flags_help() {
  return "  --html FILE         write a self-contained HTML player of the motion\n"
         "  --filmstrip FILE    write an SVG strobe filmstrip (side view)\n"
         "  --gait-svg FILE     write SVG gait-cycle plots (hip, knee, ankle)\n"
         "  --bvh FILE          write the motion as BVH (centimetres, Y up)\n"
         "  --csv FILE          write the recorded trajectory as CSV\n"
         "  --mjcf-replay FILE  write an MJCF model with one keyframe per frame\n";
}

/// If argv[i] is one of the flags, stores its value, advances i past it and returns true.
/// Throws std::invalid_argument when the flag has no value.
inline bool parse_viz_flag(int argc, char** argv, int& i, viz_outputs& out) {
  const std::string_view a = argv[i];
  struct flag {
    std::string_view name;
    std::string viz_outputs::*field;
  };
  static const flag flags[] = {
      {"--html", &viz_outputs::html},          {"--filmstrip", &viz_outputs::filmstrip_svg},
      {"--gait-svg", &viz_outputs::gait_svg},  {"--bvh", &viz_outputs::bvh},
      {"--csv", &viz_outputs::trajectory_csv}, {"--mjcf-replay", &viz_outputs::mjcf_replay}};
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

/// Removes every viz flag (and its value) from argv, updating argc; returns what they asked for.
inline viz_outputs extract_viz_flags(int& argc, char** argv) {
  viz_outputs out;
  int w = 1;
  for (int i = 1; i < argc;) {
    if (parse_viz_flag(argc, argv, i, out)) continue;
    argv[w++] = argv[i++];
  }
  argc = w;
  if (w >= 0) argv[w] = nullptr;  // argv[argc] is a null pointer, as for main's
  return out;
}

/// Writes every requested output; `log` (if given) gets one line per file written.
template <root_joint Root>
void write_viz_outputs(const model<Root>& m, const trajectory& traj, const viz_outputs& out,
                       std::ostream* log = nullptr) {
  auto done = [&](const char* what, const std::string& path) {
    if (log) *log << "wrote " << what << ": " << path << "\n";
  };
  if (!out.html.empty()) {
    save_html_player(m, traj, out.html, out.html_options);
    done("HTML player", out.html);
  }
  if (!out.filmstrip_svg.empty()) {
    save_filmstrip_svg(m, traj, out.filmstrip_svg, out.filmstrip);
    done("filmstrip", out.filmstrip_svg);
  }
  if (!out.gait_svg.empty()) {
    save_gait_plot_svg(m, traj, out.gait_svg, out.gait);
    done("gait-cycle plot", out.gait_svg);
  }
  if (!out.bvh.empty()) {
    save_bvh(m, traj, out.bvh, out.bvh_opts);
    done("BVH", out.bvh);
  }
  if (!out.trajectory_csv.empty()) {
    save_trajectory_csv(traj, out.trajectory_csv);
    done("trajectory CSV", out.trajectory_csv);
  }
  if (!out.mjcf_replay.empty()) {
    save_mjcf_replay(m, traj, out.mjcf_replay, out.mjcf);
    done("MJCF replay", out.mjcf_replay);
  }
}

}  // namespace gaitsynth
