#pragma once
/// \file contact/terrain_choice.hpp
/// One of two terrains, chosen at run time: Wu & Popovic 2010 Sec. 8.3 optimize the forward walk
/// on random height fields and on "terrain with vertical drops created with boxes", a new terrain
/// each CMA iteration, so one terrain object (read by every rollout through terrain_ref) has to
/// be either kind. Every query goes to the chosen one with its own rules: penetration through
/// terrain_penetration (a riser's horizontal push for steps_terrain, the tangent plane for a
/// height field), the height bound through terrain_max_height. One branch per query, no
/// allocation.
#include <utility>

#include "gaitsynth/contact/terrain.hpp"

namespace gaitsynth {

template <terrain A, terrain B>
struct terrain_choice {
  A first;
  B second;
  bool use_second = false;

  /// Both terrains, `first` in use unless use_second.
  terrain_choice(A a, B b, bool second_in_use = false)
      : first(std::move(a)), second(std::move(b)), use_second(second_in_use) {}

  double height(double x, double y) const {
    return use_second ? second.height(x, y) : first.height(x, y);
  }
  vec3 normal(double x, double y) const {
    return use_second ? second.normal(x, y) : first.normal(x, y);
  }
  surface_contact penetration(const vec3& p) const {
    return use_second ? terrain_penetration(second, p) : terrain_penetration(first, p);
  }
  double max_height(double x, double y, double r) const {
    return use_second ? terrain_max_height(second, x, y, r) : terrain_max_height(first, x, y, r);
  }
};

}  // namespace gaitsynth
