#pragma once
/// \file contact/terrain_ref.hpp
/// A terrain that reads another one through a pointer, so that many copies (the problem's, each
/// controller's that plans on it, each worker's) follow one terrain that the owner replaces
/// between optimizer iterations: Wu & Popovic 2010 Sec. 8.3 draw "a different random height field
/// in each CMA iteration, while samples in the same iteration use the same height field".
///
/// The referenced terrain must outlive every copy, and may only be changed while no rollout reads
/// it (between batches: an evaluator's batch ends before the optimizer's per-iteration callback
/// runs, which orders the change before the next batch's reads). Every terrain query forwards to
/// it, the optional ones (penetration, max_height) only when it has them, so contact treats a
/// terrain_ref exactly as the terrain it refers to.
#include "gaitsynth/contact/terrain.hpp"

namespace gaitsynth {

template <terrain T>
struct terrain_ref {
  const T* target = nullptr;

  /// Refers to `t`, which must outlive this and its copies.
  explicit terrain_ref(const T& t) : target(&t) {}

  double height(double x, double y) const { return target->height(x, y); }
  vec3 normal(double x, double y) const { return target->normal(x, y); }
  surface_contact penetration(const vec3& p) const requires terrain_with_penetration<T> {
    return target->penetration(p);
  }
  double max_height(double x, double y, double r) const requires terrain_with_height_bound<T> {
    return target->max_height(x, y, r);
  }
};

}  // namespace gaitsynth
