#pragma once
/// \file slope_terrain.hpp
/// An inclined plane: rising at `angle` along a horizontal `direction` (default +x, the walking
/// direction of the planar bipeds), with height `height_at_origin` at the horizontal point
/// `origin`. Wang et al. 2009 optimize uphill walkers on slopes up to 12 degrees; Wu & Popovic 2010
/// navigate slopes of +/- 0.2 (+/- 11.3 degrees).
///
///   h(x, y) = h0 + tan(angle) * dot(direction, (x, y) - origin)
///   n       = (-tan(angle) d_x, -tan(angle) d_y, 1) / sqrt(1 + tan(angle)^2)
#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

class slope_terrain {
 public:
  /// \param angle             inclination, rad, in (-pi/2, pi/2); positive rises along `direction`
  /// \param height_at_origin  height at `origin`, m
  /// \param direction         horizontal direction of steepest ascent (normalized; must be
  /// non-zero) \param origin            horizontal point (x, y) where the height is
  /// `height_at_origin`, m
  explicit slope_terrain(double angle, double height_at_origin = 0.0,
                         const Eigen::Vector2d& direction = Eigen::Vector2d::UnitX(),
                         const Eigen::Vector2d& origin = Eigen::Vector2d::Zero())
      : angle_(angle), h0_(height_at_origin), origin_(origin) {
    check_argument(std::isfinite(angle) && std::abs(angle) < 0.5 * std::numbers::pi,
                   "slope_terrain: angle must be finite and in (-pi/2, pi/2) rad, got ", angle);
    check_argument(std::isfinite(height_at_origin),
                   "slope_terrain: height_at_origin must be finite, got ", height_at_origin);
    check_argument(direction.allFinite() && direction.norm() > 1e-12,
                   "slope_terrain: direction must be finite and non-zero, got (",
                   direction.transpose(), ")");
    check_argument(origin.allFinite(), "slope_terrain: origin must be finite, got (",
                   origin.transpose(), ")");
    dir_ = direction.normalized();
    grad_ = std::tan(angle) * dir_;
    n_ = vec3(-grad_.x(), -grad_.y(), 1.0).normalized();
  }

  double height(double x, double y) const {
    return h0_ + grad_.x() * (x - origin_.x()) + grad_.y() * (y - origin_.y());
  }
  vec3 normal(double /*x*/, double /*y*/) const { return n_; }
  /// The height bound over the disc of radius r around (x, y): the centre's height plus r times
  /// the steepest slope.
  double max_height(double x, double y, double r) const {
    return height(x, y) + r * std::abs(std::tan(angle_));
  }

  double angle() const { return angle_; }
  const Eigen::Vector2d& direction() const { return dir_; }
  /// Unit vector along the surface pointing uphill (zero horizontal-perpendicular part).
  vec3 uphill() const {
    return vec3(dir_.x(), dir_.y(), 0.0) * std::cos(angle_) + vec3::UnitZ() * std::sin(angle_);
  }

 private:
  double angle_;
  double h0_;
  Eigen::Vector2d origin_;
  Eigen::Vector2d dir_;
  Eigen::Vector2d grad_;
  vec3 n_;
};

static_assert(terrain<slope_terrain>);

}  // namespace gaitsynth
