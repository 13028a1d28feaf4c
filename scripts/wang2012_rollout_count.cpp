// One or more 10 s rollouts of the saved muscle walker nwalk (the case of bench_rollout's
// BM_Rollout_Wang2012_Walk10s_Muscles), printing the summed cost to 17 digits and the time per
// step: for instruction counts that a shared host's load does not disturb, and for checking that a
// change leaves the results unchanged to the bit (docs/performance.md, "Fewer instructions per
// muscle step"). Compile against the tree's include/ (one command line each):
//
//   g++ -std=c++20 -O3 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wang2012_rollout_count.cpp -o /tmp/wang2012_rollout_count
//   valgrind --tool=callgrind /tmp/wang2012_rollout_count 1      # instructions
//   /tmp/wang2012_rollout_count 5                                # cost and us per step
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

#ifndef GAITSYNTH_NWALK_PATH
#define GAITSYNTH_NWALK_PATH "data/wang2012/walkers/nwalk.controller.json"  // from the tree's root
#endif

using namespace gaitsynth;
int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 5;
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units);
  const wang2012_saved_controller saved = load_wang2012_controller(GAITSYNTH_NWALK_PATH);
  const wang2012_reflex_controller ctrl(m);
  const auto obj = wang2012::objective(m, units, wang2012::metabolic_energy(units),
                                       {.target_speed = saved.target_speed});
  const rollout_options opt = wang2009_rollout_options(m);
  auto scr = make_rollout_scratch(m);
  semi_implicit_euler integ;
  double c = 0;
  long steps = 0;
  auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    const rollout_result r = rollout(m, act, ctrl, obj, flat_terrain{}, integ,
                                     std::span<const double>(saved.parameters), opt, scr);
    c += r.cost;
    steps += r.steps;
  }
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("cost %.17g steps %ld  %.3f us/step\n", c, steps, 1e6 * s / steps);
}
