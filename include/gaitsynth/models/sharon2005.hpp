#pragma once
/// \file sharon2005.hpp
/// The planar human characters of Sharon & van de Panne, "Synthesis of Controllers for Stylized
/// Planar Bipedal Walking", ICRA 2005 (Section VI.A, Fig. 4, Table I). Numbers and the choices made
/// where the paper is silent are listed in docs/models.md.
///
/// Both are planar_model: q = [x, z, pitch, joint angles], the biped in the x-z plane walking along
/// +x, every joint axis +y (a positive angle tilts the distal segment's bottom end backwards: hip
/// extension, knee flexion and ankle plantarflexion are positive). The root body is the torso
/// (7-link) or the pelvis (16-link) with its origin at the hip joint. All bodies lie in y = 0.
#include <Eigen/Core>
#include <string>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/detail/character_parts.hpp"

namespace gaitsynth {

/// Link parameters of the 7-link human; the defaults are Table I of the paper (mass kg, length m,
/// inertia kg m^2 about the link's centre) and its 370 N m torque limit. The paper's robustness
/// experiments (Fig. 8) change them, e.g. torso_mass = 28 or thigh_length = 0.6, shin_length = 0.25
/// (call with_rod_inertias() after changing masses or lengths to keep the table's rod inertias).
struct sharon2005_human7_parameters {
  double torso_mass = 40.0, torso_length = 0.2, torso_inertia = 0.1333;
  double thigh_mass = 7.0, thigh_length = 0.46, thigh_inertia = 0.1234;
  double shin_mass = 4.0, shin_length = 0.44, shin_inertia = 0.0645;
  double foot_mass = 2.0, foot_length = 0.22, foot_inertia = 0.00807;
  double torque_limit = 370.0;  ///< N m, hips, knees and ankles (Section VI.A)
  /// Where the ankle sits on the foot link: the heel is this fraction of the foot length behind
  /// it (ours; the paper does not say). 0 puts the ankle at the heel end of the foot.
  double heel_behind_ankle = 0.25;

  /// Table I's inertias are those of uniform thin rods, m L^2 / 12, to the printed digits; this
  /// returns a copy with every inertia recomputed that way from the current masses and lengths.
  sharon2005_human7_parameters with_rod_inertias() const {
    sharon2005_human7_parameters p = *this;
    p.torso_inertia = torso_mass * torso_length * torso_length / 12.0;
    p.thigh_inertia = thigh_mass * thigh_length * thigh_length / 12.0;
    p.shin_inertia = shin_mass * shin_length * shin_length / 12.0;
    p.foot_inertia = foot_mass * foot_length * foot_length / 12.0;
    return p;
  }
};

namespace detail::characters {
/// A thin rod's inertia about its centre: `I` about the two axes across it, and a small moment
/// (1e-3 I) about its own axis so that the tensor is positive definite (it does not enter planar
/// dynamics, where only I_yy acts).
inline Eigen::Matrix3d rod_inertia(double I, int long_axis) {
  Eigen::Vector3d d = Eigen::Vector3d::Constant(I);
  d[long_axis] = 1e-3 * I;
  return d.asDiagonal();
}
}  // namespace detail::characters

/// The 7-link planar human of Sharon & van de Panne 2005 (Fig. 4a, Table I): torso (root), thighs,
/// shins and feet; 6 pin joints, all about +y, DOF order lhip, lknee, lankle, rhip, rknee, rankle.
///
/// Geometry (docs/models.md): every link is a uniform rod (COM at its middle; Table I's inertias
/// are m L^2 / 12). The torso rises from the hip joint (the root origin), the thigh and shin hang
/// below it, and the foot is a horizontal rod through the ankle from the heel, heel_behind_ankle *
/// L behind it, to the toe (our choice: with the ankle at the heel the standing COM would be only 7
/// mm inside the support). Link end points for the mass-distance metric of eq. 2: body origin and
/// segment_end (the rod's far end; for the foot the ankle and the toe tip). Contact points: heel
/// (role sole) and toe (role toe) at the ends of each foot. Joint limits are exponential springs
/// (Section VI.A); their ranges and constants, which the paper leaves to [19], are ours.
/// \throws std::invalid_argument naming a non-positive or non-finite parameter.
inline planar_model sharon2005_human7(const sharon2005_human7_parameters& p = {}) {
  using namespace detail::characters;
  const auto pos = [](double v, const char* what) { check_positive(v, what); };
  pos(p.torso_mass, "sharon2005_human7_parameters.torso_mass");
  pos(p.torso_length, "sharon2005_human7_parameters.torso_length");
  pos(p.torso_inertia, "sharon2005_human7_parameters.torso_inertia");
  pos(p.thigh_mass, "sharon2005_human7_parameters.thigh_mass");
  pos(p.thigh_length, "sharon2005_human7_parameters.thigh_length");
  pos(p.thigh_inertia, "sharon2005_human7_parameters.thigh_inertia");
  pos(p.shin_mass, "sharon2005_human7_parameters.shin_mass");
  pos(p.shin_length, "sharon2005_human7_parameters.shin_length");
  pos(p.shin_inertia, "sharon2005_human7_parameters.shin_inertia");
  pos(p.foot_mass, "sharon2005_human7_parameters.foot_mass");
  pos(p.foot_length, "sharon2005_human7_parameters.foot_length");
  pos(p.foot_inertia, "sharon2005_human7_parameters.foot_inertia");
  pos(p.torque_limit, "sharon2005_human7_parameters.torque_limit");
  check_argument(p.heel_behind_ankle >= 0.0 && p.heel_behind_ankle <= 1.0,
                 "sharon2005_human7_parameters.heel_behind_ankle must be in [0, 1], got ",
                 p.heel_behind_ankle);
  const double heel = -p.heel_behind_ankle * p.foot_length, toe = heel + p.foot_length;

  // Exponential limit springs: tau = -k (exp(s * overshoot) - 1) - d qdot past a bound. With
  // k = 10 N m and s = 20 /rad the spring gives 64 N m at 0.1 rad overshoot and 536 N m at 0.2 rad.
  constexpr double k = 10.0, s = 20.0, d = 5.0;
  const joint_limit hip = exponential_limit(-2.0, 0.7, k, s, d);    // flexion is negative
  const joint_limit knee = exponential_limit(0.0, 2.5, k, s, d);    // flexion is positive
  const joint_limit ankle = exponential_limit(-0.6, 0.9, k, s, d);  // plantarflexion positive
  const Eigen::Vector3d Y = Eigen::Vector3d::UnitY();

  model_builder<planar_root> b("sharon2005_human7");
  b.add_body({.name = "torso",
              .mass = p.torso_mass,
              .com = {0, 0, 0.5 * p.torso_length},
              .inertia = rod_inertia(p.torso_inertia, 2),
              .shapes = {capsule({0, 0, 0}, {0, 0, p.torso_length}, 0.12)},
              .length = p.torso_length,
              .segment_end = {0, 0, p.torso_length}});
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    b.add_body(
        {.name = S + "thigh",
         .parent = "torso",
         .mass = p.thigh_mass,
         .com = {0, 0, -0.5 * p.thigh_length},
         .inertia = rod_inertia(p.thigh_inertia, 2),
         .dofs = {{.name = S + "hip", .axis = Y, .limit = hip, .torque_limit = p.torque_limit}},
         .shapes = {capsule({0, 0, 0}, {0, 0, -p.thigh_length}, 0.06)},
         .length = p.thigh_length,
         .segment_end = {0, 0, -p.thigh_length}});
    b.add_body(
        {.name = S + "shin",
         .parent = S + "thigh",
         .joint_offset = {0, 0, -p.thigh_length},
         .mass = p.shin_mass,
         .com = {0, 0, -0.5 * p.shin_length},
         .inertia = rod_inertia(p.shin_inertia, 2),
         .dofs = {{.name = S + "knee", .axis = Y, .limit = knee, .torque_limit = p.torque_limit}},
         .shapes = {capsule({0, 0, 0}, {0, 0, -p.shin_length}, 0.045)},
         .length = p.shin_length,
         .segment_end = {0, 0, -p.shin_length}});
    b.add_body(
        {.name = S + "foot",
         .parent = S + "shin",
         .joint_offset = {0, 0, -p.shin_length},
         .mass = p.foot_mass,
         .com = {0.5 * (heel + toe), 0, 0},
         .inertia = rod_inertia(p.foot_inertia, 0),
         .dofs = {{.name = S + "ankle", .axis = Y, .limit = ankle, .torque_limit = p.torque_limit}},
         .shapes = {capsule({heel, 0, 0}, {toe, 0, 0}, 0.02)},
         .length = p.foot_length,
         .segment_end = {toe, 0, 0}});
    b.add_contact_point({.name = S + "heel",
                         .body = S + "foot",
                         .position = {heel, 0, 0},
                         .role = contact_point::kind::sole});
    b.add_contact_point({.name = S + "toe",
                         .body = S + "foot",
                         .position = {toe, 0, 0},
                         .role = contact_point::kind::toe});
  }
  return b.build();
}

/// Body size of the 16-link human (docs/models.md): de Leva's reference male by default.
struct sharon2005_human16_parameters {
  double height = de_leva1996::reference_stature;  ///< standing height, sole to vertex, m
  double mass = de_leva1996::reference_mass;       ///< total mass, kg
  double torque_limit = 370.0;  ///< N m at hips, knees, ankles, back and chest (Sharon's value)
};

/// A 16-link planar human: the paper gives no numbers for it (it refers to Sharon's thesis [19]),
/// so this is the 16-segment Zatsiorsky-Seluyanov body of de Leva 1996 (Table 4, male; see
/// anthropometry.hpp) in the sagittal plane: pelvis (root; lower trunk, origin at the hip joint),
/// thighs, shanks, feet, abdomen (middle trunk), thorax (upper trunk), head, upper arms, forearms
/// and hands; 15 pin joints about +y in the order
///   lhip, lknee, lankle, rhip, rknee, rankle, back, chest, neck,
///   lshoulder, lelbow, lwrist, rshoulder, relbow, rwrist
/// (the first six as in the 7-link human). Masses are de Leva's percentages of `mass`, inertias
/// his radii of gyration; all lengths are de Leva's scaled by one factor so that the vertex stands
/// `height` above the sole. As in the 7-link model the foot is a horizontal link through the ankle
/// at the sole, its heel 25 % of its length behind the ankle, with heel (sole) and toe (toe)
/// contact points at its ends.
/// \throws std::invalid_argument naming a non-positive or non-finite height, mass or torque limit.
inline planar_model sharon2005_human16(const sharon2005_human16_parameters& p = {}) {
  using namespace detail::characters;
  namespace dl = de_leva1996;
  check_positive(p.height, "sharon2005_human16_parameters.height");
  check_positive(p.mass, "sharon2005_human16_parameters.mass");
  check_positive(p.torque_limit, "sharon2005_human16_parameters.torque_limit");
  // With the ankle on the sole, the vertical chain vertex..AJC is the whole standing height.
  const double scale = p.height / (dl::vertical_chain_mm * 1e-3);
  const auto len = [&](const dl::segment& s) { return scale * s.length_mm * 1e-3; };
  const auto mass = [&](const dl::segment& s) {
    return p.mass * s.mass_percent / dl::mass_percent_sum;
  };
  // COM along an upright segment from its lower end, given de Leva's COM from its upper landmark.
  const auto com_up = [&](const dl::segment& s) { return len(s) * (1.0 - 0.01 * s.com_percent); };
  const auto com_down = [&](const dl::segment& s) { return -len(s) * 0.01 * s.com_percent; };

  // Exponential limit springs (amplitude k N m, sharpness 20 /rad, damping d), scaled with the
  // body (k, d proportional to mass * height^2) so that the presets behave alike.
  const double body_scale = (p.mass / dl::reference_mass) * (p.height / dl::reference_stature) *
                            (p.height / dl::reference_stature);
  const auto lim = [&](double lo, double hi, double k, double d) {
    return exponential_limit(lo, hi, k * body_scale, 20.0, d * body_scale);
  };
  const Eigen::Vector3d Y = Eigen::Vector3d::UnitY();
  const double T = p.torque_limit;

  model_builder<planar_root> b("sharon2005_human16");
  const double Llpt = len(dl::lower_trunk), Lmpt = len(dl::middle_trunk),
               Lupt = len(dl::upper_trunk), Lhead = len(dl::head);
  b.add_body({.name = "pelvis",
              .mass = mass(dl::lower_trunk),
              .com = {0, 0, com_up(dl::lower_trunk)},
              .inertia = dl::upright_inertia(dl::lower_trunk, mass(dl::lower_trunk), Llpt),
              .shapes = {box({0, 0, 0.5 * Llpt}, {0.08, 0.14, 0.5 * Llpt})},
              .length = Llpt,
              .segment_end = {0, 0, Llpt}});
  const double Lth = len(dl::thigh), Lsh = len(dl::shank), Lft = len(dl::foot);
  const double heel = -0.25 * Lft, toe = heel + Lft;
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    b.add_body(
        {.name = S + "thigh",
         .parent = "pelvis",
         .mass = mass(dl::thigh),
         .com = {0, 0, com_down(dl::thigh)},
         .inertia = dl::upright_inertia(dl::thigh, mass(dl::thigh), Lth),
         .dofs =
             {{.name = S + "hip", .axis = Y, .limit = lim(-2.0, 0.7, 10, 5), .torque_limit = T}},
         .shapes = {capsule({0, 0, 0}, {0, 0, -Lth}, 0.07)},
         .length = Lth,
         .segment_end = {0, 0, -Lth}});
    b.add_body(
        {.name = S + "shin",
         .parent = S + "thigh",
         .joint_offset = {0, 0, -Lth},
         .mass = mass(dl::shank),
         .com = {0, 0, com_down(dl::shank)},
         .inertia = dl::upright_inertia(dl::shank, mass(dl::shank), Lsh),
         .dofs =
             {{.name = S + "knee", .axis = Y, .limit = lim(0.0, 2.5, 10, 5), .torque_limit = T}},
         .shapes = {capsule({0, 0, 0}, {0, 0, -Lsh}, 0.05)},
         .length = Lsh,
         .segment_end = {0, 0, -Lsh}});
    b.add_body(
        {.name = S + "foot",
         .parent = S + "shin",
         .joint_offset = {0, 0, -Lsh},
         .mass = mass(dl::foot),
         .com = {heel + 0.01 * dl::foot.com_percent * Lft, 0, 0},
         .inertia = dl::foot_inertia(mass(dl::foot), Lft),
         .dofs =
             {{.name = S + "ankle", .axis = Y, .limit = lim(-0.6, 0.9, 10, 2), .torque_limit = T}},
         .shapes = {capsule({heel, 0, 0}, {toe, 0, 0}, 0.025)},
         .length = Lft,
         .segment_end = {toe, 0, 0}});
    b.add_contact_point({.name = S + "heel",
                         .body = S + "foot",
                         .position = {heel, 0, 0},
                         .role = contact_point::kind::sole});
    b.add_contact_point({.name = S + "toe",
                         .body = S + "foot",
                         .position = {toe, 0, 0},
                         .role = contact_point::kind::toe});
  }
  b.add_body(
      {.name = "abdomen",
       .parent = "pelvis",
       .joint_offset = {0, 0, Llpt},
       .mass = mass(dl::middle_trunk),
       .com = {0, 0, com_up(dl::middle_trunk)},
       .inertia = dl::upright_inertia(dl::middle_trunk, mass(dl::middle_trunk), Lmpt),
       .dofs = {{.name = "back", .axis = Y, .limit = lim(-0.5, 0.8, 10, 5), .torque_limit = T}},
       .shapes = {box({0, 0, 0.5 * Lmpt}, {0.08, 0.13, 0.5 * Lmpt})},
       .length = Lmpt,
       .segment_end = {0, 0, Lmpt}});
  b.add_body(
      {.name = "thorax",
       .parent = "abdomen",
       .joint_offset = {0, 0, Lmpt},
       .mass = mass(dl::upper_trunk),
       .com = {0, 0, com_up(dl::upper_trunk)},
       .inertia = dl::upright_inertia(dl::upper_trunk, mass(dl::upper_trunk), Lupt),
       .dofs = {{.name = "chest", .axis = Y, .limit = lim(-0.3, 0.5, 10, 5), .torque_limit = T}},
       .shapes = {box({0, 0, 0.5 * Lupt}, {0.09, 0.16, 0.5 * Lupt})},
       .length = Lupt,
       .segment_end = {0, 0, Lupt}});
  b.add_body(
      {.name = "head",
       .parent = "thorax",
       .joint_offset = {0, 0, Lupt},
       .mass = mass(dl::head),
       .com = {0, 0, com_up(dl::head)},
       .inertia = dl::upright_inertia(dl::head, mass(dl::head), Lhead),
       .dofs = {{.name = "neck", .axis = Y, .limit = lim(-0.8, 0.8, 5, 1), .torque_limit = 50.0}},
       .shapes = {sphere({0, 0, 0.62 * Lhead}, 0.38 * Lhead)},
       .length = Lhead,
       .segment_end = {0, 0, Lhead}});
  // Shoulder joint centre 0.06 height below cervicale (docs/models.md).
  const double shoulder_z = Lupt - 0.06 * p.height;
  const double Lua = len(dl::upper_arm), Lfa = len(dl::forearm), Lha = len(dl::hand);
  for (const char* side : {"l", "r"}) {
    const std::string S = side;
    b.add_body({.name = S + "upper_arm",
                .parent = "thorax",
                .joint_offset = {0, 0, shoulder_z},
                .mass = mass(dl::upper_arm),
                .com = {0, 0, com_down(dl::upper_arm)},
                .inertia = dl::upright_inertia(dl::upper_arm, mass(dl::upper_arm), Lua),
                .dofs = {{.name = S + "shoulder",
                          .axis = Y,
                          .limit = lim(-3.0, 1.0, 5, 1),
                          .torque_limit = 100.0}},
                .shapes = {capsule({0, 0, 0}, {0, 0, -Lua}, 0.045)},
                .length = Lua,
                .segment_end = {0, 0, -Lua}});
    b.add_body({.name = S + "forearm",
                .parent = S + "upper_arm",
                .joint_offset = {0, 0, -Lua},
                .mass = mass(dl::forearm),
                .com = {0, 0, com_down(dl::forearm)},
                .inertia = dl::upright_inertia(dl::forearm, mass(dl::forearm), Lfa),
                .dofs = {{.name = S + "elbow",
                          .axis = Y,
                          .limit = lim(-2.6, 0.0, 3, 0.5),
                          .torque_limit = 60.0}},
                .shapes = {capsule({0, 0, 0}, {0, 0, -Lfa}, 0.035)},
                .length = Lfa,
                .segment_end = {0, 0, -Lfa}});
    b.add_body({.name = S + "hand",
                .parent = S + "forearm",
                .joint_offset = {0, 0, -Lfa},
                .mass = mass(dl::hand),
                .com = {0, 0, com_down(dl::hand)},
                .inertia = dl::upright_inertia(dl::hand, mass(dl::hand), Lha),
                .dofs = {{.name = S + "wrist",
                          .axis = Y,
                          .limit = lim(-1.2, 1.2, 1, 0.1),
                          .torque_limit = 20.0}},
                .shapes = {capsule({0, 0, 0}, {0, 0, -Lha}, 0.03)},
                .length = Lha,
                .segment_end = {0, 0, -Lha}});
  }
  return b.build();
}

}  // namespace gaitsynth
