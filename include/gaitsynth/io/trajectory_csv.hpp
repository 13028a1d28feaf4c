#pragma once
/// \file trajectory_csv.hpp
/// A recorded trajectory (rollout/trajectory.hpp) as CSV: one row per frame, a header naming every
/// column and its unit, and '#' metadata lines above it (model name, planar flag, frame count, body
/// tree, contact points, terrain samples) so that the file reads back into the same trajectory.
/// pandas: `pd.read_csv(path, comment='#')`; spreadsheets: skip the '#' lines. docs/viewer.md.
///
///   # gaitsynth trajectory csv 1
///   # model: walker2d
///   ...                          (trajectory_csv/metadata.hpp)
///   t [s],q:root_x [m],...,controller_state [1]
///
/// The columns come from trajectory_channels (rollout/trajectory.hpp), in its order; a channel's
/// columns are left out when every frame leaves it empty (trajectory_csv/schema.hpp). Today:
///   t [s]; q:<name> (root_x/y/z [m], root_pitch [rad], root_qw..qz [1], joints [rad]);
///   v:<name> ([m/s] root translation, [rad/s] otherwise); tau:<name> ([N] root translation,
///   [N m] otherwise); body:<name>:x/y/z [m] and :qw/qx/qy/qz [1] (world pose);
///   com:x/y/z [m]; contact:<name>:x/y/z [m], :fx/fy/fz [N], :active [1];
///   push:<body>:fx/fy/fz [N] (only bodies pushed in some frame: the sum of that frame's pushes on
///   the body; a frame's pushes read back in body order, zero forces are not pushes);
///   obj:<name> [-] (objective terms, in the units of their definition); controller_state [1].
///
/// Numbers are written in the shortest form that reads back to the same double (std::to_chars), so
/// write-then-read is exact; `precision` > 0 writes that many significant digits instead.
///
/// Reading checks everything and throws trajectory_csv_error (a std::runtime_error) whose message
/// names the source, the line and, for a bad cell or value, the column number and header cell: a
/// missing or foreign first line, a header cell without a [unit], with the wrong unit, of unknown
/// kind, repeated or missing, a row with too few or too many fields, a value that is not a number
/// (or not 0/1, not an int; nan and inf are values, but not as the time), a last line without its
/// end-of-line, or fewer rows than the "# frames:" line declares (a truncated file).
///
/// Parts: trajectory_csv/writer.hpp, reader.hpp (tokenizer.hpp, metadata.hpp, header.hpp,
/// rows.hpp), both over schema.hpp.
#include "gaitsynth/io/trajectory_csv/reader.hpp"
#include "gaitsynth/io/trajectory_csv/writer.hpp"
