#pragma once
/// \file filmstrip_svg.hpp
/// Strobe filmstrip of a recorded trajectory as SVG, like the papers' figures: the character drawn
/// in side view (orthographic projection on the x-z plane, seen from -y) at a fixed time interval,
/// each copy at its own place along the path, earlier copies fainter. The front view (on the y-z
/// plane, seen from +x, the walker coming towards the viewer) sets the copies side by side,
/// `spread` apart, so that the lateral sway, step width and arm swing of a 3-D walker show. Bodies
/// are drawn from the model's shapes (box outlines, capsules, spheres; a segment to the children or
/// to segment_end when a body has none), far (left, +y) limbs first, with the terrain profile under
/// the path, the contact points that touch and the COM path. docs/viewer.md.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/scene.hpp"
#include "gaitsynth/viz/svg.hpp"

namespace gaitsynth {

/// Where the filmstrip is seen from.
enum class filmstrip_view {
  side,  ///< from -y: x to the right, frames at their own x (plus `spread`)
  front  ///< from +x: y to the right, frames `spread` (default 0.9 m) apart
};

struct filmstrip_options {
  double interval = 0.0;  ///< s between strobe frames; 0: (t_end - t_begin) / (count - 1)
  int count = 10;         ///< strobe frames when interval == 0
  double t_begin = -std::numeric_limits<double>::infinity();  ///< s (clamped to the trajectory)
  double t_end = std::numeric_limits<double>::infinity();     ///< s
  /// Extra shift per strobe frame along the picture's horizontal, m: in side view it separates
  /// frames of a slow walk (the terrain is drawn at the shifted places, so this is meant for flat
  /// ground); in front view it sets the frames side by side (0: 0.9 m).
  double spread = 0.0;
  double width = 1200;        ///< SVG width, px (height follows from the drawing's aspect ratio)
  bool fade = true;           ///< earlier frames fainter
  bool show_contacts = true;  ///< touching contact points as red dots
  bool show_forces = false;   ///< contact force arrows (0.5 m per body weight)
  bool show_com_path = true;  ///< COM path as a dashed line
  bool show_terrain = true;   ///< terrain profile at the COM's y
  bool show_times = false;    ///< "t = ..." under each strobe frame
  std::string title;          ///< shown above the strip when not empty
  filmstrip_view view = filmstrip_view::side;
};

namespace viz_detail {

struct film_item {
  double depth;  ///< view-frame y (larger: farther from the viewer)
  int order;     ///< tie breaker: draw order
  std::string svg;
};

/// Convex hull (Andrew's monotone chain) of 2-D points, counter-clockwise.
inline std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

inline const char* side_colour(body_side s) {
  switch (s) {
    case body_side::left:
      return "#6f9bd8";
    case body_side::right:
      return "#dd8452";
    default:
      return "#a3a3a3";
  }
}

}  // namespace viz_detail

/// Writes the filmstrip SVG. Throws std::invalid_argument for a trajectory that does not fit the
/// model (q size), bad options, or an empty time window.
template <root_joint Root>
void write_filmstrip_svg(const model<Root>& m, const trajectory& traj, std::ostream& os,
                         const filmstrip_options& opt = {}) {
  using namespace viz_detail;
  check_trajectory(m, traj, "write_filmstrip_svg");
  check_argument(!traj.frames.empty(), "write_filmstrip_svg: the trajectory has no frames");
  check_argument(opt.count >= 1, "write_filmstrip_svg: count must be >= 1, got ", opt.count);
  check_argument(std::isfinite(opt.interval) && opt.interval >= 0,
                 "write_filmstrip_svg: interval must be finite and >= 0, got ", opt.interval);
  check_argument(std::isfinite(opt.spread), "write_filmstrip_svg: spread is not finite");
  check_positive(opt.width, "write_filmstrip_svg: width");
  const double ta = std::max(opt.t_begin, traj.frames.front().t);
  const double tb = std::min(opt.t_end, traj.frames.back().t);
  check_argument(ta <= tb, "write_filmstrip_svg: empty time window [", opt.t_begin, ", ", opt.t_end,
                 "] s for a trajectory over [", traj.frames.front().t, ", ", traj.frames.back().t,
                 "] s");
  // Strobe times.
  std::vector<int> strobe;
  const double step =
      opt.interval > 0 ? opt.interval : (opt.count > 1 ? (tb - ta) / (opt.count - 1) : 0.0);
  for (int k = 0;; ++k) {
    const double t = ta + k * step;
    if (t > tb + 1e-9 || (step == 0 && k > 0) || k > 100000) break;
    const int f = nearest_frame(traj, t);
    if (strobe.empty() || strobe.back() != f) strobe.push_back(f);
  }
  const int nb = m.num_bodies();
  const double weight = m.total_mass() * m.gravity.norm();
  const double force_scale = weight > 0 ? 0.5 / weight : 0.0;
  // Geometry of every strobe frame in world coordinates, plus the bounding box.
  double xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
  auto grow = [&](double x, double z) {
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
    zmin = std::min(zmin, z);
    zmax = std::max(zmax, z);
  };
  std::vector<std::vector<Eigen::Vector3d>> P(strobe.size());
  std::vector<std::vector<Eigen::Quaterniond>> R(strobe.size());
  std::vector<Eigen::Vector3d> local;
  // The picture is drawn in a view frame: x to the right, z up, y away from the viewer. Side view:
  // the world frame. Front view: the world turned 90 degrees about z (world y to the right, world
  // -x away from the viewer).
  const bool front = opt.view == filmstrip_view::front;
  const Eigen::Matrix3d V = front ? (Eigen::Matrix3d() << 0, 1, 0, -1, 0, 0, 0, 0, 1).finished()
                                  : Eigen::Matrix3d::Identity();
  const double spread = front && opt.spread == 0.0 ? 0.9 : opt.spread;
  auto shift_of = [&](std::size_t k) { return Eigen::Vector3d(k * spread, 0, 0); };
  for (std::size_t k = 0; k < strobe.size(); ++k) {
    frame_body_poses(m, traj.frames[strobe[k]], P[k], R[k]);
    for (int i = 0; i < nb; ++i) {
      P[k][i] = V * P[k][i] + shift_of(k);
      R[k][i] = Eigen::Quaterniond(V) * R[k][i];
      body_points(m, i, local);
      double r = 0;
      for (const shape& s : m.bodies[i].shapes) r = std::max(r, s.radius);
      for (const auto& l : local) {
        const Eigen::Vector3d w = P[k][i] + R[k][i] * l;
        grow(w.x() - r, w.z() - r);
        grow(w.x() + r, w.z() + r);
      }
    }
  }
  const double ground_y = traj.frames[strobe.front()].com.y();
  double gx0 = xmin, gx1 = xmax;
  // Front view: under each frame, the terrain across the walking direction at its COM.
  const double half_slot = 0.5 * std::max(spread, 0.2);
  auto front_ground = [&](std::size_t k, double u) {
    const Eigen::Vector3d& c = traj.frames[strobe[k]].com;
    return terrain_height(traj.terrain, c.x(), u);
  };
  if (opt.show_terrain && front) {
    for (std::size_t k = 0; k < strobe.size(); ++k) {
      const double y0 = traj.frames[strobe[k]].com.y();
      for (const double u : {y0 - half_slot, y0 + half_slot}) {
        grow(u + shift_of(k).x(), front_ground(k, u));
        grow(u + shift_of(k).x(), front_ground(k, u) - 0.05);
      }
    }
  } else if (opt.show_terrain) {
    const double pad = 0.04 * (xmax - xmin) + 0.05;
    gx0 = xmin - pad;
    gx1 = xmax + pad;
    for (int s = 0; s <= 200; ++s) {
      const double x = gx0 + (gx1 - gx0) * s / 200.0;
      grow(x, terrain_height(traj.terrain, x, ground_y));
    }
    grow(gx0, zmin - 0.05);
  }
  const double margin = 0.05 * std::max(xmax - xmin, zmax - zmin) + 0.02;
  xmin -= margin;
  xmax += margin;
  zmin -= margin;
  zmax += margin;
  const double scale = opt.width / (xmax - xmin);  // px per m
  const double title_h = opt.title.empty() ? 0.0 : 30.0;
  const double times_h = opt.show_times ? 18.0 : 0.0;
  const double H = (zmax - zmin) * scale + title_h + times_h;
  auto X = [&](double x) { return (x - xmin) * scale; };
  auto Z = [&](double z) { return title_h + (zmax - z) * scale; };
  auto pt = [&](double x, double z) {
    std::string s = fnum(X(x), 1);
    s += ',';
    s += fnum(Z(z), 1);
    return s;
  };

  svg_open(os, opt.width, H, opt.title.empty() ? m.name + " filmstrip" : opt.title);
  if (!opt.title.empty())
    os << "<text x=\"" << fnum(opt.width / 2) << "\" y=\"20\" text-anchor=\"middle\" "
       << "font-family=\"sans-serif\" font-size=\"15\" font-weight=\"bold\">"
       << xml_escape(opt.title) << "</text>\n";
  if (opt.show_terrain && front) {
    for (std::size_t k = 0; k < strobe.size(); ++k) {
      const double y0 = traj.frames[strobe[k]].com.y(), h0 = shift_of(k).x();
      std::string pts = pt(y0 - half_slot + h0, zmin);
      for (int s = 0; s <= 20; ++s) {
        const double u = y0 - half_slot + 2 * half_slot * s / 20.0;
        pts += " " + pt(u + h0, front_ground(k, u));
      }
      pts += " " + pt(y0 + half_slot + h0, zmin);
      os << "<polygon class=\"terrain\" fill=\"#ecebe4\" stroke=\"#77756b\" "
            "stroke-width=\"1.2\" points=\""
         << pts << "\"/>\n";
    }
  } else if (opt.show_terrain) {
    std::string pts = pt(gx0, zmin);
    for (int s = 0; s <= 200; ++s) {
      const double x = gx0 + (gx1 - gx0) * s / 200.0;
      pts += " " + pt(x, terrain_height(traj.terrain, x, ground_y));
    }
    pts += " " + pt(gx1, zmin);
    os << "<polygon class=\"terrain\" fill=\"#ecebe4\" stroke=\"#77756b\" stroke-width=\"1.2\" "
          "points=\""
       << pts << "\"/>\n";
  }
  if (opt.show_com_path) {
    std::string pts;
    for (const auto& fr : traj.frames)
      if (fr.t >= ta - 1e-12 && fr.t <= tb + 1e-12 && fr.com.allFinite() && spread == 0)
        pts += pt(fr.com.x(), fr.com.z()) + " ";
    if (!pts.empty())
      os << "<polyline class=\"com-path\" fill=\"none\" stroke=\"#555\" stroke-width=\"1\" "
            "stroke-dasharray=\"4 3\" points=\""
         << pts << "\"/>\n";
  }
  const double px_per_m = scale;
  for (std::size_t k = 0; k < strobe.size(); ++k) {
    const trajectory_frame& fr = traj.frames[strobe[k]];
    const double opacity = opt.fade && strobe.size() > 1
                               ? 0.45 + 0.55 * static_cast<double>(k) / (strobe.size() - 1)
                               : 1.0;
    std::vector<film_item> items;
    int order = 0;
    for (int i = 0; i < nb; ++i) {
      const body& b = m.bodies[i];
      const body_side side = side_of_body(m, i);
      const char* col = side_colour(side);
      // Far side first: larger y, and for planar models (all y = 0) left before centre and right.
      const double depth = P[k][i].y() + (side == body_side::left    ? 1e-6
                                          : side == body_side::right ? -1e-6
                                                                     : 0.0);
      auto W = [&](const Eigen::Vector3d& l) -> Eigen::Vector3d { return P[k][i] + R[k][i] * l; };
      std::ostringstream s;
      for (const shape& sh : b.shapes) {
        if (sh.type == shape::kind::box) {
          std::vector<Eigen::Vector2d> corners;
          for (int c = 0; c < 8; ++c) {
            const Eigen::Vector3d w = W(
                sh.center + Eigen::Vector3d((c & 1) ? sh.half_extents.x() : -sh.half_extents.x(),
                                            (c & 2) ? sh.half_extents.y() : -sh.half_extents.y(),
                                            (c & 4) ? sh.half_extents.z() : -sh.half_extents.z()));
            corners.emplace_back(w.x(), w.z());
          }
          s << "<polygon fill=\"" << col << "\" stroke=\"#333\" stroke-width=\"1\" points=\"";
          for (const auto& c : convex_hull(corners)) s << pt(c.x(), c.y()) << " ";
          s << "\"/>";
        } else if (sh.type == shape::kind::capsule) {
          const Eigen::Vector3d a = W(sh.p0), e = W(sh.p1);
          const double w = 2 * sh.radius * px_per_m;
          for (int pass = 0; pass < 2; ++pass)
            s << "<line x1=\"" << fnum(X(a.x()), 1) << "\" y1=\"" << fnum(Z(a.z()), 1) << "\" x2=\""
              << fnum(X(e.x()), 1) << "\" y2=\"" << fnum(Z(e.z()), 1) << "\" stroke=\""
              << (pass == 0 ? "#333" : col) << "\" stroke-width=\""
              << fnum(pass == 0 ? w + 2 : w, 1) << "\" stroke-linecap=\"round\"/>";
        } else {
          const Eigen::Vector3d c = W(sh.center);
          s << "<circle cx=\"" << fnum(X(c.x()), 1) << "\" cy=\"" << fnum(Z(c.z()), 1) << "\" r=\""
            << fnum(sh.radius * px_per_m, 1) << "\" fill=\"" << col
            << "\" stroke=\"#333\" stroke-width=\"1\"/>";
        }
      }
      if (b.shapes.empty()) {
        std::vector<Eigen::Vector3d> ends;
        if (!b.segment_end.isZero()) ends.push_back(b.segment_end);
        for (int c = i + 1; c < nb; ++c)
          if (m.bodies[c].parent == i) ends.push_back(m.bodies[c].joint_offset);
        const Eigen::Vector3d a = P[k][i];
        for (const auto& l : ends) {
          const Eigen::Vector3d e = W(l);
          s << "<line x1=\"" << fnum(X(a.x()), 1) << "\" y1=\"" << fnum(Z(a.z()), 1) << "\" x2=\""
            << fnum(X(e.x()), 1) << "\" y2=\"" << fnum(Z(e.z()), 1) << "\" stroke=\"" << col
            << "\" stroke-width=\"" << fnum(std::max(2.0, 0.03 * px_per_m), 1)
            << "\" stroke-linecap=\"round\"/>";
        }
        s << "<circle cx=\"" << fnum(X(a.x()), 1) << "\" cy=\"" << fnum(Z(a.z()), 1) << "\" r=\""
          << fnum(std::max(1.5, 0.015 * px_per_m), 1) << "\" fill=\"#333\"/>";
      }
      items.push_back({depth, order++, s.str()});
    }
    std::stable_sort(items.begin(), items.end(), [](const film_item& a, const film_item& b) {
      return a.depth > b.depth || (a.depth == b.depth && a.order < b.order);
    });
    os << "<g class=\"strobe\" data-t=\"" << fnum(fr.t, 4) << "\" opacity=\"" << fnum(opacity, 3)
       << "\">\n";
    for (const auto& it : items) os << it.svg << "\n";
    const Eigen::Vector3d shift = shift_of(k);
    if (opt.show_contacts || opt.show_forces) {
      for (std::size_t c = 0; c < fr.contact_active.size() && c < fr.contact_position.size(); ++c) {
        if (!fr.contact_active[c]) continue;
        const Eigen::Vector3d p = V * fr.contact_position[c] + shift;
        if (opt.show_contacts)
          os << "<circle class=\"contact\" cx=\"" << fnum(X(p.x()), 1) << "\" cy=\""
             << fnum(Z(p.z()), 1) << "\" r=\"3\" fill=\"#d62728\"/>\n";
        if (opt.show_forces && c < fr.contact_force.size()) {
          const Eigen::Vector3d e = p + force_scale * (V * fr.contact_force[c]);
          os << "<line class=\"force\" x1=\"" << fnum(X(p.x()), 1) << "\" y1=\""
             << fnum(Z(p.z()), 1) << "\" x2=\"" << fnum(X(e.x()), 1) << "\" y2=\""
             << fnum(Z(e.z()), 1) << "\" stroke=\"#2ca02c\" stroke-width=\"1.5\"/>\n";
        }
      }
    }
    os << "</g>\n";
    if (opt.show_times)
      os << "<text x=\"" << fnum(X(P[k][0].x()), 1) << "\" y=\"" << fnum(H - 4, 1)
         << "\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"10\" fill=\"#555\">"
         << fnum(fr.t, 2) << " s</text>\n";
  }
  svg_close(os);
}

/// Writes the filmstrip to `path` (nothing is written when the arguments are invalid).
template <root_joint Root>
void save_filmstrip_svg(const model<Root>& m, const trajectory& traj, const std::string& path,
                        const filmstrip_options& opt = {}) {
  std::ostringstream s;
  write_filmstrip_svg(m, traj, s, opt);
  viz_detail::save_text(path, s.str(), "save_filmstrip_svg");
}

}  // namespace gaitsynth
