#pragma once
/// \file options.hpp
/// Settings of one rollout (rollout/rollout.hpp). Plain data; validated by rollout() at set-up,
/// which throws std::invalid_argument naming the bad value.
#include <cstdint>
#include <vector>

#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/rollout/trajectory.hpp"

namespace gaitsynth {

/// Stall detection: a walker that stays upright but stops advancing has not walked. The rollout
/// stops with stop_reason::stalled when the COM has advanced less than `min_progress` along +x
/// (the walking direction of every model here) over a window of `window` seconds; windows are
/// consecutive from the start, so a stall is caught within two windows. Off while window is 0.
struct stall_detection {
  double window = 0.0;        ///< s; 0: off
  double min_progress = 0.1;  ///< m along +x per window
};

struct rollout_options {
  double dt = 1.0 / 2400.0;  ///< physics timestep, s (2400 Hz as in Wang et al. 2009/2012)
  double duration = 10.0;    ///< horizon, s (the papers evaluate 10 s rollouts)
  /// Start state (q, v, t). Empty q: the model's neutral configuration placed on the terrain (its
  /// lowest contact point touching the ground), at rest, t = 0.
  sim_state initial_state;
  /// Added to the start velocities after the controller has set its start state (empty: none;
  /// else size nv). Perturbed starts of a controller whose parameters include its start state
  /// (Wang et al. 2009): rollout/start_perturbations.hpp draws them.
  Eigen::VectorXd initial_velocity_offset;

  /// Fall detection: stop when the COM is lower than the fall height above the terrain under it.
  bool detect_falls = true;
  double fall_height = 0.0;    ///< m; if > 0 used as is
  double fall_fraction = 0.5;  ///< else: this fraction of the initial COM height above terrain
  stall_detection stall{};     ///< off by default (a cost that turns it on must charge a stall)
  /// Divergence by speed: a COM faster than this (m/s) ends the rollout as stop_reason::non_finite.
  /// An explicit step that blows up often leaves q and v huge but finite for a step or two, and the
  /// fall test then reported a "fall" 1e10 m away; no biped's COM moves at 100 m/s (a 10 m free
  /// fall reaches 14 m/s). Infinity turns it off.
  double divergence_com_speed = 100.0;
  /// Off (the default): a diverged rollout costs +infinity (failed_rollout_cost) and the
  /// objective's finish() is not called. On: it is scored like any early stop at its last sane
  /// step, finish() seeing stop_reason::non_finite and terms that only ever accumulated finite
  /// states; for an objective that charges the horizon left unsimulated (a fall guard), so that an
  /// optimizer whose candidates mostly diverge while falling can still rank them by how long they
  /// lasted. The result stays diverged(); a non-finite objective value still costs +infinity.
  bool score_divergence = false;

  /// Joint dampers taken implicitly (backward Euler), off by default. The actuator's rate
  /// coefficients (actuator_with_joint_damping: kd of every PD servo whose torque is not clamped)
  /// and the damping of every soft joint limit past its bound enter the step as an armature
  /// dt c_j on the joint-space inertia, (M + dt diag(c)) ddq = tau - C, so each damper applies
  /// -c_j (v_j + dt ddq_j), the damper at the end of the step, instead of -c_j v_j. Explicit
  /// dampers are stable only while c dt / I < 2 for the inertia I they move, and a 3-DOF Euler
  /// joint (the humanoids' hips: x, then y, then z) has a mode of vanishing inertia near hip_y =
  /// +-pi/2, where its x and z axes align: there any explicit damper diverges. The torques the
  /// objective and the observers see are the applied ones (the explicit torque minus
  /// c_j dt ddq_j); the clamp of a torque limit applies to the explicit part. General (6D) path
  /// only: the rollout throws for a workspace on the planar fast path (disable_planar_path) and
  /// for an actuator integrated with (q, v) (its torques are re-evaluated at integrator stages).
  bool implicit_joint_damping = false;

  contact_parameters contact{};  ///< penalty contact (kp 75000 N/m, kd 2000 N s/m, mu 1)
  /// Collisions between the character's own bodies (contact/self_contact.hpp), e.g. Wu &
  /// Popovic 2010's legs (wu2010_leg_collisions); no pairs (the default): none.
  self_contact_parameters self_contact{};
  std::vector<push> pushes;  ///< external pushes (force on a body's COM over a time window)

  trajectory* record = nullptr;  ///< if set, the rollout is recorded into it
  int record_every = 1;          ///< physics steps per recorded frame (40 at 2400 Hz: 60 fps)
};

}  // namespace gaitsynth
