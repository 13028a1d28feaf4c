// Table 1 of Wang, Fleet & Hertzmann 2009: the largest push (force components, N) a walker
// survives from each of 8 directions, with a 0.4 s push to the torso COM every 4 s for 40 s
// (rollout/push_test.hpp). Without arguments it tests the SIMBICON baseline
// (controllers/fsm/simbicon.hpp) and prints its column next to the paper's.
//
//   wang2009_push_test [--resolution N] [--max-force N] [--from-yin]
//
// --from-yin tests Yin et al.'s walk as published (simbicon_yin2007_walk_parameters) instead of
// the library's adjusted one.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"

using namespace gaitsynth;

int main(int argc, char** argv) try {
  push_protocol proto;
  bool from_yin = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--from-yin")
      from_yin = true;
    else if (a == "--resolution" && i + 1 < argc)
      proto.resolution = std::stod(argv[++i]);
    else if (a == "--max-force" && i + 1 < argc)
      proto.max_force = std::stod(argv[++i]);
    else {
      std::cerr << "usage: " << argv[0] << " [--resolution N] [--max-force N] [--from-yin]\n";
      return 2;
    }
  }
  const floating_model m = wang2009_humanoid();
  const auto [kp, kd] = simbicon_walk_gains(m);
  const simbicon_controller c(m, kp, kd);
  const std::vector<double> p =
      from_yin ? simbicon_yin2007_walk_parameters() : simbicon_walk_parameters();
  rollout_options opt;
  opt.contact.mu = 10.0;  // Wang et al. 2009 Sec. 4.2
  opt.fall_height = 0.7;  // E_fail's height
  opt.initial_state = simbicon_start_state(m);
  // Table 1, "simbicon" column (Wang et al.'s implementation).
  const std::array<double, 8> paper{225, 150, 250, 100, 120, 100, 275, 125};
  const int torso = m.body_index("torso");
  std::printf("direction  max force (N)  paper SIMBICON (N)\n");
  for (int k = 0; k < 8; ++k) {
    const vec3& d = table1_directions()[k];
    const double f =
        max_push_force(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                       std::span<const double>(p), opt, torso, d, proto);
    std::printf("(%2.0f,%2.0f)    %8.0f       %8.0f\n", d.x(), d.y(), f, paper[k]);
    std::fflush(stdout);
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "wang2009_push_test: " << e.what() << "\n";
  return 1;
}
