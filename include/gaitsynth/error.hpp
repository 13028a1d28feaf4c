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
}  // namespace detail

/// Throws std::invalid_argument with the concatenation of `parts` when `condition` is false.
template <class... Parts>
inline void check_argument(bool condition, Parts&&... parts) {
  if (!condition) throw std::invalid_argument(detail::concat(std::forward<Parts>(parts)...));
}

/// Throws std::invalid_argument unless `actual == expected`, naming what was checked.
inline void check_size(std::ptrdiff_t actual, std::ptrdiff_t expected, const char* what) {
  if (actual != expected)
    throw std::invalid_argument(
        detail::concat(what, ": wrong size, expected ", expected, ", got ", actual));
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
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument(
        detail::concat(what, " must be finite and > 0, got ", value));
}

}  // namespace gaitsynth
