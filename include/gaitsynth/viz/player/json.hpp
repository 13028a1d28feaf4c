#pragma once
/// \file json.hpp
/// How the HTML player's data becomes JSON text inside the page: numbers rounded to the digits the
/// page needs, and a dump that is safe inside a <script> element.
///
/// Numbers: nlohmann::json writes the shortest text that reads back as the same double, so a value
/// rounded to `sig` significant digits first is written with at most those digits (a 6-digit
/// position is 9 characters, a full double 19: the frames are most of a page that can be megabytes
/// long) and the browser reads exactly the rounded double. NaN and infinities are written as null
/// (nlohmann's rule, and the only JSON for them); the player's script treats null as "no value".
/// Integral values are written as integers ("0", not "0.0").
/// Needs nlohmann::json (Debian: nlohmann-json3-dev).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

namespace gaitsynth::viz_detail {

/// x rounded to `sig` significant decimal digits (the double nearest to its `%.{sig}g` text); 0 for
/// -0 (the page has no use for the sign); non-finite values unchanged.
inline double round_digits(double x, int sig) {
  if (!std::isfinite(x)) return x;
  if (x == 0) return 0.0;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", sig, x);
  // strtod reads in the same C locale that snprintf wrote in; nlohmann's output is
  // locale-independent, so the JSON has a decimal point whatever the program's locale is.
  return std::strtod(buf, nullptr);
}

/// x rounded to `sig` digits as a JSON number: an integer when the rounded value is one (nlohmann
/// writes a double 0 as "0.0"; zeros are common, e.g. the y of a planar character), else a double.
inline nlohmann::ordered_json page_number(double x, int sig) {
  const double v = round_digits(x, sig);
  // 2^53: every integer up to it is a double, so the integer reads back as the same value.
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) <= 9007199254740992.0)
    return static_cast<std::int64_t>(v);
  return v;
}

/// `j` as compact JSON text that cannot end or alter the <script> element holding it: '<', '>'
/// and '&' (which only occur inside strings) are written as \u escapes, so a name containing
/// "</script>" or "<!--" stays text. Invalid UTF-8 in names becomes U+FFFD instead of throwing.
inline std::string script_json(const nlohmann::ordered_json& j) {
  const std::string s = j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    if (c == '<')
      o += "\\u003c";
    else if (c == '>')
      o += "\\u003e";
    else if (c == '&')
      o += "\\u0026";
    else
      o += c;
  }
  return o;
}

}  // namespace gaitsynth::viz_detail
