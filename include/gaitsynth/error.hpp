#pragma once
/// \file error.hpp
/// Argument checks that name the offending value (Pinocchio's CHECK_ARGUMENT_SIZE, but saying what
/// was expected *and* what was given).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace gaitsynth {

namespace detail {
template <class... Parts>
std::string concat(Parts&&... parts) {
  std::ostringstream os;
  os.precision(17);
  (os << ... << std::forward<Parts>(parts));
  return os.str();
}

// The throwing halves of the checks below, kept out of line and marked cold: the checks sit on
// hot paths (every algorithm validates its arguments), where they must cost a compare and a
// never-taken branch, not a call.
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] inline void throw_wrong_size(std::ptrdiff_t actual,
                                                                          std::ptrdiff_t expected,
                                                                          const char* what) {
  throw std::invalid_argument(concat(what, ": wrong size, expected ", expected, ", got ", actual));
}
[[noreturn]] [[gnu::cold]] [[gnu::noinline]] inline void throw_not_positive(double value,
                                                                            const char* what) {
  throw std::invalid_argument(concat(what, " must be finite and > 0, got ", value));
}
}  // namespace detail

/// Throws std::invalid_argument with the concatenation of `parts` when `condition` is false.
template <class... Parts>
inline void check_argument(bool condition, Parts&&... parts) {
  if (!condition) throw std::invalid_argument(detail::concat(std::forward<Parts>(parts)...));
}

/// Throws std::invalid_argument unless `actual == expected`, naming what was checked.
inline void check_size(std::ptrdiff_t actual, std::ptrdiff_t expected, const char* what) {
  if (actual != expected) [[unlikely]]
    detail::throw_wrong_size(actual, expected, what);
}

/// Throws std::invalid_argument unless every coefficient of `x` is finite; names the first bad one.
template <class Vector>
inline void check_finite(const Vector& x, const char* what) {
  for (decltype(x.size()) i = 0; i < x.size(); ++i)
    if (!std::isfinite(static_cast<double>(x[i])))
      throw std::invalid_argument(
          detail::concat(what, ": element ", i, " is not finite (", x[i], ")"));
}

/// Throws std::invalid_argument unless `value` is finite and > 0.
inline void check_positive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) [[unlikely]]
    detail::throw_not_positive(value, what);
}

}  // namespace gaitsynth
