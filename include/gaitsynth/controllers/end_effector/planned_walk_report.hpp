#pragma once
/// \file controllers/end_effector/planned_walk_report.hpp
/// What planned_walk reports per step (controllers/concept.hpp's report hook) for the offline
/// optimization cost of Wu & Popovic 2010, Sec. 8.1 and 8.2 (objectives/wu2010/), and where each
/// quantity sits in the report.
///
/// Frame-tracking "forces" (Sec. 8.1): eqs. 1-3 with the PD coefficients replaced by the square
/// roots of the tracking weights and the biases set to zero. Sec. 8.3's weights w_kp = w_ko = w_kr
/// = 1, w_bp = w_bo = w_br = 0 make them the position errors p - p^ (LA, L), r - r^ (LR) and eq.
/// 2's orientation error sum_j e^_j x (e_j - e^_j) (~ 2 phi a for a small rotation phi about a).
/// The report holds their squared norms: the upper body's force and torque, then one per action
/// frame (the layout's order).
///
/// COM target (Sec. 8.1): c_k = c^_{k-1} + R_z(psi_m) (r x) (the paper's r y, our forward axis is
/// +x: docs/reproductions/wu2010.md's convention mapping), horizontal, set when half-cycle k is
/// planned from the COM c^_{k-1} sensed at that command.
#include <cmath>
#include <cstddef>

#include "gaitsynth/controllers/end_effector/pd_forces.hpp"

namespace gaitsynth {

/// Sec. 8.1's replacement coefficients (weights; the coefficients are their square roots).
struct tracking_weights {
  double kp = 1.0, bp = 0.0;  ///< LA and L frames' position (eq. 1)
  double ko = 1.0, bo = 0.0;  ///< LA frame's orientation (eq. 2)
  double kr = 1.0, br = 0.0;  ///< LR frames (eq. 3)

  /// The gains that make compute_ideal_wrenches return the tracking "forces": sqrt of the
  /// weights, zero biases. \throws std::invalid_argument for a negative or non-finite weight.
  end_effector_gains as_gains() const {
    for (const double w : {kp, bp, ko, bo, kr, br})
      check_argument(std::isfinite(w) && w >= 0.0,
                     "tracking_weights: weights must be finite and >= 0, got ", w);
    end_effector_gains g;
    g.ub_kp = g.ankle_kp = std::sqrt(kp);
    g.ub_bp = g.ankle_bp = std::sqrt(bp);
    g.ub_cp = g.ankle_cp = 0.0;
    g.ub_ko = std::sqrt(ko);
    g.ub_bo = std::sqrt(bo);
    g.toe_heel_kr = std::sqrt(kr);
    g.toe_heel_br = std::sqrt(br);
    return g;
  }
};

/// Indices into planned_walk's report.
struct planned_walk_report_layout {
  std::size_t tracking_begin = 0;  ///< first squared tracking norm (upper-body force)
  std::size_t tracking_count = 0;  ///< 2 + N: upper-body force and torque, N action frames
  std::size_t half_cycle = 0;      ///< k (-1 before the first command)
  std::size_t com_target = 0;      ///< c_k's x; c_k's y at com_target + 1 (world, m)
  std::size_t h_max = 0;           ///< Sec. 8.2's bound (0 without the helper force), N
  std::size_t helper_max = 0;      ///< largest |entry| of the applied helper force, N or N m
  std::size_t size = 0;

  /// For N action frames.
  static planned_walk_report_layout for_action_frames(int N) {
    planned_walk_report_layout L;
    L.tracking_begin = 0;
    L.tracking_count = static_cast<std::size_t>(N) + 2;
    L.half_cycle = L.tracking_count;
    L.com_target = L.half_cycle + 1;
    L.h_max = L.com_target + 2;
    L.helper_max = L.h_max + 1;
    L.size = L.helper_max + 1;
    return L;
  }
};

}  // namespace gaitsynth
