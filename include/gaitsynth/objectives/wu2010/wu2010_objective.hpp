#pragma once
/// \file objectives/wu2010/wu2010_objective.hpp
/// The offline-optimization cost of Wu & Popovic 2010, eq. 6 with eq. 7's helper penalty:
///     E(P) + w_h L {h_max}+ = sum_j sum_i e_track,i + sum_k ||dc_k||^2_{W_c}
///                             + sum_j ||tau_theta||^2_{W_tau} + w_h L {h_max}+,
/// as a weighted_sum of the four terms (one file each in this folder) with unit weights: the
/// paper's weights (eps_track, W_c, W_tau, w_h; Sec. 8.3) are inside the terms' options. Every sum
/// over j is over the paper's 1/64 s timesteps (common.hpp: a physics step counts dt / timestep),
/// so the cost does not depend on the simulation rate; `timestep` = 0 counts physics steps
/// instead (the runs f1 and f2 of data/wu2010/). The terms read planned_walk's report, so the
/// objective is made from the controller's report layout:
///
///   planned_walk<> ctrl(m, ground, {.helper_force = true});
///   auto obj = wu2010_objective(ctrl.report_layout());
///
/// Without the helper force h_max reads 0 and the penalty is 0 (eq. 6 alone).
#include <array>
#include <cstddef>

#include "gaitsynth/objectives/weighted_sum.hpp"
#include "gaitsynth/objectives/wu2010/com_deviation.hpp"
#include "gaitsynth/objectives/wu2010/energy.hpp"
#include "gaitsynth/objectives/wu2010/helper_penalty.hpp"
#include "gaitsynth/objectives/wu2010/tracking_error.hpp"

namespace gaitsynth {

struct wu2010_objective_options {
  wu2010::tracking_error_options tracking{};  ///< eps_track = 2.5e-3
  wu2010::com_deviation_options com{};        ///< W_c = 100 I
  wu2010::energy_options energy{};            ///< W_tau = 8e-2 W_pref
  wu2010::helper_penalty_options helper{};    ///< w_h = 5e-3
  /// Multipliers of the four terms (1: eq. 6 and 7 as published; 0 ablates a term, which is
  /// still measured and recorded).
  std::array<double, 4> weights{1.0, 1.0, 1.0, 1.0};
  /// Eq. 6's timestep for the three per-timestep terms (common.hpp), s; replaces theirs.
  double timestep = wu2010::paper_timestep;
};

using wu2010_objective_type = weighted_sum<wu2010::tracking_error, wu2010::com_deviation,
                                           wu2010::energy, wu2010::helper_penalty>;

/// Part indices of wu2010_objective_type (obj.part<wu2010_term::com>()).
struct wu2010_term {
  static constexpr std::size_t track = 0, com = 1, energy = 2, helper = 3;
};

inline wu2010_objective_type wu2010_objective(const planned_walk_report_layout& layout,
                                              const wu2010_objective_options& o = {}) {
  auto tracking = o.tracking;
  auto energy = o.energy;
  auto helper = o.helper;
  tracking.timestep = energy.timestep = helper.timestep = o.timestep;
  return wu2010_objective_type(o.weights, wu2010::tracking_error(layout, tracking),
                               wu2010::com_deviation(layout, o.com), wu2010::energy(energy),
                               wu2010::helper_penalty(layout, helper));
}

}  // namespace gaitsynth
