#pragma once
/// \file options.hpp
/// Settings of one rollout (rollout/rollout.hpp). Plain data; validated by rollout() at set-up,
/// which throws std::invalid_argument naming the bad value.
#include <cstdint>
#include <vector>

#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

struct rollout_options {
  double dt = 1.0 / 2400.0;  ///< physics timestep, s (2400 Hz as in Wang et al. 2009/2012)
  double duration = 10.0;    ///< horizon, s (the papers evaluate 10 s rollouts)
  /// Start state (q, v, t). Empty q: the model's neutral configuration placed on the terrain (its
  /// lowest contact point touching the ground), at rest, t = 0.
  sim_state initial_state;

  /// Fall detection: stop when the COM is lower than the fall height above the terrain under it.
  bool detect_falls = true;
  double fall_height = 0.0;    ///< m; if > 0 used as is
  double fall_fraction = 0.5;  ///< else: this fraction of the initial COM height above terrain

  contact_parameters contact{};  ///< penalty contact (kp 75000 N/m, kd 2000 N s/m, mu 1)
  std::vector<push> pushes;      ///< external pushes (force on a body's COM over a time window)

  trajectory* record = nullptr;  ///< if set, the rollout is recorded into it
  int record_every = 1;          ///< physics steps per recorded frame (40 at 2400 Hz: 60 fps)
};

}  // namespace gaitsynth
