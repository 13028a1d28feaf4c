#pragma once
/// \file objectives/wu2010/common.hpp
/// Shared by the cost terms of Wu & Popovic 2010, Sec. 8.1 and 8.2 (this folder): reading
/// planned_walk's report (controllers/end_effector/planned_walk_report.hpp) from a step view.
#include <cmath>
#include <cstddef>
#include <span>

#include "gaitsynth/controllers/end_effector/planned_walk_report.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth::wu2010 {

/// Eq. 6's timestep j. The paper simulates and controls at 64 Hz (appendix C: "The timestep size
/// is 1/64 seconds"), so its sums over j are over 1/64 s steps; we simulate at 2400 Hz. A term
/// summed per timestep therefore weights each physics step of length dt by dt / timestep, which
/// keeps the paper's balance between the per-timestep terms and the per-half-cycle COM term
/// whatever the simulation rate. timestep = 0: each physics step counts once (the sum as eq. 6
/// prints it, read at our rate: 37.5 times the paper's weight at 2400 Hz).
inline constexpr double paper_timestep = 1.0 / 64.0;

inline double timestep_weight(double dt, double timestep) {
  return timestep > 0.0 ? dt / timestep : 1.0;
}

inline void check_timestep(double timestep, const char* who) {
  check_argument(std::isfinite(timestep) && timestep >= 0.0, who,
                 ": timestep must be finite and >= 0 s (0: per physics step), got ", timestep);
}

/// The view's controller report, checked against the layout the term was made for. Throws
/// std::invalid_argument (at the first step: a wiring error, not a rollout outcome) when the
/// controller reports less, e.g. a controller without the report hook.
inline std::span<const double> checked_report(std::span<const double> report,
                                              const planned_walk_report_layout& L,
                                              const char* who) {
  check_argument(report.size() >= L.size, who, ": the controller's report has ", report.size(),
                 " entries, the layout needs ", L.size,
                 " (use a controller with planned_walk's report and its report_layout())");
  return report;
}

}  // namespace gaitsynth::wu2010
