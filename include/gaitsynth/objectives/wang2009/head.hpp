#pragma once
/// \file objectives/wang2009/head.hpp
/// E_head of Wang, Fleet & Hertzmann 2009, eq. 11: a steady head (it stabilizes vision and the
/// vestibular system: constant forward velocity, fixed orientation),
///     E_head = Q(sqrt(sigma_head); sqrt(eps_head)) + lambda_head / T sum_t orient_t,
/// written exactly as the paper does (the square roots compare sigma_head with eps_head).
///   sigma_head: the standard deviation of the head's x velocity over the steps simulated. The
///               paper says "the head velocity"; we take the velocity of the head body's centre
///               of mass (v_origin + omega x R c), not of its origin, which is the neck joint;
///   orient_t:   1 when the norm of the head's world-frame angles (coronal, sagittal,
///               transverse: spatial/world_angles.hpp, heading +x) exceeds 0.1 rad.
/// T is the horizon's step count, as in E_land (landing.hpp says why); sigma is a property of the
/// motion that happened and uses the steps simulated (population standard deviation, Welford's
/// update: no cancellation over 24000 steps).
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"
#include "gaitsynth/objectives/wang2009/thresholded_quadratic.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

namespace gaitsynth::wang2009 {

struct head_options {
  double eps_head = 0.1;       ///< m/s
  double lambda_head = 0.012;  ///< weight of the orientation count
  double max_angle = 0.1;      ///< rad, ||Theta|| above which orient_t = 1
  std::string body = "head";   ///< the head body's name
};

class head {
 public:
  using options = head_options;
  struct accumulator_type {
    rollout_track track;
    double mean_vx = 0.0;       ///< m/s, running mean of the head x velocity
    double m2 = 0.0;            ///< sum of squared deviations (Welford), (m/s)^2
    double vx = 0.0;            ///< m/s, the last step's
    std::int64_t oriented = 0;  ///< steps with orient_t = 1
  };

  /// `m` must have the head body (options::body; \throws std::invalid_argument naming it).
  template <root_joint Root>
  explicit head(const model<Root>& m, options o = {}) : opt_(std::move(o)) {
    check_argument(std::isfinite(opt_.eps_head) && opt_.eps_head >= 0.0,
                   "wang2009::head: eps_head must be finite and >= 0, got ", opt_.eps_head);
    check_argument(std::isfinite(opt_.lambda_head) && opt_.lambda_head >= 0.0,
                   "wang2009::head: lambda_head must be finite and >= 0, got ", opt_.lambda_head);
    check_argument(std::isfinite(opt_.max_angle) && opt_.max_angle >= 0.0,
                   "wang2009::head: max_angle must be finite and >= 0, got ", opt_.max_angle);
    head_ = m.body_index(opt_.body);
    com_ = m.bodies[head_].com;
  }
  const options& opts() const { return opt_; }
  int body() const { return head_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    check_bodies(m, head_, "wang2009::head");
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    const mat3& R = v.body_rotation[head_];
    const double vx =
        (v.body_linear_velocity[head_] + v.body_angular_velocity[head_].cross(R * com_)).x();
    a.track.add(v);  // steps now counts this sample
    const double d = vx - a.mean_vx;
    a.mean_vx += d / static_cast<double>(a.track.steps);
    a.m2 += d * (vx - a.mean_vx);
    a.vx = vx;
    a.oriented += world_angles_norm_exceeds(R, opt_.max_angle) ? 1 : 0;
  }
  /// sigma_head, m/s: population standard deviation of the head x velocity.
  static double velocity_std(const accumulator_type& a) {
    return a.track.steps > 0 ? std::sqrt(a.m2 / static_cast<double>(a.track.steps)) : 0.0;
  }
  /// eq. 11, T the horizon's steps.
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const std::int64_t T = horizon_steps(out, a.track.dt, a.track.steps);
    const double orient = T > 0 ? static_cast<double>(a.oriented) / static_cast<double>(T) : 0.0;
    return thresholded_quadratic(std::sqrt(velocity_std(a)), std::sqrt(opt_.eps_head)) +
           opt_.lambda_head * orient;
  }

  /// Running values: E_head and sigma_head (m/s).
  static std::array<std::string_view, 2> term_names() { return {"E_head", "head_vx_std_m_s"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
    out[1] = velocity_std(a);
  }

 private:
  options opt_;
  int head_ = -1;
  vec3 com_ = vec3::Zero();  ///< head COM, head frame
};

}  // namespace gaitsynth::wang2009
