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
/// Readers check every key in order and throw std::runtime_error naming the key and the file
/// position on any mismatch (wrong optimizer kind, other dimension, truncated file).
#include <Eigen/Core>

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

/// Reads what checkpoint_writer wrote, in the same order.
class checkpoint_reader {
 public:
  explicit checkpoint_reader(std::istream& is) : is_(is) {}

  double real(std::string_view key) {
    expect(key);
    return get();
  }
  std::int64_t integer(std::string_view key) {
    expect(key);
    std::int64_t v = 0;
    if (!(is_ >> v)) fail(key, "an integer");
    return v;
  }
  std::string text(std::string_view key) {
    expect(key);
    std::size_t n = 0;
    if (!(is_ >> n)) fail(key, "a length");
    is_.get();  // the single separating space
    std::string s(n, '\0');
    if (n > 0 && !is_.read(s.data(), static_cast<std::streamsize>(n))) fail(key, "text");
    return s;
  }
  Eigen::VectorXd vector(std::string_view key) {
    expect(key);
    Eigen::Index n = 0;
    if (!(is_ >> n) || n < 0) fail(key, "a size");
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i) v[i] = get();
    return v;
  }
  Eigen::VectorXd vector(std::string_view key, Eigen::Index expected_size) {
    Eigen::VectorXd v = vector(key);
    if (v.size() != expected_size)
      throw std::runtime_error(std::string("checkpoint: '") + std::string(key) + "' has size " +
                               std::to_string(v.size()) + ", expected " +
                               std::to_string(expected_size));
    return v;
  }
  std::vector<double> reals(std::string_view key) {
    expect(key);
    std::size_t n = 0;
    if (!(is_ >> n)) fail(key, "a size");
    std::vector<double> v(n);
    for (auto& x : v) x = get();
    return v;
  }
  Eigen::MatrixXd matrix(std::string_view key, Eigen::Index rows, Eigen::Index cols) {
    expect(key);
    Eigen::Index r = 0, c = 0;
    if (!(is_ >> r >> c)) fail(key, "matrix sizes");
    if (r != rows || c != cols)
      throw std::runtime_error(std::string("checkpoint: '") + std::string(key) + "' is " +
                               std::to_string(r) + "x" + std::to_string(c) + ", expected " +
                               std::to_string(rows) + "x" + std::to_string(cols));
    Eigen::MatrixXd m(r, c);
    for (Eigen::Index j = 0; j < c; ++j)
      for (Eigen::Index i = 0; i < r; ++i) m(i, j) = get();
    return m;
  }
  std::vector<Eigen::VectorXd> vectors(std::string_view key) {
    const auto n = integer(key);
    if (n < 0) fail(key, "a non-negative count");
    std::vector<Eigen::VectorXd> vs;
    vs.reserve(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) vs.push_back(vector(key));
    return vs;
  }
  void rng(std::string_view key, std::mt19937_64& g) {
    expect(key);
    if (!(is_ >> g)) fail(key, "a mt19937_64 state");
  }
  /// Reads an integer and checks it equals `expected` (dimension, population size...).
  void require(std::string_view key, std::int64_t expected) {
    const auto v = integer(key);
    if (v != expected)
      throw std::runtime_error(std::string("checkpoint: '") + std::string(key) + "' is " +
                               std::to_string(v) + ", but this optimizer has " +
                               std::to_string(expected));
  }
  void require_text(std::string_view key, std::string_view expected) {
    const auto v = text(key);
    if (v != expected)
      throw std::runtime_error(std::string("checkpoint: '") + std::string(key) + "' is '" + v +
                               "', expected '" + std::string(expected) + "'");
  }

 private:
  void expect(std::string_view key) {
    std::string k;
    if (!(is_ >> k) || k != key)
      throw std::runtime_error(std::string("checkpoint: expected key '") + std::string(key) +
                               "', found '" + k + "'");
  }
  double get() {
    std::string tok;
    if (!(is_ >> tok)) throw std::runtime_error("checkpoint: truncated (expected a number)");
    // strtod parses hexadecimal floats, inf and nan (operator>> does not parse "%a" reliably).
    char* end = nullptr;
    const double v = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0')
      throw std::runtime_error("checkpoint: '" + tok + "' is not a number");
    return v;
  }
  [[noreturn]] void fail(std::string_view key, const char* what) {
    throw std::runtime_error(std::string("checkpoint: '") + std::string(key) + "': expected " +
                             what);
  }
  std::istream& is_;
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
/// the same parameter space and options (dimension, population size and kind are checked).
template <optimizer O>
void load_checkpoint(O& opt, const std::filesystem::path& path) {
  std::ifstream is(path, std::ios::binary);
  if (!is) throw std::runtime_error("cannot read checkpoint '" + path.string() + "'");
  checkpoint_reader r(is);
  r.require_text("magic", checkpoint_magic);
  const std::int64_t version = r.integer("version");
  if (version != 1 && version != checkpoint_version)
    throw std::runtime_error("checkpoint '" + path.string() + "': version " +
                             std::to_string(version) + " is not one this library reads (1, " +
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
        throw std::runtime_error("checkpoint '" + path.string() + "' was written for parameter " +
                                 std::to_string(i) + " '" + name +
                                 "', but this optimizer's parameter " + std::to_string(i) +
                                 " is '" + params[i].name + "'");
    }
  }
  opt.load(r);
  r.require_text("end", "end");
}

}  // namespace gaitsynth
