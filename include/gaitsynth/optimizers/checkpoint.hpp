#pragma once
/// \file checkpoint.hpp
/// Checkpoint files: the complete state of an optimizer as a small text file of `key value` lines.
///
/// Doubles are written as C99 hexadecimal floats ("%a"), so every bit survives the round trip
/// (including inf and nan); the Mersenne Twister is written with its standard `operator<<`, which
/// the standard guarantees to restore exactly. A resumed optimizer therefore continues
/// bit-identically. Files are written to `<path>.tmp` and renamed over `<path>`, so a run killed
/// while writing leaves the previous checkpoint intact.
///
/// Readers check every key in order and throw checkpoint_error (a std::runtime_error) naming the
/// file, the line, the key and the bad value on any mismatch (wrong optimizer kind, other
/// dimension, truncated file). A failed load_checkpoint leaves the optimizer as it was.
#include <Eigen/Core>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "gaitsynth/optimizers/concept.hpp"

namespace gaitsynth {

/// Writes `key value` lines. Keys must not contain white space.
class checkpoint_writer {
 public:
  explicit checkpoint_writer(std::ostream& os) : os_(os) {}

  void real(std::string_view key, double v) {
    os_ << key << ' ';
    put(v);
    os_ << '\n';
  }
  void integer(std::string_view key, std::int64_t v) { os_ << key << ' ' << v << '\n'; }
  void text(std::string_view key, std::string_view v) {
    // Length-prefixed so any content (spaces, commas) survives.
    os_ << key << ' ' << v.size() << ' ' << v << '\n';
  }
  void vector(std::string_view key, const Eigen::VectorXd& v) {
    os_ << key << ' ' << v.size();
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      os_ << ' ';
      put(v[i]);
    }
    os_ << '\n';
  }
  void reals(std::string_view key, const std::vector<double>& v) {
    os_ << key << ' ' << v.size();
    for (double x : v) {
      os_ << ' ';
      put(x);
    }
    os_ << '\n';
  }
  void matrix(std::string_view key, const Eigen::MatrixXd& m) {
    os_ << key << ' ' << m.rows() << ' ' << m.cols();
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) {
        os_ << ' ';
        put(m(i, j));
      }
    os_ << '\n';
  }
  void vectors(std::string_view key, const std::vector<Eigen::VectorXd>& vs) {
    integer(key, static_cast<std::int64_t>(vs.size()));
    for (const auto& v : vs) vector(key, v);
  }
  void rng(std::string_view key, const std::mt19937_64& g) { os_ << key << ' ' << g << '\n'; }

 private:
  void put(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", v);
    os_ << buf;
  }
  std::ostream& os_;
};

/// A malformed checkpoint (or one of another optimizer): what() names the file, the line and key,
/// and the bad value.
class checkpoint_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads what checkpoint_writer wrote, in the same order. Every problem throws checkpoint_error
/// "checkpoint '<source>', line <n>, key '<key>': <what>, got '<value>'". Sizes are checked before
/// anything is allocated for them, so a corrupt size fails as a short file rather than as a
/// std::bad_alloc.
class checkpoint_reader {
 public:
  /// `source` names the stream in messages (a file name); is must be seekable for line numbers.
  explicit checkpoint_reader(std::istream& is, std::string source = {})
      : is_(is), source_(std::move(source)) {}

  double real(std::string_view key) {
    expect(key);
    return get(0, 1);
  }
  std::int64_t integer(std::string_view key) {
    expect(key);
    return integer_value("an integer");
  }
  std::string text(std::string_view key) {
    expect(key);
    const std::size_t n = size_value("a length");
    is_.get();  // the single separating space
    // In pieces: a corrupt length must not allocate before the text is there.
    std::string s;
    char buf[4096];
    while (s.size() < n) {
      const std::size_t k = std::min(sizeof buf, n - s.size());
      if (!is_.read(buf, static_cast<std::streamsize>(k)))
        error("text of length " + std::to_string(n) + " ends after " +
              std::to_string(s.size() + static_cast<std::size_t>(is_.gcount())) +
              " characters (truncated file?)");
      s.append(buf, k);
    }
    return s;
  }
  Eigen::VectorXd vector(std::string_view key) {
    expect(key);
    return values(size_value("a size"));
  }
  Eigen::VectorXd vector(std::string_view key, Eigen::Index expected_size) {
    expect(key);
    const std::size_t n = size_value("a size");
    if (n != static_cast<std::size_t>(expected_size))
      error("'" + std::string(key) + "' has size " + std::to_string(n) + ", expected " +
            std::to_string(expected_size));
    return values(n);
  }
  std::vector<double> reals(std::string_view key) {
    expect(key);
    const std::size_t n = size_value("a size");
    std::vector<double> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back(get(i, n));
    return v;
  }
  Eigen::MatrixXd matrix(std::string_view key, Eigen::Index rows, Eigen::Index cols) {
    expect(key);
    const std::size_t r = size_value("the number of rows");
    const std::size_t c = size_value("the number of columns");
    if (r != static_cast<std::size_t>(rows) || c != static_cast<std::size_t>(cols))
      error("'" + std::string(key) + "' is " + std::to_string(r) + "x" + std::to_string(c) +
            ", expected " + std::to_string(rows) + "x" + std::to_string(cols));
    const Eigen::VectorXd v = values(r * c);  // column-major, as written
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), rows, cols);
  }
  std::vector<Eigen::VectorXd> vectors(std::string_view key) {
    const auto n = integer(key);
    if (n < 0) error("expected a non-negative count, got '" + std::to_string(n) + "'");
    std::vector<Eigen::VectorXd> vs;
    for (std::int64_t k = 0; k < n; ++k) vs.push_back(vector(key));
    return vs;
  }
  void rng(std::string_view key, std::mt19937_64& g) {
    expect(key);
    if (!(is_ >> g)) error("expected a mt19937_64 state (312 integers)");
  }
  /// Reads an integer and checks it equals `expected` (dimension, population size...).
  void require(std::string_view key, std::int64_t expected) {
    const auto v = integer(key);
    if (v != expected)
      error("'" + std::string(key) + "' is " + std::to_string(v) + ", but this optimizer has " +
            std::to_string(expected));
  }
  void require_text(std::string_view key, std::string_view expected) {
    const auto v = text(key);
    if (v != expected)
      error("'" + std::string(key) + "' is '" + v + "', expected '" + std::string(expected) + "'");
  }

  /// Throws checkpoint_error "checkpoint '<source>', line <n>, key '<key>': <message>" for the key
  /// read last (for checks of its value by the optimizer).
  [[noreturn]] void error(const std::string& message) {
    std::string where = "checkpoint";
    if (!source_.empty()) where += " '" + source_ + "'";
    if (const long line = key_line(); line > 0)
      where += ", line " + std::to_string(line) +
               (key_pos_ == std::streampos(-1) ? " (the end of the file)" : "");
    if (!key_.empty()) where += ", key '" + key_ + "'";
    throw checkpoint_error(where + ": " + message);
  }

 private:
  void expect(std::string_view key) {
    key_ = std::string(key);
    is_ >> std::ws;
    key_pos_ = is_.tellg();
    std::string k;
    if (!(is_ >> k))
      error("expected key '" + key_ + "', found the end of the file (truncated file?)");
    if (k != key) error("expected key '" + key_ + "', found '" + shown(k) + "'");
  }
  /// The next white-space separated word ("" at the end of the stream).
  std::string token() {
    std::string t;
    is_ >> t;
    return t;
  }
  static std::string shown(const std::string& t) {
    return t.size() <= 40 ? t : t.substr(0, 40) + "...";
  }
  std::int64_t integer_value(const char* what) {
    const std::string t = token();
    std::int64_t v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty()) error(std::string("expected ") + what + ", found the end of the file");
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      error(std::string("expected ") + what + ", got '" + shown(t) + "'");
    return v;
  }
  std::size_t size_value(const char* what) {
    const std::int64_t n = integer_value(what);
    if (n < 0) error(std::string("expected ") + what + ", got '" + std::to_string(n) + "'");
    return static_cast<std::size_t>(n);
  }
  /// Value i of n (for messages) of the current key.
  double get(std::size_t i, std::size_t n) {
    const std::string which = n == 1
                                  ? std::string("a number")
                                  : "number " + std::to_string(i + 1) + " of " + std::to_string(n);
    const std::string t = token();
    if (t.empty()) error("expected " + which + ", found the end of the file (truncated file?)");
    // strtod parses hexadecimal floats, inf and nan (operator>> does not parse "%a" reliably).
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0') error("expected " + which + ", got '" + shown(t) + "'");
    return v;
  }
  Eigen::VectorXd values(std::size_t n) {
    std::vector<double> v;  // grows with the values actually there
    for (std::size_t i = 0; i < n; ++i) v.push_back(get(i, n));
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(n));
  }
  /// 1-based line of the current key (of the end of the stream when the key was not there; 0:
  /// unknown), counted from the start of the stream.
  long key_line() {
    is_.clear();
    std::streampos pos = key_pos_;
    if (pos == std::streampos(-1) && is_.seekg(0, std::ios::end)) pos = is_.tellg();
    if (pos == std::streampos(-1) || !is_.seekg(0)) return 0;
    long line = 1;
    for (std::streamoff i = 0; i < static_cast<std::streamoff>(pos); ++i) {
      const auto c = is_.get();
      if (c == std::istream::traits_type::eof()) break;
      line += c == '\n';
    }
    return line;
  }
  std::istream& is_;
  std::string source_;
  std::string key_;
  std::streampos key_pos_ = -1;
};

inline constexpr std::string_view checkpoint_magic = "gaitsynth-optimizer-checkpoint";
/// 2: the parameter names follow the optimizer's name (1: without them; still read).
inline constexpr std::int64_t checkpoint_version = 2;

/// Writes the optimizer's full state to `path` (atomically: `<path>.tmp`, then rename).
template <optimizer O>
void save_checkpoint(const O& opt, const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if (!os) throw std::runtime_error("cannot write checkpoint '" + tmp.string() + "'");
    checkpoint_writer w(os);
    w.text("magic", checkpoint_magic);
    w.integer("version", checkpoint_version);
    w.text("optimizer", opt.name());
    const auto& params = opt.space().parameters();
    w.integer("parameters", static_cast<std::int64_t>(params.size()));
    for (const auto& p : params) w.text("parameter", p.name);
    opt.save(w);
    w.text("end", "end");
    os.flush();
    if (!os) throw std::runtime_error("error while writing checkpoint '" + tmp.string() + "'");
  }
  std::filesystem::rename(tmp, path);
}

/// Restores the state saved by save_checkpoint into `opt`, which must have been constructed with
/// the same parameter space and options (dimension, population size and kind are checked). Throws
/// checkpoint_error (a std::runtime_error) naming the file, the line, the key and the bad value; on
/// any error `opt` is left exactly as it was (its state is saved first and put back).
template <optimizer O>
void load_checkpoint(O& opt, const std::filesystem::path& path) {
  std::ifstream is(path, std::ios::binary);
  if (!is) throw checkpoint_error("cannot read checkpoint '" + path.string() + "'");
  checkpoint_reader r(is, path.string());
  r.require_text("magic", checkpoint_magic);
  const std::int64_t version = r.integer("version");
  if (version != 1 && version != checkpoint_version)
    r.error("version " + std::to_string(version) + " is not one this library reads (1, " +
            std::to_string(checkpoint_version) + ")");
  r.require_text("optimizer", opt.name());
  if (version >= 2) {
    // A checkpoint of another search space (other controller, other free DOFs) must not be
    // resumed into this one, even when the dimensions agree: compare the names.
    const auto& params = opt.space().parameters();
    r.require("parameters", static_cast<std::int64_t>(params.size()));
    for (std::size_t i = 0; i < params.size(); ++i) {
      const std::string name = r.text("parameter");
      if (name != params[i].name)
        r.error("the checkpoint was written for parameter " + std::to_string(i) + " '" + name +
                "', but this optimizer's parameter " + std::to_string(i) + " is '" +
                params[i].name + "'");
    }
  }
  // Optimizers load field by field: keep the state to put back if the file turns out bad.
  std::stringstream before;
  {
    checkpoint_writer w(before);
    opt.save(w);
  }
  try {
    opt.load(r);
    r.require_text("end", "end");
  } catch (const std::exception& e) {
    checkpoint_reader back(before, "(the state before loading)");
    opt.load(back);
    if (dynamic_cast<const checkpoint_error*>(&e) != nullptr) throw;
    r.error(e.what());  // an optimizer's own check (or std::bad_alloc): add the file and key
  }
}

}  // namespace gaitsynth
