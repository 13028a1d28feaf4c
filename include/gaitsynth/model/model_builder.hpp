#pragma once
/// \file model_builder.hpp
/// Mutable, validating builder for model<Root> (Drake's Finalize() as a change of type: the builder
/// accepts anything, build() checks everything and returns the immutable model).
///
///   model_builder<floating_root> b("my_biped");
///   b.add_body({.name = "pelvis", .mass = 10, .inertia = I});          // the root body
///   b.add_body({.name = "lthigh", .parent = "pelvis", .joint_offset = {0, 0.1, -0.05},
///               .mass = 7, .com = {0, 0, -0.2}, .inertia = I2,
///               .dofs = {{.name = "lhip_x", .axis = {1, 0, 0}}, {.name = "lhip_y"}}});
///   b.add_contact_point({.name = "lheel", .body = "lfoot", .position = {-0.05, 0, -0.05}});
///   auto m = b.build();  // throws std::invalid_argument naming the first problem found
#include <Eigen/Eigenvalues>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

struct dof_spec {
  std::string name;
  Eigen::Vector3d axis{0, 1, 0};  ///< body frame; normalized by build()
  joint_limit limit{};
  double torque_limit = 1e9;  ///< N m
};

struct body_spec {
  std::string name;
  std::string parent;  ///< empty: this is the root body (exactly one)
  Eigen::Vector3d joint_offset = Eigen::Vector3d::Zero();
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  std::vector<dof_spec> dofs;
  std::vector<shape> shapes;
  double length = 0.0;
  Eigen::Vector3d segment_end = Eigen::Vector3d::Zero();
};

struct contact_point_spec {
  std::string name;
  std::string body;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  contact_point::kind role = contact_point::kind::sole;
};

template <root_joint Root>
class model_builder {
 public:
  explicit model_builder(std::string name) : name_(std::move(name)) {}

  model_builder& add_body(body_spec b) {
    bodies_.push_back(std::move(b));
    return *this;
  }
  model_builder& add_contact_point(contact_point_spec c) {
    contacts_.push_back(std::move(c));
    return *this;
  }
  model_builder& set_gravity(const Eigen::Vector3d& g) {
    gravity_ = g;
    return *this;
  }
  /// Names starting with `left` and `right` (default "l" / "r") are mirror pairs, e.g. lhip_x <->
  /// rhip_x, lfoot <-> rfoot. Everything else mirrors to itself.
  model_builder& set_mirror_prefixes(std::string left, std::string right) {
    left_ = std::move(left);
    right_ = std::move(right);
    return *this;
  }

  const std::vector<body_spec>& bodies() const { return bodies_; }
  std::vector<body_spec>& bodies() { return bodies_; }

  /// Validates and returns the immutable model. Throws std::invalid_argument naming the problem.
  model<Root> build() const;

 private:
  std::string name_;
  std::vector<body_spec> bodies_;
  std::vector<contact_point_spec> contacts_;
  Eigen::Vector3d gravity_{0, 0, -9.81};
  std::string left_ = "l", right_ = "r";
};

namespace detail {
inline bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }

inline std::string mirror_name(const std::string& n, const std::string& l, const std::string& r) {
  if (n.rfind(l, 0) == 0) return r + n.substr(l.size());
  if (n.rfind(r, 0) == 0) return l + n.substr(r.size());
  return n;
}
}  // namespace detail

template <root_joint Root>
model<Root> model_builder<Root>::build() const {
  model<Root> m;
  m.name = name_;
  check_argument(gravity_.allFinite(), "model '", name_, "': gravity is not finite");
  m.gravity = gravity_;
  check_argument(!bodies_.empty(), "model '", name_, "': has no bodies");
  std::set<std::string> body_names, dof_names, contact_names;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const body_spec& s = bodies_[i];
    const std::string where = "model '" + name_ + "', body '" + s.name + "'";
    check_argument(!s.name.empty(), "model '", name_, "': body ", i, " has an empty name");
    check_argument(body_names.insert(s.name).second, "model '", name_, "': duplicate body name '",
                   s.name, "'");
    body b;
    b.name = s.name;
    if (s.parent.empty() || s.parent == "world") {
      check_argument(i == 0, where, ": only the first body may be the root (parent empty), but '",
                     bodies_[0].name, "' already is");
      b.parent = -1;
      check_argument(s.dofs.empty(), where,
                     ": the root body's DOFs come from the root joint and must not be listed");
    } else {
      check_argument(i != 0, where, ": the first body must be the root (empty parent), got parent '",
                     s.parent, "'");
      b.parent = m.find_body(s.parent);
      check_argument(b.parent >= 0, where, ": unknown parent '", s.parent,
                     "' (parents must be added before their children)");
      check_argument(!s.dofs.empty(), where,
                     ": a non-root body needs at least one DOF (weld bodies by merging inertias)");
    }
    check_argument(std::isfinite(s.mass) && s.mass > 0.0, where,
                   ": mass must be finite and > 0, got ", s.mass);
    check_argument(detail::finite3(s.com), where, ": com is not finite");
    check_argument(detail::finite3(s.joint_offset), where, ": joint_offset is not finite");
    check_argument(s.inertia.allFinite(), where, ": inertia is not finite");
    check_argument((s.inertia - s.inertia.transpose()).cwiseAbs().maxCoeff() <=
                       1e-12 * (1.0 + s.inertia.cwiseAbs().maxCoeff()),
                   where, ": inertia is not symmetric");
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(s.inertia);
    const Eigen::Vector3d ev = es.eigenvalues();
    check_argument(ev.minCoeff() > 0.0, where,
                   ": inertia is not positive definite (principal moments ", ev.transpose(),
                   " kg m^2)");
    // A real body satisfies the triangle inequality of its principal moments (MuJoCo checks it too).
    const double tol = 1e-9 * ev.sum();
    check_argument(ev[0] + ev[1] + tol >= ev[2] && ev[0] + ev[2] + tol >= ev[1] &&
                       ev[1] + ev[2] + tol >= ev[0],
                   where, ": principal moments ", ev.transpose(),
                   " violate the triangle inequality (no physical body has them)");
    b.joint_offset = s.joint_offset;
    b.mass = s.mass;
    b.com = s.com;
    b.inertia = 0.5 * (s.inertia + s.inertia.transpose());
    b.first_dof = m.num_joint_dofs();
    b.num_dofs = static_cast<int>(s.dofs.size());
    b.shapes = s.shapes;
    b.length = s.length;
    b.segment_end = s.segment_end;
    for (const dof_spec& d : s.dofs) {
      const std::string dwhere = where + ", DOF '" + d.name + "'";
      check_argument(!d.name.empty(), where, ": a DOF has an empty name");
      check_argument(dof_names.insert(d.name).second, "model '", name_, "': duplicate DOF name '",
                     d.name, "'");
      for (auto rn : Root::dof_names)
        check_argument(d.name != rn, dwhere, ": name is reserved for the root joint");
      check_argument(d.axis.allFinite() && d.axis.norm() > 1e-9, dwhere,
                     ": axis must be finite and non-zero, got (", d.axis.transpose(), ")");
      check_argument(std::isfinite(d.limit.lower) && std::isfinite(d.limit.upper), dwhere,
                     ": limits must be finite, got [", d.limit.lower, ", ", d.limit.upper, "]");
      check_argument(d.limit.lower <= d.limit.upper, dwhere, ": limit lower ", d.limit.lower,
                     " > upper ", d.limit.upper);
      check_argument(std::isfinite(d.limit.stiffness) && d.limit.stiffness >= 0 &&
                         std::isfinite(d.limit.damping) && d.limit.damping >= 0 &&
                         std::isfinite(d.limit.sharpness) && d.limit.sharpness > 0,
                     dwhere, ": limit stiffness/damping must be >= 0 and sharpness > 0, got ",
                     d.limit.stiffness, ", ", d.limit.damping, ", ", d.limit.sharpness);
      check_argument(d.torque_limit > 0 && !std::isnan(d.torque_limit), dwhere,
                     ": torque_limit must be > 0, got ", d.torque_limit);
      joint_dof j;
      j.name = d.name;
      j.body = static_cast<int>(i);
      j.axis = d.axis.normalized();
      j.limit = d.limit;
      j.torque_limit = d.torque_limit;
      m.dofs.push_back(std::move(j));
    }
    m.bodies.push_back(std::move(b));
  }
  for (const contact_point_spec& c : contacts_) {
    check_argument(!c.name.empty(), "model '", name_, "': a contact point has an empty name");
    check_argument(contact_names.insert(c.name).second, "model '", name_,
                   "': duplicate contact point name '", c.name, "'");
    contact_point p;
    p.name = c.name;
    p.body = m.find_body(c.body);
    check_argument(p.body >= 0, "model '", name_, "', contact point '", c.name,
                   "': unknown body '", c.body, "'");
    check_argument(c.position.allFinite(), "model '", name_, "', contact point '", c.name,
                   "': position is not finite");
    p.position = c.position;
    p.role = c.role;
    m.contact_points.push_back(std::move(p));
  }
  // Left/right mirror map. Mirroring across the sagittal (x-z) plane maps an axial vector a to
  // (-ax, ay, -az); the sign relating two DOFs is the projection of one's mirrored axis on the other.
  const int nj = m.num_joint_dofs();
  m.mirror_dof.assign(nj, -1);
  m.mirror_sign.assign(nj, 1.0);
  for (int j = 0; j < nj; ++j) {
    const std::string mn = detail::mirror_name(m.dofs[j].name, left_, right_);
    int k = m.find_dof(mn);
    if (k < 0) k = j;
    m.mirror_dof[j] = k;
    const Eigen::Vector3d& a = m.dofs[j].axis;
    const Eigen::Vector3d ma(-a.x(), a.y(), -a.z());
    const double s = ma.dot(m.dofs[k].axis);
    m.mirror_sign[j] = s >= 0 ? 1.0 : -1.0;
  }
  m.mirror_body.assign(m.num_bodies(), -1);
  for (int i = 0; i < m.num_bodies(); ++i) {
    const int k = m.find_body(detail::mirror_name(m.bodies[i].name, left_, right_));
    m.mirror_body[i] = k < 0 ? i : k;
  }
  return m;
}

}  // namespace gaitsynth
