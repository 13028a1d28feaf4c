#pragma once
/// \file mjcf.hpp
/// Export any gaitsynth model as MuJoCo MJCF (XML), to look at a character in MuJoCo's viewer, to
/// use MuJoCo as a test oracle for the dynamics (tests/io/mjcf.mujoco.cpp) and as the benchmark
/// peer (benchmarks/mujoco_peer). The exporter does not depend on MuJoCo. docs/mjcf.md.
///
/// What the file contains, and why it reproduces gaitsynth's rigid-body dynamics exactly:
/// * Root joint: floating_root -> <freejoint name="root"/> (MuJoCo's qpos = [p, quat w x y z],
///   qvel = [world linear velocity of the body origin, body-frame angular velocity]: the same
///   convention as floating_root); planar_root -> slide x "root_x", slide z "root_z", hinge y
///   "root_pitch" in the root body (q = [x, z, pitch]); fixed_root -> no joint (welded).
///   The root body sits at its joint_offset (gaitsynth's root origin is joint_offset + q[0:3]).
///   MuJoCo's free joint ignores the body position, so a floating root with a non-zero
///   joint_offset is written as slides "root_x", "root_y", "root_z" and a ball joint "root",
///   which has the same qpos/qvel layout and the same dynamics.
/// * Each body sits at `joint_offset` in its parent with identity orientation (a body frame is
///   aligned with its parent's at q = 0) and carries its revolute DOFs as hinge joints at the body
///   origin, in DOF order, axes in the body frame. MuJoCo composes several hinges of one body
///   intrinsically in order, exactly as model.hpp does.
/// * Mass properties are explicit: <inertial pos=com mass quat diaginertia> with
///   <compiler inertiafromgeom="false">, so geoms (visual shapes, contact spheres) add no mass.
///   The principal axes are computed here in double precision (mjcf_principal_inertia): MuJoCo
///   2.2.2 diagonalizes a `fullinertia` with an iterative solver that stops early, which changes
///   the inertia by up to ~1e-7 relative (measured), far above rounding.
/// * Joints have no armature, damping, stiffness or friction loss (stated in a <default>), so the
///   joint-space inertia and bias forces are those of pure rigid-body dynamics.
/// * Joint position limits become hard limits (limited="true" range in radians, compiler
///   angle="radian"); gaitsynth's soft limit springs have no MuJoCo counterpart.
///
/// Order of coordinates. MuJoCo numbers bodies and joints in depth-first order of the XML tree,
/// while model<Root> only requires parents before children. The file is written depth-first
/// (children in index order), so MuJoCo's qpos/qvel may be a permutation of gaitsynth's q/v:
/// mjcf_qpos_index / mjcf_qvel_index give it, to_mjcf_qpos / from_mjcf_qvel etc. apply it. Names
/// are kept (body, joint and site names are gaitsynth's), so mj_name2id also works. Actuators (one
/// motor per DOF, gear 1) are written in gaitsynth DOF order: ctrl[j] is the torque of DOF j.
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

/// MuJoCo's numerical integrator (<option integrator>).
enum class mjcf_integrator {
  euler,    ///< semi-implicit Euler, as gaitsynth's default integrator
  rk4,      ///< fourth-order Runge-Kutta
  implicit  ///< implicit in velocity (damping)
};

struct mjcf_options {
  /// Physics timestep, s (<option timestep>); the papers' 2400 Hz by default.
  double timestep = 1.0 / 2400.0;
  mjcf_integrator integrator = mjcf_integrator::euler;
  /// Model name in the file; empty: the gaitsynth model's name.
  std::string name;

  /// A plane geom "floor" at z = 0 (collides with contact geoms and colliding shapes).
  bool include_floor = true;
  /// Sliding friction coefficient mu of the floor and the contact geoms (MuJoCo takes the larger of
  /// the two geoms' coefficients).
  double friction = 1.0;

  /// The model's shapes as geoms (boxes, capsules, spheres), for the viewer.
  bool visual_geoms = true;
  /// contype / conaffinity of the shape geoms; 0 / 0: shapes never collide (contact is handled by
  /// the contact geoms). Set both to 1 to let the shapes themselves touch the floor.
  int visual_contype = 0;
  int visual_conaffinity = 0;

  /// A small sphere site at every contact point (named like the contact point), to look at them.
  bool contact_sites = true;
  double contact_site_radius = 0.008;  ///< m
  /// A sphere geom centred at every contact point (named like the contact point), colliding with
  /// the floor only (contype 1, conaffinity 0, condim 3): MuJoCo's counterpart of gaitsynth's point
  /// contacts, used by the benchmark peer. The sphere touches the floor when its centre, the
  /// contact point, is `contact_geom_radius` above it.
  bool contact_geoms = false;
  double contact_geom_radius = 0.01;  ///< m

  /// Export joint position limits as hard MuJoCo limits (a DOF whose range is the builder's
  /// default, |bound| >= 1e8 rad, stays unlimited).
  bool joint_limits = true;
  /// One <motor> per joint DOF, gear 1, ctrlrange = +-torque_limit (unclamped when >= 1e8 N m).
  bool actuators = true;

  /// A keyframe "initial" with this q (gaitsynth order, size nq; written in MuJoCo's order) and v
  /// (size nv, zero when empty). Empty q: no keyframe. mj_resetDataKeyframe(m, d, 0) applies it.
  Eigen::VectorXd keyframe_q;
  Eigen::VectorXd keyframe_v;
};

namespace detail::mjcf {

/// Bounds at or beyond this magnitude mean "no limit" (the builder's defaults are +-1e9).
inline constexpr double unbounded = 1e8;

/// Shortest decimal text that reads back as the same double (so the file loses no precision).
inline std::string num(double x) {
  check_argument(std::isfinite(x), "write_mjcf: a number to write is not finite (", x, ")");
  if (x == 0.0) return "0";  // also turns -0 into 0
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof(buf), x);
  return std::string(buf, r.ptr);
}

inline std::string vec(const Eigen::Vector3d& v) {
  return num(v.x()) + " " + num(v.y()) + " " + num(v.z());
}

/// The name as XML attribute text: the five special characters are escaped; control characters
/// (not allowed in XML 1.0) and empty names are rejected.
inline std::string xml_name(std::string_view what, std::string_view n) {
  check_argument(!n.empty(), "write_mjcf: ", what, " has an empty name");
  std::string out;
  out.reserve(n.size());
  for (char c : n) {
    const auto u = static_cast<unsigned char>(c);
    check_argument(u >= 0x20 && u != 0x7f, "write_mjcf: ", what, " name '", n,
                   "' contains a control character (code ", static_cast<int>(u),
                   "), which XML cannot hold");
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// MuJoCo requires names to be unique per object type (body, joint, geom, site, actuator).
struct name_registry {
  std::set<std::string> used;
  std::string_view kind;
  void add(const std::string& n) {
    check_argument(used.insert(n).second, "write_mjcf: ", kind, " name '", n,
                   "' is used twice in the exported file (MuJoCo needs unique ", kind,
                   " names; the exporter reserves 'world', 'root', 'floor' and root_x/root_z/"
                   "root_pitch)");
  }
};

inline const char* integrator_name(mjcf_integrator i) {
  switch (i) {
    case mjcf_integrator::rk4:
      return "RK4";
    case mjcf_integrator::implicit:
      return "implicit";
    case mjcf_integrator::euler:
      break;
  }
  return "Euler";
}

template <root_joint Root>
std::vector<std::vector<int>> children_of(const model<Root>& m) {
  std::vector<std::vector<int>> ch(m.bodies.size());
  for (int i = 1; i < m.num_bodies(); ++i) {
    const int p = m.bodies[i].parent;
    check_argument(p >= 0 && p < i, "write_mjcf: body '", m.bodies[i].name, "' has parent index ",
                   p, ", which does not precede it");
    ch[p].push_back(i);
  }
  return ch;
}

}  // namespace detail::mjcf

/// Bodies in the order MuJoCo numbers them: element k is the gaitsynth body index of MuJoCo body
/// id k + 1 (id 0 is MuJoCo's world). Depth-first, children in gaitsynth index order.
template <root_joint Root>
std::vector<int> mjcf_body_order(const model<Root>& m) {
  check_argument(!m.bodies.empty(), "write_mjcf: model '", m.name, "' has no bodies");
  const auto ch = detail::mjcf::children_of(m);
  std::vector<int> order;
  order.reserve(m.bodies.size());
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int b = stack.back();
    stack.pop_back();
    order.push_back(b);
    for (auto it = ch[b].rbegin(); it != ch[b].rend(); ++it) stack.push_back(*it);
  }
  return order;
}

/// Joint DOFs in MuJoCo's order: element k is the gaitsynth DOF index of the k-th hinge after the
/// root joint(s).
template <root_joint Root>
std::vector<int> mjcf_dof_order(const model<Root>& m) {
  std::vector<int> order;
  order.reserve(m.dofs.size());
  for (int b : mjcf_body_order(m))
    for (int k = 0; k < m.bodies[b].num_dofs; ++k) order.push_back(m.bodies[b].first_dof + k);
  return order;
}

/// index[k]: the gaitsynth q index of MuJoCo's qpos[k] (size nq). The root block is the identity.
template <root_joint Root>
std::vector<int> mjcf_qpos_index(const model<Root>& m) {
  std::vector<int> idx;
  idx.reserve(m.nq());
  for (int i = 0; i < Root::nq; ++i) idx.push_back(i);
  for (int j : mjcf_dof_order(m)) idx.push_back(Root::nq + j);
  return idx;
}

/// index[k]: the gaitsynth v index of MuJoCo's qvel[k] (size nv). A MuJoCo joint-space matrix is
/// M_mj(k, l) = M(index[k], index[l]).
template <root_joint Root>
std::vector<int> mjcf_qvel_index(const model<Root>& m) {
  std::vector<int> idx;
  idx.reserve(m.nv());
  for (int i = 0; i < Root::nv; ++i) idx.push_back(i);
  for (int j : mjcf_dof_order(m)) idx.push_back(Root::nv + j);
  return idx;
}

namespace detail::mjcf {
inline Eigen::VectorXd gather(const Eigen::VectorXd& x, const std::vector<int>& idx,
                              const char* what) {
  check_size(x.size(), static_cast<std::ptrdiff_t>(idx.size()), what);
  Eigen::VectorXd y(x.size());
  for (std::size_t k = 0; k < idx.size(); ++k) y[static_cast<Eigen::Index>(k)] = x[idx[k]];
  return y;
}
inline Eigen::VectorXd scatter(const Eigen::VectorXd& y, const std::vector<int>& idx,
                               const char* what) {
  check_size(y.size(), static_cast<std::ptrdiff_t>(idx.size()), what);
  Eigen::VectorXd x(y.size());
  for (std::size_t k = 0; k < idx.size(); ++k) x[idx[k]] = y[static_cast<Eigen::Index>(k)];
  return x;
}
}  // namespace detail::mjcf

/// gaitsynth q (size nq) -> MuJoCo qpos of the exported file.
template <root_joint Root>
Eigen::VectorXd to_mjcf_qpos(const model<Root>& m, const Eigen::VectorXd& q) {
  return detail::mjcf::gather(q, mjcf_qpos_index(m), "to_mjcf_qpos: q");
}
/// MuJoCo qpos of the exported file -> gaitsynth q.
template <root_joint Root>
Eigen::VectorXd from_mjcf_qpos(const model<Root>& m, const Eigen::VectorXd& qpos) {
  return detail::mjcf::scatter(qpos, mjcf_qpos_index(m), "from_mjcf_qpos: qpos");
}
/// gaitsynth v (or any vector indexed like v: tau, bias, ddq) -> MuJoCo qvel order.
template <root_joint Root>
Eigen::VectorXd to_mjcf_qvel(const model<Root>& m, const Eigen::VectorXd& v) {
  return detail::mjcf::gather(v, mjcf_qvel_index(m), "to_mjcf_qvel: v");
}
/// A MuJoCo vector in qvel order (qvel, qacc, qfrc_bias) -> gaitsynth v order.
template <root_joint Root>
Eigen::VectorXd from_mjcf_qvel(const model<Root>& m, const Eigen::VectorXd& qvel) {
  return detail::mjcf::scatter(qvel, mjcf_qvel_index(m), "from_mjcf_qvel: qvel");
}

/// Principal moments and axes of an inertia tensor, as written to <inertial quat diaginertia>.
struct mjcf_principal_inertia {
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();             ///< kg m^2
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< principal axes in the body
  bool identity = true;  ///< the tensor is diagonal: moments are its diagonal, no quat written
};

/// I = R(rotation) diag(moments) R(rotation)^T, to rounding (~1e-16 relative). A diagonal tensor is
/// passed through exactly. Moments that break the triangle inequality by rounding only (the
/// builder accepts 1e-9 of their sum, MuJoCo none) are clamped onto it.
inline mjcf_principal_inertia mjcf_principal_axes(const Eigen::Matrix3d& I) {
  mjcf_principal_inertia out;
  const Eigen::Matrix3d sym = 0.5 * (I + I.transpose());
  if (sym(0, 1) == 0.0 && sym(0, 2) == 0.0 && sym(1, 2) == 0.0) {
    out.moments = sym.diagonal();
  } else {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(sym);
    check_argument(es.info() == Eigen::Success, "write_mjcf: inertia eigen-decomposition failed");
    Eigen::Matrix3d V = es.eigenvectors();
    if (V.determinant() < 0) V.col(2) = -V.col(2);  // a proper rotation
    out.moments = es.eigenvalues();
    out.rotation = Eigen::Quaterniond(V).normalized();
    if (out.rotation.w() < 0) out.rotation.coeffs() = -out.rotation.coeffs();
    out.identity = false;
  }
  Eigen::Vector3d& d = out.moments;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (d[k] > d[i] + d[j]) d[k] = d[i] + d[j];
  }
  return out;
}

/// Writes `m` as an MJCF document to `os`. Throws std::invalid_argument for a name that XML cannot
/// hold (control characters), names MuJoCo would see twice, non-finite numbers, bad options
/// (non-positive timestep, radii or friction; a keyframe of the wrong size).
template <root_joint Root>
void write_mjcf(const model<Root>& m, std::ostream& os, const mjcf_options& opt = {}) {
  using namespace detail::mjcf;
  check_positive(opt.timestep, "write_mjcf: options.timestep");
  check_positive(opt.friction, "write_mjcf: options.friction");
  if (opt.contact_sites) check_positive(opt.contact_site_radius, "write_mjcf: contact_site_radius");
  if (opt.contact_geoms) check_positive(opt.contact_geom_radius, "write_mjcf: contact_geom_radius");
  if (opt.keyframe_q.size() > 0) {
    check_size(opt.keyframe_q.size(), m.nq(), "write_mjcf: options.keyframe_q");
    check_finite(opt.keyframe_q, "write_mjcf: options.keyframe_q");
    if (opt.keyframe_v.size() > 0) {
      check_size(opt.keyframe_v.size(), m.nv(), "write_mjcf: options.keyframe_v");
      check_finite(opt.keyframe_v, "write_mjcf: options.keyframe_v");
    }
  } else {
    check_argument(opt.keyframe_v.size() == 0, "write_mjcf: options.keyframe_v is given (size ",
                   opt.keyframe_v.size(), ") without keyframe_q");
  }
  check_argument(m.gravity.allFinite(), "write_mjcf: gravity is not finite");

  // Build the whole document first: a bad name throws before anything reaches `os`.
  name_registry bodies{{}, "body"}, joints{{}, "joint"}, geoms{{}, "geom"}, sites{{}, "site"},
      actuators{{}, "actuator"};
  bodies.add("world");
  const std::vector<int> order = mjcf_body_order(m);
  const auto ch = children_of(m);
  std::vector<std::vector<int>> contacts_of(m.bodies.size());
  for (int c = 0; c < static_cast<int>(m.contact_points.size()); ++c) {
    const int b = m.contact_points[c].body;
    check_argument(b >= 0 && b < m.num_bodies(), "write_mjcf: contact point '",
                   m.contact_points[c].name, "' has a bad body index ", b);
    contacts_of[b].push_back(c);
  }

  std::string x;
  x.reserve(8192);
  const std::string mu = num(opt.friction);
  x += "<mujoco model=\"" + xml_name("model", opt.name.empty() ? m.name : opt.name) + "\">\n";
  x += "  <!-- Exported by gaitsynth (include/gaitsynth/io/mjcf.hpp), root: ";
  x += std::string(Root::name) + ". Units SI, angles in radians, z up. -->\n";
  x += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  x += "  <option timestep=\"" + num(opt.timestep) + "\" gravity=\"" + vec(m.gravity) +
       "\" integrator=\"" + integrator_name(opt.integrator) + "\"/>\n";
  x += "  <default>\n";
  x += "    <joint armature=\"0\" damping=\"0\" stiffness=\"0\" frictionloss=\"0\"/>\n";
  x += "    <geom contype=\"" + std::to_string(opt.visual_contype) + "\" conaffinity=\"" +
       std::to_string(opt.visual_conaffinity) + "\" friction=\"" + mu +
       " 0.005 0.0001\" rgba=\"0.8 0.6 0.4 1\"/>\n";
  x += "    <site rgba=\"0.9 0.1 0.1 1\"/>\n";
  x += "  </default>\n";
  if (opt.include_floor) {
    x += "  <asset>\n";
    x += "    <texture name=\"grid\" type=\"2d\" builtin=\"checker\" rgb1=\"0.2 0.3 0.4\" "
         "rgb2=\"0.3 0.4 0.5\" width=\"512\" height=\"512\"/>\n";
    x += "    <material name=\"grid\" texture=\"grid\" texrepeat=\"1 1\" texuniform=\"true\"/>\n";
    x += "  </asset>\n";
  }
  x += "  <worldbody>\n";
  x += "    <light name=\"sun\" directional=\"true\" pos=\"0 0 5\" dir=\"0 0 -1\"/>\n";
  if (opt.include_floor) {
    geoms.add("floor");
    x += "    <geom name=\"floor\" type=\"plane\" size=\"0 0 0.05\" material=\"grid\" "
         "contype=\"1\" conaffinity=\"1\" condim=\"3\" friction=\"" +
         mu + " 0.005 0.0001\"/>\n";
  }

  // Depth-first writer with an explicit stack of open bodies (close tags when leaving a subtree).
  auto indent = [](int depth) { return std::string(static_cast<std::size_t>(2 * depth + 4), ' '); };
  std::vector<int> depth(m.bodies.size(), 0);
  std::vector<int> open;  // bodies whose </body> is pending
  for (int b : order) {
    const body& bd = m.bodies[b];
    const int d = bd.parent < 0 ? 0 : depth[bd.parent] + 1;
    depth[b] = d;
    while (!open.empty() && depth[open.back()] >= d) {
      x += indent(depth[open.back()]) + "</body>\n";
      open.pop_back();
    }
    const std::string in = indent(d + 1);
    bodies.add(bd.name);
    x += indent(d) + "<body name=\"" + xml_name("body", bd.name) + "\" pos=\"" +
         vec(bd.joint_offset) + "\">\n";
    // Root joint(s).
    if (bd.parent < 0) {
      if constexpr (Root::nv == 6) {
        if (bd.joint_offset.isZero(0.0)) {
          joints.add("root");
          x += in + "<freejoint name=\"root\"/>\n";
        } else {
          // gaitsynth puts the root origin at joint_offset + q[0:3]; a MuJoCo free joint ignores
          // the body position, so an offset root gets the equivalent slide x, y, z + ball chain
          // (same qpos and qvel layout: world linear velocity, body-frame angular velocity).
          for (const char* n : {"root_x", "root_y", "root_z", "root"}) joints.add(n);
          x += in + "<joint name=\"root_x\" type=\"slide\" pos=\"0 0 0\" axis=\"1 0 0\"/>\n";
          x += in + "<joint name=\"root_y\" type=\"slide\" pos=\"0 0 0\" axis=\"0 1 0\"/>\n";
          x += in + "<joint name=\"root_z\" type=\"slide\" pos=\"0 0 0\" axis=\"0 0 1\"/>\n";
          x += in + "<joint name=\"root\" type=\"ball\" pos=\"0 0 0\"/>\n";
        }
      } else if constexpr (Root::nv == 3) {
        for (auto n : Root::dof_names) joints.add(std::string(n));
        x += in + "<joint name=\"root_x\" type=\"slide\" pos=\"0 0 0\" axis=\"1 0 0\"/>\n";
        x += in + "<joint name=\"root_z\" type=\"slide\" pos=\"0 0 0\" axis=\"0 0 1\"/>\n";
        x += in + "<joint name=\"root_pitch\" type=\"hinge\" pos=\"0 0 0\" axis=\"0 1 0\"/>\n";
      }
    }
    const mjcf_principal_inertia pi = mjcf_principal_axes(bd.inertia);
    x += in + "<inertial pos=\"" + vec(bd.com) + "\" mass=\"" + num(bd.mass) + "\"";
    if (!pi.identity)
      x += " quat=\"" + num(pi.rotation.w()) + " " + num(pi.rotation.x()) + " " +
           num(pi.rotation.y()) + " " + num(pi.rotation.z()) + "\"";
    x += " diaginertia=\"" + vec(pi.moments) + "\"/>\n";
    for (int k = 0; k < bd.num_dofs; ++k) {
      const joint_dof& j = m.dofs[bd.first_dof + k];
      joints.add(j.name);
      x += in + "<joint name=\"" + xml_name("joint", j.name) +
           "\" type=\"hinge\" pos=\"0 0 0\" axis=\"" + vec(j.axis) + "\"";
      const bool has_range = !(j.limit.lower <= -unbounded && j.limit.upper >= unbounded) &&
                             j.limit.lower < j.limit.upper;
      if (opt.joint_limits && has_range)
        x += " limited=\"true\" range=\"" + num(j.limit.lower) + " " + num(j.limit.upper) + "\"";
      else
        x += " limited=\"false\"";
      x += "/>\n";
    }
    if (opt.visual_geoms) {
      for (const shape& s : bd.shapes) {
        switch (s.type) {
          case shape::kind::box:
            x += in + "<geom type=\"box\" pos=\"" + vec(s.center) + "\" size=\"" +
                 vec(s.half_extents) + "\"/>\n";
            break;
          case shape::kind::capsule:
            if ((s.p1 - s.p0).norm() > 1e-9)
              x += in + "<geom type=\"capsule\" fromto=\"" + vec(s.p0) + " " + vec(s.p1) +
                   "\" size=\"" + num(s.radius) + "\"/>\n";
            else  // a degenerate capsule is a sphere (MuJoCo rejects zero-length fromto)
              x += in + "<geom type=\"sphere\" pos=\"" + vec(s.p0) + "\" size=\"" + num(s.radius) +
                   "\"/>\n";
            break;
          case shape::kind::sphere:
            x += in + "<geom type=\"sphere\" pos=\"" + vec(s.center) + "\" size=\"" +
                 num(s.radius) + "\"/>\n";
            break;
        }
      }
    }
    for (int c : contacts_of[b]) {
      const contact_point& cp = m.contact_points[c];
      if (opt.contact_sites) {
        sites.add(cp.name);
        x += in + "<site name=\"" + xml_name("contact point", cp.name) + "\" pos=\"" +
             vec(cp.position) + "\" size=\"" + num(opt.contact_site_radius) + "\"/>\n";
      }
      if (opt.contact_geoms) {
        geoms.add(cp.name);
        x += in + "<geom name=\"" + xml_name("contact point", cp.name) +
             "\" type=\"sphere\" pos=\"" + vec(cp.position) + "\" size=\"" +
             num(opt.contact_geom_radius) +
             "\" contype=\"1\" conaffinity=\"0\" condim=\"3\" group=\"3\" friction=\"" + mu +
             " 0.005 0.0001\" rgba=\"0.1 0.8 0.1 1\"/>\n";
      }
    }
    if (ch[b].empty())
      x += indent(d) + "</body>\n";
    else
      open.push_back(b);
  }
  while (!open.empty()) {
    x += indent(depth[open.back()]) + "</body>\n";
    open.pop_back();
  }
  x += "  </worldbody>\n";

  if (opt.actuators && m.num_joint_dofs() > 0) {
    x += "  <actuator>\n";
    for (const joint_dof& j : m.dofs) {
      actuators.add(j.name);
      const std::string n = xml_name("joint", j.name);
      x += "    <motor name=\"" + n + "\" joint=\"" + n + "\" gear=\"1\"";
      if (j.torque_limit < unbounded)
        x += " ctrllimited=\"true\" ctrlrange=\"" + num(-j.torque_limit) + " " +
             num(j.torque_limit) + "\"";
      else
        x += " ctrllimited=\"false\"";
      x += "/>\n";
    }
    x += "  </actuator>\n";
  }

  if (opt.keyframe_q.size() > 0) {
    const Eigen::VectorXd qpos = to_mjcf_qpos(m, opt.keyframe_q);
    const Eigen::VectorXd qvel =
        opt.keyframe_v.size() > 0 ? to_mjcf_qvel(m, opt.keyframe_v) : Eigen::VectorXd::Zero(m.nv());
    x += "  <keyframe>\n    <key name=\"initial\" qpos=\"";
    for (Eigen::Index i = 0; i < qpos.size(); ++i) x += (i ? " " : "") + num(qpos[i]);
    x += "\"";
    if (qvel.size() > 0) {
      x += " qvel=\"";
      for (Eigen::Index i = 0; i < qvel.size(); ++i) x += (i ? " " : "") + num(qvel[i]);
      x += "\"";
    }
    x += "/>\n  </keyframe>\n";
  }
  x += "</mujoco>\n";
  os << x;
}

/// The MJCF document as a string (for mj_loadXML through a virtual file system, tests).
template <root_joint Root>
std::string to_mjcf_string(const model<Root>& m, const mjcf_options& opt = {}) {
  std::ostringstream os;
  write_mjcf(m, os, opt);
  return os.str();
}

/// Writes the MJCF document to the file `path`. Throws std::invalid_argument as write_mjcf does,
/// and std::runtime_error when the file cannot be written.
template <root_joint Root>
void save_mjcf(const model<Root>& m, const std::string& path, const mjcf_options& opt = {}) {
  const std::string text = to_mjcf_string(m, opt);  // validate before touching the file
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("save_mjcf: cannot open '" + path + "' for writing");
  f << text;
  f.flush();
  if (!f) throw std::runtime_error("save_mjcf: failed writing '" + path + "'");
}

}  // namespace gaitsynth
