#pragma once
/// \file controllers/reflex/leg_phase.hpp
/// The per-leg state machine of the reflex controller (Wang et al. 2012 Sec. 4, Figure 4): a leg
/// is in stance while its foot touches the ground (as sensed after the contact delay) and in
/// swing otherwise; within stance, swing initiation begins when the COM is far enough ahead of the
/// ankle (d > d_SI) or when the other leg has touched down after this one (double stance with
/// this leg trailing) and lasts until lift-off; within swing, stance preparation begins when the
/// ankle is far enough ahead of the COM (d < d_SP) and lasts until touch-down.
///
/// d is the signed horizontal distance from the ankle to the COM along the heading, over the leg
/// length (positive: the COM ahead). A pure value type: update() takes what the leg senses now.
#include <cstdint>

namespace gaitsynth::reflex {

enum class leg_phase : std::uint8_t {
  stance,              ///< foot on the ground
  swing_initiation,    ///< late stance: d > d_SI, or the other leg touched down after this one
  swing,               ///< foot in the air
  stance_preparation,  ///< late swing: d < d_SP
};

constexpr bool in_stance(leg_phase p) {
  return p == leg_phase::stance || p == leg_phase::swing_initiation;
}

/// One leg's phase and when its current stance or swing began.
struct leg_state {
  leg_phase phase = leg_phase::stance;
  double phase_start = 0.0;  ///< s: when this stance (or swing) began

  /// The phase after sensing contact (this leg), the other leg's state, d and the thresholds,
  /// at time t.
  void update(bool contact, const leg_state& other, double d, double d_si, double d_sp, double t) {
    if (in_stance(phase)) {
      if (!contact) {
        phase = leg_phase::swing;
        phase_start = t;
        return;
      }
      const bool other_landed_later = in_stance(other.phase) && other.phase_start > phase_start;
      if (phase == leg_phase::stance && (d > d_si || other_landed_later))
        phase = leg_phase::swing_initiation;
    } else {
      if (contact) {
        phase = leg_phase::stance;
        phase_start = t;
        return;
      }
      if (phase == leg_phase::swing && d < d_sp) phase = leg_phase::stance_preparation;
    }
  }
};

}  // namespace gaitsynth::reflex
