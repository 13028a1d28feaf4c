// Sharon & van de Panne 2005, Figure 5a/b: a normal walk of the 7-link planar human.
//
// From the keyframes of data/sharon2005/normal_walk.keyframes.json (one step listed, the other is
// its mirror image), a 12-node nearest-neighbor controller (6 free nodes x 12 parameters = 72) is
// initialized along the target motion and optimized with SDS on the mass-distance cost over
// bootstrapped episodes of 0.2 s to 2 s. Each candidate is evaluated from the first keyframe's
// state and from three perturbed copies of it (velocities x0.9 and x1.1, 1 cm higher: the remedy
// the paper's section VII proposes; --single-start evaluates from the first state alone, as the
// paper did). The result is then simulated for 70 s (the paper's test).
//
//   ./sharon2005_normal_walk [--out DIR] [--threads N] [--single-start] ...
//
// Writes DIR/sharon2005_normal_walk.controller.json, .csv (70 s trajectory, 60 frames/s) and
// .convergence.csv; prints a one-line JSON summary on stdout, progress on stderr.
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/keyframes_json.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "sharon2005_common.hpp"
#include "sharon2005_scenarios.hpp"

namespace {
constexpr int kDefaultBumpyTraining = 0;
constexpr int kDefaultBodyTraining = 0;
}

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv, "optimize a normal walk of the 7-link human (Sharon & van de Panne 2005, Fig. 5a)");
  const planar_model m = sharon2005_human7();
  const std::string kf_path =
      c.keyframes.empty() ? sharon_example::data_file("normal_walk.keyframes.json") : c.keyframes;
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);

  const nearest_neighbor_controller<planar_root> c0 = sharon_example::initial_controller(
      m, c, nearest_neighbor_controller<planar_root>(m, target, sharon_example::human7_options()));
  rollout_options ro;
  ro.initial_state = target.initial_state();
  nn_problem prob{m, torque_actuator{}, c0, mass_distance<planar_root>(m, target, sharon_example::style_options(c)),
                        flat_terrain{}, semi_implicit_euler{}, ro};
  sharon_example::set_starts(prob, c);
  const nlohmann::ordered_json extra{{"keyframes", kf_path}, {"figure", "5a"}};
  const sharon_example::cli& args = c;
  auto run = [&](const auto& problem) {
    return sharon_example::synthesize_and_report("sharon2005_normal_walk", problem,
                                                 sharon_example::synthesis_defaults(), args, extra);
  };
  // Blind walking over bumps (Fig. 8d) in the cost: the same controller from the first keyframe's
  // state on each training terrain (never the test's; sharon_scenarios::training_terrains).
  using bumpy_problem = nn_problem<planar_root, torque_actuator, mass_distance<planar_root>,
                                   height_field_terrain, semi_implicit_euler>;
  std::vector<bumpy_problem> bumpy;
  const int n_bumpy = c.bumpy_training < 0 ? kDefaultBumpyTraining : c.bumpy_training;
  for (const auto& ground : sharon_scenarios::training_terrains(n_bumpy)) {
    rollout_options rb = ro;
    rb.initial_state = target_start_states(m, target, ground, {0.0}).front();
    bumpy.push_back(bumpy_problem{m, torque_actuator{}, c0, mass_distance<planar_root>(m, target, sharon_example::style_options(c)),
                                  ground, semi_implicit_euler{}, rb});
  }
  // Modeling errors (Fig. 8a-c) in the cost: randomized bodies (sharon_scenarios::training_bodies;
  // the problems keep references to the models, so they live in a vector sized once).
  using body_problem = decltype(prob);
  const int n_bodies = c.body_training < 0 ? kDefaultBodyTraining : c.body_training;
  std::vector<planar_model> bodies;
  bodies.reserve(static_cast<std::size_t>(n_bodies));
  std::vector<body_problem> changed;
  for (const auto& p : sharon_scenarios::training_bodies(n_bodies)) {
    bodies.push_back(sharon2005_human7(p));
    rollout_options rb = ro;
    rb.initial_state = sharon_scenarios::start_state_for(bodies.back(), target);
    changed.push_back(body_problem{bodies.back(), torque_actuator{}, c0,
                                   mass_distance<planar_root>(bodies.back(), target, sharon_example::style_options(c)),
                                   flat_terrain{}, semi_implicit_euler{}, rb});
  }
  if (bumpy.empty() && changed.empty()) return run(prob);
  if (changed.empty()) return run(make_problem_with_variants(prob, std::move(bumpy)));
  if (bumpy.empty()) return run(make_problem_with_variants(prob, std::move(changed)));
  return run(make_problem_with_variants(make_problem_with_variants(prob, std::move(bumpy)),
                                        std::move(changed)));
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
