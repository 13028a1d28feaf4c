#pragma once
/// \file data.hpp
/// The data the HTML player's script (player/player.js, which reads it as `D`) draws: one JSON
/// object, built with nlohmann::json and embedded in the page by viz/html_player.hpp.
///
///   name, planar, autoplay, speed     model name; side view; playback at load
///   size, force_scale                 character size (m, camera distance); arrow m per N
///   bodies[]  {n, p, side, shapes[], ends[]}  name, parent, "l"/"r"/"c", shapes in the body
///             frame ({k:"box",c,h} | {k:"cap",a,b,r} | {k:"sph",c,r}), segment ends when none
///   contacts[] {n, b}                 contact point name and body
///   joint_names[], plot_joints[]      joint DOF names; the indices plotted at first
///   obj_names[], foot, cycles[]       objective terms; heel-strike foot and cycle start times (s)
///   terrain {nx, ny, x0, y0, dx, dy, h[]}  height samples, h[j * nx + i]; nx = ny = 0: flat
/// and per kept frame f, flattened in frame order (NB bodies, NC contacts, NJ joints, NO terms):
///   t[f]  bp[(f*NB+b)*3+c]  bq[(f*NB+b)*4+c] (w,x,y,z)  cm[f*3+c]  cp, cf [(f*NC+k)*3+c]
///   ca[f*NC+k] (1: touching)  pushes[f] = [[body, fx, fy, fz], ...]  q[f*NJ+j]  obj[f*NO+o]
///   cs[f] (controller state)
///
/// Numbers are rounded to what the page needs (significant digits below; player/json.hpp says
/// why); a missing objective term and any non-finite value are null.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/player/json.hpp"
#include "gaitsynth/viz/player/options.hpp"
#include "gaitsynth/viz/player/selection.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace gaitsynth::viz_detail {

/// Significant digits per kind of number: times keep 8 (10 ns over 1000 s), lengths 6 (1 um at
/// 1 m), unit quaternions, angles, terrain and objective terms 5, forces and the derived scales 4:
/// each finer than the drawing or the plots can show.
struct player_digits {
  static constexpr int time = 8, length = 6, rotation = 5, terrain = 5, objective = 5, force = 4,
                       scale = 4, option = 6;
};

/// The page data (see the file comment). Throws std::invalid_argument, naming `who`, when the
/// trajectory does not fit the model (q sizes, names), has no frames, or the options are invalid.
template <root_joint Root>
nlohmann::ordered_json player_data(const model<Root>& m, const trajectory& traj,
                                   const html_player_options& opt,
                                   const char* who = "write_html_player") {
  using json = nlohmann::ordered_json;
  using dg = player_digits;
  check_trajectory(m, traj, who);
  check_argument(!traj.frames.empty(), who, ": the trajectory has no frames");
  check_positive(opt.max_frame_rate, (std::string(who) + ": max_frame_rate").c_str());
  check_positive(opt.speed, (std::string(who) + ": speed").c_str());
  check_argument(std::isfinite(opt.force_scale) && opt.force_scale >= 0, who,
                 ": force_scale must be finite and >= 0, got ", opt.force_scale);
  const int nb = m.num_bodies();
  const int nc = static_cast<int>(m.contact_points.size());
  const int nj = m.num_joint_dofs();
  const std::size_t no = traj.objective_term_names.size();
  const std::vector<int> keep = player_frames(traj, opt.max_frame_rate);
  int foot = -1;
  const std::vector<double> cycles = player_cycles(m, traj, opt.cycles, foot);
  auto r = [](double x, int sig) { return page_number(x, sig); };
  auto v3 = [&](const Eigen::Vector3d& v) {
    return json::array({r(v.x(), dg::length), r(v.y(), dg::length), r(v.z(), dg::length)});
  };

  json d = json::object();
  d["name"] = m.name;
  d["planar"] = traj.planar || Root::nq == 3;
  d["autoplay"] = opt.autoplay;
  d["speed"] = r(opt.speed, dg::option);
  d["size"] = r(character_size(m, traj.frames[keep[0]]), dg::scale);
  d["force_scale"] = r(player_force_scale(m, opt.force_scale), dg::scale);
  json bodies = json::array();
  for (int i = 0; i < nb; ++i) {
    const body& b = m.bodies[i];
    const body_side s = side_of_body(m, i);
    json shapes = json::array(), ends = json::array();
    for (const shape& sh : b.shapes) {
      if (sh.type == shape::kind::box)
        shapes.push_back({{"k", "box"}, {"c", v3(sh.center)}, {"h", v3(sh.half_extents)}});
      else if (sh.type == shape::kind::capsule)
        shapes.push_back(
            {{"k", "cap"}, {"a", v3(sh.p0)}, {"b", v3(sh.p1)}, {"r", r(sh.radius, dg::length)}});
      else
        shapes.push_back({{"k", "sph"}, {"c", v3(sh.center)}, {"r", r(sh.radius, dg::length)}});
    }
    if (b.shapes.empty()) {  // drawn as segments from the origin to these points
      if (!b.segment_end.isZero()) ends.push_back(v3(b.segment_end));
      for (int c = i + 1; c < nb; ++c)
        if (m.bodies[c].parent == i) ends.push_back(v3(m.bodies[c].joint_offset));
    }
    bodies.push_back({{"n", b.name},
                      {"p", b.parent},
                      {"side", s == body_side::left    ? "l"
                               : s == body_side::right ? "r"
                                                       : "c"},
                      {"shapes", std::move(shapes)},
                      {"ends", std::move(ends)}});
  }
  d["bodies"] = std::move(bodies);
  json contacts = json::array();
  for (const contact_point& cp : m.contact_points)
    contacts.push_back({{"n", cp.name}, {"b", cp.body}});
  d["contacts"] = std::move(contacts);
  std::vector<std::string> joint_names;
  for (int j = 0; j < nj; ++j) joint_names.push_back(m.dofs[j].name);
  d["joint_names"] = std::move(joint_names);
  d["plot_joints"] = player_plot_joints(m, opt.plot_joints);
  d["obj_names"] = traj.objective_term_names;
  d["foot"] = foot >= 0 ? m.bodies[foot].name : std::string();
  json cyc = json::array();
  for (double c : cycles) cyc.push_back(r(c, dg::time));
  d["cycles"] = std::move(cyc);
  const terrain_samples& ts = traj.terrain;
  const bool has_terrain =
      ts.nx > 0 && ts.ny > 0 && ts.height.size() == static_cast<std::size_t>(ts.nx) * ts.ny;
  json h = json::array();
  if (has_terrain)
    for (double x : ts.height) h.push_back(r(x, dg::terrain));
  d["terrain"] = {{"nx", has_terrain ? ts.nx : 0},
                  {"ny", has_terrain ? ts.ny : 0},
                  {"x0", r(ts.x0, dg::length)},
                  {"y0", r(ts.y0, dg::length)},
                  {"dx", r(ts.dx, dg::length)},
                  {"dy", r(ts.dy, dg::length)},
                  {"h", std::move(h)}};

  // Per-frame arrays, flattened (the script indexes them; nested arrays would cost a JavaScript
  // object per frame and body).
  json t = json::array(), bp = json::array(), bq = json::array(), cm = json::array();
  json cp = json::array(), cf = json::array(), ca = json::array(), pushes = json::array();
  json q = json::array(), obj = json::array(), cs = json::array();
  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Quaterniond> R;
  for (int f : keep) {
    const trajectory_frame& fr = traj.frames[f];
    frame_body_poses(m, fr, P, R);
    t.push_back(r(fr.t, dg::time));
    for (int i = 0; i < nb; ++i) {
      for (int c = 0; c < 3; ++c) bp.push_back(r(P[i][c], dg::length));
      for (double x : {R[i].w(), R[i].x(), R[i].y(), R[i].z()}) bq.push_back(r(x, dg::rotation));
    }
    // COM: recorded, or the mean of the body origins when a hand-made frame left it at zero.
    Eigen::Vector3d com = fr.com;
    if (com.isZero(0.0)) {
      com.setZero();
      for (const auto& x : P) com += x / static_cast<double>(P.size());
    }
    for (int c = 0; c < 3; ++c) cm.push_back(r(com[c], dg::length));
    const bool has_cp = static_cast<int>(fr.contact_position.size()) == nc;
    const bool has_cf = static_cast<int>(fr.contact_force.size()) == nc;
    const bool has_ca = static_cast<int>(fr.contact_active.size()) == nc;
    for (int k = 0; k < nc; ++k) {
      const contact_point& pt = m.contact_points[k];
      const Eigen::Vector3d p =
          has_cp ? fr.contact_position[k] : Eigen::Vector3d(P[pt.body] + R[pt.body] * pt.position);
      for (int c = 0; c < 3; ++c) {
        cp.push_back(r(p[c], dg::length));
        cf.push_back(has_cf ? r(fr.contact_force[k][c], dg::force) : json(0));
      }
      ca.push_back(has_ca && fr.contact_active[k] ? 1 : 0);
    }
    json pu = json::array();
    for (const auto& [b, force] : fr.pushes)
      if (b >= 0 && b < nb)
        pu.push_back(
            {b, r(force.x(), dg::force), r(force.y(), dg::force), r(force.z(), dg::force)});
    pushes.push_back(std::move(pu));
    for (int j = 0; j < nj; ++j) q.push_back(r(fr.q[Root::nq + j], dg::rotation));
    for (std::size_t k = 0; k < no; ++k)
      obj.push_back(k < fr.objective_terms.size() ? r(fr.objective_terms[k], dg::objective)
                                                  : json(nullptr));
    cs.push_back(fr.controller_state);
  }
  d["t"] = std::move(t);
  d["bp"] = std::move(bp);
  d["bq"] = std::move(bq);
  d["cm"] = std::move(cm);
  d["cp"] = std::move(cp);
  d["cf"] = std::move(cf);
  d["ca"] = std::move(ca);
  d["pushes"] = std::move(pushes);
  d["q"] = std::move(q);
  d["obj"] = std::move(obj);
  d["cs"] = std::move(cs);
  return d;
}

}  // namespace gaitsynth::viz_detail
