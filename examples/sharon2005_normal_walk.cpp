// Sharon & van de Panne 2005, Figure 5a/b: a normal walk of the 7-link planar human.
//
// From the keyframes of data/sharon2005/normal_walk.keyframes.json (one step listed, the other is
// its mirror image), a 12-node nearest-neighbor controller (6 free nodes x 12 parameters = 72) is
// initialized along the target motion and optimized with SDS on the mass-distance cost over
// bootstrapped episodes of 0.2 s to 2 s (stage 1, the paper's pipeline). Each candidate is
// evaluated from the first keyframe's state and from three perturbed copies of it (velocities
// x0.9 and x1.1, 1 cm higher: the remedy the paper's section VII proposes; --single-start evaluates
// from the first state alone, as the paper did). Stage 2 continues from that result over episodes
// of 2, 3, 4 and 5 s with the same controller also evaluated blindly on 4 bumpy training profiles
// (section VII: "the addition of disturbances during the controller evaluation may encourage
// robustness"): stage 1 alone often gives a controller that walks its 2 s episodes and then
// falls within 10 s. The result is then simulated for 70 s (the paper's test).
//
//   ./sharon2005_normal_walk [--out DIR] [--threads N] [--stage1-only] [--single-start] ...
//
// With --initial-controller, --horizons, --max-horizon, --bumpy-training or --body-training it runs
// one stage with those settings (docs/reproductions/sharon2005.md chains such stages).
//
// Writes DIR/sharon2005_normal_walk.controller.json, .csv (70 s trajectory, 60 frames/s) and
// .convergence.csv; prints a one-line JSON summary on stdout, progress on stderr.
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"
#include "sharon2005_common.hpp"

#include <algorithm>
#include <filesystem>

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv,
      "optimize a normal walk of the 7-link human (Sharon & van de Panne 2005, Fig. 5a)",
      {.normal_walk = true});
  const planar_model m = sharon2005_human7();
  const std::string kf_path = sharon_example::keyframes_path(c, "normal_walk.keyframes.json");
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);

  auto c0 = sharon_example::initial_controller(m, target, sharon_example::human7_options(), c);
  const nlohmann::ordered_json extra{{"keyframes", kf_path}, {"figure", "5a"}};

  // The default run: stage 1 (flat ground, episodes 0.2 .. 2 s), then stage 2 below.
  const bool two_stages = !c.stage1_only && c.initial_controller.empty() && c.horizons.empty() &&
                          c.max_horizon < 0 && c.bumpy_training < 0 && c.body_training < 0;
  sharon_example::cli args = c;
  sharon_example::earlier_stages before;
  if (two_stages) {
    const auto flat = sharon_example::make_problem(m, target, c0, c);
    nn_synthesis_options so = sharon_example::synthesis_defaults();
    so.threads = c.threads;
    if (c.evaluations_per_episode >= 0) so.evaluations_per_episode = c.evaluations_per_episode;
    so.run.progress = &std::cerr;
    so.run.progress_interval = 2.0;
    std::filesystem::create_directories(c.out_dir);
    so.run.log_file = c.out_dir / "sharon2005_normal_walk.stage1.convergence.csv";
    sharon_example::checkpoint_into(so.run, c, "sharon2005_normal_walk.stage1");
    std::cerr << "sharon2005_normal_walk: stage 1 of 2, flat ground, episodes 0.2 .. 2 s\n";
    const nn_synthesis_result r1 = synthesize_nearest_neighbor(flat, so);
    before.evaluations = r1.evaluations;
    before.rollouts =
        r1.evaluations * static_cast<long long>(sharon_example::rollouts_per_evaluation(flat));
    before.wall_seconds = r1.wall_seconds;
    std::cerr << "sharon2005_normal_walk: stage 1: " << r1.evaluations << " evaluations in "
              << r1.wall_seconds
              << " s; stage 2 of 2, also on 4 bumpy profiles, episodes 2 .. 5 s\n";
    c0 = flat.controller_with(r1.x);
    args.bumpy_training = 4;
    args.horizons = {2.0, 3.0, 4.0, 5.0};
    if (c.evaluations_per_episode < 0) args.evaluations_per_episode = 300;
  }

  auto prob = sharon_example::make_problem(m, target, c0, c);
  auto run = [&](const auto& problem) {
    return sharon_example::synthesize_and_report("sharon2005_normal_walk", problem,
                                                 sharon_example::synthesis_defaults(), args, extra,
                                                 before);
  };
  // Blind walking over bumps (Fig. 8d) in the cost: the same controller from the first keyframe's
  // state on each training terrain (never the test's; sharon_scenarios::training_terrains).
  using bumpy_problem = nn_problem<planar_root, torque_actuator, mass_distance<planar_root>,
                                   height_field_terrain, semi_implicit_euler>;
  std::vector<bumpy_problem> bumpy;
  const int n_bumpy = std::max(args.bumpy_training, 0);
  for (const auto& ground : sharon_scenarios::training_terrains(n_bumpy)) {
    rollout_options rb = prob.options;
    rb.initial_state = target_start_states(m, target, ground, {0.0}).front();
    bumpy.push_back(
        bumpy_problem{m, torque_actuator{}, c0,
                      mass_distance<planar_root>(m, target, sharon_example::style_options(c)),
                      ground, semi_implicit_euler{}, rb});
  }
  // Modeling errors (Fig. 8a-c) in the cost: training bodies (sharon_scenarios::training_bodies;
  // the problems keep references to the models, so they live in a vector sized once).
  using body_problem = decltype(prob);
  const int n_bodies = std::max(args.body_training, 0);
  std::vector<planar_model> bodies;
  bodies.reserve(static_cast<std::size_t>(n_bodies));
  std::vector<body_problem> changed;
  for (const auto& p : sharon_scenarios::training_bodies(n_bodies)) {
    bodies.push_back(sharon2005_human7(p));
    rollout_options rb = prob.options;
    rb.initial_state = sharon_scenarios::start_state_for(bodies.back(), target);
    changed.push_back(body_problem{
        bodies.back(), torque_actuator{}, c0,
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
