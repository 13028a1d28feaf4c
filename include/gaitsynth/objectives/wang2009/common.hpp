#pragma once
/// \file objectives/wang2009/common.hpp
/// What the terms of Wang, Fleet & Hertzmann 2009, Sec. 4.1 (eqs. 3-16) share:
///   - rollout_track: the first and last COM, the start velocity and the step count, kept by
///     every term's accumulator so that its recorded (running) value is the term "as if the
///     rollout ended now";
///   - average_com_velocity: v_x, v_y, v_z of eqs. 4, 5 and 12 (COM displacement / time);
///   - horizon_steps: T of eqs. 6, 7 and 11, the step count of the requested horizon;
///   - the feet and the phase convention of Fig. 2 (E_land, the step length of E_user).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "gaitsynth/model/model.hpp"
#include "gaitsynth/objectives/concept.hpp"

namespace gaitsynth::wang2009 {

/// A running summary of the steps seen so far.
struct rollout_track {
  std::int64_t steps = 0;  ///< accumulate calls (steps simulated)
  double dt = 0.0;         ///< s, of the last step
  vec3 com_first = vec3::Zero();
  vec3 com_last = vec3::Zero();
  vec3 com_velocity_first = vec3::Zero();  ///< the start state's COM velocity, m/s

  template <class View>
  void add(const View& v) {
    if (steps == 0) {
      com_first = v.com;
      com_velocity_first = v.com_velocity;
    }
    com_last = v.com;
    dt = v.dt;
    ++steps;
  }
  /// The outcome of a rollout that reached its horizon now: T = steps so far, and the COM
  /// displacement over the (steps - 1) dt between the first and last COM seen.
  rollout_outcome outcome() const {
    rollout_outcome o;
    o.reason = stop_reason::horizon;
    o.steps = steps;
    o.duration = static_cast<double>(steps) * dt;
    o.time = static_cast<double>(std::max<std::int64_t>(steps - 1, 0)) * dt;
    o.com_initial = com_first;
    o.com_final = com_last;
    return o;
  }
};

/// Average COM velocity over the rollout, (com_final - com_initial) / time (m/s); zero when no
/// time was simulated.
inline vec3 average_com_velocity(const rollout_outcome& out) {
  if (!(out.time > 0.0)) return vec3::Zero();
  return (out.com_final - out.com_initial) / out.time;
}

/// T of eqs. 6, 7 and 11: the steps of the requested horizon (duration / dt, rounded), at least
/// the steps simulated; 0 when dt is unknown (nothing was simulated).
inline std::int64_t horizon_steps(const rollout_outcome& out, double dt, std::int64_t simulated) {
  if (!(dt > 0.0) || !std::isfinite(out.duration)) return simulated;
  return std::max(static_cast<std::int64_t>(std::llround(out.duration / dt)), simulated);
}

/// Body indices of the feet and toes (the contact bodies of Wang et al. 2009, Sec. 4.2).
struct foot_bodies {
  int lfoot = -1, ltoes = -1, rfoot = -1, rtoes = -1;

  /// By name ("lfoot", "ltoes", "rfoot", "rtoes"). \throws std::invalid_argument naming a missing
  /// body.
  template <root_joint Root>
  static foot_bodies of(const model<Root>& m) {
    return {m.body_index("lfoot"), m.body_index("ltoes"), m.body_index("rfoot"),
            m.body_index("rtoes")};
  }
  /// As of(), or nothing when a body is missing.
  template <root_joint Root>
  static std::optional<foot_bodies> find(const model<Root>& m) {
    const foot_bodies f{m.find_body("lfoot"), m.find_body("ltoes"), m.find_body("rfoot"),
                        m.find_body("rtoes")};
    if (f.lfoot < 0 || f.ltoes < 0 || f.rfoot < 0 || f.rtoes < 0) return std::nullopt;
    return f;
  }
  int max_index() const { return std::max({lfoot, ltoes, rfoot, rtoes}); }
  int foot(bool left) const { return left ? lfoot : rfoot; }
  int toes(bool left) const { return left ? ltoes : rtoes; }
};

/// The stance side of a controller phase (Fig. 2): in phases 0 and 1 the right foot is the stance
/// foot and the left swings (0: right), in 2 and 3 the reverse (1: left); -1 for a phase outside
/// 0..3 (a controller without Wang's state machine).
inline int stance_side(int phase) {
  if (phase == 0 || phase == 1) return 0;
  if (phase == 2 || phase == 3) return 1;
  return -1;
}

/// Throws unless the bodies exist in m (a model other than the one a term was made for).
template <root_joint Root>
void check_bodies(const model<Root>& m, int max_index, const char* what) {
  check_argument(max_index < m.num_bodies(), what, ": model '", m.name, "' has ", m.num_bodies(),
                 " bodies, the term reads body ", max_index);
}

}  // namespace gaitsynth::wang2009
