#pragma once
/// \file analysis/flight_phases.hpp
/// Whether a recorded gait runs: the flight phases, spans with no contact point of the body on
/// the ground, per gait cycle. Wang et al. 2012 Sec. 6.3's runner has "a flight phase in every
/// cycle" (issue 13); a walk has double support instead and none.
///
///   const flight_phase_report f = flight_phases(m, tr, {.t_begin = 2.0});
///   bool runs = f.every_cycle();
///
/// Cycles run from heel strike to heel strike of one side's foot (viz/gait_cycles.hpp's
/// heel_strike_times) unless given. A flight is a run of recorded frames with no active contact
/// point anywhere (hands and knees count: a stumble onto them is not flight), timed from its first
/// airborne frame to the first frame in contact after it, so a trajectory recorded every dt seconds
/// measures a flight to within dt. It belongs to the cycle in which it begins.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/gait_cycles.hpp"

namespace gaitsynth {

struct flight_phase_options {
  std::string side = "l";  ///< "l" or "r": whose heel strikes start the cycles
  double t_begin = 0.0;    ///< s: strikes and flights before it are left out (the start)
  /// s: shorter airborne spans are contact chatter, not flight (a runner's flights last 0.05-0.15
  /// s; penalty contact can lose a foot's last point for a step or two)
  double min_flight = 0.02;
  std::vector<double> cycle_starts;  ///< s, increasing; empty: the side's heel strikes
};

struct flight_phase_report {
  int cycles = 0;                  ///< complete cycles from t_begin on
  int cycles_with_flight = 0;      ///< of them, those in which a flight begins
  int flights = 0;                 ///< flights that begin in a complete cycle
  double mean_flight = 0.0;        ///< s, their mean duration (0 without any)
  double airborne_fraction = 0.0;  ///< their total duration over the cycles' total
  bool every_cycle() const { return cycles > 0 && cycles_with_flight == cycles; }
};

/// The flight phases of trajectory tr of model m (file comment). \throws std::invalid_argument
/// for a side other than "l" or "r", a min_flight or t_begin that is not finite and >= 0 (t_begin
/// finite), cycle starts that do not increase, or a trajectory without contact records (naming
/// the frame).
template <root_joint Root>
flight_phase_report flight_phases(const model<Root>& m, const trajectory& tr,
                                  const flight_phase_options& o = {}) {
  check_argument(o.side == "l" || o.side == "r",
                 "flight_phases: side must be \"l\" or \"r\", got \"", o.side, "\"");
  check_argument(std::isfinite(o.t_begin), "flight_phases: t_begin is not finite");
  check_argument(std::isfinite(o.min_flight) && o.min_flight >= 0.0,
                 "flight_phases: min_flight must be finite and >= 0, got ", o.min_flight);
  check_argument(!tr.contact_bodies.empty(),
                 "flight_phases: the trajectory names no contact points (record contacts)");
  for (std::size_t f = 0; f < tr.frames.size(); ++f)
    check_argument(tr.frames[f].contact_active.size() == tr.contact_bodies.size(),
                   "flight_phases: frame ", f, " (t = ", tr.frames[f].t, " s) has ",
                   tr.frames[f].contact_active.size(), " contact flags, the trajectory names ",
                   tr.contact_bodies.size(), " points");
  std::vector<double> starts = o.cycle_starts;
  if (starts.empty()) starts = heel_strike_times(tr, default_foot_body(m, o.side));
  for (std::size_t k = 1; k < starts.size(); ++k)
    check_argument(starts[k] > starts[k - 1], "flight_phases: cycle starts must increase, got ",
                   starts[k - 1], " then ", starts[k]);
  std::erase_if(starts, [&](double t) { return t < o.t_begin; });
  flight_phase_report r;
  if (starts.size() < 2) return r;
  r.cycles = static_cast<int>(starts.size()) - 1;
  auto airborne = [](const trajectory_frame& fr) {
    for (unsigned char a : fr.contact_active)
      if (a) return false;
    return true;
  };
  std::vector<bool> has_flight(static_cast<std::size_t>(r.cycles), false);
  double total = 0.0;
  for (std::size_t f = 0; f < tr.frames.size(); ++f) {
    if (!airborne(tr.frames[f]) || (f > 0 && airborne(tr.frames[f - 1]))) continue;
    std::size_t e = f;  // the first frame in contact after the span (none: it lasts to the end)
    while (e < tr.frames.size() && airborne(tr.frames[e])) ++e;
    if (e == tr.frames.size()) break;  // no landing recorded: not a flight
    const double t0 = tr.frames[f].t, duration = tr.frames[e].t - t0;
    if (duration < o.min_flight || t0 < starts.front() || t0 >= starts.back()) continue;
    std::size_t k = 0;
    while (t0 >= starts[k + 1]) ++k;
    has_flight[k] = true;
    ++r.flights;
    total += duration;
  }
  for (bool h : has_flight) r.cycles_with_flight += h;
  if (r.flights > 0) r.mean_flight = total / r.flights;
  r.airborne_fraction = total / (starts.back() - starts.front());
  return r;
}

}  // namespace gaitsynth
