#pragma once
/// \file objectives/wang2009/torso_posture.hpp
/// E_posture (ours, not in Wang, Fleet & Hertzmann 2009): an upright torso,
///     E_posture = 1/T sum_t Q(tilt_t; eps_posture),
/// tilt_t the angle between the torso body's up vector and the world vertical (rad; forward,
/// backward or sideways alike), Q the thresholded quadratic of eq. 3 and T the horizon's step
/// count, as in E_head (eq. 11).
///
/// Why: the paper's walkers stand upright with eq. 16 alone, but ours, pressed towards the human
/// power ratio, reach it by stooping (31-81 degrees, docs/reproductions/wang2009.md), and bounding
/// the torso's PD targets does not stop it (the servos lag, and the optimizer uses the lag). This
/// term measures the posture itself. Its weight in eq. 16 is 0 unless asked for
/// (wang2009_weights::posture), so that eq. 16 stays the paper's.
///
/// The same measure on the pelvis is E_pelvis (options::body = "pelvis", term = "E_pelvis";
/// wang2009_weights::pelvis): walkers held upright by E_posture alone tilt the pelvis back 11-20
/// degrees and flex the back over it, so their hips read extended (docs/reproductions/
/// wang2009.md, "Against a person").
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

struct torso_posture_options {
  /// rad: tilts up to this cost nothing (adults walk with the trunk within a few degrees of the
  /// vertical; 0.15 rad is 8.6 degrees).
  double eps_posture = 0.15;
  std::string body = "torso";      ///< the torso body's name
  std::string term = "E_posture";  ///< the term's name in the recorder (E_pelvis on the pelvis)
};

class torso_posture {
 public:
  using options = torso_posture_options;
  struct accumulator_type {
    rollout_track track;
    double sum = 0.0;         ///< sum of Q(tilt_t; eps), rad^2
    vec3 up = vec3::UnitZ();  ///< the torso's up vector at the last step (world)
  };

  /// `m` must have the torso body (options::body; \throws std::invalid_argument naming it).
  template <root_joint Root>
  explicit torso_posture(const model<Root>& m, options o = {}) : opt_(std::move(o)) {
    check_argument(std::isfinite(opt_.eps_posture) && opt_.eps_posture >= 0.0,
                   "wang2009::torso_posture: eps_posture must be finite and >= 0, got ",
                   opt_.eps_posture);
    torso_ = m.body_index(opt_.body);
    cos_eps_ = std::cos(opt_.eps_posture);
    names_ = {opt_.term, opt_.body + "_tilt_rad"};
  }
  const options& opts() const { return opt_; }
  int body() const { return torso_; }

  /// The angle between a unit up vector and +z, rad (spatial/world_angles.hpp).
  static double tilt(const vec3& up) { return tilt_from_vertical(up); }
  /// The tilt of a body with world rotation R (its up vector is R's third column), rad.
  static double tilt(const mat3& R) { return tilt(vec3(R.col(2))); }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    check_bodies(m, torso_, "wang2009::torso_posture");
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.track.add(v);
    a.up = v.body_rotation[torso_].col(2);
    // Within eps (up_z >= cos eps) Q is 0: the angle is only computed beyond it.
    if (a.up.z() < cos_eps_) a.sum += thresholded_quadratic(tilt(a.up), opt_.eps_posture);
  }
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    const std::int64_t T = horizon_steps(out, a.track.dt, a.track.steps);
    return T > 0 ? a.sum / static_cast<double>(T) : 0.0;
  }

  /// Running values: the term (options::term) and the body's tilt this step (rad), named
  /// "<body>_tilt_rad".
  const std::array<std::string, 2>& term_names() const { return names_; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = finish(a, a.track.outcome());
    out[1] = tilt(a.up);
  }

 private:
  options opt_;
  int torso_ = -1;
  double cos_eps_ = 1.0;
  std::array<std::string, 2> names_;
};

}  // namespace gaitsynth::wang2009
