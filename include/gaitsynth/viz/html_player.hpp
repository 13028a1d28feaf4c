#pragma once
/// \file html_player.hpp
/// A self-contained HTML player for a recorded trajectory: one file, no network access (all script
/// and style inline, no library), drawn on a 2-D canvas with its own small 3-D projection.
///
/// It shows the character (bodies as the model's boxes, capsules and spheres; a segment to the
/// children when a body has no shape), the ground or the recorded terrain samples, the contact
/// points (red when touching) with their force arrows, push forces (orange arrows into the body)
/// and the COM. Orbit camera (drag to rotate, wheel to zoom, following the COM); planar characters
/// start in an orthographic side view. Play / pause (space), speed, a time scrubber, frame
/// stepping (arrow keys). Beside the view: joint angles against time or percent of the gait cycle
/// (cycles between heel strikes, gait_cycles.hpp) and the objective terms against time.
///
/// The page checks itself: after a few animation frames it reads the canvas pixels and writes
/// "ok frames=N nonblank=1 character_px=a/b/c ..." into <div id="status" hidden> (or "error: ..."
/// when a script error happened, caught by window.onerror), which tests read with headless
/// Chromium's --dump-dom (tests/viz/player_chromium.cpp). The line is hidden from people unless
/// the page is opened with ?selftest or a script error happened. docs/viewer.md.
///
/// The page is assembled here from parts kept in files of their own: the script, style and
/// markup (player/player.js, player.css, player_body.html, embedded by player/assets.hpp, which
/// scripts/embed_player_assets.py generates) and the data the script draws (player/data.hpp, JSON
/// written with nlohmann::json: this header needs <nlohmann/json.hpp>).
#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/player/assets.hpp"
#include "gaitsynth/viz/player/data.hpp"
#include "gaitsynth/viz/player/json.hpp"
#include "gaitsynth/viz/player/options.hpp"
#include "gaitsynth/viz/svg.hpp"

namespace gaitsynth {

namespace viz_detail {

/// Writes an asset (player/assets.hpp) piece by piece.
inline void write_asset(std::ostream& os, std::span<const std::string_view> pieces) {
  for (std::string_view p : pieces) os << p;
}

}  // namespace viz_detail

/// Writes the player page (see the file comment). Throws std::invalid_argument when the trajectory
/// does not fit the model (q sizes, names), has no frames, or the options are invalid.
template <root_joint Root>
void write_html_player(const model<Root>& m, const trajectory& traj, std::ostream& os,
                       const html_player_options& opt = {}) {
  using namespace viz_detail;
  // All of the data first: invalid arguments throw before anything is written.
  const nlohmann::ordered_json data = player_data(m, traj, opt, "write_html_player");
  const std::size_t nf = data["t"].size();
  const int nb = m.num_bodies(), nj = m.num_joint_dofs();
  const int nc = static_cast<int>(m.contact_points.size());
  const std::string title = opt.title.empty() ? m.name + " - gaitsynth player" : opt.title;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
     << "<title>" << xml_escape(title) << "</title>\n<style>\n";
  write_asset(os, player_assets::css);
  os << "</style>\n"
     << "</head>\n<body>\n<header><h1>" << xml_escape(title) << "</h1><span>" << xml_escape(m.name)
     << ", " << nb << " bodies, " << nj << " joint DOFs, " << nc << " contact points, "
     << fnum(traj.duration(), 3) << " s, " << nf << " frames"
     << "</span><span>drag: orbit, wheel: zoom, space: play/pause, arrows: step</span></header>\n";
  write_asset(os, player_assets::body);
  os << "<script id=\"gaitsynth-data\" type=\"application/json\">" << script_json(data)
     << "</script>\n<script>\n";
  write_asset(os, player_assets::js);
  os << "</script>\n</body>\n</html>\n";
}

/// Writes the player page to `path` (nothing when the arguments are invalid); std::runtime_error
/// when the file cannot be written.
template <root_joint Root>
void save_html_player(const model<Root>& m, const trajectory& traj, const std::string& path,
                      const html_player_options& opt = {}) {
  std::ostringstream s;
  write_html_player(m, traj, s, opt);
  viz_detail::save_text(path, s.str(), "save_html_player");
}

}  // namespace gaitsynth
