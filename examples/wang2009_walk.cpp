// Wang, Fleet & Hertzmann 2009: optimize a 3D walking controller from Table 2's unstable
// initialization with CMA-ES (Sec. 4.3: sigma 0.0025 on normalized parameters, default population,
// stop after 300 iterations without improvement or 3000 iterations) on the objective of eq. 16,
// evaluating 10 s rollouts (2400 Hz, kp 75000, kd 2000, mu 10, joint dampers taken implicitly) on
// every core it is given (--threads, default all). A run writes into its run folder (--out DIR,
// default out/wang2009_walk/<UTC time>/), with options.json recording every option; it
// checkpoints every 10 iterations and `--resume DIR` continues it with the same result.
//
//   wang2009_walk [--shape stocky] [--speed V] [--step-length S] [--iterations N]
//                 [--threads N] [--seed K] [--out DIR] [--init FILE]
//   wang2009_walk --resume DIR [--threads N]
//                 (--init with --shape of another body carries the controller to it, gains
//                 scaled by the weights: controllers/fsm/wang2009_shape_transfer.hpp)
//                 [--check-seconds S] [--horizon S] [--sigma S]
//                 [--robust-starts K] [--start-sigma S] [--robust-pushes K] [--push-force N]
//                 [--push-direction-step D] [--push-period S] [--push-phase fixed|random]
//                 [--without TERM]...   (E_ratio, E_ang, ...: the term's weight set to 0)
//                 [--weight TERM=W]...  (the term's weight of eq. 16 set to W; ours, not the
//                 paper's: a continuation stage may press one term harder)
//                 [--bound PARAM=LO:HI]...  (a parameter's search bounds, e.g.
//                 s1.target.back_y=-0.25:0.25; its start value must lie inside)
//                 [--ratio-within TOL]  (ours: eq. 13's power ratio as a constraint, every
//                 component within TOL of [0.43, 0.04, 0.53] on the unpushed rollout; a
//                 candidate outside ranks below every one inside, by how far outside:
//                 rollout/problem_with_constraint.hpp)
//                 [--step-at-least L]   (ours: the unpushed rollout's mean step length as a
//                 constraint, at least L m; with --ratio-within the violations add up)
//                 [--slope DEG] [--mu MU]   (uphill along +x; ground friction, default 10)
//   wang2009_walk --replay FILE [--check-seconds S] [--out DIR]
//                 (on the file's slope and friction, scored with the weights it was optimized
//                 with; --slope, --mu, --weight and --without override them)
//   wang2009_walk --simbicon [--check-seconds S] [--out DIR]     (the SIMBICON baseline)
//   mpirun -np R wang2009_walk --mpi [any optimization flags]
//                 (the same optimization spread over R processes, on one host or many, with the
//                 same result; --threads is then per process. Built where CMake finds MPI:
//                 optimizers/mpi_evaluator.hpp, docs/scaling.md)
//
// Robust optimization (beyond the paper): --robust-starts K adds K rollouts per candidate from
// starts whose joint velocities are perturbed by a seeded N(0, start_sigma^2), and
// --robust-pushes K adds K rollouts pushed on the torso COM for 0.4 s every 3 s (from 2 s) with
// push-force newtons in Table 1's directions, variant k starting at direction k. The starts and
// pushes are the same for every candidate, so the cost stays a deterministic function of the
// parameters whatever the thread count. --push-direction-step D turns each later push of a variant
// D directions on (1, the default; 0: each variant pushes its own direction every time, as Table
// 1's protocol does; -1: K), --push-period S sets the time between pushes (3 s; the protocol: 4),
// and --push-phase random moves each pushed variant's pushes by its own phase in [0, S), drawn anew
// every iteration from the seed and the iteration (synthesis/robust_variants.hpp), so that no
// candidate is rewarded for where in its gait cycle fixed pushes land; every candidate of an
// iteration meets the same pushes, a resumed run redraws exactly, and the run then also saves
// CMA's mean (.mean.json), since its best single candidate is partly luck. Not with --mpi.
//
// Every form takes the viewer flags (--html FILE, --filmstrip FILE, --csv FILE, ...;
// examples/command_line.hpp) for the check rollout. --help lists every flag with its default.
//
// Writes DIR/wang2009_<shape>.controller.json (parameters with their names), .convergence.csv,
// .checkpoint, .csv (the trajectory of the check rollout) and prints the objective's report on
// stderr and a one-line JSON summary on stdout.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/analysis/ankle_push_off.hpp"
#include "gaitsynth/analysis/arm_swing.hpp"
#include "gaitsynth/analysis/human_gait_comparison.hpp"
#include "gaitsynth/analysis/leg_overlap.hpp"
#include "gaitsynth/analysis/torso_lean.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/fsm/wang2009_shape_transfer.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/io/csv.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"
#include "gaitsynth/synthesis/wang2009_search_space.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#ifdef GAITSYNTH_HAVE_MPI
#include "gaitsynth/optimizers/mpi_evaluator.hpp"
#endif

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

struct cli {
  std::string shape = "stocky";
  bool shape_given = false;  // --shape with --init: carry the controller to that shape
  std::optional<double> speed, step_length;
  long long iterations = 3000;
  unsigned threads = 0;  // every core
  unsigned long long seed = 1;
  fs::path out;  // the run folder
  bool resume = false;
  std::string init, replay;
  bool simbicon = false;
  double check_seconds = 100.0;
  double horizon = 10.0;  // s, Sec. 4.3
  double sigma = 0.0025;  // Sec. 4.3, on parameters normalized to [0, 1]
  int robust_starts = 0, robust_pushes = 0;
  double start_sigma = 0.05;              // rad/s, the claim tests' perturbation
  double push_force = 100.0;              // N
  int push_direction_step = 1;            // -1: robust_pushes (robust_variant_options)
  std::vector<int> push_directions;       // --push-directions (robust_variant_options)
  bool keep_means = false;                // --keep-means: STEM.meanN.json at every checkpoint
  double push_period = 3.0;               // s between a pushed rollout's pushes
  std::string push_phase = "fixed";       // fixed: first push at 2 s; random: redrawn per iteration
  std::vector<std::string> without;       // terms of eq. 16 left out (weight 0): Figs. 3 and 4
  std::map<std::string, double> weights;  // --weight TERM=W: weights of eq. 16 set by hand
  std::map<std::string, std::pair<double, double>> bounds;  // --bound PARAM=LO:HI
  std::optional<double> ratio_within;   // --ratio-within TOL: E_ratio's r as a constraint (ours)
  std::optional<double> step_at_least;  // --step-at-least L: mean step length >= L m (ours)
  double slope_deg = 0.0;               // uphill slope along +x (Sec. 5, "Changing terrain")
  double mu = 10.0;                     // ground friction (Sec. 4.2; 0.8 and 0.3 in Sec. 5)
  bool slope_given = false, mu_given = false;
  bool mpi = false;        // --mpi: evaluate on the processes of MPI_COMM_WORLD
  std::string command;     // the command line, kept in the saved controller
  std::string out_arg;     // --out as given (empty: the default run folder)
  nlohmann::json options;  // every option's effective value, for DIR/options.json
  viz_outputs viz;
};

/// The command line (examples/command_line.hpp). --resume DIR parses the options recorded in
/// DIR/options.json again, so the run goes on exactly as it started.
cli parse(int argc, char** argv) {
  cli c;
  for (int i = 0; i < argc; ++i) c.command += (i ? " " : "") + std::string(argv[i]);
  CLI::App app{
      "Wang, Fleet & Hertzmann 2009: optimize a 3D walking controller (CMA-ES on eq. 16), or "
      "replay a saved one, or run the SIMBICON baseline.",
      "wang2009_walk"};
  app.option_defaults()->always_capture_default();
  std::string out, resume;
  std::optional<double> speed, step_length;
  std::vector<std::string> weights, bounds;
  app.add_option("--shape", c.shape, "body shape (Fig. 8)")
      ->check(CLI::IsMember({"stocky", "short", "tall", "thin", "overweight", "long_arm"}));
  app.add_option("--speed", speed, "target speed of E_user, m/s (none: E_power / v_x)")
      ->check(example_cli::in_range(0.01, 10.0));
  app.add_option("--step-length", step_length, "target step length of E_user, m")
      ->check(example_cli::in_range(0.01, 3.0));
  app.add_option("--iterations", c.iterations,
                 "CMA-ES iterations (Sec. 4.3: 3000; 0: no optimization, check the initial "
                 "controller)")
      ->check(example_cli::integer_in(0, 10000000));
  example_cli::add_threads(app, c.threads);
  example_cli::add_seed(app, c.seed);
  app.add_option("--out", out, "run folder (default out/wang2009_walk/<UTC time>/)");
  app.add_option("--resume", resume,
                 "continue the run in this folder, with the options it recorded (only --threads "
                 "and --mpi may be given with it)");
  app.add_option("--init", c.init, "start from this saved controller (JSON)")
      ->check(CLI::ExistingFile);
  app.add_option("--replay", c.replay, "replay this saved controller (JSON) instead")
      ->check(CLI::ExistingFile);
  app.add_flag("--simbicon", c.simbicon, "run the SIMBICON baseline instead");
  app.add_option("--check-seconds", c.check_seconds, "length of the check rollout, s")
      ->check(example_cli::in_range(0.01, 10000.0));
  app.add_option("--horizon", c.horizon, "evaluation length, s (Sec. 4.3: 10)")
      ->check(example_cli::in_range(0.01, 1000.0));
  app.add_option("--sigma", c.sigma, "CMA-ES step size on [0, 1] (Sec. 4.3: 0.0025)")
      ->check(example_cli::in_range(1e-9, 1.0));
  app.add_option("--robust-starts", c.robust_starts, "rollouts per candidate from perturbed starts")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--start-sigma", c.start_sigma, "joint-velocity perturbation of those, rad/s")
      ->check(example_cli::in_range(0.0, 10.0));
  app.add_option("--robust-pushes", c.robust_pushes, "rollouts per candidate with pushes")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--push-force", c.push_force, "force of those pushes, N")
      ->check(example_cli::in_range(0.0, 10000.0));
  example_cli::add_push_schedule_flags(app, c.push_direction_step, c.push_period, c.push_phase,
                                       c.push_directions);
  example_cli::add_keep_means(app, c.keep_means);
  app.add_option("--without", c.without, "a term of eq. 16 at weight 0 (repeatable)");
  app.add_option("--weight", weights, "TERM=W: a term's weight of eq. 16 (repeatable)")
      ->check(example_cli::name_equals_number());
  app.add_option("--bound", bounds, "PARAM=LO:HI: a parameter's search bounds (repeatable)")
      ->check(example_cli::name_equals_number(true));
  app.add_option("--ratio-within", c.ratio_within,
                 "TOL: rank every candidate whose power ratio (eq. 13, unpushed rollout) has a "
                 "component more than TOL from [0.43, 0.04, 0.53] below every one within (ours)")
      ->check(example_cli::in_range(1e-6, 1.0));
  app.add_option("--step-at-least", c.step_at_least,
                 "L: rank every candidate whose mean step length (E_user's, unpushed rollout) is "
                 "below L m below every one at or above it (ours; with --ratio-within the two "
                 "violations add up)")
      ->check(example_cli::in_range(1e-3, 3.0));
  app.add_option("--slope", c.slope_deg, "uphill slope along +x, degrees")
      ->check(example_cli::in_range(-44.9, 44.9));
  app.add_option("--mu", c.mu, "ground friction (Sec. 4.2: 10)")
      ->check(example_cli::in_range(1e-6, 1e6));
  app.add_flag("--mpi", c.mpi, "evaluate on the processes of an MPI job (under mpirun)");
  example_cli::add_viewer_flags(app, c.viz);
  example_cli::parse(app, argc, argv);
  if (!resume.empty()) {
    // (the thread count and MPI do not change the result: this command's own apply)
    example_cli::reparse_recorded(app, argv[0], resume, {"threads", "mpi"});
    out = resume;
    c.resume = true;
  }
  check_argument(!(c.mpi && c.push_phase == "random"),
                 "--push-phase random redraws the pushes between iterations in this process; "
                 "with --mpi the other processes would keep the old ones: use --push-phase fixed "
                 "or the thread pool");
#ifndef GAITSYNTH_HAVE_MPI
  check_argument(!c.mpi,
                 "--mpi: this build has no MPI (install Open MPI, libopenmpi-dev, and configure "
                 "again)");
#endif
  c.shape_given = app.get_option("--shape")->count() > 0;
  c.slope_given = app.get_option("--slope")->count() > 0;
  c.mu_given = app.get_option("--mu")->count() > 0;
  c.speed = speed;
  c.step_length = step_length;
  for (const std::string& v : weights) {
    const std::size_t eq = v.find('=');
    check_argument(eq != std::string::npos, "--weight wants TERM=W, got '", v, "'");
    c.weights[v.substr(0, eq)] = std::stod(v.substr(eq + 1));
  }
  for (const std::string& v : bounds) {
    const std::size_t eq = v.find('='), colon = v.find(':', eq);
    check_argument(eq != std::string::npos && colon != std::string::npos,
                   "--bound wants PARAM=LO:HI, got '", v, "'");
    c.bounds[v.substr(0, eq)] = {std::stod(v.substr(eq + 1, colon - eq - 1)),
                                 std::stod(v.substr(colon + 1))};
  }
  example_cli::check_push_directions(c.push_directions, c.robust_pushes);
  c.threads = example_cli::resolve_threads(c.threads);
  c.out_arg = out;
  c.options = example_cli::effective_options(app);
  return c;
}

/// Writes the controller with the run's shape and targets.
void save(const fs::path& path, const cli& c, const wang2009_controller& ctrl,
          const Eigen::VectorXd& x, double cost) {
  wang2009_saved_controller s;
  s.shape = c.shape;
  s.target_speed = c.speed;
  s.target_step_length = c.step_length;
  s.cost = cost;
  s.parameters.assign(x.data(), x.data() + x.size());
  s.info["command"] = c.command;
  s.info["without"] = c.without;
  s.info["weights"] = c.weights;
  s.info["bounds"] = c.bounds;
  if (c.ratio_within) s.info["ratio_within"] = *c.ratio_within;
  if (c.step_at_least) s.info["step_at_least"] = *c.step_at_least;
  s.info["slope_deg"] = c.slope_deg;
  s.info["mu"] = c.mu;
  save_wang2009_controller(path.string(), ctrl, s);
}

/// The views of a check rollout (viewer flags), titled.
void write_views(const floating_model& m, const trajectory& tr, const cli& c,
                 const std::string& title) {
  if (!c.viz.any()) return;
  viz_outputs v = c.viz;
  v.html_options.title = title;
  v.filmstrip.t_begin = 0.0;
  v.filmstrip.t_end = std::min(3.0, tr.frames.back().t);
  v.filmstrip.interval = 0.1;
  v.filmstrip.title = title;
  // From the front, one gait cycle (about 0.8 s) of steady walking, side by side.
  v.filmstrip_front.t_end = std::min(4.8, tr.frames.back().t);
  v.filmstrip_front.t_begin = std::max(0.0, v.filmstrip_front.t_end - 0.8);
  v.filmstrip_front.interval = 0.1;
  v.filmstrip_front.title = title + ", from the front";
  // Fig. 6's curves, the left thigh's and foot's world pitch and the left knee, over the cycles
  // from left heel strike to left heel strike; between them the hip and ankle joint angles, which
  // Fig. 6 does not draw, so that all three joints meet the human data.
  using kind = gait_channel::kind;
  const std::vector<gait_channel> joints = human_sagittal_channels("l");
  v.gait.cycles.channels = {
      {.type = kind::segment_pitch, .label = "thigh orientation", .name = "lthigh"},
      joints[0],
      joints[1],
      joints[2],
      {.type = kind::segment_pitch, .label = "foot orientation", .name = "lfoot"}};
  v.gait.cycles.channels[1].label = "hip flexion";
  v.gait.cycles.channels[2].label = "knee angle";
  v.gait.cycles.channels[3].label = "ankle dorsiflexion";
  v.gait.title = title + ": gait cycles (Fig. 6, with the hip and ankle angles)";
  // The human joints over the same cycle, as Fig. 6 overlays motion capture (data/normative_gait/:
  // one adult at 1.32 m/s, mean and s.d. over 11 trials). Only the joints: the data has joint
  // angles, and Fig. 6's thigh and foot curves are segment orientations.
  const std::string human =
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv";
  if (std::ifstream(human).good()) {
    const normative_gait data = load_normative_gait(human);
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const normative_curve& h = data.curve(joints[k].label);
      v.gait.references.push_back({.channel = k + 1,
                                   .label = "human, 1.32 m/s (Falisse et al. 2019)",
                                   .percent = h.percent,
                                   .mean = h.mean,
                                   .sd = h.sd});
    }
  }
  v.gait.show_cycles = false;  // the mean and its band, as Fig. 6 draws them
  write_viz_outputs(m, tr, v, &std::cerr);
}

/// The one-line JSON summary's fields of a check rollout.
nlohmann::json check_summary(const cli& c, const rollout_result& r, const wang2009_breakdown& rep) {
  nlohmann::json sum;
  sum["shape"] = c.shape;
  sum["check_seconds"] = c.check_seconds;
  sum["walked_seconds"] = r.time;
  sum["fell"] = r.reason == stop_reason::fell;
  sum["stalled"] = r.reason == stop_reason::stalled;
  sum["walked"] = walked(r);
  sum["speed"] = rep.average_speed;
  sum["step_length"] = rep.step_length;
  sum["power_ratio"] = rep.power_ratio;
  sum["e_power"] = rep.e_power;
  return sum;
}

/// Ankle push-off of both feet over the check rollout (analysis/ankle_push_off.hpp): the share of
/// stances whose ankle power peaks in late stance, where it peaks, how high.
nlohmann::json push_off_summary(const floating_model& m, const trajectory& tr) {
  nlohmann::json j;
  for (const char* side : {"l", "r"}) {
    const std::string s = side;
    const ankle_push_off_report a = ankle_push_off(m, tr, s + "ankle_y", s + "foot", s + "toes");
    j[s] = {{"stances", a.stances.size()},
            {"late_peak_fraction", a.late_peak_fraction},
            {"mean_peak_fraction", a.mean_peak_fraction},
            {"mean_peak_power", a.mean_peak_power},
            {"mean_curve_peak_fraction", a.mean_curve_peak_fraction},
            {"mean_power_by_tenth", a.mean_power_by_tenth}};
  }
  return j;
}

/// The left hip, knee and ankle angles and moments per kg after the first 2 s against the adult
/// of data/normative_gait/ (analysis/human_gait_comparison.hpp): sum["standard_scores"] and
/// sum["human_mean_differences"] (degrees, N m/kg), each null where the walk has no complete cycle
/// there.
void add_human_comparison(nlohmann::json& sum, const floating_model& m, const trajectory& tr) {
  sum["standard_scores"] = nullptr;
  sum["human_mean_differences"] = nullptr;
  const std::string file =
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv";
  if (tr.frames.empty() || tr.frames.back().t < 4.0 || !std::ifstream(file).good()) return;
  const normative_gait human = load_normative_gait(file);
  const human_gait_comparison hc = compare_with_human(m, tr, human);
  if (hc.scores.empty()) return;
  for (std::size_t k = 0; k < hc.labels.size(); ++k) {
    sum["standard_scores"][hc.labels[k]] = hc.scores[k];
    sum["human_mean_differences"][hc.labels[k]] = hc.mean_differences[k];
  }
}

/// How far one leg passes through the other after the first 2 s (analysis/leg_overlap.hpp: the
/// humanoid's legs do not collide with each other in the simulation).
nlohmann::json leg_overlap_summary(const floating_model& m, const trajectory& tr) {
  const std::vector<self_collision_pair> pairs = leg_capsule_pairs(m);
  const leg_overlap_report o = leg_overlap(m, tr, pairs, 2.0);
  return {{"max_depth_m", o.max_depth},
          {"overlapping_fraction", o.overlapping_fraction},
          {"worst_pair", leg_overlap_pair_name(m, pairs, o.worst_pair)},
          {"worst_time", o.worst_time}};
}

/// The torso's lean (analysis/torso_lean.hpp) after the first 2 s, degrees: its mean world
/// sagittal angle (positive leaning forward) and the largest tilt from the vertical; the pelvis's
/// mean world sagittal angle.
void add_torso_lean(nlohmann::json& sum, const floating_model& m, const trajectory& tr) {
  sum["torso_pitch_deg"] = nullptr;
  if (tr.frames.empty() || tr.frames.back().t < 2.0) return;
  const torso_lean_report t = torso_lean(m, tr, 2.0);
  sum["torso_pitch_deg"] = t.mean_pitch * 180.0 / std::numbers::pi;
  sum["torso_max_tilt_deg"] = t.max_tilt * 180.0 / std::numbers::pi;
  // The pelvis too: the hips' angles are measured from it, so a pelvis tilted back reads as
  // extended hips under an upright torso.
  sum["pelvis_pitch_deg"] = torso_lean(m, tr, 2.0, "pelvis").mean_pitch * 180.0 / std::numbers::pi;
}

/// Fig. 4's arm swing (analysis/arm_swing.hpp) after the first 2 s: opposite-leg correlation
/// near +1 is the human pattern.
nlohmann::json arm_swing_summary(const floating_model& m, const trajectory& tr) {
  if (tr.frames.empty() || tr.frames.back().t < 3.0) return nullptr;
  const arm_swing_report a = arm_swing(m, tr, 2.0);
  return {{"opposite_leg_correlation", a.opposite_leg_correlation},
          {"same_leg_correlation", a.same_leg_correlation},
          {"arm_pitch_amplitude_rad", a.arm_pitch_amplitude}};
}

/// --simbicon: the baseline walk (controllers/fsm/simbicon.hpp) for check_seconds, scored and
/// reported by eq. 16 like an optimized walker.
int run_simbicon(const floating_model& m, const cli& c) {
  const auto [kp, kd] = simbicon_walk_gains(m);
  simbicon_controller ctrl(m, kp, kd);
  const std::vector<double> p = simbicon_walk_parameters();
  wang2009_objective_options oo;
  oo.target_speed = c.speed;
  oo.target_step_length = c.step_length;
  const auto obj = wang2009_objective(m, oo);
  rollout_options opt = wang2009_rollout_options(m);
  opt.implicit_joint_damping = false;  // SIMBICON's walk was set with explicit dampers
  opt.initial_state = simbicon_start_state(m);
  opt = walk_options(opt);  // rollout/walk_check.hpp: stall detection on
  trajectory tr;
  opt.record = &tr;
  opt.record_every = 40;
  opt.duration = c.check_seconds;
  auto scratch = make_rollout_scratch(m);
  rollout_policy_states<mixed_pd_actuator, simbicon_controller, wang2009_objective_type> states;
  semi_implicit_euler integ;
  const rollout_result r = rollout(m, mixed_pd_actuator{}, ctrl, obj, flat_terrain{}, integ,
                                   std::span<const double>(p), opt, scratch, states);
  const wang2009_breakdown rep = wang2009_report(obj, *states.objective, r, opt);
  print_wang2009_report(std::cerr, rep);
  fs::create_directories(c.out);
  save_csv((c.out / ("simbicon_" + c.shape + ".csv")).string(), tr);
  write_views(m, tr, c, "SIMBICON (Yin et al. 2007), " + c.shape);
  nlohmann::json sum = check_summary(c, r, rep);
  sum["controller"] = "simbicon";
  sum["ankle_push_off"] = push_off_summary(m, tr);
  sum["arm_swing"] = arm_swing_summary(m, tr);
  add_torso_lean(sum, m, tr);
  add_human_comparison(sum, m, tr);
  sum["leg_overlap"] = leg_overlap_summary(m, tr);
  example_cli::report_summary(sum, c.out);
  return 0;
}

/// The search space of Sec. 4.3 with the bounds given by --bound. \throws std::invalid_argument
/// naming an unknown parameter, or one whose start value lies outside its new bounds.
parameter_space search_space(const floating_model& m, const wang2009_controller& ctrl,
                             const std::vector<double>& x0,
                             const std::map<std::string, std::pair<double, double>>& bounds) {
  const parameter_space space = wang2009_search_space(m, ctrl, x0);
  if (bounds.empty()) return space;
  std::vector<parameter_spec> specs = space.parameters();
  for (const auto& [name, lohi] : bounds) {
    const auto it = std::find_if(specs.begin(), specs.end(),
                                 [&](const parameter_spec& p) { return p.name == name; });
    check_argument(it != specs.end(), "--bound: no parameter '", name,
                   "' (names as in a saved controller, e.g. s1.target.back_y)");
    it->lower = lohi.first;
    it->upper = lohi.second;
  }
  return parameter_space(std::move(specs));
}

/// Optimizes (unless --replay) and checks the walker on `ground`; prints the summary.
template <class Terrain>
int optimize_and_check(const floating_model& m, const cli& c, const wang2009_controller& ctrl,
                       const std::vector<double>& x0, const wang2009_objective_type& obj,
                       const rollout_options& opt, const Terrain& ground) {
  const rollout_problem prob{m, mixed_pd_actuator{}, ctrl, obj, ground, semi_implicit_euler{}, opt};
  if (!c.out.empty()) fs::create_directories(c.out);  // (empty on MPI ranks other than 0)
  const std::string stem = (c.out / ("wang2009_" + c.shape)).string();

  Eigen::VectorXd best = Eigen::Map<const Eigen::VectorXd>(x0.data(), std::ssize(x0));
  double best_cost = prob.cost(best, c.horizon);
  optimization_result res;
  bool served = false;  // --mpi, ranks other than 0: they evaluated, rank 0 reports
  // CMA-ES on `problem`'s cost at the horizon: the paper's problem or one with robust variants,
  // evaluated by `eval` (a thread pool, or the processes of an MPI job).
  // before_iteration(i) runs before iteration i + 1 (from 0; after a resume, first with the
  // checkpoint's count): where --push-phase random redraws the pushes.
  auto optimize_with = [&](const auto& problem, auto& eval, auto&& before_iteration,
                           bool save_mean) {
    problem_contexts ctx(problem, eval.thread_count());
    problem_cost cost(problem, c.horizon, ctx);
#ifdef GAITSYNTH_HAVE_MPI
    if constexpr (std::is_same_v<std::decay_t<decltype(eval)>, mpi_evaluator>) {
      if (!eval.is_root()) {
        eval.serve(cost);
        served = true;
        return;
      }
    }
#endif
    cmaes_options co;
    co.sigma0 = c.sigma;
    co.seed = c.seed;
    co.stop.max_iterations = c.iterations;
    co.stop.no_improvement_iterations = 300;
    cmaes opt_cma(search_space(m, ctrl, x0, c.bounds), co);
    run_options ro;
    ro.progress = &std::cerr;
    ro.progress_interval = 10.0;
    ro.log_file = stem + ".convergence.csv";
    ro.checkpoint_file = stem + ".checkpoint";
    ro.checkpoint_every = 10;
    ro.resume = c.resume;
    std::int64_t done = 0;
    if (c.resume && fs::exists(ro.checkpoint_file)) {
      load_checkpoint(opt_cma, ro.checkpoint_file);  // (minimize loads it again) its count
      done = opt_cma.status().iteration;
    }
    before_iteration(done);
    // The distribution's mean, clipped to the bounds (its cost is not evaluated: NaN).
    const parameter_space space = search_space(m, ctrl, x0, c.bounds);
    auto save_cma_mean = [&] {
      const Eigen::VectorXd mu = space.clamp_user(opt_cma.mean_user());
      save(stem + ".mean.json", c, ctrl, mu, std::numeric_limits<double>::quiet_NaN());
      if (c.keep_means)
        save(stem + example_cli::kept_mean_suffix(opt_cma.status().iteration), c, ctrl, mu,
             std::numeric_limits<double>::quiet_NaN());
    };
    // The best point so far is saved with every checkpoint, so a stopped run leaves a controller.
    auto keep_best = [&](const optimizer_status& st) {
      if (st.iteration % 10 == 0 && std::isfinite(opt_cma.best_value()))
        save(stem + ".controller.json", c, ctrl, opt_cma.best_x(), opt_cma.best_value());
      if (save_mean && st.iteration % 10 == 0) save_cma_mean();
      before_iteration(st.iteration);
    };
    res = minimize(opt_cma, cost, eval, ro, keep_best);
    best = res.x;
    best_cost = res.value;
    save(stem + ".controller.json", c, ctrl, best, best_cost);
    if (save_mean) save_cma_mean();
  };
  auto optimize = [&](const auto& problem, auto&& before_iteration, bool save_mean) {
    save_mean = save_mean || c.keep_means;
#ifdef GAITSYNTH_HAVE_MPI
    if (c.mpi) {
      mpi_evaluator eval(MPI_COMM_WORLD, {.threads = c.threads});
      optimize_with(problem, eval, before_iteration, save_mean);
      if (eval.is_root()) eval.release();
      return;
    }
#endif
    thread_pool_evaluator pool(c.threads);
    optimize_with(problem, pool, before_iteration, save_mean);
  };
  // The paper's problem, or with --ratio-within the same problem with the power ratio of its
  // (unpushed) rollout as a constraint; either with the robust variants around it.
  auto optimize_stage = [&](const auto& main) {
    if (c.robust_starts == 0 && c.robust_pushes == 0) {
      optimize(
          main, [](std::int64_t) {}, false);
    } else {
      // Training perturbations are seeded apart from the check's (seed 2009 below), so the check
      // judges the walker on starts it was not optimized for.
      const robust_variant_options vo{.starts = c.robust_starts,
                                      .start_sigma = c.start_sigma,
                                      .seed = 1000 + c.seed,
                                      .pushes = c.robust_pushes,
                                      .push_force = c.push_force,
                                      .push_period = c.push_period,
                                      .horizon = c.horizon,
                                      .push_direction_step = c.push_direction_step < 0
                                                                 ? c.robust_pushes
                                                                 : c.push_direction_step,
                                      .push_directions = c.push_directions};
      auto robust = make_problem_with_variants(main, robust_variants(prob, vo));
      const bool random_phase = c.push_phase == "random";
      auto redraw = [&](std::int64_t i) {
        if (random_phase) redraw_push_phases(robust.variants, prob, vo, push_phase_seed(c.seed, i));
      };
      optimize(robust, redraw, random_phase);
    }
  };
  if (c.replay.empty() && c.iterations > 0) {
    if (c.ratio_within || c.step_at_least) {
      // Both constraints read the main (unpushed) rollout; their violations add up (Deb's rules
      // rank infeasible candidates by the total). Ratio alone: 0 + v, the same value as before.
      const wang2009::power_ratio term = obj.template part<wang2009_term::ratio>();
      const std::optional<double> tol = c.ratio_within, min_step = c.step_at_least;
      optimize_stage(make_problem_with_constraint(prob, [term, tol, min_step](const auto& ctx) {
        const auto& acc = *ctx.states.objective;
        double v = 0.0;
        if (tol) v += term.violation(std::get<wang2009_term::ratio>(acc), *tol);
        if (min_step)
          v += std::max(0.0, *min_step - wang2009::user_gait::step_length(
                                             std::get<wang2009_term::user>(acc)));
        return v;
      }));
    } else {
      optimize_stage(prob);
    }
  }
  if (served) return 0;
  // Check: the walk for check_seconds, recorded, with the report of eq. 16's terms over it.
  trajectory tr;
  rollout_options check = walk_options(opt);  // rollout/walk_check.hpp: stall detection on
  check.record = &tr;
  check.record_every = 40;  // 60 frames per second
  check.duration = c.check_seconds;
  auto cc = prob.controller_with(best);
  auto scratch = make_rollout_scratch(m);
  rollout_policy_states<mixed_pd_actuator, wang2009_controller, wang2009_objective_type> states;
  semi_implicit_euler integ;
  const rollout_result r =
      rollout(m, mixed_pd_actuator{}, cc, obj, ground, integ,
              std::span<const double>(best.data(), static_cast<std::size_t>(best.size())), check,
              scratch, states);
  const wang2009_breakdown rep = wang2009_report(obj, *states.objective, r, check);
  print_wang2009_report(std::cerr, rep);
  save_csv(stem + ".csv", tr);
  write_views(m, tr, c, "Wang et al. 2009, " + c.shape);
  nlohmann::json sum = check_summary(c, r, rep);
  sum["cost"] = best_cost;
  sum["ankle_push_off"] = push_off_summary(m, tr);
  sum["arm_swing"] = arm_swing_summary(m, tr);
  add_torso_lean(sum, m, tr);
  add_human_comparison(sum, m, tr);
  sum["leg_overlap"] = leg_overlap_summary(m, tr);
  sum["horizon"] = c.horizon;
  sum["without"] = c.without;
  sum["weights"] = c.weights;
  sum["slope_deg"] = c.slope_deg;
  sum["mu"] = c.mu;
  sum["evaluations"] = res.evaluations;
  sum["iterations"] = res.iterations;
  // The claim tests' robustness check: 10 starts with joint velocities perturbed by a seeded
  // N(0, 0.05 rad/s), each walked for check_seconds.
  int walking = 0;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2009)) {
    rollout_options po = walk_options(opt);
    po.initial_velocity_offset = dv;
    po.duration = c.check_seconds;
    wang2009_controller pc = prob.controller_with(best);
    rollout_policy_states<mixed_pd_actuator, wang2009_controller, wang2009_objective_type> ps;
    const rollout_result pr =
        rollout(m, mixed_pd_actuator{}, pc, obj, ground, integ,
                std::span<const double>(best.data(), static_cast<std::size_t>(best.size())), po,
                scratch, ps);
    walking += walked(pr);
  }
  sum["perturbed_starts_walked"] = walking;
  example_cli::report_summary(sum, c.out);
  return 0;
}

/// Sets the weight of term `name` (E_user, ..., E_ratio) of eq. 16.
void set_weight(wang2009_weights& w, const std::string& name, double value) {
  const auto k = std::find(wang2009_term_names.begin(), wang2009_term_names.end(), name);
  check_argument(
      k != wang2009_term_names.end(), "unknown term '", name,
      "' (E_user, E_vel, E_land, E_fail, E_sym, E_ang, E_head, E_power, E_ratio, E_posture, "
      "E_pelvis)");
  check_argument(std::isfinite(value) && value >= 0.0, "weight of ", name,
                 " must be finite and >= 0, got ", value);
  double* slot[] = {&w.user, &w.vel,  &w.land,  &w.fail,    &w.sym,   &w.ang,
                    &w.head, nullptr, &w.ratio, &w.posture, &w.pelvis};
  const auto i = static_cast<std::size_t>(k - wang2009_term_names.begin());
  if (slot[i])
    *slot[i] = value;
  else
    w.power = value;
}

}  // namespace

int main(int argc, char** argv) try {
  cli c = parse(argc, argv);
#ifdef GAITSYNTH_HAVE_MPI
  std::optional<mpi_environment> mpi;
  if (c.mpi) {
    check_argument(c.replay.empty() && !c.simbicon && c.iterations > 0,
                   "--mpi: only an optimization runs under MPI (not --replay, --simbicon or "
                   "--iterations 0)");
    mpi.emplace(argc, argv);
  }
  const bool writes = !c.mpi || mpi_environment::rank() == 0;  // MPI: rank 0 writes the run
#else
  const bool writes = true;
#endif
  if (writes) {
    c.out = example_cli::run_folder("wang2009_walk", c.out_arg);
    if (!c.resume) example_cli::write_options(c.command, c.options, c.out);
  }
  std::string from_shape;
  if (!c.replay.empty() || !c.init.empty()) {
    // The file names its shape; a controller for it is needed to read the parameter names.
    from_shape = wang2009_saved_shape(c.replay.empty() ? c.init : c.replay);
    if (!c.replay.empty() || !c.shape_given) c.shape = from_shape;
  }
  const floating_model m = wang2009_humanoid(wang2009_preset(c.shape));
  if (c.simbicon) return run_simbicon(m, c);
  wang2009_controller ctrl(m);
  std::vector<double> x0 = wang2009_table2_parameters(m, ctrl);
  if (!c.replay.empty() || !c.init.empty()) {
    const floating_model fm = wang2009_humanoid(wang2009_preset(from_shape));
    const wang2009_controller fc(fm);
    const wang2009_saved_controller from =
        load_wang2009_controller(c.replay.empty() ? c.init : c.replay, fc);
    // --init of another shape: gains scaled by the weights, as Table 2 is (Sec. 4.3).
    x0 = wang2009_transfer_parameters(fm, fc, from.parameters, m, ctrl);
    if (!c.speed) c.speed = from.target_speed;
    if (!c.step_length) c.step_length = from.target_step_length;
    // A replay walks where the walker was optimized unless told otherwise.
    if (!c.replay.empty() && !c.slope_given) c.slope_deg = from.info.value("slope_deg", 0.0);
    if (!c.replay.empty() && !c.mu_given) c.mu = from.info.value("mu", 10.0);
    // ... and is scored with the weights it was optimized with (its saved cost is comparable),
    // unless the command line sets weights of its own.
    if (!c.replay.empty() && c.weights.empty() && c.without.empty()) {
      c.weights = from.info.value("weights", std::map<std::string, double>{});
      c.without = from.info.value("without", std::vector<std::string>{});
    }
  }
  ctrl.bind(x0);
  wang2009_objective_options oo;
  oo.target_speed = c.speed;
  oo.target_step_length = c.step_length;
  for (const std::string& t : c.without) set_weight(oo.weights, t, 0.0);
  for (const auto& [t, w] : c.weights) set_weight(oo.weights, t, w);
  oo.fail_height = wang2009_fail_height(c.shape);  // Sec. 4.1
  rollout_options opt = wang2009_rollout_options(m, oo.fail_height);
  opt.contact.mu = c.mu;
  const auto obj = wang2009_objective(m, oo);
  if (c.slope_deg != 0.0)
    return optimize_and_check(m, c, ctrl, x0, obj, opt,
                              slope_terrain(c.slope_deg * std::numbers::pi / 180.0));
  return optimize_and_check(m, c, ctrl, x0, obj, opt, flat_terrain{});
} catch (const std::exception& e) {
  std::cerr << "wang2009_walk: " << e.what() << "\n";
  return 1;
}
