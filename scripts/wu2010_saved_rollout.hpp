#pragma once
// The rollout options a saved Wu & Popovic 2010 controller ran with, for the hand-compiled
// scripts/wu2010_*.cpp: the legs collide when its "leg_collisions" says so and the joint-limit
// dampers are implicit when its "implicit_damping" does (none recorded: neither, as wu2010_walk
// --replay reads them), `seconds` long from the standing start placed on flat ground.
#include <string>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/rollout/options.hpp"

namespace gaitsynth_scripts {

inline bool saved_flag(const gaitsynth::planned_walk_saved& s, const std::string& key) {
  return s.info.contains(key) && s.info[key].is_boolean() && s.info[key].get<bool>();
}

inline gaitsynth::rollout_options saved_rollout_options(const gaitsynth::floating_model& m,
                                                        const gaitsynth::planned_walk_saved& s,
                                                        double seconds) {
  gaitsynth::rollout_options o;
  if (saved_flag(s, "leg_collisions")) o.self_contact = gaitsynth::wu2010_leg_collisions(m);
  o.implicit_joint_damping = saved_flag(s, "implicit_damping");
  o.duration = seconds;
  o.initial_state = gaitsynth::make_state(m);
  gaitsynth::place_on_terrain(m, gaitsynth::flat_terrain{}, o.initial_state.q);
  return o;
}

}  // namespace gaitsynth_scripts
