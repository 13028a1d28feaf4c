#pragma once
/// \file synthesis/sharon2005_disturbances.hpp
/// Disturbances that no figure of Sharon & van de Panne 2005 shows, for the 7-link walkers: a
/// sloped ground, low friction, periodic pushes on the torso and a changed torso mass. They
/// measure how robust a saved controller is beyond Figure 8 (examples/sharon2005_robustness
/// --disturbances, tests/sharon2005/disturbances.cpp), and, with other magnitudes and timings, they
/// train robustness into a controller (the examples' --disturbance-training; section VII: "the
/// addition of disturbances during the controller evaluation may encourage robustness").
///
/// The test set is the hardening issue's outside measurement: slopes of -5 and +3 degrees,
/// friction 0.5, 50 N pushes forward and backward, torso mass -20 % and +20 %. The pushes follow
/// Wang et al. 2009's protocol (0.4 s on the torso COM every 4 s, here from t = 2 s); the
/// training set never uses a test magnitude or timing.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/rollout/options.hpp"

namespace gaitsynth::sharon_scenarios {

struct disturbance {
  std::string name;
  std::string description;
  double slope_deg = 0.0;      ///< ground inclination, rising along +x, degrees
  double friction = 1.0;       ///< Coulomb friction coefficient of the ground
  double push_force = 0.0;     ///< N along +x (negative: backward) on the torso COM; 0: none
  double push_start = 2.0;     ///< s, the first push
  double push_period = 4.0;    ///< s between pushes
  double push_duration = 0.4;  ///< s
  double torso_mass = 40.0;    ///< kg (Table I: 40), inertia scaled as a rod

  /// The body: Table I with this torso mass.
  sharon2005_human7_parameters body() const {
    sharon2005_human7_parameters p;
    p.torso_mass = torso_mass;
    return p.with_rod_inertias();
  }

  /// The ground: a plane through the origin at slope_deg (flat for 0).
  slope_terrain ground() const { return slope_terrain(slope_deg * std::numbers::pi / 180.0); }

  /// o with this friction and the pushes that start before `horizon` (torso = body 0 of the
  /// 7-link model). \throws std::invalid_argument for a non-finite or negative horizon.
  rollout_options apply(rollout_options o, double horizon) const {
    check_argument(std::isfinite(horizon) && horizon >= 0.0,
                   "disturbance::apply: horizon must be finite and >= 0, got ", horizon);
    o.contact.mu = friction;
    o.pushes.clear();
    if (push_force != 0.0 && push_start < horizon) {
      const int count = 1 + static_cast<int>(std::floor((horizon - push_start) / push_period));
      o.pushes = periodic_pushes(0, vec3(push_force, 0.0, 0.0), push_start, push_period,
                                 push_duration, count);
    }
    return o;
  }
};

/// The measured conditions (hardening issue): none is in the training set below.
inline std::vector<disturbance> test_disturbances() {
  return {
      {.name = "slope_-5deg", .description = "downhill, 5 degrees", .slope_deg = -5.0},
      {.name = "slope_+3deg", .description = "uphill, 3 degrees", .slope_deg = 3.0},
      {.name = "friction_0.5", .description = "friction 0.5 (nominal 1)", .friction = 0.5},
      {.name = "push_+50N",
       .description = "50 N forward on the torso, 0.4 s every 4 s",
       .push_force = 50.0},
      {.name = "push_-50N",
       .description = "50 N backward on the torso, 0.4 s every 4 s",
       .push_force = -50.0},
      {.name = "torso_32kg", .description = "torso mass 40 -> 32 kg (-20 %)", .torso_mass = 32.0},
      {.name = "torso_48kg", .description = "torso mass 40 -> 48 kg (+20 %)", .torso_mass = 48.0},
  };
}

/// Training conditions for a cost that rewards robustness (--disturbance-training): other slopes,
/// friction, push magnitudes and timings (every 2.5 s from 0.9 or 2.1 s, so that short episodes
/// meet them) and torso masses than the test set's.
inline std::vector<disturbance> training_disturbances() {
  return {
      {.name = "slope_-6deg", .description = "downhill, 6 degrees", .slope_deg = -6.0},
      {.name = "slope_-4deg", .description = "downhill, 4 degrees", .slope_deg = -4.0},
      {.name = "slope_-2deg", .description = "downhill, 2 degrees", .slope_deg = -2.0},
      {.name = "slope_+2deg", .description = "uphill, 2 degrees", .slope_deg = 2.0},
      {.name = "slope_+4deg", .description = "uphill, 4 degrees", .slope_deg = 4.0},
      {.name = "friction_0.4", .description = "friction 0.4", .friction = 0.4},
      {.name = "push_+60N",
       .description = "60 N forward, 0.4 s every 2.5 s from 0.9 s",
       .push_force = 60.0,
       .push_start = 0.9,
       .push_period = 2.5},
      {.name = "push_-60N",
       .description = "60 N backward, 0.4 s every 2.5 s from 2.1 s",
       .push_force = -60.0,
       .push_start = 2.1,
       .push_period = 2.5},
      {.name = "torso_30kg", .description = "torso mass 30 kg", .torso_mass = 30.0},
      {.name = "torso_50kg", .description = "torso mass 50 kg", .torso_mass = 50.0},
  };
}

}  // namespace gaitsynth::sharon_scenarios
