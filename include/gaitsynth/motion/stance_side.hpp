#pragma once
/// \file motion/stance_side.hpp
/// Which leg supports the body: keyframed segments (motion/keyframes.hpp), the nearest-neighbor
/// controller's nodes and the end-effector planner's half-cycles (Wu & Popovic 2010) share one
/// type, so that every header of the library can be included together.
namespace gaitsynth {

/// Which leg supports the body. `none`: no stance leg is given (a keyframed segment that does not
/// say); the planner's half-cycles are always `left` or `right`.
enum class stance_side { none, left, right };

/// The other leg (`none` stays `none`).
inline stance_side opposite(stance_side s) {
  return s == stance_side::left ? stance_side::right
                                : (s == stance_side::right ? stance_side::left : stance_side::none);
}

}  // namespace gaitsynth
