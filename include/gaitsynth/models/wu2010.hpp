#pragma once
/// \file wu2010.hpp
/// The biped of Wu & Popovic, "Terrain-Adaptive Bipedal Locomotion Control", ACM TOG 29(4), 2010
/// (Appendix B, Table 3): upper body, spherical hip link, thighs, shanks and feet.
///
/// Table 3 (mass kg and principal inertias (lx, ly, lz) kg m^2; length m; joint; tau_max N m):
///   upper body  40,    (1, 1, 0.1)          0.8            spherical (waist)  1600
///   hip         8.8,   (0.1, 0.1, 0.1)      0.15 (radius)
///   thigh       8.552, (0.1, 0.1, 0.05)     0.5            revolute (knee)     700
///   shank       4.352, (0.04, 0.04, 0.01)   0.55           spherical (ankle)   400
///   foot        1,     (0.03, 0.001, 0.03)  0.25
/// Each row's joint is the one at the link's distal end (the upper body, the paper's root, ends in
/// the spherical waist; the knee is revolute, Section 7 "inverted knees"). The hip row's joint
/// cells are empty in the table: we make the hips spherical with 700 N m, the knee's limit. Total
/// mass 76.608 kg. Everything the table leaves out (joint placement, foot geometry, COMs, ranges)
/// is our choice and listed in docs/models.md.
///
/// floating_model with the hip link (pelvis) as the root body, origin at its centre; the dynamics
/// do not depend on which body is the root. Frames x forward, y left, z up. DOF order (17):
///   lhip_x lhip_y lhip_z lknee lankle_x lankle_y lankle_z
///   rhip_x rhip_y rhip_z rknee rankle_x rankle_y rankle_z   waist_x waist_y waist_z
/// The foot's small moment (0.001) is about its long axis, so Table 3's (lx, ly, lz) have y along
/// the foot: we store the foot as diag(0.001, 0.03, 0.03) in our x-forward frame. Contacts: each
/// foot carries a heel box and a toe box with a gap between them (Fig. 9), 4 bottom corners each
/// (roles sole and toe) and 2 toe-top points.
///
/// Section 9's morphology changes (Fig. 4), for running an unaltered controller on another body:
/// wu2010_biped_options::knees = inverted bends both knees forward (range [-2.4, 0] instead of
/// [0, 2.4]; the end-effector layout reads the bending sign from the range), and
/// frozen_left_knee sets the left knee's range to zero ("setting the joint movement range to
/// zero") at frozen_knee_angle: a limit spring 100 times the knee's, which holds it within 6 mrad
/// against the knee's whole 700 N m. The variants keep the name "wu2010_biped" with a suffix.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/models/detail/character_parts.hpp"
#include "gaitsynth/models/detail/humanoid30.hpp"

namespace gaitsynth {

/// Which way the knees bend (Section 9, Fig. 4).
enum class wu2010_knees {
  normal,   ///< flexion positive, range [0, 2.4] rad (as the 30-DOF humanoid's)
  inverted  ///< bending forward: range [-2.4, 0] rad
};

struct wu2010_biped_options {
  wu2010_knees knees = wu2010_knees::normal;
  bool frozen_left_knee = false;   ///< Sec. 9: the left knee's range set to zero
  double frozen_knee_angle = 0.0;  ///< rad, where the frozen knee is held (within its range)
  /// The frozen knee's limit spring and damper as multiples of the knee's (k_scale x 1000 N m/rad,
  /// x 20 N m s/rad): 100 x k holds 700 N m within 6 mrad; 10 x d keeps the explicit step of the
  /// shank and foot (0.67 kg m^2 about the knee) well damped at 2400 Hz (h d / I = 0.2).
  double frozen_stiffness_factor = 100.0, frozen_damping_factor = 10.0;
};

/// \throws std::invalid_argument naming a frozen knee angle outside the knee's range or a
/// non-finite or non-positive factor.
inline floating_model wu2010_biped(const wu2010_biped_options& opt = {}) {
  using namespace detail::characters;
  // Geometry not in Table 3 (docs/models.md).
  constexpr double hip_radius = 0.15;     // Table 3
  constexpr double hip_half_width = 0.1;  // ours: hip joints inside the hip sphere
  constexpr double thigh = 0.5, shank = 0.55, upper = 0.8, foot_len = 0.25;  // Table 3
  constexpr double ankle_height = 0.06, foot_width = 0.1;                    // ours
  constexpr double heel_x = -0.06;               // ours: heel 6 cm behind the ankle
  constexpr double box_len = 0.1, box_h = 0.03;  // ours: heel and toe boxes, 5 cm gap (Fig. 9)
  const double toe_x0 = heel_x + foot_len - box_len;

  // Soft limits at Wu's size scale like the 30-DOF humanoid's (k, d proportional to mass
  // height^2; reference 70 kg, 1.75 m); standing height here is 0.06 + 0.55 + 0.5 + 0.8 = 1.91 m.
  const double M = 76.608, H = ankle_height + shank + thigh + upper;
  const double k_scale =
      (M / reference_limit_mass) * (H / reference_limit_height) * (H / reference_limit_height);
  const auto sided = [&](const dof_row& r, const std::string& S, bool right, double tau_max) {
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis[r.axis] = 1.0;
    joint_limit L =
        spring_damper_limit(r.lower, r.upper, r.stiffness * k_scale, r.damping * k_scale);
    if (right) L = mirrored_limit(L, axis);
    return dof_spec{.name = S + r.name, .axis = axis, .limit = L, .torque_limit = tau_max};
  };
  // Ranges as for the 30-DOF humanoid; the ankle's third (z) DOF gets +-0.5 rad, the waist the
  // back's ranges.
  constexpr dof_row ankle_z{"ankle_z", 2, -0.5, 0.5, 500, 2, 400};
  constexpr dof_row waist[3] = {{"waist_x", 0, -0.5, 0.5, 1000, 50, 1600},
                                {"waist_y", 1, -0.5, 1.2, 1000, 50, 1600},
                                {"waist_z", 2, -0.6, 0.6, 1000, 50, 1600}};

  const bool inverted = opt.knees == wu2010_knees::inverted;
  const dof_row knee_row =
      inverted ? dof_row{knee_rows[0].name,        knee_rows[0].axis,      -knee_rows[0].upper,
                         -knee_rows[0].lower,      knee_rows[0].stiffness, knee_rows[0].damping,
                         knee_rows[0].torque_limit}
               : knee_rows[0];
  if (opt.frozen_left_knee) {
    check_argument(std::isfinite(opt.frozen_knee_angle) &&
                       opt.frozen_knee_angle >= knee_row.lower &&
                       opt.frozen_knee_angle <= knee_row.upper,
                   "wu2010_biped: frozen_knee_angle must lie in the knee's range [", knee_row.lower,
                   ", ", knee_row.upper, "], got ", opt.frozen_knee_angle);
    check_argument(std::isfinite(opt.frozen_stiffness_factor) && opt.frozen_stiffness_factor > 0,
                   "wu2010_biped: frozen_stiffness_factor must be finite and > 0, got ",
                   opt.frozen_stiffness_factor);
    check_argument(std::isfinite(opt.frozen_damping_factor) && opt.frozen_damping_factor > 0,
                   "wu2010_biped: frozen_damping_factor must be finite and > 0, got ",
                   opt.frozen_damping_factor);
  }
  const auto knee_dof = [&](const std::string& S, bool right) {
    dof_spec d = sided(knee_row, S, right, 700);
    if (!right && opt.frozen_left_knee) {
      d.limit.lower = d.limit.upper = opt.frozen_knee_angle;
      d.limit.stiffness *= opt.frozen_stiffness_factor;
      d.limit.damping *= opt.frozen_damping_factor;
    }
    return d;
  };
  std::string name = "wu2010_biped";
  if (inverted) name += "_inverted_knees";
  if (opt.frozen_left_knee) name += "_frozen_left_knee";

  model_builder<floating_root> b(name);
  b.add_body({.name = "hip",
              .mass = 8.8,
              .inertia = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal(),
              .shapes = {sphere({0, 0, 0}, hip_radius)},
              .length = 2 * hip_radius,
              .segment_end = {0, 0, hip_radius}});
  for (const bool right : {false, true}) {
    const std::string S = right ? "r" : "l";
    const double side = right ? -1.0 : 1.0;
    b.add_body({.name = S + "thigh",
                .parent = "hip",
                .joint_offset = {0, side * hip_half_width, 0},
                .mass = 8.552,
                .com = {0, 0, -0.5 * thigh},
                .inertia = Eigen::Vector3d(0.1, 0.1, 0.05).asDiagonal(),
                .dofs = {sided(hip_rows[0], S, right, 700), sided(hip_rows[1], S, right, 700),
                         sided(hip_rows[2], S, right, 700)},
                .shapes = {capsule({0, 0, -0.06}, {0, 0, -thigh + 0.06}, 0.06)},
                .length = thigh,
                .segment_end = {0, 0, -thigh}});
    b.add_body({.name = S + "shank",
                .parent = S + "thigh",
                .joint_offset = {0, 0, -thigh},
                .mass = 4.352,
                .com = {0, 0, -0.5 * shank},
                .inertia = Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal(),
                .dofs = {knee_dof(S, right)},
                .shapes = {capsule({0, 0, -0.045}, {0, 0, -shank + 0.045}, 0.045)},
                .length = shank,
                .segment_end = {0, 0, -shank}});
    const Eigen::Vector3d heel_c(heel_x + 0.5 * box_len, 0, -ankle_height + 0.5 * box_h);
    const Eigen::Vector3d toe_c(toe_x0 + 0.5 * box_len, 0, -ankle_height + 0.5 * box_h);
    const Eigen::Vector3d half(0.5 * box_len, 0.5 * foot_width, 0.5 * box_h);
    b.add_body({.name = S + "foot",
                .parent = S + "shank",
                .joint_offset = {0, 0, -shank},
                .mass = 1.0,
                .com = {heel_x + 0.5 * foot_len, 0, -0.5 * ankle_height},
                .inertia = Eigen::Vector3d(0.001, 0.03, 0.03).asDiagonal(),
                .dofs = {sided(ankle_rows[0], S, right, 400), sided(ankle_rows[1], S, right, 400),
                         sided(ankle_z, S, right, 400)},
                .shapes = {box(heel_c, half), box(toe_c, half),
                           box({heel_x + 0.5 * foot_len, 0, -ankle_height + box_h + 0.01},
                               {0.5 * foot_len, 0.4 * foot_width, 0.01})},
                .length = foot_len,
                .segment_end = {heel_x + foot_len, 0, -ankle_height}});
    const double lat = side * 0.5 * foot_width, med = -lat;
    using ck = contact_point::kind;
    const double zb = -ankle_height, zt = -ankle_height + box_h;
    const double xh0 = heel_x, xh1 = heel_x + box_len, xt0 = toe_x0, xt1 = toe_x0 + box_len;
    b.add_contact_point({S + "heel_back_lat", S + "foot", {xh0, lat, zb}, ck::sole});
    b.add_contact_point({S + "heel_back_med", S + "foot", {xh0, med, zb}, ck::sole});
    b.add_contact_point({S + "heel_front_lat", S + "foot", {xh1, lat, zb}, ck::sole});
    b.add_contact_point({S + "heel_front_med", S + "foot", {xh1, med, zb}, ck::sole});
    b.add_contact_point({S + "toe_back_lat", S + "foot", {xt0, lat, zb}, ck::toe});
    b.add_contact_point({S + "toe_back_med", S + "foot", {xt0, med, zb}, ck::toe});
    b.add_contact_point({S + "toe_front_lat", S + "foot", {xt1, lat, zb}, ck::toe});
    b.add_contact_point({S + "toe_front_med", S + "foot", {xt1, med, zb}, ck::toe});
    b.add_contact_point({S + "toe_top_lat", S + "foot", {xt1, lat, zt}, ck::toe_top});
    b.add_contact_point({S + "toe_top_med", S + "foot", {xt1, med, zt}, ck::toe_top});
  }
  b.add_body({.name = "upper_body",
              .parent = "hip",
              .mass = 40.0,
              .com = {0, 0, 0.5 * upper},
              .inertia = Eigen::Vector3d(1, 1, 0.1).asDiagonal(),
              .dofs = {sided(waist[0], "", false, 1600), sided(waist[1], "", false, 1600),
                       sided(waist[2], "", false, 1600)},
              .shapes = {box({0, 0, 0.35 * upper}, {0.1, 0.17, 0.35 * upper}),
                         sphere({0, 0, 0.88 * upper}, 0.12 * upper)},
              .length = upper,
              .segment_end = {0, 0, upper}});
  return b.build();
}

/// The capsule of a foot for inter-leg collisions (ours): along the sole, of radius half the foot's
/// width, spanning its sole contact points (heel to toe, the sole plane as its bottom).
inline collision_capsule wu2010_foot_capsule(const floating_model& m, int foot) {
  double x0 = 1e9, x1 = -1e9, z = 0.0, half_width = 0.0;
  int n = 0;
  for (const contact_point& c : m.contact_points) {
    if (c.body != foot || c.role == contact_point::kind::toe_top) continue;
    x0 = std::min(x0, c.position.x());
    x1 = std::max(x1, c.position.x());
    half_width = std::max(half_width, std::abs(c.position.y()));
    z = c.position.z();
    ++n;
  }
  check_argument(n > 0 && half_width > 0.0 && x1 - x0 > 2.0 * half_width, "body ", foot,
                 " of model '", m.name, "' has no sole contact points a foot capsule fits");
  const double r = half_width;
  return {foot, vec3(x0 + r, 0.0, z + r), vec3(x1 - r, 0.0, z + r), r};
}

/// Wu & Popovic 2010's inter-leg collisions (contact/self_contact.hpp; PhysX collides the legs,
/// Sec. 9) for a wu2010_biped (any of its variants): each of the left thigh, shank and foot
/// against each of the right ones, 9 pairs; thighs and shanks are their shapes' capsules, the
/// feet wu2010_foot_capsule's.
inline self_contact_parameters wu2010_leg_collisions(const floating_model& m) {
  const auto capsule_of = [&](const std::string& name) -> collision_capsule {
    const int b = m.body_index(name);  // throws naming a missing body
    if (name.ends_with("foot")) return wu2010_foot_capsule(m, b);
    for (const shape& s : m.bodies[static_cast<std::size_t>(b)].shapes)
      if (s.type == shape::kind::capsule) return {b, s.p0, s.p1, s.radius};
    throw std::invalid_argument("wu2010_leg_collisions: body '" + name + "' has no capsule");
  };
  self_contact_parameters p;
  for (const char* l : {"lthigh", "lshank", "lfoot"})
    for (const char* r : {"rthigh", "rshank", "rfoot"})
      p.pairs.push_back({capsule_of(l), capsule_of(r)});
  validate(m, p);
  return p;
}

}  // namespace gaitsynth
