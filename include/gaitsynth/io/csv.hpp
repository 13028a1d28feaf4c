#pragma once
/// \file io/csv.hpp
/// A recorded rollout (rollout/trajectory.hpp, filled by rollout_options::record) as CSV. There is
/// one trajectory CSV format in gaitsynth, io/trajectory_csv.hpp (docs/viewer.md): a header that
/// names every column with its unit in brackets ("t [s]", "q:lknee [rad]", "v:root_x [m/s]",
/// "tau:lknee [N m]", "body:pelvis:qw [1]", "contact:lheel:fz [N]", ...), '#' metadata lines above
/// it, and numbers that read back exactly. This header is the short spelling used next to the
/// rollout:
///
///   trajectory tr;
///   options.record = &tr;
///   rollout(...);
///   save_csv("walk.csv", tr);   // pandas: pd.read_csv("walk.csv", comment='#')
#include <istream>
#include <ostream>
#include <string>

#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// Writes tr as CSV to os. \throws std::invalid_argument for an inconsistent trajectory.
inline void write_csv(std::ostream& os, const trajectory& tr) {
  write_trajectory_csv(tr, os);
}

/// Writes tr as CSV to the file `path`. \throws std::runtime_error if it cannot be written.
inline void save_csv(const std::string& path, const trajectory& tr) {
  save_trajectory_csv(tr, path);
}

/// Reads a trajectory written by write_csv / save_csv. \throws trajectory_csv_error (a
/// std::runtime_error) naming the line and column of a problem.
inline trajectory read_csv(std::istream& is) {
  return read_trajectory_csv(is);
}
inline trajectory load_csv(const std::string& path) {
  return load_trajectory_csv(path);
}

}  // namespace gaitsynth
