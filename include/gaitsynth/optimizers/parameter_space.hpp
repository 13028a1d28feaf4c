#pragma once
/// \file parameter_space.hpp
/// The search space: named parameters with bounds, initial values and per-parameter scaling, and
/// the map between user coordinates (what the objective sees: gains in N m/rad, angles in rad...)
/// and the normalized coordinates the optimizers work in.
///
/// Wu 2010 (Sec. 6) bounds every unknown and normalizes the bounds to [0, 1] before handing them
/// to CMA; Wang 2009 assumes "the parameters are scaled to lie roughly between 0 and 1". The
/// mapping of one parameter is
///   - linear:      x = offset + scale * u, with offset = lower (or 0 when lower = -inf) and
///                  scale = upper - lower by default when both bounds are finite (so u in [0, 1]),
///                  else a user-given scale (default 1);
///   - logarithmic: x = lower * (upper / lower)^u, u in [0, 1]; needs 0 < lower < upper < inf
///                  (for gains spanning decades, where equal ratios should be equally easy to
///                  reach).
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

enum class parameter_scaling { linear, logarithmic };

/// One optimized parameter, in user units.
struct parameter_spec {
  std::string name;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double initial = 0.0;
  /// User units per normalized unit (linear scaling). 0: upper - lower when both bounds are finite,
  /// else 1. Must be 0 for logarithmic scaling.
  double scale = 0.0;
  parameter_scaling scaling = parameter_scaling::linear;
};

class parameter_space {
 public:
  parameter_space() = default;

  /// Validates every parameter: names unique and non-empty, bounds not NaN, lower < upper,
  /// initial value finite and within the bounds, scale finite and >= 0, logarithmic scaling only on
  /// 0 < lower < upper < inf, a finite upper - lower where it is the scale. Throws
  /// std::invalid_argument naming the parameter and the value.
  explicit parameter_space(std::vector<parameter_spec> params) {
    for (auto& p : params) add(std::move(p));
  }

  /// Appends one parameter (validated as above).
  parameter_space& add(parameter_spec p) {
    const std::string label = "parameter '" + p.name + "'";
    check_argument(!p.name.empty(), "parameter ", params_.size(), ": empty name");
    check_argument(names_.insert(p.name).second, label, ": duplicate name");
    check_argument(!std::isnan(p.lower) && !std::isnan(p.upper), label,
                   ": bounds must not be NaN, got [", p.lower, ", ", p.upper, "]");
    check_argument(p.lower < p.upper, label, ": lower bound (", p.lower,
                   ") must be < upper bound (", p.upper, ")");
    check_argument(std::isfinite(p.initial), label, ": initial value must be finite, got ",
                   p.initial);
    check_argument(p.initial >= p.lower && p.initial <= p.upper, label, ": initial value ",
                   p.initial, " is outside the bounds [", p.lower, ", ", p.upper, "]");
    check_argument(std::isfinite(p.scale) && p.scale >= 0.0, label,
                   ": scale must be finite and >= 0, got ", p.scale);
    mapping m;
    if (p.scaling == parameter_scaling::logarithmic) {
      check_argument(p.lower > 0.0 && std::isfinite(p.upper), label,
                     ": logarithmic scaling needs 0 < lower < upper < inf, got [", p.lower, ", ",
                     p.upper, "]");
      check_argument(p.scale == 0.0, label,
                     ": scale must be 0 (automatic) for logarithmic "
                     "scaling, got ",
                     p.scale);
      m.log = true;
      m.offset = std::log(p.lower);
      m.scale = std::log(p.upper) - std::log(p.lower);
      m.lower = 0.0;
      m.upper = 1.0;
    } else {
      const bool both = std::isfinite(p.lower) && std::isfinite(p.upper);
      m.offset = std::isfinite(p.lower) ? p.lower : 0.0;
      m.scale = p.scale > 0.0 ? p.scale : (both ? p.upper - p.lower : 1.0);
      check_argument(std::isfinite(m.scale), label, ": the bounds' range upper - lower overflows (",
                     p.lower, ", ", p.upper, "); give a finite scale");
      m.lower = std::isfinite(p.lower) ? (p.lower - m.offset) / m.scale : p.lower;
      m.upper = std::isfinite(p.upper) ? (p.upper - m.offset) / m.scale : p.upper;
      if (both && p.scale == 0.0) m.upper = 1.0;  // exact, not (upper - lower) / (upper - lower)
    }
    params_.push_back(std::move(p));
    maps_.push_back(m);
    return *this;
  }

  /// n unbounded parameters x0, x1, ... with the given initial values; normalized = user / scale.
  static parameter_space unbounded(const Eigen::VectorXd& initial, double scale = 1.0) {
    check_finite(initial, "parameter_space::unbounded initial");
    check_positive(scale, "parameter_space::unbounded scale");
    parameter_space s;
    for (Eigen::Index i = 0; i < initial.size(); ++i)
      s.add({indexed_name(i), -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(), initial[i], scale,
             parameter_scaling::linear});
    return s;
  }

  /// n box-bounded parameters x0, x1, ..., each normalized to [0, 1].
  static parameter_space box(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                             const Eigen::VectorXd& initial) {
    check_size(upper.size(), lower.size(), "parameter_space::box upper");
    check_size(initial.size(), lower.size(), "parameter_space::box initial");
    parameter_space s;
    for (Eigen::Index i = 0; i < lower.size(); ++i)
      s.add({indexed_name(i), lower[i], upper[i], initial[i], 0.0, parameter_scaling::linear});
    return s;
  }

  /// A copy with other initial values (user coordinates), e.g. the previous stage's result in a
  /// continuation. Throws std::invalid_argument on a wrong size or a value outside the bounds.
  parameter_space with_initial(const Eigen::VectorXd& x0) const {
    check_size(x0.size(), size(), "initial point x0");
    std::vector<parameter_spec> ps = params_;
    for (std::size_t i = 0; i < ps.size(); ++i) ps[i].initial = x0[static_cast<Eigen::Index>(i)];
    return parameter_space(std::move(ps));
  }

  Eigen::Index size() const { return static_cast<Eigen::Index>(params_.size()); }
  const std::vector<parameter_spec>& parameters() const { return params_; }
  const parameter_spec& operator[](Eigen::Index i) const {
    return params_[static_cast<std::size_t>(i)];
  }

  /// Normalized coordinates -> user coordinates.
  Eigen::VectorXd to_user(const Eigen::VectorXd& u) const {
    check_size(u.size(), size(), "normalized point");
    Eigen::VectorXd x(u.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      const auto& m = maps_[static_cast<std::size_t>(i)];
      x[i] = m.log ? std::exp(m.offset + m.scale * u[i]) : m.offset + m.scale * u[i];
      // exp/log and offset+scale*u may land one ulp outside a bound: never hand the objective a
      // value outside [lower, upper] for a point inside the normalized bounds.
      const auto& p = params_[static_cast<std::size_t>(i)];
      if (u[i] >= m.lower && u[i] <= m.upper) x[i] = std::clamp(x[i], p.lower, p.upper);
    }
    return x;
  }

  /// User coordinates -> normalized coordinates.
  Eigen::VectorXd to_normalized(const Eigen::VectorXd& x) const {
    check_size(x.size(), size(), "user point");
    Eigen::VectorXd u(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const auto& m = maps_[static_cast<std::size_t>(i)];
      u[i] = m.log ? (std::log(x[i]) - m.offset) / m.scale : (x[i] - m.offset) / m.scale;
    }
    return u;
  }

  Eigen::VectorXd normalized_lower() const {
    Eigen::VectorXd l(size());
    for (Eigen::Index i = 0; i < size(); ++i) l[i] = maps_[static_cast<std::size_t>(i)].lower;
    return l;
  }
  Eigen::VectorXd normalized_upper() const {
    Eigen::VectorXd h(size());
    for (Eigen::Index i = 0; i < size(); ++i) h[i] = maps_[static_cast<std::size_t>(i)].upper;
    return h;
  }
  Eigen::VectorXd initial() const {
    Eigen::VectorXd x(size());
    for (Eigen::Index i = 0; i < size(); ++i) x[i] = params_[static_cast<std::size_t>(i)].initial;
    return x;
  }
  Eigen::VectorXd initial_normalized() const { return to_normalized(initial()); }

  /// True when at least one bound is finite (bound handling has work to do).
  bool bounded() const {
    return std::any_of(maps_.begin(), maps_.end(), [](const mapping& m) {
      return std::isfinite(m.lower) || std::isfinite(m.upper);
    });
  }
  bool contains_normalized(const Eigen::VectorXd& u) const {
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      const auto& m = maps_[static_cast<std::size_t>(i)];
      if (!(u[i] >= m.lower && u[i] <= m.upper)) return false;
    }
    return true;
  }
  /// Closest point of the bounds to a user point (coordinate-wise clamp): e.g. CMA-ES's mean,
  /// which may lie outside them, saved as a controller.
  Eigen::VectorXd clamp_user(const Eigen::VectorXd& x) const {
    check_size(x.size(), size(), "user point");
    Eigen::VectorXd p(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const auto& s = params_[static_cast<std::size_t>(i)];
      p[i] = std::clamp(x[i], s.lower, s.upper);
    }
    return p;
  }
  /// Closest point of the normalized box (coordinate-wise clamp).
  Eigen::VectorXd project_normalized(const Eigen::VectorXd& u) const {
    Eigen::VectorXd p(u.size());
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      const auto& m = maps_[static_cast<std::size_t>(i)];
      p[i] = std::clamp(u[i], m.lower, m.upper);
    }
    return p;
  }

 private:
  static std::string indexed_name(Eigen::Index i) {
    std::string s = "x";  // (not "x" + to_string: GCC 12 warns falsely, -Wrestrict)
    s += std::to_string(i);
    return s;
  }
  struct mapping {
    double offset = 0.0, scale = 1.0;
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
    bool log = false;
  };
  std::vector<parameter_spec> params_;
  std::vector<mapping> maps_;
  std::unordered_set<std::string> names_;
};

}  // namespace gaitsynth
