#pragma once
/// \file humanoid30.hpp
/// The 30-DOF SIMBICON-style humanoid (Yin et al. 2007 plus toes, Wang et al. 2009 Section 3) built
/// from de Leva's segment table (models/anthropometry.hpp) for any height and mass. Used by
/// wang2009_humanoid and wang2012_humanoid; the geometry rules are in docs/models.md. Contact
/// points: the feet and toes (roles sole, toe, toe_top; as the papers), then 43 body points (role
/// other) on the trunk, head, arms and legs, so that a fallen character lies on the ground.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/models/anthropometry.hpp"
#include "gaitsynth/models/detail/character_parts.hpp"

namespace gaitsynth::detail::characters {

/// Proportions of the humanoid (all fractions are of the standing height H unless noted).
struct humanoid30_proportions {
  double ankle_height = 0.039;   ///< ankle joint centre above the sole (Drillis-Contini, in Winter)
  double foot_width = 0.055;     ///< foot breadth (Drillis-Contini, in Winter)
  double hip_half_width = 0.05;  ///< hip joint centre from the mid-line
  double shoulder_half_width = 0.105;  ///< shoulder joint centre from the mid-line
  double shoulder_drop = 0.06;         ///< shoulder joint centre below cervicale
  double heel_behind_ankle = 0.25;     ///< heel behind the ankle, fraction of foot length
  double toe_fraction = 0.27;          ///< toe segment (MTP joint to tip), fraction of foot length
  double toe_height = 0.5;             ///< toe box height, fraction of ankle height
};

enum class foot_contact_style {
  box,       ///< foot and toe are boxes; 4 bottom corners each (Wang et al. 2009)
  cylinders  ///< heel and ball cylinders under the foot (Wang et al. 2012); toe box as above
};

struct humanoid30_spec {
  std::string name;
  double height = 1.65;  ///< m
  double mass = 70.0;    ///< kg
  double arm_length_scale = 1.0;
  double arm_mass_scale = 1.0;
  double trunk_mass_scale = 1.0;
  foot_contact_style feet = foot_contact_style::box;
  bool geyer_herr_sagittal_limits = false;  ///< Wang et al. 2012: soft limits of Geyer & Herr 2010
  humanoid30_proportions prop{};
};

/// Soft-limit and torque-limit table of one (left-side) DOF at the reference body (70 kg, 1.75 m).
struct dof_row {
  const char* name;     ///< without the l/r prefix for sided DOFs
  int axis;             ///< 0 x, 1 y, 2 z
  double lower, upper;  ///< rad (left side)
  double stiffness;     ///< N m / rad at the reference body
  double damping;       ///< N m s / rad at the reference body
  double torque_limit;  ///< N m at the reference body
};

inline constexpr double reference_limit_mass = 70.0;    // kg
inline constexpr double reference_limit_height = 1.75;  // m

// Ranges: typical active ranges of motion of adults (docs/models.md), signs by the right-hand rule
// about the body axes (x forward, y left, z up): hip/shoulder x + = abduction (left side), hip y
// + = extension, knee + = flexion, ankle x + = inversion (left), ankle y + = plantarflexion,
// toe + = flexion, back/neck y + = forward flexion, elbow y - = flexion.
inline constexpr std::array<dof_row, 3> back_rows{{{"back_x", 0, -0.5, 0.5, 1000, 50, 300},
                                                   {"back_y", 1, -0.5, 1.2, 1000, 50, 300},
                                                   {"back_z", 2, -0.6, 0.6, 1000, 50, 300}}};
inline constexpr std::array<dof_row, 3> neck_rows{{{"neck_x", 0, -0.7, 0.7, 200, 5, 50},
                                                   {"neck_y", 1, -0.9, 1.0, 200, 5, 50},
                                                   {"neck_z", 2, -1.2, 1.2, 200, 5, 50}}};
inline constexpr std::array<dof_row, 3> shoulder_rows{{{"shoulder_x", 0, -0.5, 2.8, 200, 2, 100},
                                                       {"shoulder_y", 1, -3.0, 1.0, 200, 2, 100},
                                                       {"shoulder_z", 2, -1.5, 1.5, 200, 2, 100}}};
inline constexpr std::array<dof_row, 2> elbow_rows{
    {{"elbow_y", 1, -2.6, 0.0, 100, 1, 60}, {"elbow_z", 2, -1.4, 1.4, 100, 1, 60}}};
inline constexpr std::array<dof_row, 3> hip_rows{{{"hip_x", 0, -0.5, 0.8, 1000, 20, 300},
                                                  {"hip_y", 1, -2.1, 0.5, 1000, 20, 300},
                                                  {"hip_z", 2, -0.7, 0.7, 1000, 20, 300}}};
inline constexpr std::array<dof_row, 1> knee_rows{{{"knee", 1, 0.0, 2.4, 1000, 20, 300}}};
inline constexpr std::array<dof_row, 2> ankle_rows{
    {{"ankle_x", 0, -0.35, 0.6, 500, 2, 100}, {"ankle_y", 1, -0.5, 0.87, 500, 2, 300}}};
inline constexpr std::array<dof_row, 1> toe_rows{{{"toe", 1, -1.2, 0.6, 200, 0.3, 60}}};

/// Geyer & Herr 2010 soft limits (Wang et al. 2012 Section 3): 0.3 N m/deg past the bound; ankle
/// 70..130 deg (shank-foot angle, 90 = our 0), knee hyperextension beyond 175 deg (5 deg of
/// flexion), hip beyond 230 deg (50 deg of extension). Bounds Geyer & Herr leave open keep our
/// anatomical ones.
inline constexpr double geyer_herr_stiffness = 0.3 / deg;  // N m / rad (17.19)
inline constexpr double geyer_herr_damping = 1.0;          // N m s / rad (ours, see docs)

template <std::size_t N>
std::vector<dof_spec> make_dofs(const std::array<dof_row, N>& rows, const std::string& prefix,
                                bool right, double k_scale, double tau_scale,
                                bool geyer_herr = false) {
  std::vector<dof_spec> out;
  for (const dof_row& r : rows) {
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis[r.axis] = 1.0;
    joint_limit L =
        spring_damper_limit(r.lower, r.upper, r.stiffness * k_scale, r.damping * k_scale);
    const std::string base = r.name;
    if (geyer_herr && (base == "hip_y" || base == "knee" || base == "ankle_y")) {
      if (base == "hip_y") L.upper = 50.0 * deg;
      if (base == "knee") L.lower = 5.0 * deg;
      if (base == "ankle_y") {
        L.lower = -20.0 * deg;
        L.upper = 40.0 * deg;
      }
      L.stiffness = geyer_herr_stiffness;
      L.damping = geyer_herr_damping;
    }
    if (right) L = mirrored_limit(L, axis);
    out.push_back({.name = prefix + base,
                   .axis = axis,
                   .limit = L,
                   .torque_limit = r.torque_limit * tau_scale});
  }
  return out;
}

/// Box shape for a trunk segment of mass m and length L: volume m / 1000 kg/m^3, width 1.5 depth.
inline shape trunk_box(double m, double z0, double L) {
  const double area = m / 1000.0 / L;
  const double depth = std::sqrt(area / 1.5);
  return box({0, 0, z0 + 0.5 * L}, {0.5 * depth, 0.75 * depth, 0.5 * L});
}
/// Capsule along -z for a limb of mass m and length L with the volume of a cylinder of density
/// 1000.
inline shape limb_capsule(double m, double L) {
  const double r = std::sqrt(m / 1000.0 / (std::numbers::pi * L));
  return capsule({0, 0, -r}, {0, 0, -L + r}, r);
}

inline floating_model build_humanoid30(const humanoid30_spec& sp) {
  namespace dl = de_leva1996;
  const std::string who = sp.name.empty() ? std::string("humanoid") : sp.name;
  check_positive(sp.height, (who + " height (m)").c_str());
  check_positive(sp.mass, (who + " mass (kg)").c_str());
  check_positive(sp.arm_length_scale, (who + " arm_length_scale").c_str());
  check_positive(sp.arm_mass_scale, (who + " arm_mass_scale").c_str());
  check_positive(sp.trunk_mass_scale, (who + " trunk_mass_scale").c_str());
  const humanoid30_proportions& pr = sp.prop;
  const double H = sp.height, M = sp.mass;

  // Lengths: de Leva's, scaled so that ankle height + vertical chain = H.
  const double ha = pr.ankle_height * H;
  const double s = (H - ha) / (dl::vertical_chain_mm * 1e-3);
  const auto len = [&](const dl::segment& g) { return s * g.length_mm * 1e-3; };
  const double Lhead = len(dl::head), Lupt = len(dl::upper_trunk), Lmpt = len(dl::middle_trunk),
               Llpt = len(dl::lower_trunk), Lth = len(dl::thigh), Lsh = len(dl::shank),
               Lft = len(dl::foot);
  const double as = sp.arm_length_scale;
  const double Lua = as * len(dl::upper_arm), Lfa = as * len(dl::forearm), Lha = as * len(dl::hand);

  // Masses: de Leva's percentages, arms and trunk optionally re-weighted, normalized to M.
  const double ts = sp.trunk_mass_scale, ms = sp.arm_mass_scale;
  const double total_percent =
      dl::head.mass_percent +
      ts * (dl::upper_trunk.mass_percent + dl::middle_trunk.mass_percent +
            dl::lower_trunk.mass_percent) +
      2.0 * (ms * (dl::upper_arm.mass_percent + dl::forearm.mass_percent + dl::hand.mass_percent) +
             dl::thigh.mass_percent + dl::shank.mass_percent + dl::foot.mass_percent);
  const auto mass = [&](const dl::segment& g, double w) {
    return M * w * g.mass_percent / total_percent;
  };
  const double m_head = mass(dl::head, 1), m_upt = mass(dl::upper_trunk, ts),
               m_mpt = mass(dl::middle_trunk, ts), m_lpt = mass(dl::lower_trunk, ts),
               m_ua = mass(dl::upper_arm, ms), m_fa = mass(dl::forearm, ms),
               m_ha = mass(dl::hand, ms), m_th = mass(dl::thigh, 1), m_sh = mass(dl::shank, 1),
               m_ft = mass(dl::foot, 1);

  // Foot: a box from the heel to the MTP joint and a toe box (half as high) to the tip; the mass
  // splits by volume (equal density). Their combined COM lies 44.3 % of the foot length from the
  // heel, against de Leva's 44.15 %.
  const double heel_x = -pr.heel_behind_ankle * Lft;
  const double Ltoe = pr.toe_fraction * Lft;
  const double mtp_x = heel_x + Lft - Ltoe;
  const double wf = pr.foot_width * H;
  const double ht = pr.toe_height * ha;
  const double v_foot = (Lft - Ltoe) * ha, v_toe = Ltoe * ht;
  const double m_toe = m_ft * v_toe / (v_foot + v_toe), m_foot = m_ft - m_toe;

  // Soft-limit constants scale with mass * height^2 (as the subtree inertias do), torque limits
  // with mass * height (as gravity torques do).
  const double k_scale =
      (M / reference_limit_mass) * (H / reference_limit_height) * (H / reference_limit_height);
  const double tau_scale = (M / reference_limit_mass) * (H / reference_limit_height);
  const bool gh = sp.geyer_herr_sagittal_limits;

  // Visual shapes that also carry the body contact points (role other, at the end).
  const shape pelvis_box = trunk_box(m_lpt, 0, Llpt);
  const shape thigh_capsule = limb_capsule(m_th, Lth), shin_capsule = limb_capsule(m_sh, Lsh);

  model_builder<floating_root> b(sp.name);
  // Pelvis (root): lower trunk, origin at the mid-point of the hip joint centres.
  b.add_body({.name = "pelvis",
              .mass = m_lpt,
              .com = {0, 0, Llpt * (1 - 0.01 * dl::lower_trunk.com_percent)},
              .inertia = dl::upright_inertia(dl::lower_trunk, m_lpt, Llpt),
              .shapes = {pelvis_box},
              .length = Llpt,
              .segment_end = {0, 0, Llpt}});
  for (const bool right : {false, true}) {
    const std::string S = right ? "r" : "l";
    const double side = right ? -1.0 : 1.0;
    b.add_body({.name = S + "thigh",
                .parent = "pelvis",
                .joint_offset = {0, side * pr.hip_half_width * H, 0},
                .mass = m_th,
                .com = {0, 0, -0.01 * dl::thigh.com_percent * Lth},
                .inertia = dl::upright_inertia(dl::thigh, m_th, Lth),
                .dofs = make_dofs(hip_rows, S, right, k_scale, tau_scale, gh),
                .shapes = {thigh_capsule},
                .length = Lth,
                .segment_end = {0, 0, -Lth}});
    b.add_body({.name = S + "shin",
                .parent = S + "thigh",
                .joint_offset = {0, 0, -Lth},
                .mass = m_sh,
                .com = {0, 0, -0.01 * dl::shank.com_percent * Lsh},
                .inertia = dl::upright_inertia(dl::shank, m_sh, Lsh),
                .dofs = make_dofs(knee_rows, S, right, k_scale, tau_scale, gh),
                .shapes = {shin_capsule},
                .length = Lsh,
                .segment_end = {0, 0, -Lsh}});
    const Eigen::Vector3d foot_size(Lft - Ltoe, wf, ha);
    const Eigen::Vector3d foot_c(0.5 * (heel_x + mtp_x), 0, -0.5 * ha);
    std::vector<shape> foot_shapes{box(foot_c, 0.5 * foot_size)};
    const double rc = 0.3 * ha;  // heel and ball cylinder radius (cylinders style)
    if (sp.feet == foot_contact_style::cylinders)
      for (const double cx : {heel_x + rc, mtp_x - rc})
        foot_shapes.push_back(
            capsule({cx, 0.5 * wf - rc, -ha + rc}, {cx, -0.5 * wf + rc, -ha + rc}, rc));
    b.add_body({.name = S + "foot",
                .parent = S + "shin",
                .joint_offset = {0, 0, -Lsh},
                .mass = m_foot,
                .com = foot_c,
                .inertia = solid::box_inertia(m_foot, foot_size),
                .dofs = make_dofs(ankle_rows, S, right, k_scale, tau_scale, gh),
                .shapes = foot_shapes,
                .length = Lft - Ltoe,
                .segment_end = {mtp_x, 0, -ha}});
    const Eigen::Vector3d toe_size(Ltoe, wf, ht);
    const Eigen::Vector3d toe_c(0.5 * Ltoe, 0, 0);
    b.add_body({.name = S + "toes",
                .parent = S + "foot",
                .joint_offset = {mtp_x, 0, -ha + 0.5 * ht},
                .mass = m_toe,
                .com = toe_c,
                .inertia = solid::box_inertia(m_toe, toe_size),
                .dofs = make_dofs(toe_rows, S, right, k_scale, tau_scale, gh),
                .shapes = {box(toe_c, 0.5 * toe_size)},
                .length = Ltoe,
                .segment_end = {Ltoe, 0, -0.5 * ht}});
    // Contact points; "lat" is the lateral edge (+y on the left, -y on the right).
    const double lat = side * 0.5 * wf, med = -lat;
    using ck = contact_point::kind;
    if (sp.feet == foot_contact_style::box) {
      b.add_contact_point({S + "foot_heel_lat", S + "foot", {heel_x, lat, -ha}, ck::sole});
      b.add_contact_point({S + "foot_heel_med", S + "foot", {heel_x, med, -ha}, ck::sole});
      b.add_contact_point({S + "foot_ball_lat", S + "foot", {mtp_x, lat, -ha}, ck::sole});
      b.add_contact_point({S + "foot_ball_med", S + "foot", {mtp_x, med, -ha}, ck::sole});
    } else {
      // Heel and ball cylinders (axis y, radius 0.3 ankle height) tangent to the sole plane; each
      // is sampled at three points of its lower arc (-45, 0, +45 deg from straight down) at both
      // ends so that the foot can roll on them.
      const std::array<double, 3> angles{-45.0 * deg, 0.0, 45.0 * deg};
      const std::array<const char*, 3> tag{"back", "mid", "front"};
      for (const auto& [where, cx] :
           {std::pair{"heel", heel_x + rc}, std::pair{"ball", mtp_x - rc}})
        for (int e = 0; e < 2; ++e)
          for (int a = 0; a < 3; ++a) {
            const double y = e == 0 ? lat : med;
            const Eigen::Vector3d p(cx + rc * std::sin(angles[a]), y,
                                    -ha + rc - rc * std::cos(angles[a]));
            b.add_contact_point({S + "foot_" + where + "_" + (e == 0 ? "lat_" : "med_") + tag[a],
                                 S + "foot", p, ck::sole});
          }
    }
    b.add_contact_point({S + "toes_base_lat", S + "toes", {0, lat, -0.5 * ht}, ck::toe});
    b.add_contact_point({S + "toes_base_med", S + "toes", {0, med, -0.5 * ht}, ck::toe});
    b.add_contact_point({S + "toes_tip_lat", S + "toes", {Ltoe, lat, -0.5 * ht}, ck::toe});
    b.add_contact_point({S + "toes_tip_med", S + "toes", {Ltoe, med, -0.5 * ht}, ck::toe});
    // The top front edge of the toe: touching the ground with it is a stubbed toe (eq. 6).
    b.add_contact_point({S + "toes_top_lat", S + "toes", {Ltoe, lat, 0.5 * ht}, ck::toe_top});
    b.add_contact_point({S + "toes_top_med", S + "toes", {Ltoe, med, 0.5 * ht}, ck::toe_top});
  }
  // Torso: middle and upper trunk welded together, origin at omphalion (the back joint).
  const solid::lumped mpt{m_mpt,
                          {0, 0, Lmpt * (1 - 0.01 * dl::middle_trunk.com_percent)},
                          dl::upright_inertia(dl::middle_trunk, m_mpt, Lmpt)};
  const solid::lumped upt{m_upt,
                          {0, 0, Lmpt + Lupt * (1 - 0.01 * dl::upper_trunk.com_percent)},
                          dl::upright_inertia(dl::upper_trunk, m_upt, Lupt)};
  const solid::lumped torso = solid::combine(mpt, upt);
  const double Ltorso = Lmpt + Lupt;
  const shape torso_box = trunk_box(torso.mass, 0, Ltorso);
  const shape head_ball = sphere({0, 0, 0.62 * Lhead}, 0.38 * Lhead);
  b.add_body({.name = "torso",
              .parent = "pelvis",
              .joint_offset = {0, 0, Llpt},
              .mass = torso.mass,
              .com = torso.com,
              .inertia = torso.inertia,
              .dofs = make_dofs(back_rows, "", false, k_scale, tau_scale),
              .shapes = {torso_box},
              .length = Ltorso,
              .segment_end = {0, 0, Ltorso}});
  b.add_body({.name = "head",
              .parent = "torso",
              .joint_offset = {0, 0, Ltorso},
              .mass = m_head,
              .com = {0, 0, Lhead * (1 - 0.01 * dl::head.com_percent)},
              .inertia = dl::upright_inertia(dl::head, m_head, Lhead),
              .dofs = make_dofs(neck_rows, "", false, k_scale, tau_scale),
              .shapes = {head_ball, capsule({0, 0, 0}, {0, 0, 0.3 * Lhead}, 0.2 * Lhead)},
              .length = Lhead,
              .segment_end = {0, 0, Lhead}});
  const shape upper_arm_capsule = limb_capsule(m_ua, Lua),
              forearm_capsule = limb_capsule(m_fa, Lfa);
  const shape hand_capsule = capsule({0, 0, -Lfa}, {0, 0, -Lfa - Lha}, 0.025 * as);
  for (const bool right : {false, true}) {
    const std::string S = right ? "r" : "l";
    const double side = right ? -1.0 : 1.0;
    b.add_body(
        {.name = S + "upper_arm",
         .parent = "torso",
         .joint_offset = {0, side * pr.shoulder_half_width * H, Ltorso - pr.shoulder_drop * H},
         .mass = m_ua,
         .com = {0, 0, -0.01 * dl::upper_arm.com_percent * Lua},
         .inertia = dl::upright_inertia(dl::upper_arm, m_ua, Lua),
         .dofs = make_dofs(shoulder_rows, S, right, k_scale, tau_scale),
         .shapes = {upper_arm_capsule},
         .length = Lua,
         .segment_end = {0, 0, -Lua}});
    // Lower arm: forearm and hand welded together (the hand has no joint in the 30-DOF model).
    const solid::lumped fa{m_fa,
                           {0, 0, -0.01 * dl::forearm.com_percent * Lfa},
                           dl::upright_inertia(dl::forearm, m_fa, Lfa)};
    const solid::lumped ha_{m_ha,
                            {0, 0, -Lfa - 0.01 * dl::hand.com_percent * Lha},
                            dl::upright_inertia(dl::hand, m_ha, Lha)};
    const solid::lumped lower = solid::combine(fa, ha_);
    b.add_body({.name = S + "lower_arm",
                .parent = S + "upper_arm",
                .joint_offset = {0, 0, -Lua},
                .mass = lower.mass,
                .com = lower.com,
                .inertia = lower.inertia,
                .dofs = make_dofs(elbow_rows, S, right, k_scale, tau_scale),
                .shapes = {forearm_capsule, hand_capsule},
                .length = Lfa + Lha,
                .segment_end = {0, 0, -Lfa - Lha}});
  }

  // Body contact points (role other; 43, after the foot and toe points, whose indices and per-body
  // counts stay as they were): without them a character that falls sinks through the ground. They
  // lie on the visual shapes above (so they scale with the body) where a falling, kneeling,
  // sitting or lying body meets the ground (docs/models.md). At q = 0 the lowest, the knees' front
  // points (the long-armed preset's hand tips), are 0.24-0.26 H above the sole plane.
  const auto other = [&](std::string name, const std::string& body, const Eigen::Vector3d& p) {
    b.add_contact_point({std::move(name), body, p, contact_point::kind::other});
  };
  // Trunk boxes: corner (sx, sy, sz), named <body>_<front|back>_<left|right>_<top|bottom>. The
  // pelvis needs only its bottom corners (its top ones are next to the torso's bottom ones).
  const auto corner = [&](const std::string& body, const shape& bx, int sx, int sy, int sz) {
    other(body + (sx > 0 ? "_front" : "_back") + (sy > 0 ? "_left" : "_right") +
              (sz > 0 ? "_top" : "_bottom"),
          body, bx.center + bx.half_extents.cwiseProduct(Eigen::Vector3d(sx, sy, sz)));
  };
  for (const int sx : {1, -1})
    for (const int sy : {1, -1}) corner("pelvis", pelvis_box, sx, sy, -1);
  for (const int sz : {1, -1})
    for (const int sx : {1, -1})
      for (const int sy : {1, -1}) corner("torso", torso_box, sx, sy, sz);
  // Head sphere: the top, 8 points around the equator (every 45 degrees) and 4 at 45 degrees of
  // elevation (front, left, back, right), so that no part of the upper half is more than about
  // 35 degrees from a point (it sinks at most 0.38 Lhead (1 - cos 35 deg) = 0.07 Lhead).
  const double c45 = 0.5 * std::numbers::sqrt2;
  const std::array<std::pair<const char*, Eigen::Vector2d>, 8> around{
      {{"front", {1, 0}},
       {"front_left", {c45, c45}},
       {"left", {0, 1}},
       {"back_left", {-c45, c45}},
       {"back", {-1, 0}},
       {"back_right", {-c45, -c45}},
       {"right", {0, -1}},
       {"front_right", {c45, -c45}}}};
  const Eigen::Vector3d hc = head_ball.center;
  const double hr = head_ball.radius;
  other("head_top", "head", hc + Eigen::Vector3d(0, 0, hr));
  for (std::size_t k = 0; k < around.size(); ++k) {
    const auto& [where, u] = around[k];
    other(std::string("head_") + where, "head", hc + hr * Eigen::Vector3d(u.x(), u.y(), 0));
    if (k % 2 == 0)
      other(std::string("head_") + where + "_top", "head",
            hc + hr * c45 * Eigen::Vector3d(u.x(), u.y(), 1));
  }
  // Limb capsules: points on their end spheres (centre p0 at the proximal end, p1 at the distal
  // end) offset by the radius: forward (+x), backward, lateral (+y on the left, -y on the right),
  // medial or down.
  const Eigen::Vector3d fwd = Eigen::Vector3d::UnitX(), down = -Eigen::Vector3d::UnitZ();
  for (const bool right : {false, true}) {
    const std::string S = right ? "r" : "l";
    const Eigen::Vector3d lat(0, right ? -1.0 : 1.0, 0);
    const double rt = thigh_capsule.radius, ru = upper_arm_capsule.radius;
    other(S + "buttock", S + "thigh", thigh_capsule.p0 - rt * fwd);
    other(S + "hip_lat", S + "thigh", thigh_capsule.p0 + rt * lat);
    other(S + "knee_lat", S + "thigh", thigh_capsule.p1 + rt * lat);
    other(S + "knee_front", S + "shin", shin_capsule.p0 + shin_capsule.radius * fwd);
    other(S + "shoulder_lat", S + "upper_arm", upper_arm_capsule.p0 + ru * lat);
    other(S + "elbow_lat", S + "upper_arm", upper_arm_capsule.p1 + ru * lat);
    other(S + "elbow_med", S + "upper_arm", upper_arm_capsule.p1 - ru * lat);
    other(S + "elbow_back", S + "lower_arm", forearm_capsule.p0 - forearm_capsule.radius * fwd);
    other(S + "hand_tip", S + "lower_arm", hand_capsule.p1 + hand_capsule.radius * down);
  }
  return b.build();
}

}  // namespace gaitsynth::detail::characters
