#pragma once
/// \file mass_distance.hpp
/// The style objective of Sharon & van de Panne 2005 (section V.B): how far the simulated character
/// is from a kinematic target motion, measured by a mass-distance metric (eq. 2)
///
///     delta(t) = sum_i  integral over link i of  rho_i |x_i(t) - x'_i(t)|^2 dx,
///
/// approximated, as in the paper, by two point masses per link placed at the link's ends, each with
/// half the link's mass, and integrated over the simulation (eq. 3):
///
///     C = integral_0^T delta(t) dt        (kg m^2 s).
///
/// x_i are points of the simulated character (from the rollout's forward kinematics); x'_i are the
/// same points on the target motion at the same time (forward kinematics of the keyframe pose).
/// The link ends are the body origin (its joint) and `body.segment_end` (body frame); a body whose
/// segment_end is zero (a model without segment data) uses 2 com, the end point of a segment whose
/// centre of mass is in its middle.
///
/// Falls: the rollout stops when the character falls, which would make a fall *cheaper* than
/// walking on. As the paper says, falling "naturally cause[s] larger deviations": the character
/// would lie on the ground for the rest of the episode. finish() charges the remaining time at the
/// rate max(delta at the fall, fall_rate), where fall_rate defaults to the mass distance of the
/// target's first pose from the same pose collapsed to the ground (every point's height set to 0):
/// the error of a character lying on the floor. A rollout stopped by the stall rule (a cost that
/// turns rollout_options::stall on) is charged the same way: otherwise standing still would end the
/// episode early and cheaply.
///
/// Usable with any controller; any model with a keyframe_motion of the same root type.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// A point mass of the metric: `mass` (kg) at `position` in body `body`'s frame.
struct mass_point {
  int body = 0;
  vec3 position = vec3::Zero();
  double mass = 0.0;
};

/// The two-point-per-link approximation of eq. 2: each body's mass split equally between its origin
/// and its segment end (2 com when segment_end is zero).
template <root_joint Root>
std::vector<mass_point> link_end_points(const model<Root>& m) {
  std::vector<mass_point> pts;
  pts.reserve(2 * m.bodies.size());
  for (int b = 0; b < m.num_bodies(); ++b) {
    const body& bd = m.bodies[b];
    const vec3 end = bd.segment_end.isZero() ? vec3(2.0 * bd.com) : vec3(bd.segment_end);
    pts.push_back({b, vec3::Zero(), 0.5 * bd.mass});
    pts.push_back({b, end, 0.5 * bd.mass});
  }
  return pts;
}

/// delta of eq. 2 between two sets of body poses (e.g. two workspaces after forward_kinematics):
/// sum_p m_p |R_b p + o_b - (R'_b p + o'_b)|^2, kg m^2.
inline double mass_distance_error(std::span<const mass_point> points, std::span<const mat3> R,
                                  std::span<const vec3> o, std::span<const mat3> R_target,
                                  std::span<const vec3> o_target) {
  double d = 0.0;
  for (const mass_point& p : points) {
    const vec3 x = o[p.body] + R[p.body] * p.position;
    const vec3 xt = o_target[p.body] + R_target[p.body] * p.position;
    d += p.mass * (x - xt).squaredNorm();
  }
  return d;
}

struct mass_distance_options {
  /// Time of the target motion at the rollout's start (the rollout time t maps to t + offset).
  double time_offset = 0.0;
  /// Error rate charged for the time left after a fall (kg m^2); < 0: the default described above.
  double fall_rate = -1.0;
  /// Compare shapes only: translate the target along x so that its centre of mass is above the
  /// simulated one's at every instant. Off for the optimization (eq. 2 as published: the target's
  /// progression is part of the style); on, it measures how well the *pose sequence* is followed
  /// over long runs whose speed differs slightly from the target's (the style report).
  bool align_horizontal = false;
};

/// The objective C of eq. 3 (cost in kg m^2 s). Copyable; each accumulator owns the workspace it
/// uses for the target's forward kinematics, so concurrent rollouts never share scratch.
template <root_joint Root>
class mass_distance {
 public:
  using options = mass_distance_options;

  struct accumulator_type {
    workspace<Root> target_ws;  ///< forward kinematics of the target pose
    Eigen::VectorXd target_q;   ///< nq
    double integral = 0.0;      ///< sum delta dt so far, kg m^2 s
    double delta = 0.0;         ///< last delta, kg m^2
    double delta_max = 0.0;     ///< largest delta seen, kg m^2
    double time = 0.0;          ///< integrated time, s
  };

  /// `target` is copied; `m` must be the model the rollout simulates (same bodies and DOFs).
  mass_distance(const model<Root>& m, keyframe_motion<Root> target, options o = {})
      : target_(std::move(target)), points_(link_end_points(m)), opt_(o) {
    check_argument(target_.nq() == m.nq(), "mass_distance: target motion has nq = ", target_.nq(),
                   ", model '", m.name, "' has ", m.nq());
    check_argument(std::isfinite(opt_.time_offset), "mass_distance: time_offset is not finite (",
                   opt_.time_offset, ")");
    check_argument(!std::isnan(opt_.fall_rate), "mass_distance: fall_rate is NaN");
    if (opt_.fall_rate < 0.0) {
      // Error of the target's first pose against itself collapsed onto the ground plane z = 0.
      auto ws = make_workspace(m);
      Eigen::VectorXd q(m.nq());
      target_.pose(opt_.time_offset, q);
      forward_kinematics(m, ws, q);
      double r = 0.0;
      for (const mass_point& p : points_) {
        const vec3 x = ws.body_position[p.body] + ws.body_rotation[p.body] * p.position;
        r += p.mass * x.z() * x.z();
      }
      fall_rate_ = r;
    } else {
      fall_rate_ = opt_.fall_rate;
    }
  }

  const keyframe_motion<Root>& target() const { return target_; }
  const std::vector<mass_point>& points() const { return points_; }
  double fall_rate() const { return fall_rate_; }
  /// Total mass of the metric's points (the model's mass).
  double total_mass() const {
    double s = 0.0;
    for (const auto& p : points_) s += p.mass;
    return s;
  }

  accumulator_type make_accumulator(const model<Root>& m) const {
    check_argument(m.nq() == target_.nq(), "mass_distance: model '", m.name, "' has nq = ", m.nq(),
                   ", the target motion ", target_.nq());
    for (const mass_point& p : points_)
      check_argument(p.body < m.num_bodies(), "mass_distance: model '", m.name, "' has ",
                     m.num_bodies(), " bodies, the metric uses body ", p.body);
    accumulator_type a{make_workspace(m), Eigen::VectorXd::Zero(m.nq())};
    return a;
  }

  /// a as make_accumulator(m) returns it, keeping its memory (a worker's next rollout).
  void reset_accumulator(const model<Root>& m, accumulator_type& a) const {
    check_argument(a.target_q.size() == m.nq(),
                   "mass_distance: accumulator was made for nq = ", a.target_q.size(), ", model '",
                   m.name, "' has ", m.nq());
    a.target_q.setZero();
    a.integral = a.delta = a.delta_max = a.time = 0.0;
  }

  /// delta(t) at the start of the step's interval, integrated with the rectangle rule (eq. 3).
  template <class View>
  requires std::derived_from<View, step_view<Root>>
  void accumulate(accumulator_type& a, const View& v) const {
    target_.pose(v.t + opt_.time_offset, a.target_q);
    forward_kinematics(v.model(), a.target_ws, a.target_q);
    if (opt_.align_horizontal) {
      a.target_q[0] += v.com.x() - center_of_mass(v.model(), a.target_ws).x();
      forward_kinematics(v.model(), a.target_ws, a.target_q);
    }
    const double d = mass_distance_error(points_, v.body_rotation, v.body_position,
                                         a.target_ws.body_rotation, a.target_ws.body_position);
    a.delta = d;
    a.delta_max = std::max(a.delta_max, d);
    a.integral += d * v.dt;
    a.time += v.dt;
  }

  /// eq. 3, plus the fall charge for a fall or a stall (see the file comment).
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    double c = a.integral;
    if (out.reason == stop_reason::fell || out.reason == stop_reason::stalled)
      c += std::max(out.duration - out.time, 0.0) * std::max(a.delta, fall_rate_);
    return c;
  }

  /// Recorder hooks: delta(t) (kg m^2) and the running integral (kg m^2 s).
  static std::array<std::string_view, 2> term_names() {
    return {"mass_distance", "mass_distance_integral"};
  }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.delta;
    out[1] = a.integral;
  }

 private:
  keyframe_motion<Root> target_;
  std::vector<mass_point> points_;
  options opt_;
  double fall_rate_ = 0.0;
};

/// Style error of a recorded motion (rollout/trajectory.hpp) over [t0, t1): the mean of delta
/// (eq. 2, two points per link) against the target motion shifted in time by the phase phi in
/// [0, period) that fits best (searched on a grid of phase_step s) and moved along x under the
/// recorded COM at every frame. It compares the *shape* of the motion with the keyframed style,
/// whatever the drift in speed and timing over a long run. Returns {mean delta (kg m^2), phi (s)}.
template <root_joint Root>
std::pair<double, double> phase_aligned_style_error(const model<Root>& m,
                                                    const keyframe_motion<Root>& target,
                                                    const trajectory& tr, double t0, double t1,
                                                    double phase_step = 0.01) {
  check_positive(phase_step, "phase_aligned_style_error: phase_step (s)");
  const std::vector<mass_point> pts = link_end_points(m);
  std::vector<const trajectory_frame*> frames;
  for (const auto& f : tr.frames)
    if (f.t >= t0 && f.t < t1) frames.push_back(&f);
  check_argument(!frames.empty(), "phase_aligned_style_error: no recorded frame in [", t0, ", ", t1,
                 ")");
  for (const auto* f : frames)
    check_argument(static_cast<int>(f->body_position.size()) == m.num_bodies() &&
                       static_cast<int>(f->body_orientation.size()) == m.num_bodies(),
                   "phase_aligned_style_error: frame at t = ", f->t,
                   " has no body poses for model '", m.name, "'");
  auto ws = make_workspace(m);
  Eigen::VectorXd q(m.nq());
  std::vector<mat3> R(m.num_bodies());
  double best = std::numeric_limits<double>::infinity(), best_phi = 0.0;
  const int n_phase = std::max(1, static_cast<int>(std::ceil(target.period() / phase_step)));
  for (int k = 0; k < n_phase; ++k) {
    const double phi = k * phase_step;
    double sum = 0.0;
    for (const auto* f : frames) {
      target.pose(f->t + phi, q);
      forward_kinematics(m, ws, q);
      q[0] += f->com.x() - center_of_mass(m, ws).x();
      forward_kinematics(m, ws, q);
      for (int b = 0; b < m.num_bodies(); ++b) R[b] = f->body_orientation[b].toRotationMatrix();
      sum += mass_distance_error(pts, R, f->body_position, ws.body_rotation, ws.body_position);
      if (sum / static_cast<double>(frames.size()) >= best) break;  // cannot win any more
    }
    const double mean = sum / static_cast<double>(frames.size());
    if (mean < best) best = mean, best_phi = phi;
  }
  return {best, best_phi};
}

}  // namespace gaitsynth
