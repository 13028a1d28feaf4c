// Which part of Wu & Popovic 2010's helper force a saved forward walk needs
// (docs/reproductions/wu2010.md, "Where eq. 5 falls short"): replays the controller on flat ground
// for SECONDS with its helper (Sec. 8.2) acting on every row of eq. 4, on the upper body's rows
// (force and torque, force, torque) or on the feet's frames (planned_walk_options::helper_rows),
// at each bound H given
// (N; the saved controller's own h_max when none), and prints how long each walk lasts. The legs
// collide when the saved controller did. Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_helper_scope.cpp -o /tmp/wu2010_helper_scope
//   /tmp/wu2010_helper_scope data/wu2010/runs/f9/wu2010_walk.mean.json 20 16.45 25 40
//
// (one command line each).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

#include "wu2010_saved_rollout.hpp"

using namespace gaitsynth;

int main(int argc, char** argv) try {
  if (argc < 3)
    throw std::invalid_argument("usage: wu2010_helper_scope CONTROLLER.json SECONDS [H ...]");
  const char* file = argv[1];
  const double seconds = std::atof(argv[2]);
  if (!(seconds > 0.0)) throw std::invalid_argument("SECONDS must be > 0");
  const floating_model m = wu2010_biped();
  const planned_walk_saved saved = load_planned_walk(file);
  planned_walk_options po = saved_planned_walk_options(saved, file);
  po.helper_force = true;
  rollout_options o = gaitsynth_scripts::saved_rollout_options(m, saved, seconds);
  auto scratch = make_rollout_scratch(m);
  std::vector<double> bounds;
  for (int i = 3; i < argc; ++i) bounds.push_back(std::atof(argv[i]));
  std::printf("%s on flat ground, %.1f s; the helper on\n%8s %-20s %-20s %-20s %-20s %-20s\n", file,
              seconds, "h_max", "every row", "the upper body", "its force", "its torque",
              "the feet");
  const helper_scope scopes[] = {helper_scope::all, helper_scope::upper_body,
                                 helper_scope::upper_body_force, helper_scope::upper_body_torque,
                                 helper_scope::feet};
  for (std::size_t b = 0; b < std::max<std::size_t>(bounds.size(), 1); ++b) {
    double h = 0.0;
    std::string row;
    for (const helper_scope scope : scopes) {
      po.helper_rows = scope;
      const planned_walk<> c(m, flat_terrain{}, po);
      std::vector<double> x = planned_walk_values(saved, c.parameter_names(), file);
      if (!bounds.empty()) x.back() = bounds[b];
      h = x.back();
      const rollout_result r = rollout(m, torque_actuator{}, c, distance_objective(),
                                       flat_terrain{}, semi_implicit_euler{}, x, o, scratch);
      char cell[64];
      std::snprintf(
          cell, sizeof cell, " %-20s",
          (std::to_string(r.time).substr(0, 5) + " s " + std::string(to_string(r.reason))).c_str());
      row += cell;
    }
    std::printf("%8.2f%s\n", h, row.c_str());
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_helper_scope: %s\n", e.what());
  return 1;
}
