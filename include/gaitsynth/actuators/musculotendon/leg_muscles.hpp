#pragma once
/// \file actuators/musculotendon/leg_muscles.hpp
/// The eight MTUs of each leg of Wang et al. 2012 (Sec. 3, Figure 1): GLU, HFL, VAS, TA, SOL, HAM,
/// RF, GAS on the sagittal hip, knee and ankle DOFs. Seven are Geyer & Herr 2010's (Tables I and
/// II); Geyer & Herr have no RF, whose values come from Song & Geyer 2015 (J Physiol 593(16),
/// Table S1; its knee arm, variable between 4 and 6 cm there, is Wang's r0 cos(phi - phi_max)
/// with r0 = 6 cm here: ours). The paper's own adjusted values are in its supplement, which we do
/// not have; docs/models.md lists every number. Order per leg: GLU, HFL, VAS, TA, SOL, HAM, RF,
/// GAS; left leg first.
///
/// The model's DOFs map to Geyer & Herr's angles (path.hpp) as for the humanoids of
/// models/wang2009.hpp and models/wang2012.hpp: hip_y + = extension (phi = 180 deg + q), knee + =
/// flexion (phi = 180 deg - q), ankle_y + = plantarflexion (phi = 90 deg + q).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth::musculotendon {

/// The names of a leg's sagittal DOFs, after the side prefix ("l" or "r").
struct leg_dof_names {
  std::string left_prefix = "l";
  std::string right_prefix = "r";
  std::string hip = "hip_y";
  std::string knee = "knee";
  std::string ankle = "ankle_y";
};

/// The 16 MTUs (8 per leg) on model m's sagittal hip, knee and ankle DOFs. Throws
/// std::invalid_argument naming a DOF the model lacks.
template <root_joint Root>
std::vector<unit> geyer_herr_leg_muscles(const model<Root>& m, const leg_dof_names& names = {}) {
  constexpr double deg = std::numbers::pi / 180.0;
  constexpr double pi = std::numbers::pi;
  std::vector<unit> out;
  for (const std::string& side : {names.left_prefix, names.right_prefix}) {
    const int hip = m.dof_index(side + names.hip);
    const int knee = m.dof_index(side + names.knee);
    const int ankle = m.dof_index(side + names.ankle);
    // Geyer angle = offset + scale q (file comment).
    auto hip_x = [&](double s, double r, double ref, double rho) {
      return joint_crossing{.dof = hip,
                            .action = s,
                            .moment_arm = r,
                            .angle_of_max_arm = NAN,
                            .reference_angle = ref * deg,
                            .length_factor = rho,
                            .angle_offset = pi,
                            .angle_scale = 1.0};
    };
    // A variable-arm crossing of DOF `dof` whose Geyer angle is offset + scale q.
    auto variable_x = [&](int dof, double offset, double scale, double s, double r, double max,
                          double ref, double rho) {
      return joint_crossing{.dof = dof,
                            .action = s,
                            .moment_arm = r,
                            .angle_of_max_arm = max * deg,
                            .reference_angle = ref * deg,
                            .length_factor = rho,
                            .angle_offset = offset,
                            .angle_scale = scale};
    };
    auto knee_x = [&](double s, double r, double max, double ref, double rho) {
      return variable_x(knee, pi, -1.0, s, r, max, ref, rho);
    };
    auto ankle_x = [&](double s, double r, double max, double ref, double rho) {
      return variable_x(ankle, pi / 2, 1.0, s, r, max, ref, rho);
    };
    auto one = [&](const char* n, unit_parameters p, joint_crossing a) {
      out.push_back({.name = side + n, .parameters = p, .crossings = {a, {}}, .num_crossings = 1});
    };
    auto two = [&](const char* n, unit_parameters p, joint_crossing a, joint_crossing b) {
      out.push_back({.name = side + n, .parameters = p, .crossings = {a, b}, .num_crossings = 2});
    };
    //            F_max    l_opt  l_slack v_max          s    r0    phi_max phi_ref rho
    one("GLU", {1500.0, 0.11, 0.13, 12.0}, hip_x(+1, 0.10, 150.0, 0.5));
    one("HFL", {2000.0, 0.11, 0.10, 12.0}, hip_x(-1, 0.10, 180.0, 0.5));
    one("VAS", {6000.0, 0.08, 0.23, 12.0}, knee_x(+1, 0.06, 165.0, 125.0, 0.7));
    one("TA", {800.0, 0.06, 0.24, 12.0}, ankle_x(-1, 0.04, 80.0, 110.0, 0.7));
    one("SOL", {4000.0, 0.04, 0.26, 6.0}, ankle_x(+1, 0.05, 110.0, 80.0, 0.5));
    two("HAM", {3000.0, 0.10, 0.31, 12.0}, hip_x(+1, 0.08, 155.0, 0.7),
        knee_x(-1, 0.05, 180.0, 180.0, 0.7));
    two("RF", {1200.0, 0.08, 0.35, 12.0}, hip_x(-1, 0.08, 170.0, 0.3),
        knee_x(+1, 0.06, 165.0, 125.0, 0.5));
    two("GAS", {1500.0, 0.05, 0.40, 12.0}, knee_x(-1, 0.05, 140.0, 165.0, 0.7),
        ankle_x(+1, 0.05, 110.0, 80.0, 0.7));
  }
  return out;
}

/// Weakens (factor < 1) or strengthens the MTUs named `name`: their F_max times factor (Wang et al.
/// 2012 Sec. 6.2 weaken GAS and SOL to 1/4, HAM to 1/4, VAS to 1/10). A name without its side
/// prefix ("GAS") scales the unit in both legs; a full one ("lGAS") that unit alone. Throws
/// std::invalid_argument naming a factor that is not finite and positive, or a name no unit has.
inline void scale_max_isometric_force(std::vector<unit>& units, const std::string& name,
                                      double factor) {
  check_argument(std::isfinite(factor) && factor > 0.0, "scale_max_isometric_force: factor for '",
                 name, "' must be finite and > 0, got ", factor);
  int hit = 0;
  for (unit& u : units)
    if (u.name == name || (u.name.size() > 1 && u.name.substr(1) == name)) {
      u.parameters.max_isometric_force *= factor;
      ++hit;
    }
  if (hit == 0) {
    std::string names;
    for (const unit& u : units) names += (names.empty() ? "" : ", ") + u.name;
    throw std::invalid_argument("scale_max_isometric_force: no MTU named '" + name + "' (" + names +
                                ")");
  }
}

}  // namespace gaitsynth::musculotendon
