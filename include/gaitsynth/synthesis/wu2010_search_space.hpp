#pragma once
/// \file synthesis/wu2010_search_space.hpp
/// The search space of Wu & Popovic 2010 (Sec. 8.3, Table 1) for the cyclical controller
/// planned_walk (controllers/end_effector/planned_walk.hpp): its parameters with Table 1's bounds,
/// which parameter_space maps onto [0, 1] ("When passed to CMA, the bounds are normalized to
/// [0, 1]"; the paper then starts CMA at 0.5 with sigma 0.3, parameter_space's initial values are
/// the caller's).
///
/// Table 1 (paper frame -> ours: planner_parameters.hpp), per Omega:
///   t_e [0, 0.6] x t_h; c_sw, c_ub [-0.3, 0.3] m; the K+ and K- entries [0, 3]; gamma1, gamma2
///   [0, 1]; w_sw1.u [0, 0.8], w_sw2.u [0.2, 1.0], w_sw1.v, w_sw2.v [0, 0.8] m; w_ub1.u [0, 0.66],
///   w_ub2.u [0.33, 1]; z_ub [-0.3, 0.3] + z_ub0 (z_ub0 "the natural height of the upper body");
///   theta_ub, phi_ub [-15, 15] deg; psi_ub [-30, 30] deg.
///   Our readings: the K row of Table 1 is garbled in our copy ("k_w, k_r (in K, and K)"); we
///   apply its [0, 3] to K+, K- and K_ub (planner_parameters.hpp says Table 1 names K+-'s only).
///   theta_sw1, theta_sw2: Table 1 prints [-180, 80] deg; we use [-80, 80] deg (a foot pitched
///   by -180 deg is upside down; docs/reproductions/wu2010.md).
/// Per Pi: upper body kp [0, 4000], bp [0, 800], cp [0, 140] x 9.8, ko [0, 4000] (Table 1's k_a),
///   bo [0, 80] (b_a); ankle kp [0, 4000], bp [0, 400], cp [0, 10] x 9.8; toe and heel kr
///   [0, 8000], br [0, 100]. Not in Table 1, ours: W's upper-body weight [0, 10] and appendix B's
///   rho [0, 1000] (end_effector_gains' defaults 1 and 300).
/// The helper force's h_max [-200, 1000] N (Sec. 8.3; the negative lower bound lets CMA sample
///   controllers without helper force), the last parameter when planned_walk_options::helper_force
///   is on.
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"

namespace gaitsynth {

/// Table 1's bounds of one Omega's flat vector (planner_vector_names' order), for a half-cycle of
/// t_h seconds and a natural upper-body height z_ub0 (m).
inline std::vector<std::pair<double, double>> wu2010_planner_bounds(double t_h, double z_ub0) {
  check_argument(std::isfinite(t_h) && t_h > 0.0,
                 "wu2010_planner_bounds: t_h must be finite and > 0, got ", t_h);
  check_argument(std::isfinite(z_ub0), "wu2010_planner_bounds: z_ub0 must be finite, got ", z_ub0);
  constexpr double deg = std::numbers::pi / 180.0;
  const std::pair<double, double> k{0.0, 3.0}, c{-0.3, 0.3}, unit{0.0, 1.0};
  const std::pair<double, double> tilt{-15 * deg, 15 * deg}, foot_pitch{-80 * deg, 80 * deg};
  return {
      {0.0, 0.6 * t_h},            // t_e
      k,                           // k_sw_plus.along
      k,                           // k_sw_plus.left
      k,                           // k_sw_minus.along
      k,                           // k_sw_minus.left
      c,                           // c_sw.along
      c,                           // c_sw.left
      k,                           // k_ub.along (ours: Table 1's K bound)
      k,                           // k_ub.left
      c,                           // c_ub.along
      c,                           // c_ub.left
      {z_ub0 - 0.3, z_ub0 + 0.3},  // z_ub
      tilt,                        // theta_ub
      tilt,                        // phi_ub
      {-30 * deg, 30 * deg},       // psi_ub
      unit,                        // gamma1
      unit,                        // gamma2
      {0.0, 0.8},                  // w_sw1.u
      {0.0, 0.8},                  // w_sw1.v
      {0.2, 1.0},                  // w_sw2.u
      {0.0, 0.8},                  // w_sw2.v
      foot_pitch,                  // theta_sw1 (Table 1 prints [-180, 80] deg)
      foot_pitch,                  // theta_sw2
      {0.0, 0.66},                 // w_ub1.u
      {0.33, 1.0},                 // w_ub2.u
  };
}

/// Table 1's bounds of one Pi (end_effector_gains::names' order); the last two are ours.
inline std::vector<std::pair<double, double>> wu2010_gain_bounds() {
  return {{0.0, 4000.0}, {0.0, 800.0},  {0.0, 140.0 * 9.8}, {0.0, 4000.0},
          {0.0, 80.0},   {0.0, 4000.0}, {0.0, 400.0},       {0.0, 10.0 * 9.8},
          {0.0, 8000.0}, {0.0, 100.0},  {0.0, 10.0},        {0.0, 1000.0}};
}

/// Sec. 8.3's bounds of the helper force's h_max, N.
inline constexpr std::pair<double, double> wu2010_h_max_bounds{-200.0, 1000.0};

/// The natural height z_ub0 of models/wu2010.hpp's upper body: its COM (the planned point) stands
/// 1.45 m above the ankles with straight legs.
inline constexpr double wu2010_natural_upper_body_height = 1.45;

/// The parameter space of controller c (its symmetry decides the layout) with `initial` (e.g.
/// c.default_parameters() or a saved controller) as the initial values.
/// \throws std::invalid_argument naming a parameter whose initial value lies outside its bounds.
template <terrain T, root_joint Root>
parameter_space wu2010_search_space(const planned_walk<T, Root>& c,
                                    const std::vector<double>& initial,
                                    double z_ub0 = wu2010_natural_upper_body_height) {
  check_size(static_cast<std::ptrdiff_t>(initial.size()),
             static_cast<std::ptrdiff_t>(c.num_parameters()), "wu2010_search_space: initial");
  const std::vector<std::string> names = c.parameter_names();
  std::vector<std::pair<double, double>> bounds;
  bounds.reserve(names.size());
  const auto omega = wu2010_planner_bounds(c.half_cycle_duration(), z_ub0);
  const auto pi = wu2010_gain_bounds();
  for (int h = 0; h < c.num_planner_sets(); ++h)
    bounds.insert(bounds.end(), omega.begin(), omega.end());
  for (int h = 0; h < c.num_gain_sets(); ++h) bounds.insert(bounds.end(), pi.begin(), pi.end());
  if (c.opts().helper_force) bounds.emplace_back(wu2010_h_max_bounds);
  check_size(static_cast<std::ptrdiff_t>(bounds.size()), static_cast<std::ptrdiff_t>(names.size()),
             "wu2010_search_space: bounds");
  parameter_space space;
  for (std::size_t i = 0; i < names.size(); ++i)
    space.add({.name = names[i],
               .lower = bounds[i].first,
               .upper = bounds[i].second,
               .initial = initial[i]});
  return space;
}

}  // namespace gaitsynth
