#pragma once
/// \file flat_terrain.hpp
/// A horizontal plane z = h0 (the ground plane of Wang et al. 2009 and Sharon & van de Panne 2005).
#include <cmath>

#include "gaitsynth/contact/terrain.hpp"
#include "gaitsynth/error.hpp"

namespace gaitsynth {

class flat_terrain {
 public:
  /// \param height  height of the plane, m (finite)
  explicit flat_terrain(double height = 0.0) : h0_(height) {
    check_argument(std::isfinite(height), "flat_terrain: height must be finite, got ", height);
  }
  double height(double /*x*/, double /*y*/) const { return h0_; }
  vec3 normal(double /*x*/, double /*y*/) const { return vec3::UnitZ(); }
  double plane_height() const { return h0_; }
  /// The height bound over any disc: the plane's height.
  double max_height(double /*x*/, double /*y*/, double /*r*/) const { return h0_; }

 private:
  double h0_;
};

static_assert(terrain<flat_terrain>);

}  // namespace gaitsynth
