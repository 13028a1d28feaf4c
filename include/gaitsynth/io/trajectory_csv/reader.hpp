#pragma once
/// \file trajectory_csv/reader.hpp
/// read_trajectory_csv / load_trajectory_csv: the text into lines (tokenizer.hpp), the '#' lines
/// (metadata.hpp), the header (header.hpp), then one frame per data line (rows.hpp), and last the
/// frame count against "# frames:" so that a file cut at a line boundary is caught too.
#include <fstream>
#include <istream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/io/trajectory_csv/header.hpp"
#include "gaitsynth/io/trajectory_csv/metadata.hpp"
#include "gaitsynth/io/trajectory_csv/rows.hpp"
#include "gaitsynth/io/trajectory_csv/tokenizer.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// Reads a trajectory CSV written by write_trajectory_csv. Throws trajectory_csv_error naming the
/// source, line and column of the first problem (io/trajectory_csv.hpp).
inline trajectory read_trajectory_csv(std::istream& is, const std::string& source = "<stream>") {
  using namespace detail::trajectory_csv;
  const std::string text((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  const locator fail{source};
  const text_lines tl = split_lines(text);
  const std::vector<std::string_view>& lines = tl.lines;
  if (lines.empty()) throw fail(0, 0, "empty file");
  if (lines[0] != magic_line)
    throw fail(1, 0,
               "not a gaitsynth trajectory CSV (first line must be '" + std::string(magic_line) +
                   "', got '" + std::string(lines[0].substr(0, 60)) + "')");
  trajectory traj;
  long long declared_frames = 0;
  std::size_t li = read_metadata(lines, traj, declared_frames, fail);
  if (li >= lines.size())
    throw fail(static_cast<int>(li) + 1, 0, "missing header line (truncated file?)");
  const header h = read_header(lines[li], static_cast<int>(li) + 1, traj, fail);
  const trajectory_frame empty = empty_frame(h, traj);
  std::vector<std::string_view> fields;
  for (++li; li < lines.size(); ++li) {
    const int ln = static_cast<int>(li) + 1;
    const std::string_view l = lines[li];
    if (l.empty()) {
      if (li + 1 == lines.size()) break;
      throw fail(ln, 0, "empty line inside the data");
    }
    if (l[0] == '#') continue;
    if (li + 1 == lines.size() && !tl.last_terminated)
      throw fail(ln, 0, "the last line has no end-of-line (truncated file?)");
    traj.frames.push_back(empty);
    read_row(l, ln, h, traj.frames.back(), fields, fail);
  }
  if (static_cast<long long>(traj.frames.size()) != declared_frames)
    throw fail(static_cast<int>(lines.size()), 0,
               "truncated or padded file: the metadata declares " +
                   std::to_string(declared_frames) + " frames, found " +
                   std::to_string(traj.frames.size()) + " data rows");
  return traj;
}

/// Reads the trajectory CSV at `path`; std::runtime_error when it cannot be opened.
inline trajectory load_trajectory_csv(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("load_trajectory_csv: cannot open '" + path + "'");
  return read_trajectory_csv(f, path);
}

}  // namespace gaitsynth
