#pragma once
// Test helpers for contact (helper E1): small models with contact points and a plain simulation
// loop (semi-implicit Euler, zero joint torques, contact and pushes), independent of the rollout.
#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>

#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth::test_e1 {

/// "prefix<k>" (snprintf: GCC 12 warns falsely (-Wrestrict) on "literal" + std::to_string).
inline std::string indexed_name(const char* prefix, int k) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%d", prefix, k);
  return buf;
}

/// Inertia of a solid box with half extents h about its centre.
inline Eigen::Matrix3d box_inertia(double mass, const Eigen::Vector3d& h) {
  const Eigen::Vector3d s = 2.0 * h;
  return (mass / 12.0 *
          Eigen::Vector3d(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                          s.x() * s.x() + s.y() * s.y()))
      .asDiagonal();
}

/// A single box body (origin at its centre) with its 8 corners as contact points.
template <root_joint Root>
model<Root> box_model(double mass, const Eigen::Vector3d& half,
                      const Eigen::Vector3d& gravity = {0, 0, -9.81}) {
  model_builder<Root> b("box");
  b.add_body({.name = "box", .mass = mass, .inertia = box_inertia(mass, half)});
  int k = 0;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1})
        b.add_contact_point(
            {.name = indexed_name("c", k++),
             .body = "box",
             .position = Eigen::Vector3d(sx * half.x(), sy * half.y(), sz * half.z()),
             .role = sz < 0 ? contact_point::kind::sole : contact_point::kind::other});
  b.set_gravity(gravity);
  return b.build();
}

/// Steps `steps` times at dt from s (zero generalized forces): contact + pushes + ABA,
/// semi-implicit Euler. `observe(s, cs)` runs after each step's force computation (cs holds that
/// step's forces).
template <root_joint Root, terrain T, class Observe>
void simulate(const model<Root>& m, const T& t, const contact_parameters& p, sim_state& s,
              double dt, int steps, std::span<const push> pushes, Observe&& observe) {
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  semi_implicit_euler integ(m);
  const Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double time,
                 Eigen::VectorXd& ddq) {
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, t, p, cs, dt);
    apply_pushes(m, ws, pushes, time);
    ddq = aba(m, ws, q, v, tau);
  };
  for (int i = 0; i < steps; ++i) {
    integ.step(m, s, dt, sys);
    observe(static_cast<const sim_state&>(s), static_cast<const contact_state&>(cs));
  }
}

template <root_joint Root, terrain T>
void simulate(const model<Root>& m, const T& t, const contact_parameters& p, sim_state& s,
              double dt, int steps) {
  simulate(m, t, p, s, dt, steps, {}, [](const sim_state&, const contact_state&) {});
}

/// Floating-root q for position x and rotation R.
inline Eigen::VectorXd floating_q(const Eigen::Vector3d& x, const Eigen::Matrix3d& R, int nj = 0) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7 + nj);
  const Eigen::Quaterniond qu(R);
  q << x, qu.w(), qu.x(), qu.y(), qu.z(), Eigen::VectorXd::Zero(nj);
  return q;
}

}  // namespace gaitsynth::test_e1
