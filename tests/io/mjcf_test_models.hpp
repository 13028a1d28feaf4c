#pragma once
// Models for the MJCF exporter tests (tests/io/mjcf.cpp and tests/io/mjcf.mujoco.cpp), built here
// so the tests do not depend on the built-in characters: a 7-link planar biped, a 3D humanoid with
// the DOF layout of Wang et al. 2009 (multi-DOF hips, shoulders, back, neck; 2-DOF ankles; toes), a
// fixed-base branching arm, and random trees. Bodies are deliberately listed breadth-first (parents
// before children, but not depth-first), so MuJoCo's numbering is a non-trivial permutation, and
// inertia tensors are full (rotated principal axes) with COMs off the joint axes, so that every
// term of the dynamics is exercised.
#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "gaitsynth/model/model_builder.hpp"

namespace gaitsynth::mjcf_test {

/// Inertia about the COM of a solid box of mass m and half sizes h, principal axes rotated by R.
inline Eigen::Matrix3d box_inertia(double m, const Eigen::Vector3d& h,
                                   const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  const Eigen::Vector3d d(m * (h.y() * h.y() + h.z() * h.z()) / 3.0,
                          m * (h.x() * h.x() + h.z() * h.z()) / 3.0,
                          m * (h.x() * h.x() + h.y() * h.y()) / 3.0);
  return R * d.asDiagonal() * R.transpose();
}

inline Eigen::Matrix3d tilt(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

inline shape box_shape(const Eigen::Vector3d& center, const Eigen::Vector3d& half) {
  shape s;
  s.type = shape::kind::box;
  s.center = center;
  s.half_extents = half;
  return s;
}

inline shape capsule_shape(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, double r) {
  shape s;
  s.type = shape::kind::capsule;
  s.p0 = p0;
  s.p1 = p1;
  s.radius = r;
  return s;
}

/// 7-link planar biped (torso root; thighs, shins, feet), listed breadth-first.
inline model<planar_root> planar_biped7() {
  model_builder<planar_root> b("planar_biped7");
  b.add_body({.name = "torso",
              .mass = 70.0 * 0.5,
              .com = {0.01, 0, 0.25},
              .inertia = box_inertia(35, {0.1, 0.15, 0.3}, tilt(0, 0.1, 0)),
              .shapes = {box_shape({0, 0, 0.3}, {0.1, 0.15, 0.3})}});
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    b.add_body({.name = p + "thigh",
                .parent = "torso",
                .joint_offset = {0, 0, 0},
                .mass = 7,
                .com = {0.005, 0, -0.2},
                .inertia = box_inertia(7, {0.06, 0.06, 0.23}, tilt(0, 0.05, 0)),
                .dofs = {{.name = p + "hip",
                          .axis = {0, 1, 0},
                          .limit = {.lower = -1.5, .upper = 2.0},
                          .torque_limit = 300}},
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.46}, 0.06)}});
  }
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    b.add_body({.name = p + "shin",
                .parent = p + "thigh",
                .joint_offset = {0, 0, -0.46},
                .mass = 3.5,
                .com = {0, 0, -0.22},
                .inertia = box_inertia(3.5, {0.05, 0.05, 0.22}),
                .dofs = {{.name = p + "knee",
                          .axis = {0, 1, 0},
                          .limit = {.lower = -2.5, .upper = 0},
                          .torque_limit = 300}},
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.45}, 0.05)}});
  }
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    b.add_body({.name = p + "foot",
                .parent = p + "shin",
                .joint_offset = {0, 0, -0.45},
                .mass = 1.0,
                .com = {0.05, 0, -0.04},
                .inertia = box_inertia(1.0, {0.1, 0.04, 0.03}),
                .dofs = {{.name = p + "ankle",
                          .axis = {0, 1, 0},
                          .limit = {.lower = -0.8, .upper = 0.8},
                          .torque_limit = 200}},
                .shapes = {box_shape({0.05, 0, -0.04}, {0.1, 0.04, 0.03})}});
    b.add_contact_point({.name = p + "heel", .body = p + "foot", .position = {-0.05, 0, -0.07}});
    b.add_contact_point({.name = p + "toe", .body = p + "foot", .position = {0.15, 0, -0.07}});
  }
  return b.build();
}

/// A 3D humanoid with the DOF layout of Wang et al. 2009 (back 3, neck 3, shoulders 3, elbows 1,
/// hips 3, knees 1, ankles 2, toes 1 = 28 joint DOFs), box feet and toes with 4 + 4 contact points
/// per foot (16 in all), listed breadth-first. Axes are the anatomical ones except where tilted to
/// exercise non-axis-aligned hinges.
inline model<floating_root> humanoid3d() {
  model_builder<floating_root> b("humanoid3d");
  const Eigen::Vector3d ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  auto dofs3 = [&](const std::string& n, double lim) {
    return std::vector<dof_spec>{
        {.name = n + "_x", .axis = ex, .limit = {.lower = -lim, .upper = lim}, .torque_limit = 200},
        {.name = n + "_y", .axis = ey, .limit = {.lower = -lim, .upper = lim}, .torque_limit = 200},
        {.name = n + "_z",
         .axis = ez,
         .limit = {.lower = -lim, .upper = lim},
         .torque_limit = 200}};
  };
  b.add_body({.name = "pelvis",
              .mass = 11.0,
              .com = {0.0, 0.0, 0.02},
              .inertia = box_inertia(11, {0.1, 0.16, 0.08}, tilt(0.02, 0.05, 0.0)),
              .shapes = {box_shape({0, 0, 0}, {0.1, 0.16, 0.08})}});
  b.add_body({.name = "torso",
              .parent = "pelvis",
              .joint_offset = {0, 0, 0.1},
              .mass = 26.0,
              .com = {0.01, 0, 0.22},
              .inertia = box_inertia(26, {0.11, 0.17, 0.22}, tilt(0, 0.08, 0)),
              .dofs = dofs3("back", 0.8),
              .shapes = {box_shape({0, 0, 0.22}, {0.11, 0.17, 0.22})}});
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    const double y = p == "l" ? 1 : -1;
    b.add_body({.name = p + "thigh",
                .parent = "pelvis",
                .joint_offset = {0, 0.09 * y, -0.06},
                .mass = 8.5,
                .com = {0.01, 0.005 * y, -0.19},
                .inertia = box_inertia(8.5, {0.07, 0.07, 0.22}, tilt(0.03 * y, 0.02, 0)),
                .dofs = dofs3(p + "hip", 2.0),
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.43}, 0.07)}});
  }
  b.add_body({.name = "head",
              .parent = "torso",
              .joint_offset = {0, 0, 0.47},
              .mass = 5.0,
              .com = {0.02, 0, 0.1},
              .inertia = box_inertia(5, {0.09, 0.08, 0.11}),
              .dofs = dofs3("neck", 0.7),
              .shapes = {box_shape({0.02, 0, 0.1}, {0.09, 0.08, 0.11})}});
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    const double y = p == "l" ? 1 : -1;
    b.add_body({.name = p + "upperarm",
                .parent = "torso",
                .joint_offset = {0, 0.2 * y, 0.42},
                .mass = 2.0,
                .com = {0, 0.01 * y, -0.14},
                .inertia = box_inertia(2, {0.04, 0.04, 0.15}, tilt(0.1 * y, 0, 0)),
                .dofs = dofs3(p + "shoulder", 3.0),
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.29}, 0.04)}});
    b.add_body({.name = p + "shin",
                .parent = p + "thigh",
                .joint_offset = {0, 0, -0.43},
                .mass = 3.5,
                .com = {0, 0, -0.19},
                .inertia = box_inertia(3.5, {0.05, 0.05, 0.21}),
                .dofs = {{.name = p + "knee",
                          .axis = ey,
                          .limit = {.lower = 0, .upper = 2.6},
                          .torque_limit = 300}},
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.42}, 0.05)}});
  }
  for (const char* s : {"l", "r"}) {
    const std::string p(s);
    const double y = p == "l" ? 1 : -1;
    b.add_body({.name = p + "forearm",
                .parent = p + "upperarm",
                .joint_offset = {0, 0, -0.29},
                .mass = 1.5,
                .com = {0, 0, -0.13},
                .inertia = box_inertia(1.5, {0.035, 0.035, 0.14}),
                .dofs = {{.name = p + "elbow",
                          .axis = ey,
                          .limit = {.lower = -2.6, .upper = 0},
                          .torque_limit = 100}},
                .shapes = {capsule_shape({0, 0, 0}, {0, 0, -0.27}, 0.035)}});
    b.add_body({.name = p + "foot",
                .parent = p + "shin",
                .joint_offset = {0, 0, -0.42},
                .mass = 1.0,
                .com = {0.03, 0, -0.04},
                .inertia = box_inertia(1.0, {0.08, 0.045, 0.03}),
                // 2-DOF ankle: flexion about y, then inversion about a slightly tilted x axis.
                .dofs = {{.name = p + "ankle_y",
                          .axis = ey,
                          .limit = {.lower = -0.9, .upper = 0.9},
                          .torque_limit = 200},
                         {.name = p + "ankle_x",
                          .axis = Eigen::Vector3d(1, 0, 0.2 * y).normalized(),
                          .limit = {.lower = -0.5, .upper = 0.5},
                          .torque_limit = 200}},
                .shapes = {box_shape({0.03, 0, -0.04}, {0.08, 0.045, 0.03})}});
    b.add_body({.name = p + "toes",
                .parent = p + "foot",
                .joint_offset = {0.11, 0, -0.05},
                .mass = 0.2,
                .com = {0.025, 0, -0.01},
                .inertia = box_inertia(0.2, {0.025, 0.045, 0.02}),
                .dofs = {{.name = p + "toe",
                          .axis = ey,
                          .limit = {.lower = -0.3, .upper = 1.0},
                          .torque_limit = 50}},
                .shapes = {box_shape({0.025, 0, -0.01}, {0.025, 0.045, 0.02})}});
    for (double cx : {-0.05, 0.11})
      for (double cy : {-0.045, 0.045})
        b.add_contact_point(
            {.name = p + "foot_" + (cx < 0 ? "heel" : "ball") + (cy < 0 ? "_right" : "_left"),
             .body = p + "foot",
             .position = {cx, cy, -0.07},
             .role = contact_point::kind::sole});
    for (double cx : {0.0, 0.05})
      for (double cy : {-0.045, 0.045})
        b.add_contact_point(
            {.name = p + "toe_" + (cx == 0 ? "base" : "tip") + (cy < 0 ? "_right" : "_left"),
             .body = p + "toes",
             .position = {cx, cy, -0.03},
             .role = contact_point::kind::toe});
  }
  return b.build();
}

/// A fixed-base branching arm: 1 root link with 2 chains, 1-3 DOFs per body, tilted axes.
inline model<fixed_root> fixed_arm() {
  model_builder<fixed_root> b("fixed_arm");
  b.add_body({.name = "base",
              .joint_offset = {0, 0, 1.0},
              .mass = 5,
              .com = {0, 0, 0.05},
              .inertia = box_inertia(5, {0.1, 0.1, 0.05})});
  b.add_body({.name = "link_a1",
              .parent = "base",
              .joint_offset = {0.1, 0, 0.1},
              .mass = 2,
              .com = {0.1, 0.02, 0.01},
              .inertia = box_inertia(2, {0.15, 0.03, 0.04}, tilt(0.2, 0.1, 0.3)),
              .dofs = {{.name = "a1_z", .axis = {0, 0, 1}},
                       {.name = "a1_t", .axis = Eigen::Vector3d(0.3, 1, 0.2).normalized()}}});
  b.add_body({.name = "link_b1",
              .parent = "base",
              .joint_offset = {-0.1, 0, 0.1},
              .mass = 1.5,
              .com = {-0.1, 0, 0.02},
              .inertia = box_inertia(1.5, {0.12, 0.03, 0.03}, tilt(0, 0.3, 0)),
              .dofs = {{.name = "b1_x", .axis = {1, 0, 0}},
                       {.name = "b1_y", .axis = {0, 1, 0}},
                       {.name = "b1_z", .axis = {0, 0, 1}}}});
  b.add_body({.name = "link_a2",
              .parent = "link_a1",
              .joint_offset = {0.3, 0, 0},
              .mass = 1,
              .com = {0.12, 0, 0},
              .inertia = box_inertia(1, {0.13, 0.02, 0.02}, tilt(0.5, 0, 0.1)),
              .dofs = {{.name = "a2_y", .axis = {0, 1, 0}}}});
  b.add_body({.name = "link_b2",
              .parent = "link_b1",
              .joint_offset = {-0.24, 0, 0},
              .mass = 0.8,
              .com = {-0.1, 0.01, 0},
              .inertia = box_inertia(0.8, {0.11, 0.02, 0.02}),
              .dofs = {{.name = "b2_t", .axis = Eigen::Vector3d(1, 1, 1).normalized()}}});
  b.add_contact_point({.name = "a_tip", .body = "link_a2", .position = {0.25, 0, 0}});
  return b.build();
}

/// A random tree of `n` bodies: random parents (any earlier body, so the order is far from
/// depth-first), 1-3 DOFs per body with random unit axes, random offsets, COMs, masses and full
/// inertias (boxes with random principal axes), and a contact point per body.
template <root_joint Root>
model<Root> random_tree(std::mt19937& rng, int n, const std::string& name = "random_tree") {
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.3, 1.0);
  std::normal_distribution<double> g;
  auto rand_rot = [&] {
    return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
  };
  auto rand_vec = [&](double s) { return Eigen::Vector3d(s * u(rng), s * u(rng), s * u(rng)); };
  model_builder<Root> b(name);
  for (int i = 0; i < n; ++i) {
    body_spec s;
    s.name = "body" + std::to_string(i);
    s.mass = 0.3 + 5.0 * pos(rng);
    s.com = rand_vec(0.15);
    s.inertia = box_inertia(
        s.mass,
        Eigen::Vector3d(0.05 + 0.1 * pos(rng), 0.05 + 0.1 * pos(rng), 0.05 + 0.2 * pos(rng)),
        rand_rot());
    if (i > 0) {
      s.parent = "body" + std::to_string(std::uniform_int_distribution<int>(0, i - 1)(rng));
      s.joint_offset = rand_vec(0.3);
      const int nd = std::uniform_int_distribution<int>(1, 3)(rng);
      for (int k = 0; k < nd; ++k) {
        dof_spec d;
        d.name = "j";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "j" + to_string
        d.name += std::to_string(i);
        d.name += '_';
        d.name += std::to_string(k);
        Eigen::Vector3d a(g(rng), g(rng), g(rng));
        d.axis = a.normalized();
        s.dofs.push_back(d);
      }
    }
    b.add_body(s);
    contact_point_spec c;
    c.name = "contact_" + s.name;
    c.body = s.name;
    c.position = rand_vec(0.1);
    b.add_contact_point(c);
  }
  return b.build();
}

}  // namespace gaitsynth::mjcf_test
