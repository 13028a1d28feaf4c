#pragma once
/// \file rollout/push_test.hpp
/// The push-recovery protocol of Wang, Fleet & Hertzmann 2009 (Sec. 5, Table 1): "simulate
/// forward for 40 seconds, and apply a push force (F_x, F_y) for 0.4 seconds to the torso COM
/// once every 4 seconds ... The controller passes the experiment if it is still walking forward
/// (direction (1, 0)) after 40 seconds." Table 1 reports force components: direction (1, 1) at
/// 75 N is F = (75, 75) N.
///
/// Here the pushes start at t0 + period (4, 8, ..., 36 s: nine pushes, 4 s to recover from the
/// last), and "still walking forward" means the rollout did not fall (COM above the fall height)
/// and its COM advanced along +x at `min_forward_speed` or faster over the last period.
///
/// One walk is chaotic, so one start's largest force moves with the rounding (up to 35 N here);
/// max_push_force_from_starts gives the force that K of N perturbed starts survive, which moves
/// far less (docs/reproductions/wang2009.md, "Table 1 from perturbed starts").
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/options.hpp"
#include "gaitsynth/rollout/rollout.hpp"

namespace gaitsynth {

struct push_protocol {
  double duration = 40.0;          ///< s
  double period = 4.0;             ///< s between push starts
  double push_duration = 0.4;      ///< s
  double min_forward_speed = 0.1;  ///< m/s over the last period: "still walking forward"
  double max_force = 500.0;        ///< N, largest force component tried by max_push_force
  double resolution = 5.0;         ///< N, step of the force components tried
};

/// What one push trial gives.
struct push_trial {
  bool passed = false;
  rollout_result result;
  double final_speed = 0.0;  ///< m/s, the COM's mean x velocity over the last period
};

namespace detail {
/// Records the COM's x at the start of the last period.
struct last_period_observer {
  double t_mark = 0.0;
  double x_mark = std::nan("");
  template <class Ob>
  void observe(const Ob& ob) {
    if (std::isnan(x_mark) && ob.t >= t_mark) x_mark = ob.com.x();
  }
};
}  // namespace detail

/// One trial: the walk of `opt` (its initial state, contact, fall height) for proto.duration with
/// periodic pushes of `force` (world, N) on body `body`'s COM. Any other pushes in opt are kept.
template <root_joint Root, class Actuator, class Controller, terrain Terrain, class Integrator>
push_trial push_trial_run(const model<Root>& m, const Actuator& act, const Controller& ctrl,
                          const Terrain& ground, const Integrator& integ,
                          std::span<const double> params, rollout_options opt, int body,
                          const vec3& force, const push_protocol& proto = {}) {
  check_positive(proto.duration, "push_protocol::duration (s)");
  check_positive(proto.period, "push_protocol::period (s)");
  check_argument(proto.duration / proto.period < 1e6,
                 "push_protocol: duration / period must be < 1e6 pushes, got ", proto.duration,
                 " s / ", proto.period, " s");
  check_argument(std::isfinite(proto.push_duration) && proto.push_duration >= 0.0,
                 "push_protocol::push_duration must be finite and >= 0 s, got ",
                 proto.push_duration);
  check_argument(std::isfinite(proto.min_forward_speed),
                 "push_protocol::min_forward_speed must be finite, got ", proto.min_forward_speed);
  check_argument(body >= 0 && body < m.num_bodies(), "push_trial_run: body ", body,
                 " is not a body of model '", m.name, "' (", m.num_bodies(), " bodies)");
  check_argument(force.allFinite(), "push_trial_run: force (", force.transpose(),
                 ") is not finite");
  const int count = static_cast<int>(std::floor((proto.duration - 1e-9) / proto.period));
  const double t0 = opt.initial_state.q.size() > 0 ? opt.initial_state.t : 0.0;
  for (const push& p :
       periodic_pushes(body, force, t0 + proto.period, proto.period, proto.push_duration, count))
    opt.pushes.push_back(p);
  opt.duration = proto.duration;
  opt.record = nullptr;
  auto scratch = make_rollout_scratch(m);
  detail::last_period_observer ob;
  ob.t_mark = t0 + proto.duration - proto.period;
  Controller c = ctrl;
  Integrator i = integ;
  push_trial out;
  out.result = rollout(m, act, c, distance_objective(), ground, i, params, opt, scratch, ob);
  out.final_speed =
      std::isnan(ob.x_mark) ? 0.0 : (out.result.com_final.x() - ob.x_mark) / proto.period;
  out.passed =
      out.result.reason == stop_reason::horizon && out.final_speed >= proto.min_forward_speed;
  return out;
}

namespace detail {
/// A scan's grid (resolution, max_force) and direction, checked for `who`.
inline void check_push_scan(const push_protocol& proto, const vec3& direction, const char* who) {
  check_positive(proto.resolution, "push_protocol::resolution (N)");
  check_argument(std::isfinite(proto.max_force) && proto.max_force >= 0.0,
                 "push_protocol::max_force must be finite and >= 0 N, got ", proto.max_force);
  check_argument(proto.max_force / proto.resolution < 1e6,
                 "push_protocol: max_force / resolution must be < 1e6 trials, got ",
                 proto.max_force, " N / ", proto.resolution, " N");
  check_argument(direction.allFinite(), who, ": direction (", direction.transpose(),
                 ") is not finite");
}
}  // namespace detail

/// Table 1's entry for one direction (components in {-1, 0, 1}, e.g. (1, 1)): the largest force
/// component F, in steps of proto.resolution up to proto.max_force, such that every push
/// F' direction with F' <= F on that grid passes (the scan stops at the first failure). 0 if the
/// walk fails even at the first step; the walk without pushes is not checked here.
template <root_joint Root, class Actuator, class Controller, terrain Terrain, class Integrator>
double max_push_force(const model<Root>& m, const Actuator& act, const Controller& ctrl,
                      const Terrain& ground, const Integrator& integ,
                      std::span<const double> params, const rollout_options& opt, int body,
                      const vec3& direction, const push_protocol& proto = {}) {
  detail::check_push_scan(proto, direction, "max_push_force");
  double survived = 0.0;
  for (double f = proto.resolution; f <= proto.max_force + 1e-9; f += proto.resolution) {
    if (!push_trial_run(m, act, ctrl, ground, integ, params, opt, body, vec3(f * direction), proto)
             .passed)
      break;
    survived = f;
  }
  return survived;
}

/// Table 1's entry for one direction from several starts.
struct push_scan {
  double force = 0.0;  ///< N: the largest grid force that `required` of the starts survive
  /// N, per start: its own largest force (max_push_force's rule), or, where censored[k], the
  /// last force it passed before the scan could stop (a lower bound).
  std::vector<double> per_start;
  std::vector<bool> censored;  ///< start k was still passing when the scan stopped
};

/// Table 1's entry for one direction beyond one rounding: the largest force component F on
/// max_push_force's grid such that at least `required` of the starts pass every force up to F.
/// Start k is opt with `velocity_offsets[k]` as its initial_velocity_offset (an empty vector:
/// opt's own start), e.g. joint_velocity_perturbations(m, 10, 0.05, seed) with required = 8.
/// F is the required-th largest of the starts' own max_push_force values; the scan runs the
/// starts that are still passing, level by level, and stops as soon as fewer than `required`
/// can be. Deterministic: every trial is one rollout from its own start.
template <root_joint Root, class Actuator, class Controller, terrain Terrain, class Integrator>
push_scan max_push_force_from_starts(const model<Root>& m, const Actuator& act,
                                     const Controller& ctrl, const Terrain& ground,
                                     const Integrator& integ, std::span<const double> params,
                                     rollout_options opt, int body, const vec3& direction,
                                     std::span<const Eigen::VectorXd> velocity_offsets,
                                     int required, const push_protocol& proto = {}) {
  const int n = static_cast<int>(velocity_offsets.size());
  check_argument(n > 0, "max_push_force_from_starts: no starts (velocity_offsets is empty)");
  check_argument(required >= 1 && required <= n,
                 "max_push_force_from_starts: required must be in [1, ", n,
                 "] (the number of starts), got ", required);
  detail::check_push_scan(proto, direction, "max_push_force_from_starts");
  for (int k = 0; k < n; ++k) {
    const Eigen::Index size = velocity_offsets[static_cast<std::size_t>(k)].size();
    check_argument(size == 0 || size == m.nv(), "max_push_force_from_starts: velocity_offsets[", k,
                   "] has ", size, " entries, model '", m.name, "' has nv = ", m.nv());
  }
  push_scan out;
  out.per_start.assign(static_cast<std::size_t>(n), 0.0);
  out.censored.assign(static_cast<std::size_t>(n), true);
  int alive = n;
  for (double f = proto.resolution; f <= proto.max_force + 1e-9; f += proto.resolution) {
    for (int k = 0; k < n && alive >= required; ++k) {
      const auto ks = static_cast<std::size_t>(k);
      if (!out.censored[ks]) continue;  // failed at a lower force
      opt.initial_velocity_offset = velocity_offsets[ks];
      if (push_trial_run(m, act, ctrl, ground, integ, params, opt, body, vec3(f * direction), proto)
              .passed) {
        out.per_start[ks] = f;
      } else {
        out.censored[ks] = false;
        --alive;
      }
    }
    if (alive < required) break;
    out.force = f;
  }
  return out;
}

/// Table 1's eight directions, in its order: (1,0), (1,1), (0,1), (-1,1), (-1,0), (-1,-1),
/// (0,-1), (1,-1); (1, 0) is forward, (0, 1) to the left.
inline const std::array<vec3, 8>& table1_directions() {
  static const std::array<vec3, 8> d{vec3(1, 0, 0),  vec3(1, 1, 0),  vec3(0, 1, 0),
                                     vec3(-1, 1, 0), vec3(-1, 0, 0), vec3(-1, -1, 0),
                                     vec3(0, -1, 0), vec3(1, -1, 0)};
  return d;
}

}  // namespace gaitsynth
