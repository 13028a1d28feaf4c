#pragma once
// Shared plumbing of the examples/sharon2005_*.cpp programs (Sharon & van de Panne 2005): command
// line, the problem they optimize (make_problem), the synthesis run with progress, the paper's 70 s
// check, and the outputs every example writes: the optimized controller (JSON), the 70 s trajectory
// (CSV) and a one-line JSON summary on stdout. Everything else goes to stderr.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/synthesis/sharon2005_disturbances.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

namespace sharon_example {

struct cli {
  std::filesystem::path out_dir;           // the run folder
  unsigned threads = 0;                    // 0: every core
  long long evaluations_per_episode = -1;  // -1: the example's default
  double check_seconds = 70.0;
  std::string keyframes;      // empty: the example's data file
  bool single_start = false;  // the paper's cost: one start state (no perturbed copies)
  int noisy_starts = 0;       // more starts, joint velocities + N(0, 0.05 rad/s) (issue 15)
  double max_horizon = -1.0;  // -1: the example's default (2 s, section V.C)
  int bumpy_training = -1;    // -1: the example's default number of bumpy training terrains
  int body_training = -1;     // -1: the example's default number of randomized training bodies
  bool align_style =
      false;  // mass distance on shapes only (mass_distance_options::align_horizontal)
  bool stage1_only = false;           // normal walk: stop after the paper's flat-ground stage
  bool disturbance_training = false;  // 7-link styles: also under training_disturbances()
  double min_progress_speed = 0.0;    // > 0: a rollout of the cost that advances less than this
                                      // (m/s, over any 2 s window) stops, charged as a fall
  std::vector<double> horizons;       // explicit episode horizons, s (overrides --max-horizon)
  std::string initial_controller;     // start from this saved controller instead of the keyframes
  bool resume = false;                // --resume DIR: continue the run in DIR from its checkpoints
  gaitsynth::viz_outputs viz;         // --html, --filmstrip, ... of the 70 s check
};

/// The command line (command_line.hpp). The synthesis draws no random numbers (SDS is
/// deterministic and the training terrains and bodies are fixed), so there is no --seed. The run
/// folder (--out DIR, default out/<example>/<UTC time>/) gets options.json; --resume DIR parses
/// the options recorded there again and continues from the run's checkpoints.
/// Flags only some examples offer; the others do not, so a user who gives one is told (unknown
/// option) instead of having it silently ignored.
struct example_flags {
  bool normal_walk = false;   ///< its bumpy and body training variants and its stage 1
  bool disturbances = false;  ///< --disturbance-training (the 7-link styles)
};

inline cli parse(int argc, char** argv, const char* what, example_flags flags = {}) {
  const std::string name = std::filesystem::path(argv[0]).filename().string();
  cli c;
  CLI::App app{what, name};
  app.option_defaults()->always_capture_default();
  std::string out, resume, horizons;
  app.add_option("--out", out, "run folder (default out/" + name + "/<UTC time>/)");
  app.add_option("--resume", resume,
                 "continue the run in this folder with the options it recorded (only --threads "
                 "may be given with it)");
  example_cli::add_threads(app, c.threads);
  app.add_option("--evaluations-per-episode", c.evaluations_per_episode,
                 "SDS budget per bootstrapping episode (-1: the example's)")
      ->check(example_cli::integer_in(-1, 100000000));
  app.add_option("--check-seconds", c.check_seconds, "length of the final test rollout, s")
      ->check(example_cli::in_range(0.01, 10000.0));
  app.add_option("--max-horizon", c.max_horizon,
                 "last bootstrapping episode, s (episodes every 0.2 s from 0.2 s; -1: the "
                 "example's, usually 2 s)")
      ->check(example_cli::in_range(-1.0, 60.0));
  app.add_option("--horizons", horizons, "explicit episode horizons, s (e.g. 2,3,4)");
  app.add_option("--initial-controller", c.initial_controller,
                 "start the search from a saved controller (JSON)")
      ->check(CLI::ExistingFile);
  if (flags.disturbances)
    app.add_flag("--disturbance-training", c.disturbance_training,
                 "also evaluate each candidate on slopes, low friction, pushes and torso masses "
                 "(sharon_scenarios::training_disturbances; never the test's)");
  if (flags.normal_walk) {
    app.add_option("--bumpy-training", c.bumpy_training,
                   "also evaluate each candidate on N bumpy terrains (-1: the example's)")
        ->check(example_cli::integer_in(-1, 64));
    app.add_option("--body-training", c.body_training,
                   "also evaluate each candidate on N randomized bodies (-1: the example's)")
        ->check(example_cli::integer_in(-1, 64));
    app.add_flag("--stage1-only", c.stage1_only, "only the paper's flat-ground stage");
  }
  app.add_flag("--align-style", c.align_style,
               "compare shapes only: the target follows the COM along x (for long episodes)");
  app.add_option("--min-progress-speed", c.min_progress_speed,
                 "stop a rollout of the cost, charged as a fall, when its COM advances less than "
                 "this speed times 2 s in a 2 s window (0: off; with --align-style it keeps "
                 "walking in place from being cheap)")
      ->check(example_cli::in_range(0.0, 10.0));
  app.add_option("--keyframes", c.keyframes, "target motion (default: the data/sharon2005 file)")
      ->check(CLI::ExistingFile);
  app.add_flag("--single-start", c.single_start,
               "evaluate each candidate from the first keyframe only (the paper's cost); "
               "default: also from 3 perturbed copies (velocity x0.9, x1.1, 1 cm higher)");
  app.add_option("--noisy-starts", c.noisy_starts,
                 "also evaluate each candidate from N starts whose joint velocities are perturbed "
                 "by N(0, 0.05 rad/s) (seeded; the claim tests draw other seeds)")
      ->check(example_cli::integer_in(0, 64));
  example_cli::add_viewer_flags(app, c.viz, "the check rollout (the filmstrip its first 3 s)");
  example_cli::parse(app, argc, argv);
  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  if (!resume.empty()) {
    example_cli::reparse_recorded(app, argv[0], resume, {"threads"});
    c.resume = true;
    out = resume;
  }
  if (!horizons.empty()) {
    std::stringstream ss(horizons);
    std::string item;
    while (std::getline(ss, item, ',')) {
      std::size_t used = 0;
      double h = 0.0;
      try {
        h = std::stod(item, &used);
      } catch (...) {
        used = 0;
      }
      if (used != item.size() || !(h > 0.0 && h <= 600.0))
        throw std::invalid_argument(
            "--horizons: each horizon must be a number in (0, 600] s, "
            "got '" +
            item + "'");
      c.horizons.push_back(h);
    }
    if (c.horizons.empty()) throw std::invalid_argument("--horizons needs at least one value");
  }
  if (c.max_horizon != -1.0 && c.max_horizon < 0.2)
    throw std::invalid_argument("--max-horizon must be -1 or in [0.2, 60] s, got " +
                                std::to_string(c.max_horizon));
  c.threads = example_cli::resolve_threads(c.threads);
  c.out_dir = example_cli::run_folder(name, out);
  if (!c.resume)
    example_cli::write_options(command, example_cli::effective_options(app), c.out_dir);
  return c;
}

/// Checkpoints of a synthesis in the run folder, every 20 SDS probes, resumed with --resume.
inline void checkpoint_into(gaitsynth::run_options& run, const cli& c, const std::string& stem) {
  run.checkpoint_file = c.out_dir / (stem + ".checkpoint");
  run.checkpoint_every = 20;
  run.resume = c.resume;
}

/// The nearest-neighbor controller of the 7-link human: 12 nodes (6 free), input = torso pitch and
/// the six joint angles, 370 N m servos, torso servo on the stance hip. The gains are ours (the
/// paper refers to Sharon's thesis for them).
inline gaitsynth::nearest_neighbor_options human7_options() {
  gaitsynth::nearest_neighbor_options o;
  o.num_nodes = 12;
  o.default_kp = 600.0;
  o.default_kd = 60.0;
  o.torso_kp = 1000.0;
  o.torso_kd = 100.0;
  o.torque_limit = 370.0;
  return o;
}

/// The 16-link human: the same leg servos; only hips, knees and ankles are free (section VI.A) and
/// form the input with the pelvis pitch; the upper body follows the nodes' stored targets with
/// softer servos (its joints' torque limits are lower, models/sharon2005.hpp).
template <class Model>
gaitsynth::nearest_neighbor_options human16_options(const Model& m) {
  gaitsynth::nearest_neighbor_options o = human7_options();
  o.free_dofs = {"lhip", "lknee", "lankle", "rhip", "rknee", "rankle"};
  o.input = {"root_pitch", "lhip", "lknee", "lankle", "rhip", "rknee", "rankle"};
  o.kp.clear();
  for (const auto& d : m.dofs) {
    const std::string& n = d.name;
    const bool leg = n.find("hip") != std::string::npos || n.find("knee") != std::string::npos ||
                     n.find("ankle") != std::string::npos;
    const bool trunk = n == "back" || n == "chest";
    o.kp.push_back(leg                                    ? 600.0
                   : trunk                                ? 600.0
                   : n.find("wrist") != std::string::npos ? 20.0
                                                          : 100.0);
  }
  o.kd.clear();
  for (double k : o.kp) o.kd.push_back(0.1 * k);
  return o;
}

/// Bootstrapped SDS as in section V.C: episodes of 0.2, 0.4, ..., 2 s.
inline gaitsynth::nn_synthesis_options synthesis_defaults() {
  gaitsynth::nn_synthesis_options so;
  so.horizons = gaitsynth::default_episode_horizons();
  so.evaluations_per_episode = 400;
  so.initial_step = 0.1;
  so.min_step = 0.0125;
  return so;
}

inline std::string data_file(const std::string& name) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + name;
}

/// The target motion's file: --keyframes FILE, or data/sharon2005/<default_file>.
inline std::string keyframes_path(const cli& c, const std::string& default_file) {
  return c.keyframes.empty() ? data_file(default_file) : c.keyframes;
}

/// The mass-distance options of the cost (--align-style).
inline gaitsynth::mass_distance_options style_options(const cli& c) {
  gaitsynth::mass_distance_options o;
  o.align_horizontal = c.align_style;
  return o;
}

/// The controller the search starts from: the one built along the target motion with options o
/// (c0), or the saved controller of --initial-controller (which must fit the same model and node
/// layout).
inline gaitsynth::nearest_neighbor_controller<gaitsynth::planar_root> initial_controller(
    const gaitsynth::planar_model& m,
    const gaitsynth::keyframe_motion<gaitsynth::planar_root>& target,
    const gaitsynth::nearest_neighbor_options& o, const cli& c) {
  using controller = gaitsynth::nearest_neighbor_controller<gaitsynth::planar_root>;
  controller c0(m, target, o);
  if (c.initial_controller.empty()) return c0;
  controller loaded = gaitsynth::load_nearest_neighbor(m, c.initial_controller);
  if (loaded.num_parameters() != c0.num_parameters())
    throw std::invalid_argument("--initial-controller " + c.initial_controller + " has " +
                                std::to_string(loaded.num_parameters()) +
                                " parameters, this example's controller " +
                                std::to_string(c0.num_parameters()));
  return loaded;
}

/// The cost's start states: the problem's initial state, plus (unless --single-start) perturbed
/// copies of it (section VII's remedy; see perturbed_starts).
template <class Problem>
void set_starts(Problem& prob, const cli& c) {
  if (c.single_start)
    prob.starts.clear();
  else
    prob.starts = gaitsynth::perturbed_starts(prob.character, prob.options.initial_state);
  // Robustness to the claim tests' kind of perturbation, from other seeds (training != test).
  if (c.noisy_starts > 0) {
    if (prob.starts.empty()) prob.starts.push_back(prob.options.initial_state);
    for (const Eigen::VectorXd& dv : gaitsynth::joint_velocity_perturbations(
             prob.character, c.noisy_starts, 0.05, /*seed=*/4242)) {
      gaitsynth::sim_state s = prob.options.initial_state;
      s.v += dv;
      prob.starts.push_back(std::move(s));
    }
  }
}

/// The problem every example optimizes: controller c0 on model m with torque actuators and
/// semi-implicit Euler on `ground`, the mass-distance cost to `target` (eqs. 2-3; --align-style),
/// from the target's first keyframe and, unless --single-start, perturbed copies of it.
template <class Terrain = gaitsynth::flat_terrain>
auto make_problem(const gaitsynth::planar_model& m,
                  const gaitsynth::keyframe_motion<gaitsynth::planar_root>& target,
                  const gaitsynth::nearest_neighbor_controller<gaitsynth::planar_root>& c0,
                  const cli& c, const Terrain& ground = Terrain()) {
  using namespace gaitsynth;
  rollout_options ro;
  ro.initial_state = target.initial_state();
  if (c.min_progress_speed > 0.0)
    ro.stall = {.window = 2.0, .min_progress = 2.0 * c.min_progress_speed};
  rollout_problem prob{
      m,      torque_actuator{},     c0, mass_distance<planar_root>(m, target, style_options(c)),
      ground, semi_implicit_euler{}, ro};
  set_starts(prob, c);
  return prob;
}

/// `prob` with, if --disturbance-training, the training disturbances as variants (one rollout
/// each: the keyframes' first state placed on its ground, its friction, pushes and torso mass),
/// passed to run(problem); run(prob) otherwise. The variants keep references to their models,
/// which live here until run returns.
template <class Problem, class Run>
int with_disturbance_training(const Problem& prob,
                              const gaitsynth::keyframe_motion<gaitsynth::planar_root>& target,
                              const cli& c, Run&& run) {
  using namespace gaitsynth;
  if (!c.disturbance_training) return run(prob);
  using variant = nn_problem<planar_root, torque_actuator, mass_distance<planar_root>,
                             slope_terrain, semi_implicit_euler>;
  const auto training = sharon_scenarios::training_disturbances();
  std::vector<planar_model> bodies;
  bodies.reserve(training.size());
  std::vector<variant> variants;
  for (const auto& d : training) {
    bodies.push_back(sharon2005_human7(d.body()));
    // Pushes up to the last episode (the rollout checks every listed push at every step).
    const double last = c.horizons.empty()
                            ? std::max(c.max_horizon, 60.0)
                            : *std::max_element(c.horizons.begin(), c.horizons.end());
    rollout_options o = d.apply(prob.options, last);
    o.initial_state = sharon_scenarios::start_state_for(bodies.back(), target, d.ground());
    variants.push_back(variant{bodies.back(), torque_actuator{}, prob.controller,
                               mass_distance<planar_root>(bodies.back(), target, style_options(c)),
                               d.ground(), semi_implicit_euler{}, o});
  }
  return run(make_problem_with_variants(prob, std::move(variants)));
}

/// The viewer flags (--html, --filmstrip, ...; command_line.hpp) for the check rollout; the
/// filmstrip is a strobe picture of the first 3 s (frames every 0.1 s, as in Figures 5b-8).
template <class Model>
void write_views(const Model& m, const gaitsynth::trajectory& traj, const cli& c,
                 const std::string& title) {
  if (!c.viz.any()) return;
  gaitsynth::viz_outputs v = c.viz;
  v.html_options.title = title;
  v.filmstrip.t_begin = 0.0;
  v.filmstrip.t_end = std::min(3.0, traj.frames.back().t);
  v.filmstrip.interval = 0.1;
  v.filmstrip.title = title;
  gaitsynth::write_viz_outputs(m, traj, v, &std::cerr);
}

/// Rollouts behind one cost evaluation (start states, and those of the variants if any).
template <class Problem>
std::size_t rollouts_per_evaluation(const Problem& prob) {
  std::size_t n = prob.starts.empty() ? 1 : prob.starts.size();
  if constexpr (requires { prob.variants; }) {
    // The main problem of a problem with variants may have variants itself.
    n = rollouts_per_evaluation(prob.main());
    for (const auto& v : prob.variants) n += rollouts_per_evaluation(v);
  }
  return n;
}

/// Totals of stages run before the reported one (the summary counts them in).
struct earlier_stages {
  long long evaluations = 0, rollouts = 0;
  double wall_seconds = 0.0;
};

/// Runs the synthesis, the check rollout, writes the outputs and prints the summary line.
/// Returns the process exit code (0 also when the controller falls: that is a result, reported).
template <class Problem>
int synthesize_and_report(const std::string& name, const Problem& prob,
                          gaitsynth::nn_synthesis_options so, const cli& c,
                          nlohmann::ordered_json extra = nlohmann::ordered_json::object(),
                          const earlier_stages& before = {}) {
  using namespace gaitsynth;
  so.threads = c.threads;
  if (c.evaluations_per_episode >= 0) so.evaluations_per_episode = c.evaluations_per_episode;
  if (!c.horizons.empty()) {
    so.horizons = c.horizons;
  } else if (c.max_horizon > 0) {
    so.horizons.clear();
    for (int k = 1; k <= static_cast<int>(std::floor(c.max_horizon * 5.0 + 1e-9)); ++k)
      so.horizons.push_back(k / 5.0);
  }
  so.run.progress = &std::cerr;
  so.run.progress_interval = 2.0;
  std::filesystem::create_directories(c.out_dir);
  so.run.log_file = c.out_dir / (name + ".convergence.csv");
  checkpoint_into(so.run, c, name);
  const std::size_t n_params = prob.controller.num_parameters();
  const std::size_t n_starts = rollouts_per_evaluation(prob);
  std::cerr << name << ": optimizing " << n_params << " parameters of a "
            << prob.controller.num_nodes() << "-node controller ("
            << prob.controller.num_free_nodes() << " free) with SDS on " << so.threads
            << " thread(s), " << n_starts << " rollout(s) per evaluation\n";
  const nn_synthesis_result r = synthesize_nearest_neighbor(prob, so);
  std::cerr << name << ": " << r.evaluations << " evaluations in " << r.wall_seconds
            << " s; checking the controller over " << c.check_seconds << " s\n";

  trajectory traj;
  const walk_check w = check_walk(prob, r.x, c.check_seconds, &traj, 40, sharon2005_walk_criteria);
  const auto ctrl = prob.controller_with(r.x);

  nlohmann::ordered_json info;
  info["example"] = name;
  info["evaluations"] = r.evaluations;
  info["wall_seconds"] = r.wall_seconds;
  info["threads"] = so.threads;
  info["rollouts_per_evaluation"] = n_starts;
  info["rollouts"] = r.evaluations * static_cast<long long>(n_starts);
  if (before.evaluations > 0) {
    info["earlier_stages_evaluations"] = before.evaluations;
    info["earlier_stages_rollouts"] = before.rollouts;
    info["earlier_stages_wall_seconds"] = before.wall_seconds;
  }
  info["episodes"] = r.horizons;
  nlohmann::ordered_json ev = nlohmann::ordered_json::array();
  for (const auto& s : r.episodes.stages) ev.push_back(s.evaluations);
  info["evaluations_per_episode"] = ev;
  info["cost"] = r.value;
  info["check_seconds"] = c.check_seconds;
  info["seconds_walked"] = w.seconds;
  info["fell"] = w.fell;
  info["stalled"] = w.stalled;
  info["walked"] = w.walked;
  info["distance"] = w.distance;
  info["average_speed"] = w.average_speed;
  for (auto it = extra.begin(); it != extra.end(); ++it) info[it.key()] = it.value();

  const auto ctrl_path = c.out_dir / (name + ".controller.json");
  const auto csv_path = c.out_dir / (name + ".csv");
  save_nearest_neighbor(ctrl_path, prob.character, ctrl, info);
  save_trajectory_csv(traj, csv_path.string());
  write_views(prob.character, traj, c, name);

  nlohmann::ordered_json summary;
  summary["example"] = name;
  summary["evaluations"] = before.evaluations + r.evaluations;
  summary["rollouts"] = before.rollouts + r.evaluations * static_cast<long long>(n_starts);
  summary["wall_seconds"] = std::round((before.wall_seconds + r.wall_seconds) * 100) / 100;
  summary["cost"] = r.value;
  summary["seconds_walked"] = w.seconds;
  summary["fell"] = w.fell;
  summary["stalled"] = w.stalled;
  summary["walked"] = w.walked;
  summary["average_speed"] = std::round(w.average_speed * 1000) / 1000;
  summary["controller"] = ctrl_path.string();
  summary["trajectory_csv"] = csv_path.string();
  summary["convergence_csv"] = so.run.log_file.string();
  std::cerr << name << ": " << verdict(w) << " (" << w.seconds << " s), " << w.distance << " m at "
            << w.average_speed << " m/s\n"
            << name << ": controller  " << ctrl_path.string() << "\n"
            << name << ": trajectory  " << csv_path.string() << "\n"
            << name << ": convergence " << so.run.log_file.string() << "\n";
  example_cli::report_summary(summary, c.out_dir);
  return 0;
}

}  // namespace sharon_example
