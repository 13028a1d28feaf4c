#pragma once
// Shared checks of the built-in characters (tests/models/*.cpp).
#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "gaitsynth/model/model.hpp"
#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/standing.hpp"

namespace models_test {

// Inertia of the subtree rooted at `body` about `point` (q = 0, world = root frame).
template <class Root>
Eigen::Matrix3d subtree_inertia(const gaitsynth::model<Root>& m, int body,
                                const Eigen::Vector3d& point) {
  const auto o = gaitsynth::neutral_body_origins(m);
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (int k = body; k < m.num_bodies(); ++k) {
    int a = k;
    while (a > body) a = m.bodies[a].parent;
    if (a != body) continue;
    const auto& b = m.bodies[k];
    I += gaitsynth::solid::shift_inertia(b.inertia, b.mass, o[k] + b.com, point);
  }
  return I;
}

// Every DOF's soft limit is stable under semi-implicit Euler at the papers' 2400 Hz: the limit
// spring's k dt^2 / I and the damper's d dt / I (I: the moved subtree's inertia about the joint
// axis) stay below `bound` (instability starts at 4 and 2). For exponential springs k is the
// local stiffness k s exp(s * overshoot) at `overshoot` rad past the bound.
template <class Root>
void check_limit_stability(const gaitsynth::model<Root>& m, double bound = 1.0,
                           double overshoot = 0.1) {
  const double dt = 1.0 / 2400.0;
  const auto o = gaitsynth::neutral_body_origins(m);
  for (const auto& d : m.dofs) {
    const Eigen::Matrix3d I = subtree_inertia(m, d.body, o[d.body]);
    const double Ia = d.axis.dot(I * d.axis);
    double k = d.limit.stiffness;
    if (d.limit.model == gaitsynth::limit_model::exponential)
      k = d.limit.stiffness * d.limit.sharpness * std::exp(d.limit.sharpness * overshoot);
    INFO(m.name << " DOF " << d.name << ": I = " << Ia << ", k = " << k
                << ", d = " << d.limit.damping);
    CHECK(d.limit.model != gaitsynth::limit_model::none);
    CHECK(k * dt * dt / Ia < bound);
    CHECK(d.limit.damping * dt / Ia < bound);
  }
}

inline std::string mirror_name(const std::string& n) {
  std::string out = n;  // (char swap: GCC 12 -Wrestrict misfires on "r" + substr)
  if (!out.empty() && out[0] == 'l')
    out[0] = 'r';
  else if (!out.empty() && out[0] == 'r')
    out[0] = 'l';
  return out;
}

// The builder's mirror map pairs l/r DOFs and bodies; the sign is -1 exactly for rotations about
// x and z; limits, torque limits, masses, inertias and geometry of a pair are mirror images.
template <class Root>
void check_mirror(const gaitsynth::model<Root>& m, int expected_pairs) {
  int pairs = 0;
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const auto& d = m.dofs[j];
    const int k = m.mirror_dof[j];
    INFO(m.name << " DOF " << d.name);
    const std::string mn = mirror_name(d.name);
    if (mn != d.name && m.find_dof(mn) >= 0) {
      CHECK(m.dofs[k].name == mn);
      ++pairs;
    } else {
      CHECK(k == j);
    }
    const bool flips = std::abs(d.axis.x()) > 0.5 || std::abs(d.axis.z()) > 0.5;
    CHECK(m.mirror_sign[j] == (flips ? -1.0 : 1.0));
    const double s = m.mirror_sign[j];
    const auto& e = m.dofs[k];
    CHECK(e.axis.isApprox(d.axis));
    if (s > 0) {
      CHECK(e.limit.lower == Approx(d.limit.lower).margin(1e-12));
      CHECK(e.limit.upper == Approx(d.limit.upper).margin(1e-12));
    } else {
      CHECK(e.limit.lower == Approx(-d.limit.upper).margin(1e-12));
      CHECK(e.limit.upper == Approx(-d.limit.lower).margin(1e-12));
    }
    CHECK(e.limit.stiffness == d.limit.stiffness);
    CHECK(e.limit.damping == d.limit.damping);
    CHECK(e.torque_limit == d.torque_limit);
  }
  CHECK(pairs == 2 * expected_pairs);
  const auto o = gaitsynth::neutral_body_origins(m);
  const Eigen::Vector3d flip(1, -1, 1);
  for (int i = 0; i < m.num_bodies(); ++i) {
    const int k = m.mirror_body[i];
    INFO(m.name << " body " << m.bodies[i].name);
    CHECK(m.bodies[k].name == (m.find_body(mirror_name(m.bodies[i].name)) >= 0
                                   ? mirror_name(m.bodies[i].name)
                                   : m.bodies[i].name));
    CHECK(m.bodies[k].mass == m.bodies[i].mass);
    CHECK(o[k].isApprox(o[i].cwiseProduct(flip), 1e-12));
    CHECK(m.bodies[k].com.isApprox(m.bodies[i].com.cwiseProduct(flip), 1e-12));
    const Eigen::Matrix3d F = flip.asDiagonal();
    CHECK(m.bodies[k].inertia.isApprox(F * m.bodies[i].inertia * F, 1e-12));
  }
}

// Contact points of the given role exist on the named body.
template <class Root>
int count_contacts(const gaitsynth::model<Root>& m, const std::string& body,
                   gaitsynth::contact_point::kind role) {
  const int b = m.body_index(body);
  int n = 0;
  for (const auto& c : m.contact_points) n += (c.body == b && c.role == role) ? 1 : 0;
  return n;
}

// Whole-body COM at q = 0 in the root frame.
template <class Root>
Eigen::Vector3d neutral_com(const gaitsynth::model<Root>& m) {
  const auto o = gaitsynth::neutral_body_origins(m);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i = 0; i < m.num_bodies(); ++i) c += m.bodies[i].mass * (o[i] + m.bodies[i].com);
  return c / m.total_mass();
}

}  // namespace models_test
