#pragma once
/// \file objectives/wang2009/angular_momentum.hpp
/// E_ang of Wang, Fleet & Hertzmann 2009, eqs. 9 and 10: small changes of the whole-body angular
/// momentum about the vertical axis (arms swinging against the legs),
///     avgL  = 1/T sum_t Ldot_t^2,                                   (9)
///     E_ang = Q(sqrt(avgL); sqrt(eps_ang)),                         (10)
/// L_t: the vertical (z) component of the angular momentum about the COM, read from the rollout's
/// own kinematics (centroidal_momentum(view.model(), view.workspace()), no recomputation),
/// normalized as Herr & Popovic 2008 ("Angular momentum in human walking", J Exp Biol 211, Fig. 3)
/// do: divided by M V H, body mass (the model's total mass), walking speed and COM height, which
/// makes it dimensionless. Ldot_t = (L_t - L_{t-1}) / dt between consecutive steps, so avgL is
/// the mean over the T - 1 differences of the steps simulated (a rate of the motion that
/// happened; a fall is charged by E_fail).
///
/// Choices where the paper is silent: H is the model's standing COM height (COM z above its
/// lowest contact point at q = 0; options::height overrides); V is options::speed when given
/// (the target speed, in the complete objective), else the rollout's average forward COM speed
/// v_x, at least options::min_speed (standing or walking backward would divide by ~0). M V H is
/// constant over a rollout, so the sum is kept in SI units and normalized in finish().
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/momentum.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"
#include "gaitsynth/objectives/wang2009/thresholded_quadratic.hpp"

namespace gaitsynth::wang2009 {

struct angular_momentum_options {
  double eps_ang = 0.05;         ///< threshold of avgL (normalized Ldot squared, 1/s^2)
  std::optional<double> speed;   ///< V, m/s (> 0); unset: the average forward COM speed
  std::optional<double> height;  ///< H, m (> 0); unset: the standing COM height
  double min_speed = 0.1;        ///< m/s, the least V used (> 0)
};

/// Standing COM height of m: COM z above its lowest contact point (or body origin, for a model
/// without contact points) in the neutral configuration, m.
template <root_joint Root>
double standing_com_height(const model<Root>& m) {
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, neutral_configuration(m));
  double low = std::numeric_limits<double>::infinity();
  if (m.contact_points.empty()) {
    for (int b = 0; b < m.num_bodies(); ++b) low = std::min(low, ws.body_position[b].z());
  } else {
    for (const auto& c : m.contact_points)
      low = std::min(low, point_position(m, ws, c.body, c.position).z());
  }
  return center_of_mass(m, ws).z() - low;
}

class angular_momentum {
 public:
  using options = angular_momentum_options;
  struct accumulator_type {
    rollout_track track;
    double L = 0.0;          ///< last L_z, kg m^2/s
    double sum_ldot2 = 0.0;  ///< sum of Ldot^2, (kg m^2/s^2)^2
    std::int64_t diffs = 0;  ///< finite differences taken
  };

  template <root_joint Root>
  explicit angular_momentum(const model<Root>& m, options o = {}) : opt_(o), mass_(m.total_mass()) {
    check_positive(opt_.eps_ang, "wang2009::angular_momentum: eps_ang");
    if (opt_.speed) check_positive(*opt_.speed, "wang2009::angular_momentum: speed (m/s)");
    if (opt_.height) check_positive(*opt_.height, "wang2009::angular_momentum: height (m)");
    check_positive(opt_.min_speed, "wang2009::angular_momentum: min_speed (m/s)");
    check_positive(mass_, "wang2009::angular_momentum: model total mass (kg)");
    height_ = opt_.height ? *opt_.height : standing_com_height(m);
    check_positive(height_, "wang2009::angular_momentum: standing COM height of the model (m)");
  }
  const options& opts() const { return opt_; }
  double mass() const { return mass_; }      ///< M, kg
  double height() const { return height_; }  ///< H, m

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  /// One sample of L_z (kg m^2/s) at a step of length dt (s): the finite difference with the
  /// previous sample. accumulate() feeds the view's centroidal momentum here.
  static void add_sample(accumulator_type& a, double L, double dt) {
    if (a.track.steps > 0 && dt > 0.0) {
      const double ldot = (L - a.L) / dt;
      a.sum_ldot2 += ldot * ldot;
      ++a.diffs;
    }
    a.L = L;
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    add_sample(a, centroidal_momentum(v.model(), v.workspace()).angular.z(), v.dt);
    a.track.add(v);
  }
  /// V used for the normalization, m/s.
  double normalization_speed(const rollout_outcome& out) const {
    return opt_.speed ? *opt_.speed : std::max(average_com_velocity(out).x(), opt_.min_speed);
  }
  /// avgL of eq. 9 (normalized, 1/s^2); 0 with no difference taken.
  double average_ldot_squared(const accumulator_type& a, const rollout_outcome& out) const {
    if (a.diffs == 0) return 0.0;
    const double mvh = mass_ * normalization_speed(out) * height_;
    return a.sum_ldot2 / static_cast<double>(a.diffs) / (mvh * mvh);
  }
  /// eq. 10.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    return thresholded_quadratic(std::sqrt(average_ldot_squared(a, out)), std::sqrt(opt_.eps_ang));
  }

  /// Running values: E_ang and L_z (kg m^2/s, not normalized).
  static std::array<std::string_view, 2> term_names() { return {"E_ang", "L_z"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
    out[1] = a.L;
  }

 private:
  options opt_;
  double mass_ = 0.0;
  double height_ = 0.0;
};

}  // namespace gaitsynth::wang2009
