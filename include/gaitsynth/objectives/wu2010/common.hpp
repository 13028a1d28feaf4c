#pragma once
/// \file objectives/wu2010/common.hpp
/// Shared by the cost terms of Wu & Popovic 2010, Sec. 8.1 and 8.2 (this folder): reading
/// planned_walk's report (controllers/end_effector/planned_walk_report.hpp) from a step view.
#include <cstddef>
#include <span>

#include "gaitsynth/controllers/end_effector/planned_walk_report.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth::wu2010 {

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
