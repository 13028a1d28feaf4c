#pragma once
/// \file controllers/reflex/reflex_parameters.hpp
/// The 56 parameters of the MTU control laws of Wang et al. 2012 Sec. 4.2-4.3 (30 stance, 26
/// swing; "each of the u^F, u^L and u^theta laws have one, two and three parameters"), plus the
/// two SIMBICON balance-feedback gains of the shared swing-hip target (Sec. 4.3, counted with the
/// PD parameters in the paper): 58 in all, shared by both legs. Named indices, so a log, a
/// checkpoint or a test says which value is which.
///
/// Initial values (reflex_initial_parameters): Geyer & Herr 2010's reference control parameters
/// (their Table II and Geyer's reference model files), normalized (a force gain 1.2 / F_max
/// becomes 1.2 on F / F_max). Where Wang et al. use a law Geyer & Herr do not (RF, the swing
/// length laws of HAM and GLU, stance preparation, d_SI, d_SP), the value is ours and marked so.
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"

namespace gaitsynth::reflex {

/// Index of each parameter in the vector (p_: stance pre-stimulation, q_: swing).
enum reflex_parameter : int {
  // ---- stance (30) ----
  p_GLU,
  p_HFL,
  p_VAS,
  p_TA,
  p_SOL,
  p_HAM,
  p_RF,
  p_GAS,  // pre-stimulation
  G_SOL,
  G_GAS,
  G_VAS,  // force feedback u^F
  G_TA,
  H_TA,      // TA length feedback u^L
  G_SOL_TA,  // TA suppression by SOL force
  k_knee,
  knee_offset,  // VAS suppression (rad)
  K_HAM_lean,
  D_HAM_lean,
  lean_HAM,  // trunk lean PD u^Theta (rad, s)
  K_GLU_lean,
  D_GLU_lean,
  lean_GLU,
  K_HFL_lean,
  D_HFL_lean,
  lean_HFL,  // lean_HFL is also Theta_d
  s_VAS,
  s_RF,
  s_GLU,
  s_HFL,  // swing initiation offsets
  d_SI,   // swing initiation threshold
  // ---- swing (26) ----
  q_GLU,
  q_HFL,
  q_VAS,
  q_TA,
  q_SOL,
  q_HAM,
  q_RF,
  q_GAS,
  G_TA_swing,
  H_TA_swing,
  G_HAM_swing,
  H_HAM_swing,
  G_GLU_swing,
  H_GLU_swing,
  G_HFL_swing,
  H_HFL_swing,
  k_lean,  // HFL's lean offset gain
  K_VAS_knee,
  D_VAS_knee,
  knee_target,  // stance preparation, knee PD
  K_GLU_hip,
  D_GLU_hip,
  K_HFL_hip,
  D_HFL_hip,
  hip_target,  // stance preparation, hip PD
  d_SP,        // stance preparation threshold
  // ---- balance feedback of the hip target (2) ----
  c_d,
  c_v,
  reflex_parameter_count
};

static_assert(reflex_parameter_count == 58);
static_assert(q_GLU == 30 && c_d == 56, "30 stance, 26 swing MTU-law parameters");

inline constexpr std::array<std::string_view, reflex_parameter_count> reflex_parameter_names{
    "p_GLU",       "p_HFL",       "p_VAS",       "p_TA",        "p_SOL",       "p_HAM",
    "p_RF",        "p_GAS",       "G_SOL",       "G_GAS",       "G_VAS",       "G_TA",
    "H_TA",        "G_SOL_TA",    "k_knee",      "knee_offset", "K_HAM_lean",  "D_HAM_lean",
    "lean_HAM",    "K_GLU_lean",  "D_GLU_lean",  "lean_GLU",    "K_HFL_lean",  "D_HFL_lean",
    "lean_HFL",    "s_VAS",       "s_RF",        "s_GLU",       "s_HFL",       "d_SI",
    "q_GLU",       "q_HFL",       "q_VAS",       "q_TA",        "q_SOL",       "q_HAM",
    "q_RF",        "q_GAS",       "G_TA_swing",  "H_TA_swing",  "G_HAM_swing", "H_HAM_swing",
    "G_GLU_swing", "H_GLU_swing", "G_HFL_swing", "H_HFL_swing", "k_lean",      "K_VAS_knee",
    "D_VAS_knee",  "knee_target", "K_GLU_hip",   "D_GLU_hip",   "K_HFL_hip",   "D_HFL_hip",
    "hip_target",  "d_SP",        "c_d",         "c_v"};

using reflex_parameter_vector = std::array<double, reflex_parameter_count>;

/// Geyer & Herr 2010's reference values where they have the law, ours elsewhere (file comment).
inline reflex_parameter_vector reflex_initial_parameters() {
  constexpr double deg = 3.14159265358979323846 / 180.0;
  reflex_parameter_vector p{};
  // Stance pre-stimulation: 0.01, VAS 0.08, and 0.05 for the hip muscles that hold the trunk.
  p[p_GLU] = 0.05, p[p_HFL] = 0.05, p[p_VAS] = 0.08, p[p_TA] = 0.01, p[p_SOL] = 0.01;
  p[p_HAM] = 0.05, p[p_RF] = 0.01 /* ours */, p[p_GAS] = 0.01;
  p[G_SOL] = 1.2, p[G_GAS] = 1.1, p[G_VAS] = 1.2;
  p[G_TA] = 1.1, p[H_TA] = 1.0 - 0.5 * 0.56;  // 0.72 l_opt
  p[G_SOL_TA] = 0.4;
  p[k_knee] = 2.0, p[knee_offset] = 10.0 * deg;  // 170 deg in their angle
  // Trunk: K = 1 / 30 deg, D = 0.2 s, lean 6 deg, for each of HAM, GLU, HFL (G&H split one PD).
  for (int base : {K_HAM_lean, K_GLU_lean, K_HFL_lean}) {
    p[base] = 1.0 / (30.0 * deg);
    p[base + 1] = 0.2;
    p[base + 2] = 6.0 * deg;
  }
  p[s_VAS] = p[s_RF] = p[s_GLU] = p[s_HFL] = 0.25;  // G&H's K_swing; RF ours
  p[d_SI] = 1.0;  // ours: effectively off (G&H wait for double stance), left to the optimizer
  // Swing pre-stimulation: 0.01 (VAS keeps its 0.08).
  p[q_GLU] = p[q_HFL] = p[q_TA] = p[q_SOL] = p[q_HAM] = p[q_RF] = p[q_GAS] = 0.01;
  p[q_VAS] = 0.08;
  p[G_TA_swing] = 1.1, p[H_TA_swing] = 0.72;
  p[G_HAM_swing] = 0.65, p[H_HAM_swing] = 0.85;  // G&H's HAM gain, their HAM offset (ours: as u^L)
  p[G_GLU_swing] = 0.5, p[H_GLU_swing] = 0.85;   // G&H's GLU gain (ours: as u^L)
  p[G_HFL_swing] = 0.5, p[H_HFL_swing] = 0.65;
  p[k_lean] = 2.0 / 100.0 / deg;  // 2 % per degree of lean at take-off
  // Stance preparation (ours): knee to 5 deg of flexion, hip to 25 deg of flexion.
  p[K_VAS_knee] = 2.0, p[D_VAS_knee] = 0.2, p[knee_target] = 5.0 * deg;
  p[K_GLU_hip] = p[K_HFL_hip] = 1.0 / (30.0 * deg);
  p[D_GLU_hip] = p[D_HFL_hip] = 0.2;
  p[hip_target] = 25.0 * deg;
  p[d_SP] = -0.15;             // ours: the swing ankle 15 % of a leg ahead of the COM
  p[c_d] = 0.0, p[c_v] = 0.2;  // SIMBICON-like (ours: rad per m, rad per m/s)
  return p;
}

/// Copies a bound parameter vector, refusing a wrong size or a value that is not finite.
inline reflex_parameter_vector reflex_parameters_from(std::span<const double> p) {
  check_argument(p.size() == reflex_parameter_count, "reflex parameters: expected ",
                 static_cast<int>(reflex_parameter_count), " values, got ", p.size());
  reflex_parameter_vector out{};
  for (int i = 0; i < reflex_parameter_count; ++i) {
    check_argument(std::isfinite(p[static_cast<std::size_t>(i)]), "reflex parameter ",
                   reflex_parameter_names[static_cast<std::size_t>(i)], " is not finite (",
                   p[static_cast<std::size_t>(i)], ")");
    out[static_cast<std::size_t>(i)] = p[static_cast<std::size_t>(i)];
  }
  return out;
}

}  // namespace gaitsynth::reflex
