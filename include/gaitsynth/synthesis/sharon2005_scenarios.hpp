#pragma once
/// \file synthesis/sharon2005_scenarios.hpp
/// The experiments of Sharon & van de Panne 2005 as data, shared by the examples/sharon2005_*.cpp
/// programs and the tests in tests/sharon2005/ (so a test checks exactly what an example runs),
/// and the start state of a keyframed motion placed on any terrain.
///
/// Figure 8 (robustness of the unmodified normal-walk controller): (a) torso mass 40 -> 28 kg,
/// (b) shin 0.44 -> 0.25 m with thigh 0.46 -> 0.6 m, (c) shin 0.44 -> 0.8 m, (d) bumpy terrain
/// with gradients up to 11 degrees, walked blindly (the controller senses nothing of it).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/rollout/rollout.hpp"

namespace gaitsynth::sharon_scenarios {

/// A planar bumpy profile along x (a height field with one row, which planar models query at
/// y = 0): a sum of six sinusoids of wavelengths 0.5 to 2 m (by default: bumps, not hills) with
/// seeded random phases and amplitudes, sampled every 5 cm and scaled so that its steepest gradient
/// is exactly max_slope_deg (the paper gives only that); flat (and blended in over 1 m) before
/// x = flat_until so that the walk starts on level ground. With the defaults the heights span about
/// 5 to 8 cm. \throws std::invalid_argument naming a max_slope_deg outside [0, 90), wavelengths
/// not 0 < min <= max, a length outside (0, 1e6] m, a non-finite flat_until, or a profile left
/// flat over its whole length (nothing to scale).
inline gaitsynth::height_field_terrain bumpy_terrain(
    double max_slope_deg = 11.0, std::uint64_t seed = 2005, double min_wavelength = 0.5,
    double max_wavelength = 2.0, double length = 120.0, double flat_until = 1.0) {
  gaitsynth::check_argument(max_slope_deg >= 0.0 && max_slope_deg < 90.0,
                            "bumpy_terrain: max_slope_deg must be in [0, 90), got ", max_slope_deg);
  gaitsynth::check_argument(std::isfinite(min_wavelength) && std::isfinite(max_wavelength) &&
                                min_wavelength > 0.0 && min_wavelength <= max_wavelength,
                            "bumpy_terrain: need finite 0 < min_wavelength <= max_wavelength, got ",
                            min_wavelength, " and ", max_wavelength);
  gaitsynth::check_argument(length > 0.0 && length <= 1e6,
                            "bumpy_terrain: length must be in (0, 1e6] m, got ", length);
  gaitsynth::check_argument(std::isfinite(flat_until),
                            "bumpy_terrain: flat_until must be finite, got ", flat_until);
  const double spacing = 0.05, x0 = -5.0;
  const int n = static_cast<int>(std::ceil(length / spacing)) + 1;
  std::mt19937_64 rng(seed);
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  constexpr int waves = 6;
  double lambda[waves], phase[waves], amp[waves];
  for (int k = 0; k < waves; ++k) {
    lambda[k] = min_wavelength + (max_wavelength - min_wavelength) * uniform();
    phase[k] = 2.0 * std::numbers::pi * uniform();
    amp[k] = (0.5 + uniform()) * lambda[k];  // longer waves are higher: similar slopes
  }
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, 1);
  for (int i = 0; i < n; ++i) {
    const double x = x0 + spacing * i;
    double y = 0.0;
    for (int k = 0; k < waves; ++k)
      y += amp[k] * std::sin(2.0 * std::numbers::pi * x / lambda[k] + phase[k]);
    const double blend = std::clamp(x - flat_until, 0.0, 1.0);
    h(i, 0) = blend * blend * (3.0 - 2.0 * blend) * y;  // smoothstep from flat ground
  }
  h.array() -= h(0, 0);
  double g = 0.0;
  for (int i = 1; i < n; ++i) g = std::max(g, std::abs(h(i, 0) - h(i - 1, 0)) / spacing);
  gaitsynth::check_argument(g > 0.0, "bumpy_terrain: the profile is flat over its whole length (",
                            length, " m from x = ", x0, "; flat_until = ", flat_until, ")");
  h *= std::tan(max_slope_deg * std::numbers::pi / 180.0) / g;
  return gaitsynth::height_field_terrain(Eigen::Vector2d(x0, 0.0), spacing, h);
}

/// Terrains for a cost that rewards walking blindly over bumps (examples/sharon2005_normal_walk
/// --bumpy-training N): profiles like bumpy_terrain's, bumpy from the start (so a 2 s episode meets
/// them), with seeds 1..n -- never the test profile's seed 2005.
inline std::vector<gaitsynth::height_field_terrain> training_terrains(int n,
                                                                      double max_slope_deg = 11.0) {
  std::vector<gaitsynth::height_field_terrain> t;
  for (int k = 1; k <= n; ++k)
    t.push_back(bumpy_terrain(max_slope_deg, static_cast<std::uint64_t>(k), 0.5, 2.0, 20.0, -10.0));
  return t;
}

/// Training bodies for a cost that rewards robustness to modeling errors
/// (examples/sharon2005_normal_walk --body-training N), in a box around the paper's Figure 8
/// changes (torso 40 -> 28 kg, thigh 0.46 -> 0.6 m, shin 0.44 -> 0.25 or 0.8 m): torso mass in
/// [26, 48] kg, thigh length in [0.40, 0.65] m, shin length in [0.22, 0.85] m, inertias as rods.
/// The first 8 are the box's corners, the rest seeded uniform draws (seeds 1001, 1002, ...). None
/// is a Figure 8 body (the tests keep those for themselves), but those lie inside the box: for us
/// they test interpolation, where the paper's controller, optimized for the nominal body alone,
/// extrapolated.
inline std::vector<gaitsynth::sharon2005_human7_parameters> training_bodies(int n) {
  constexpr double torso[2] = {26.0, 48.0}, thigh[2] = {0.40, 0.65}, shin[2] = {0.22, 0.85};
  std::vector<gaitsynth::sharon2005_human7_parameters> v;
  for (int k = 0; k < n; ++k) {
    gaitsynth::sharon2005_human7_parameters p;
    if (k < 8) {
      p.torso_mass = torso[k & 1];
      p.thigh_length = thigh[(k >> 1) & 1];
      p.shin_length = shin[(k >> 2) & 1];
    } else {
      std::mt19937_64 rng(static_cast<std::uint64_t>(1001 + k - 8));
      auto uniform = [&](const double(&r)[2]) {
        return r[0] + (r[1] - r[0]) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
      };
      p.torso_mass = uniform(torso);
      p.thigh_length = uniform(thigh);
      p.shin_length = uniform(shin);
    }
    v.push_back(p.with_rod_inertias());
  }
  return v;
}

/// Largest |gradient| of the profile, degrees (for reports and tests).
inline double max_gradient_deg(const gaitsynth::height_field_terrain& t, double x_begin,
                               double x_end) {
  double m = 0.0;
  for (double x = x_begin; x <= x_end; x += 0.01) {
    const gaitsynth::vec3 n = t.normal(x, 0.0);
    m = std::max(m, std::atan2(std::hypot(n.x(), n.y()), n.z()));
  }
  return m * 180.0 / std::numbers::pi;
}

struct body_variant {
  std::string name;
  std::string description;
  gaitsynth::sharon2005_human7_parameters params;
};

/// Figure 8 (a)-(c). Inertias follow the changed masses and lengths (Table I's are rod inertias).
inline std::vector<body_variant> figure8_bodies() {
  std::vector<body_variant> v;
  gaitsynth::sharon2005_human7_parameters a;
  a.torso_mass = 28.0;
  v.push_back({"torso_28kg", "Fig. 8a: torso mass 40 -> 28 kg", a.with_rod_inertias()});
  gaitsynth::sharon2005_human7_parameters b;
  b.shin_length = 0.25;
  b.thigh_length = 0.6;
  v.push_back({"shin_0.25_thigh_0.6", "Fig. 8b: shin 0.44 -> 0.25 m, thigh 0.46 -> 0.6 m",
               b.with_rod_inertias()});
  gaitsynth::sharon2005_human7_parameters c;
  c.shin_length = 0.8;
  v.push_back({"shin_0.8", "Fig. 8c: shin 0.44 -> 0.8 m", c.with_rod_inertias()});
  return v;
}

/// The start state for a body on a terrain: the target's first pose and velocity (joint angles and
/// rates as keyframed), with the root lowered or raised so that the lowest contact point touches
/// `ground` under it (place_on_terrain: flat ground, slopes, height fields, steps), as for the
/// original body on flat ground.
template <terrain T = flat_terrain>
sim_state start_state_for(const planar_model& m, const keyframe_motion<planar_root>& target,
                          const T& ground = T()) {
  sim_state s = target.initial_state();
  place_on_terrain(m, ground, s.q);
  return s;
}

}  // namespace gaitsynth::sharon_scenarios
