#pragma once
/// \file viewer_outputs.hpp
/// Every file a viewer or another tool reads from one recorded motion, written in one call:
///
///   html            self-contained HTML player (viz/html_player.hpp)
///   filmstrip_svg   SVG strobe filmstrip, side view (viz/filmstrip_svg.hpp)
///   filmstrip_front_svg  the same seen from the front
///   gait_svg        SVG gait-cycle plot (viz/gait_plot_svg.hpp)
///   bvh             BVH motion (io/bvh.hpp)
///   trajectory_csv  trajectory CSV (io/trajectory_csv.hpp)
///   mjcf_replay     MJCF model with one keyframe per frame (io/mjcf_replay.hpp)
///
/// A file whose name is empty is not written. The examples fill the names from their --html,
/// --filmstrip, ... flags (examples/viewer_flags.hpp, docs/viewer.md). Needs nlohmann::json (the
/// HTML player writes its data with it).
///
///     gaitsynth::viz_outputs out;
///     out.html = "walk.html";
///     out.html_options.title = "normal walk";
///     gaitsynth::write_viz_outputs(model, traj, out, &std::cout);
#include <ostream>
#include <string>

#include "gaitsynth/io/bvh.hpp"
#include "gaitsynth/io/mjcf_replay.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"
#include "gaitsynth/viz/gait_plot_svg.hpp"
#include "gaitsynth/viz/html_player.hpp"

namespace gaitsynth {

/// Files requested (empty: not requested), with the writers' options.
struct viz_outputs {
  std::string html, filmstrip_svg, filmstrip_front_svg, gait_svg, bvh, trajectory_csv, mjcf_replay;
  html_player_options html_options;
  filmstrip_options filmstrip;
  filmstrip_options filmstrip_front{.view = filmstrip_view::front};
  gait_plot_options gait;
  bvh_options bvh_opts;
  mjcf_replay_options mjcf;
  bool any() const {
    return !(html.empty() && filmstrip_svg.empty() && filmstrip_front_svg.empty() &&
             gait_svg.empty() && bvh.empty() && trajectory_csv.empty() && mjcf_replay.empty());
  }
};

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
  if (!out.filmstrip_front_svg.empty()) {
    save_filmstrip_svg(m, traj, out.filmstrip_front_svg, out.filmstrip_front);
    done("front filmstrip", out.filmstrip_front_svg);
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
