#pragma once
/// \file trajectory_csv/tokenizer.hpp
/// The trajectory CSV reader's lowest layer: the error type and its "file, line, column" message,
/// the split of a text into lines and of a line into fields, and exact number parsing. Nothing
/// here knows the columns (schema.hpp does).
#include <charconv>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace gaitsynth {

/// A malformed or truncated trajectory CSV. line / column are 1-based (0: not applicable).
class trajectory_csv_error : public std::runtime_error {
 public:
  trajectory_csv_error(const std::string& what, int line, int column)
      : std::runtime_error(what), line_(line), column_(column) {}
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_, column_;
};

namespace detail::trajectory_csv {

/// Makes the reader's errors: "trajectory csv 'walk.csv', line 14, column 2: <message>".
struct locator {
  std::string source;
  trajectory_csv_error operator()(int line, int column, const std::string& message) const {
    std::string where = "trajectory csv '" + source + "'";
    if (line > 0) where += ", line " + std::to_string(line);
    if (column > 0) where += ", column " + std::to_string(column);
    return trajectory_csv_error(where + ": " + message, line, column);
  }
};

/// The lines of a text without their "\n" or "\r\n". A last line without its end-of-line is kept
/// (last_terminated false): the reader rejects it as a sign of a truncated file.
struct text_lines {
  std::vector<std::string_view> lines;
  bool last_terminated = true;
};

inline text_lines split_lines(std::string_view all) {
  text_lines out;
  std::size_t a = 0;
  while (a < all.size()) {
    const std::size_t e = all.find('\n', a);
    if (e == std::string_view::npos) {
      out.lines.push_back(all.substr(a));
      out.last_terminated = false;
      break;
    }
    std::string_view l = all.substr(a, e - a);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.lines.push_back(l);
    a = e + 1;
  }
  return out;
}

/// The comma-separated fields of a line (no quoting: names never contain commas or quotes).
inline void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t a = 0;
  while (true) {
    const auto e = line.find(',', a);
    fields.push_back(line.substr(a, e == std::string_view::npos ? std::string_view::npos : e - a));
    if (e == std::string_view::npos) break;
    a = e + 1;
  }
}

/// Whether all of s is one number (std::from_chars: exact, locale-free, no spaces or '+').
template <class T>
bool parse_all(std::string_view s, T& x) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  return !s.empty() && r.ec == std::errc() && r.ptr == s.data() + s.size();
}

/// The message for a value that parse_all refused: `as` is "a number" or "an integer", `what`
/// says whose value it is ("column 'q:root_x [m]'", "terrain x0").
inline std::string unreadable(std::string_view s, const char* as, const std::string& what) {
  if (s.empty()) return "empty value in " + what;
  return "cannot read '" + std::string(s.substr(0, 40)) + "' as " + as + " (" + what + ")";
}

}  // namespace detail::trajectory_csv
}  // namespace gaitsynth
