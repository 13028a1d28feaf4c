// Where Sec. 8.2's helper force works in a saved Wu & Popovic 2010 forward walk
// (docs/reproductions/wu2010.md, "Taking the helper away"): walks the controller WITH its helper
// force for SECONDS on flat ground, the legs colliding, and prints for each row of eq. 4's
// residual h = b - A f (the upper body's force, each action frame's force, the upper body's
// torque) the mean |h| after the first 2 s and the share of steps where it sits at the clip
// h_max. Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_helper_rows.cpp -o /tmp/wu2010_helper_rows
//   /tmp/wu2010_helper_rows data/wu2010/runs/f9/wu2010_walk.mean.json 20
//
// (one command line each).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

/// Reads the controller's clipped helper force after each step (rollout observer).
struct helper_rows {
  double h_max = 0.0;
  std::vector<double> sum_abs, at_clip;
  long steps = 0;
  template <class Observation>
  void observe(const Observation& ob) {
    if (ob.t < 2.0) return;
    const Eigen::VectorXd& h = ob.controller_state_ptr->helper;
    if (sum_abs.empty()) sum_abs.assign(static_cast<std::size_t>(h.size()), 0.0);
    if (at_clip.empty()) at_clip.assign(static_cast<std::size_t>(h.size()), 0.0);
    for (Eigen::Index i = 0; i < h.size(); ++i) {
      sum_abs[static_cast<std::size_t>(i)] += std::abs(h[i]);
      at_clip[static_cast<std::size_t>(i)] += std::abs(h[i]) >= (1.0 - 1e-9) * h_max ? 1.0 : 0.0;
    }
    ++steps;
  }
};

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 3) throw std::invalid_argument("usage: wu2010_helper_rows CONTROLLER.json SECONDS");
  const char* file = argv[1];
  const double seconds = std::atof(argv[2]);
  if (!(seconds > 2.0)) throw std::invalid_argument("SECONDS must be > 2");
  const floating_model m = wu2010_biped();
  const planned_walk_saved saved = load_planned_walk(file);
  const planned_walk_options po = saved_planned_walk_options(saved, file);
  if (!po.helper_force) throw std::invalid_argument(std::string(file) + " has no helper force");
  const planned_walk<> c(m, flat_terrain{}, po);
  const std::vector<double> x = planned_walk_values(saved, c.parameter_names(), file);
  rollout_options o;
  o.self_contact = wu2010_leg_collisions(m);
  o.duration = seconds;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  helper_rows rows;
  rows.h_max = x[c.helper_offset()];
  const rollout_result r = rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                                   semi_implicit_euler{}, x, o, scratch, rows);
  std::printf("%s: %s after %.2f s, h_max %.2f N, %ld steps after 2 s\n", file,
              std::string(to_string(r.reason)).c_str(), r.time, rows.h_max, rows.steps);
  if (rows.steps == 0) return 0;
  const auto& L = c.layout();
  const long n = static_cast<long>(rows.sum_abs.size());
  for (long i = 0; i < n; ++i) {
    const char* axis = i % 3 == 0 ? "x" : i % 3 == 1 ? "y" : "z";
    const std::string name = i < 3        ? "upper body force"
                             : i >= n - 3 ? "upper body torque"
                                          : L.action[static_cast<std::size_t>((i - 3) / 3)].name;
    std::printf("%-20s %s  mean |h| %6.2f  at the clip %.2f\n", name.c_str(), axis,
                rows.sum_abs[static_cast<std::size_t>(i)] / static_cast<double>(rows.steps),
                rows.at_clip[static_cast<std::size_t>(i)] / static_cast<double>(rows.steps));
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_helper_rows: %s\n", e.what());
  return 1;
}
