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
/// "ok frames=N nonblank=1 character_px=a/b/c" into <div id="status"> (or "error: ..." when a
/// script error happened, caught by window.onerror), which tests read with headless Chromium's
/// --dump-dom (tests/viz/player_chromium.cpp). docs/viewer.md.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"
#include "gaitsynth/viz/player/assets.hpp"
#include "gaitsynth/viz/scene.hpp"
#include "gaitsynth/viz/svg.hpp"

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

namespace viz_detail {

/// Writes an asset (player/assets.hpp) piece by piece.
inline void write_asset(std::ostream& os, std::span<const std::string_view> pieces) {
  for (std::string_view p : pieces) os << p;
}

/// The shape list of a body as JSON (body frame).
inline std::string shapes_json(const body& b, const std::vector<Eigen::Vector3d>& ends) {
  auto v3 = [](const Eigen::Vector3d& v) {
    return "[" + jnum(v.x()) + "," + jnum(v.y()) + "," + jnum(v.z()) + "]";
  };
  std::string s = "\"shapes\":[";
  for (std::size_t k = 0; k < b.shapes.size(); ++k) {
    const shape& sh = b.shapes[k];
    if (k) s += ",";
    if (sh.type == shape::kind::box)
      s += "{\"k\":\"box\",\"c\":" + v3(sh.center) + ",\"h\":" + v3(sh.half_extents) + "}";
    else if (sh.type == shape::kind::capsule)
      s += "{\"k\":\"cap\",\"a\":" + v3(sh.p0) + ",\"b\":" + v3(sh.p1) +
           ",\"r\":" + jnum(sh.radius) + "}";
    else
      s += "{\"k\":\"sph\",\"c\":" + v3(sh.center) + ",\"r\":" + jnum(sh.radius) + "}";
  }
  s += "],\"ends\":[";
  for (std::size_t k = 0; k < ends.size(); ++k) {
    if (k) s += ',';
    s += v3(ends[k]);
  }
  return s + "]";
}

}  // namespace viz_detail

/// Writes the player page (see the file comment). Throws std::invalid_argument when the trajectory
/// does not fit the model (q sizes, names), has no frames, or the options are invalid.
template <root_joint Root>
void write_html_player(const model<Root>& m, const trajectory& traj, std::ostream& os,
                       const html_player_options& opt = {}) {
  using namespace viz_detail;
  check_trajectory(m, traj, "write_html_player");
  check_argument(!traj.frames.empty(), "write_html_player: the trajectory has no frames");
  check_positive(opt.max_frame_rate, "write_html_player: max_frame_rate");
  check_positive(opt.speed, "write_html_player: speed");
  check_argument(std::isfinite(opt.force_scale) && opt.force_scale >= 0,
                 "write_html_player: force_scale must be finite and >= 0, got ", opt.force_scale);
  const int nb = m.num_bodies();
  const int nc = static_cast<int>(m.contact_points.size());
  const int nj = m.num_joint_dofs();
  // Frames kept: the recorded frame nearest to each tick of a max_frame_rate clock (each once),
  // and always the last one.
  std::vector<int> keep;
  const double t0 = traj.frames.front().t, t1 = traj.frames.back().t;
  for (long k = 0; k <= 100000000; ++k) {
    const double t = t0 + k / opt.max_frame_rate;
    if (t > t1 + 1e-9) break;
    const int f = nearest_frame(traj, t);
    if (keep.empty() || f > keep.back()) keep.push_back(f);
  }
  if (keep.back() != static_cast<int>(traj.frames.size()) - 1)
    keep.push_back(static_cast<int>(traj.frames.size()) - 1);
  const int nf = static_cast<int>(keep.size());

  // Heel strikes for the gait-cycle plot (the trajectory's names are needed for the contacts).
  trajectory names_only;
  names_only.body_names = traj.body_names;
  names_only.body_parents = traj.body_parents;
  names_only.contact_bodies = traj.contact_bodies;
  if (names_only.body_parents.size() != static_cast<std::size_t>(nb)) {
    names_only.body_names.clear();
    names_only.body_parents.clear();
    for (const auto& b : m.bodies) {
      names_only.body_names.push_back(b.name);
      names_only.body_parents.push_back(b.parent);
    }
  }
  if (names_only.contact_bodies.size() != static_cast<std::size_t>(nc)) {
    names_only.contact_bodies.clear();
    for (const auto& c : m.contact_points) names_only.contact_bodies.push_back(c.body);
  }
  int foot = -1;
  if (!opt.cycles.foot.empty())
    foot = m.body_index(opt.cycles.foot);
  else
    foot = default_foot_body(names_only, opt.cycles.side);
  std::vector<double> cycles = opt.cycles.cycle_starts;
  if (cycles.empty() && foot >= 0) {
    names_only.frames.reserve(traj.frames.size());
    for (const auto& fr : traj.frames) {
      trajectory_frame lite;
      lite.t = fr.t;
      lite.contact_active = fr.contact_active;
      names_only.frames.push_back(std::move(lite));
    }
    cycles = heel_strike_times(names_only, foot, opt.cycles.min_cycle_duration);
  }
  // Joints plotted at first.
  std::vector<int> plot;
  for (const auto& n : opt.plot_joints) plot.push_back(m.dof_index(n));
  if (opt.plot_joints.empty()) {
    for (const char* side : {"l", "r"}) {
      try {
        for (const auto& c : default_gait_channels(m, side)) plot.push_back(m.dof_index(c.name));
      } catch (const std::invalid_argument&) {
      }
    }
    if (plot.empty())
      for (int j = 0; j < std::min(nj, 4); ++j) plot.push_back(j);
  }
  // Size of the character (camera distance) from the first frame.
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Quaterniond> R;
  frame_body_poses(m, traj.frames[keep[0]], P, R);
  Eigen::Vector3d lo = P[0], hi = P[0];
  std::vector<Eigen::Vector3d> local;
  for (int i = 0; i < nb; ++i) {
    body_points(m, i, local);
    for (const auto& l : local) {
      const Eigen::Vector3d w = P[i] + R[i] * l;
      lo = lo.cwiseMin(w);
      hi = hi.cwiseMax(w);
    }
  }
  const double size = std::max(0.3, (hi - lo).maxCoeff());
  const double weight = m.total_mass() * m.gravity.norm();
  const double force_scale =
      opt.force_scale > 0 ? opt.force_scale : (weight > 0 ? 0.5 / weight : 0.001);

  std::string d;
  d.reserve(static_cast<std::size_t>(nf) * (nb * 7 + nc * 7 + nj + 8) * 9 + 4096);
  d += "{\"name\":" + json_string(m.name) +
       ",\"planar\":" + (traj.planar || Root::nq == 3 ? "true" : "false");
  d += ",\"autoplay\":" + std::string(opt.autoplay ? "true" : "false") +
       ",\"speed\":" + jnum(opt.speed);
  d += ",\"size\":" + jnum(size, 4) + ",\"force_scale\":" + jnum(force_scale, 4);
  d += ",\"bodies\":[";
  for (int i = 0; i < nb; ++i) {
    const body& b = m.bodies[i];
    const body_side s = side_of_body(m, i);
    std::vector<Eigen::Vector3d> ends;
    if (b.shapes.empty()) {
      if (!b.segment_end.isZero()) ends.push_back(b.segment_end);
      for (int c = i + 1; c < nb; ++c)
        if (m.bodies[c].parent == i) ends.push_back(m.bodies[c].joint_offset);
    }
    d += std::string(i ? "," : "") + "{\"n\":" + json_string(b.name) +
         ",\"p\":" + std::to_string(b.parent) + ",\"side\":\"" +
         (s == body_side::left    ? "l"
          : s == body_side::right ? "r"
                                  : "c") +
         "\"," + shapes_json(b, ends) + "}";
  }
  d += "],\"contacts\":[";
  for (int k = 0; k < nc; ++k)
    d += std::string(k ? "," : "") + "{\"n\":" + json_string(m.contact_points[k].name) +
         ",\"b\":" + std::to_string(m.contact_points[k].body) + "}";
  d += "],\"joint_names\":[";
  for (int j = 0; j < nj; ++j) {
    if (j) d += ',';
    d += json_string(m.dofs[j].name);
  }
  d += "],\"plot_joints\":[";
  for (std::size_t k = 0; k < plot.size(); ++k) {
    if (k) d += ',';
    d += std::to_string(plot[k]);
  }
  const std::size_t no = traj.objective_term_names.size();
  d += "],\"obj_names\":[";
  for (std::size_t k = 0; k < no; ++k) {
    if (k) d += ',';
    d += json_string(traj.objective_term_names[k]);
  }
  d += "],\"foot\":" + json_string(foot >= 0 ? m.bodies[foot].name : std::string()) +
       ",\"cycles\":[";
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    if (k) d += ',';
    d += jnum(cycles[k], 8);
  }
  const terrain_samples& ts = traj.terrain;
  const bool has_terrain =
      ts.nx > 0 && ts.ny > 0 && ts.height.size() == static_cast<std::size_t>(ts.nx) * ts.ny;
  d += "],\"terrain\":{\"nx\":" + std::to_string(has_terrain ? ts.nx : 0) +
       ",\"ny\":" + std::to_string(has_terrain ? ts.ny : 0) + ",\"x0\":" + jnum(ts.x0) +
       ",\"y0\":" + jnum(ts.y0) + ",\"dx\":" + jnum(ts.dx) + ",\"dy\":" + jnum(ts.dy) + ",\"h\":[";
  if (has_terrain)
    for (std::size_t k = 0; k < ts.height.size(); ++k) {
      if (k) d += ',';
      d += jnum(ts.height[k], 5);
    }
  d += "]}";
  // Per-frame arrays, flattened.
  auto list = [&](const char* key, auto&& per_frame) {
    d += ",\"";
    d += key;
    d += "\":[";
    bool first = true;
    for (int f : keep) per_frame(traj.frames[f], first);
    d += "]";
  };
  auto put = [&](bool& first, const std::string& x) {
    if (!first) d += ",";
    d += x;
    first = false;
  };
  list("t", [&](const trajectory_frame& fr, bool& first) { put(first, jnum(fr.t, 8)); });
  std::vector<std::vector<Eigen::Vector3d>> poses_p(nf);
  std::vector<std::vector<Eigen::Quaterniond>> poses_r(nf);
  for (int k = 0; k < nf; ++k) frame_body_poses(m, traj.frames[keep[k]], poses_p[k], poses_r[k]);
  d += ",\"bp\":[";
  for (int k = 0; k < nf; ++k)
    for (int i = 0; i < nb; ++i)
      for (int c = 0; c < 3; ++c) {
        if (k || i || c) d += ',';
        d += jnum(poses_p[k][i][c], 6);
      }
  d += "],\"bq\":[";
  for (int k = 0; k < nf; ++k)
    for (int i = 0; i < nb; ++i) {
      const Eigen::Quaterniond& r = poses_r[k][i];
      const double q4[4] = {r.w(), r.x(), r.y(), r.z()};
      for (int c = 0; c < 4; ++c) {
        if (k || i || c) d += ',';
        d += jnum(q4[c], 5);
      }
    }
  d += "]";
  // COM: recorded, or the mean of the body origins when a hand-made frame left it at zero.
  list("cm", [&](const trajectory_frame& fr, bool& first) {
    Eigen::Vector3d c = fr.com;
    if (c.isZero(0.0)) {
      std::vector<Eigen::Vector3d> p;
      std::vector<Eigen::Quaterniond> r;
      frame_body_poses(m, fr, p, r);
      c.setZero();
      for (const auto& x : p) c += x / static_cast<double>(p.size());
    }
    for (int k = 0; k < 3; ++k) put(first, jnum(c[k], 6));
  });
  auto contact_pos = [&](const trajectory_frame& fr, int k) -> Eigen::Vector3d {
    if (static_cast<int>(fr.contact_position.size()) == nc) return fr.contact_position[k];
    std::vector<Eigen::Vector3d> p;
    std::vector<Eigen::Quaterniond> r;
    frame_body_poses(m, fr, p, r);
    const contact_point& cp = m.contact_points[k];
    return p[cp.body] + r[cp.body] * cp.position;
  };
  list("cp", [&](const trajectory_frame& fr, bool& first) {
    for (int k = 0; k < nc; ++k) {
      const Eigen::Vector3d p = contact_pos(fr, k);
      for (int c = 0; c < 3; ++c) put(first, jnum(p[c], 6));
    }
  });
  list("cf", [&](const trajectory_frame& fr, bool& first) {
    for (int k = 0; k < nc; ++k)
      for (int c = 0; c < 3; ++c)
        put(first, static_cast<int>(fr.contact_force.size()) == nc ? jnum(fr.contact_force[k][c], 4)
                                                                   : std::string("0"));
  });
  list("ca", [&](const trajectory_frame& fr, bool& first) {
    for (int k = 0; k < nc; ++k)
      put(first,
          static_cast<int>(fr.contact_active.size()) == nc && fr.contact_active[k] ? "1" : "0");
  });
  list("pushes", [&](const trajectory_frame& fr, bool& first) {
    std::string s = "[";
    for (std::size_t k = 0; k < fr.pushes.size(); ++k) {
      const auto& pu = fr.pushes[k];
      if (pu.first < 0 || pu.first >= nb) continue;
      s += std::string(s.size() > 1 ? "," : "") + "[" + std::to_string(pu.first) + "," +
           jnum(pu.second.x(), 4) + "," + jnum(pu.second.y(), 4) + "," + jnum(pu.second.z(), 4) +
           "]";
    }
    put(first, s + "]");
  });
  list("q", [&](const trajectory_frame& fr, bool& first) {
    for (int j = 0; j < nj; ++j) put(first, jnum(fr.q[Root::nq + j], 5));
  });
  list("obj", [&](const trajectory_frame& fr, bool& first) {
    for (std::size_t k = 0; k < no; ++k)
      put(first,
          k < fr.objective_terms.size() ? jnum(fr.objective_terms[k], 5) : std::string("null"));
  });
  list("cs", [&](const trajectory_frame& fr, bool& first) {
    put(first, std::to_string(fr.controller_state));
  });
  d += "}";

  const std::string title = opt.title.empty() ? m.name + " - gaitsynth player" : opt.title;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
     << "<title>" << xml_escape(title) << "</title>\n<style>";
  write_asset(os, player_assets::css);
  os << "</style>\n"
     << "</head>\n<body>\n<header><h1>" << xml_escape(title) << "</h1><span>" << xml_escape(m.name)
     << ", " << nb << " bodies, " << nj << " joint DOFs, " << nc << " contact points, "
     << fnum(traj.duration(), 3) << " s, " << nf << " frames"
     << "</span><span>drag: orbit, wheel: zoom, space: play/pause, arrows: step</span></header>";
  write_asset(os, player_assets::body);
  os << "<script id=\"gaitsynth-data\" type=\"application/json\">" << d << "</script>\n<script>";
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
