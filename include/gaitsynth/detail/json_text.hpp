#pragma once
/// \file detail/json_text.hpp
/// JSON text as the library's loaders read it (keyframes, nearest-neighbor and Wang 2009
/// controllers). nlohmann::json parses, but it keeps the last of two equal keys without a word,
/// reports a number too large for a double without its line, and copies and writes values
/// recursively (a value nested 100000 levels deep overflows the stack when it is dumped into a
/// message). json_text_problem scans the text once before the parser and names these with their
/// line and column; parse_json_text then parses, turning every nlohmann error into one message that
/// starts with the source (a file name).
#include <charconv>
#include <cstddef>
#include <locale>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

namespace gaitsynth::detail {

/// Deepest nesting of arrays and objects accepted (the library's own files nest 5 levels).
inline constexpr int max_json_depth = 256;

/// Whether a number token that std::from_chars found out of range is too large (rather than too
/// small, which reads as 0 or a subnormal, as nlohmann reads it).
inline bool json_number_overflows(std::string_view token) {
  std::istringstream in{std::string(token)};
  in.imbue(std::locale::classic());
  double x = 0;
  in >> x;  // overflow: failbit (and +-max); underflow: no failbit
  return in.fail();
}

/// Problems of JSON text that nlohmann::json accepts or reports without a position: nesting deeper
/// than `max_depth`, a key repeated within one object (keys compared as written: escapes are not
/// decoded) and a number too large for a double. Returns "" or "line L, column C: <problem>"
/// (1-based, columns in bytes, as nlohmann counts them). Anything else that is not JSON is left to
/// the parser: the scan stops quietly at the first unbalanced bracket or unterminated string.
inline std::string json_text_problem(std::string_view s, int max_depth = max_json_depth) {
  struct level {
    bool object = false;
    bool want_key = false;                           // the next string is a key
    std::unordered_map<std::string_view, int> keys;  // key -> its line
  };
  std::vector<level> stack;
  int line = 1;
  std::size_t line_start = 0;
  auto at = [&](std::size_t i) {
    return "line " + std::to_string(line) + ", column " + std::to_string(i - line_start + 1) + ": ";
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    } else if (c == '{' || c == '[') {
      if (static_cast<int>(stack.size()) >= max_depth)
        return at(i) + "nested deeper than " + std::to_string(max_depth) +
               " levels of arrays and objects";
      stack.push_back({c == '{', c == '{', {}});
    } else if (c == '}' || c == ']') {
      if (stack.empty()) return "";
      stack.pop_back();
    } else if (c == ',') {
      if (!stack.empty() && stack.back().object) stack.back().want_key = true;
    } else if (c == ':') {
      if (!stack.empty()) stack.back().want_key = false;
    } else if (c == '"') {
      const std::size_t begin = i;
      for (++i; i < s.size() && s[i] != '"' && s[i] != '\n'; ++i)
        if (s[i] == '\\') ++i;
      if (i >= s.size() || s[i] != '"') return "";  // unterminated: the parser says where
      if (!stack.empty() && stack.back().want_key) {
        level& l = stack.back();
        l.want_key = false;
        const std::string_view key = s.substr(begin + 1, i - begin - 1);
        const auto [it, fresh] = l.keys.try_emplace(key, line);
        if (!fresh)
          return at(begin) + "duplicate key \"" + std::string(key) + "\" (first at line " +
                 std::to_string(it->second) + ")";
      }
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      while (end < s.size() && ((s[end] >= '0' && s[end] <= '9') || s[end] == '-' ||
                                s[end] == '+' || s[end] == '.' || s[end] == 'e' || s[end] == 'E'))
        ++end;
      const std::string_view token = s.substr(i, end - i);
      double x = 0;
      if (std::from_chars(token.data(), token.data() + token.size(), x).ec ==
              std::errc::result_out_of_range &&
          json_number_overflows(token)) {
        const std::string shown = token.size() <= 40
                                      ? std::string(token)
                                      : std::string(token.substr(0, 32)) + "... (" +
                                            std::to_string(token.size()) + " characters)";
        return at(i) + "number " + shown + " is too large for a double";
      }
      i = end - 1;
    }
  }
  return "";
}

/// Parses JSON text; every problem (json_text_problem's and the parser's, which give the line and
/// column) throws Error("<source>: ...").
template <class Error>
nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
  if (const std::string p = json_text_problem(text); !p.empty()) throw Error(source + ": " + p);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(source + ": malformed JSON: " + e.what());
  }
}

}  // namespace gaitsynth::detail
