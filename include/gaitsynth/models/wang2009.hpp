#pragma once
/// \file wang2009.hpp
/// The 3D humanoid of Wang, Fleet & Hertzmann, "Optimizing Walking Controllers", ACM TOG 28(5),
/// 2009 (Section 3, Fig. 8): the SIMBICON character (Yin et al. 2007) with toes, 30 internal DOFs
///   back (3), neck (3), shoulders (3 each), elbows (2 each), hips (3 each), knees (1 each),
///   ankles (2 each), toe hinges (1 each),
/// box feet and toes with 4 contact points each (plus 43 body points of role other on the trunk,
/// head, arms and legs, so that a fall lies on the ground), and the six body shapes of Fig. 8 as
/// presets.
/// The paper takes its mass distribution from Wooten & Hodgins 1996 without printing it; we use de
/// Leva 1996 (models/anthropometry.hpp). Every number and choice is in docs/models.md.
///
/// floating_model: q = [pelvis position (3), pelvis quaternion (w, x, y, z), 30 joint angles],
/// v = [pelvis linear velocity (world), angular velocity (pelvis frame), 30 joint rates]. The root
/// body is the pelvis, its origin the mid-point of the hip joint centres. Body frames: x forward,
/// y left, z up at q = 0 (standing upright, arms hanging, feet flat). Joint DOF order:
///   lhip_x lhip_y lhip_z lknee lankle_x lankle_y ltoe
///   rhip_x rhip_y rhip_z rknee rankle_x rankle_y rtoe
///   back_x back_y back_z neck_x neck_y neck_z
///   lshoulder_x lshoulder_y lshoulder_z lelbow_y lelbow_z
///   rshoulder_x rshoulder_y rshoulder_z relbow_y relbow_z
/// Several DOFs of one joint compose in the listed order (x, then y, then z) about the joint
/// centre. Left/right DOFs about x and z have mirror sign -1 (model.mirror_sign).
#include <array>
#include <concepts>
#include <string>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/models/detail/humanoid30.hpp"

namespace gaitsynth {

/// Body shape of the Wang 2009 humanoid. height and mass are the standing height (sole to vertex)
/// and total mass; the scales re-weight de Leva's proportions (1 = de Leva).
struct wang2009_body {
  std::string name = "stocky";    ///< also the model's name suffix
  double height = 1.65;           ///< m
  double mass = 70.0;             ///< kg
  double arm_length_scale = 1.0;  ///< upper arm, forearm and hand lengths
  double arm_mass_scale = 1.0;    ///< weight of the arm segments' mass percentages
  double trunk_mass_scale = 1.0;  ///< weight of the three trunk segments' mass percentages

  /// A copy with another height and mass (proportions kept).
  wang2009_body scaled_to(double new_height, double new_mass) const {
    wang2009_body b = *this;
    b.height = new_height;
    b.mass = new_mass;
    return b;
  }
};

/// The six characters of Wang et al. 2009, Fig. 8 (bottom), left to right.
enum class wang2009_shape { long_arm, thin, short_, stocky, overweight, tall };

inline constexpr std::array<wang2009_shape, 6> wang2009_shapes{
    wang2009_shape::long_arm, wang2009_shape::thin,       wang2009_shape::short_,
    wang2009_shape::stocky,   wang2009_shape::overweight, wang2009_shape::tall};

/// Preset of Fig. 8: "long arm" (127 cm, 65 kg), "thin" (165 cm, 41 kg), "short" (165 cm, 57 kg),
/// "stocky" (165 cm, 70 kg), "overweight" (161 cm, 86 kg), "tall" (196 cm, 79 kg). Heights and
/// masses are the paper's; the paper describes but does not quantify the long-armed humanoid's
/// "heavy arms" and the overweight subject's build, so arm_length_scale = 1.5, arm_mass_scale = 2.5
/// (long arm) and trunk_mass_scale = 1.3 (overweight) are our choices (docs/models.md).
inline wang2009_body wang2009_preset(wang2009_shape s) {
  switch (s) {
    case wang2009_shape::long_arm:
      return {.name = "long_arm",
              .height = 1.27,
              .mass = 65.0,
              .arm_length_scale = 1.5,
              .arm_mass_scale = 2.5};
    case wang2009_shape::thin:
      return {.name = "thin", .height = 1.65, .mass = 41.0};
    case wang2009_shape::short_:
      return {.name = "short", .height = 1.65, .mass = 57.0};
    case wang2009_shape::stocky:
      return {.name = "stocky", .height = 1.65, .mass = 70.0};
    case wang2009_shape::overweight:
      return {.name = "overweight", .height = 1.61, .mass = 86.0, .trunk_mass_scale = 1.3};
    case wang2009_shape::tall:
      return {.name = "tall", .height = 1.96, .mass = 79.0};
  }
  throw std::invalid_argument("wang2009_preset: unknown shape");
}

/// Preset by the paper's name: "long arm" (or "long_arm"), "thin", "short", "stocky",
/// "overweight", "tall". \throws std::invalid_argument naming an unknown name.
inline wang2009_body wang2009_preset(std::string_view name) {
  for (wang2009_shape s : wang2009_shapes) {
    const wang2009_body b = wang2009_preset(s);
    if (name == b.name) return b;
  }
  if (name == "long arm") return wang2009_preset(wang2009_shape::long_arm);
  throw std::invalid_argument(
      detail::concat("wang2009_preset: unknown body shape '", name,
                     "' (expected long arm, thin, short, stocky, overweight or tall)"));
}

/// The Wang 2009 humanoid with body shape `body` (default: "stocky", 165 cm, 70 kg, the character
/// the paper's initial controller was tuned on). Model name "wang2009_<body.name>".
/// \throws std::invalid_argument naming a non-positive or non-finite height, mass or scale.
inline floating_model wang2009_humanoid(const wang2009_body& body = {}) {
  detail::characters::humanoid30_spec sp;
  sp.name = "wang2009_" + (body.name.empty() ? std::string("custom") : body.name);
  sp.height = body.height;
  sp.mass = body.mass;
  sp.arm_length_scale = body.arm_length_scale;
  sp.arm_mass_scale = body.arm_mass_scale;
  sp.trunk_mass_scale = body.trunk_mass_scale;
  sp.feet = detail::characters::foot_contact_style::box;
  return detail::characters::build_humanoid30(sp);
}

/// Convenience: the preset `s` (wang2009_humanoid(wang2009_preset(s))). A template so that
/// wang2009_humanoid({}) still means the default body, not the enum's first value.
template <std::same_as<wang2009_shape> Shape>
floating_model wang2009_humanoid(Shape s) {
  return wang2009_humanoid(wang2009_preset(s));
}

}  // namespace gaitsynth
