// Wang, Hamner, Delp & Koltun 2012: optimize a muscle-driven 3D walker (16 Hill-type MTUs on the
// sagittal hips, knees and ankles, reflex control with neural delays, Sec. 4) for a target speed
// with CMA-ES (Sec. 5: sigma 0.005 on normalized parameters, 50 samples per iteration) on the task
// terms and the metabolic effort (objectives/wang2012/wang2012_objective.hpp), evaluating 10 s
// rollouts at 2400 Hz on every core it is given. The run writes into its run folder (--out DIR,
// default out/wang2012_walk/<UTC time>/), checkpoints every 10 iterations, and `--resume DIR`
// continues it with the same result.
//
//   wang2012_walk [--speed 1.25] [--iterations N] [--threads N] [--seed K] [--out DIR]
//                 [--init FILE] [--horizon S] [--sigma S] [--population N] [--check-seconds S]
//                 [--robust-starts K] [--start-sigma S] [--weight TERM=W]...
//                 [--robust-pushes K] [--push-force N] [--check-pushes N]
//                 [--push-direction-step D] [--push-period S] [--push-phase fixed|random]
//                 [--effort metabolic|torque|activation]
//                 [--weaken MTU=F]... [--gait walk|run] [--muscle-svg FILE [--muscle MTU]]
//                 [--leg-collisions off|on]
//   wang2012_walk --resume DIR [--threads N]
//   wang2012_walk --replay FILE [--check-seconds S] [--check-pushes N [--check-push-starts K]]
//                 [--leg-collisions off|on] [--out DIR]
//
// --robust-starts K (beyond the paper, as wang2009_walk's) adds K rollouts per candidate from
// starts whose joint velocities are perturbed by a seeded N(0, start_sigma^2), the same for every
// candidate, so the cost stays a deterministic function of the parameters. --robust-pushes K adds
// K rollouts pushed on the torso for 0.4 s every 3 s (synthesis/robust_variants.hpp), the push-
// robust walker of Sec. 6.4, --push-force newtons along each of Table 1's eight directions (the
// diagonals too: Sec. 6.4's "100 N pushes"); each later push of a rollout turns K directions on,
// so K = 3 pushes all eight (--push-direction-step D turns D instead: 0 with K = 8 pushes each
// rollout along its own direction every --push-period seconds, as Table 1's protocol does).
// Those pushes start at 2 s; --push-phase random moves each pushed rollout's pushes by its own
// phase in [0, push period), drawn anew every iteration (seed * 1000003 + iteration, so a resume
// continues alike): a walker cannot learn where in its gait the pushes land. With it the best
// single candidate is partly luck, so the run also saves CMA's mean (.mean.json, every 10
// iterations) as wu2010_walk does on its random terrain.
// --check-pushes N adds Table 1's 40 s push protocol to the check (rollout/push_test.hpp: a 0.4 s
// push to the torso every 4 s, N newtons along each of the eight directions, one walk each; the
// summary's pushes_survived); --check-push-starts K runs it from K perturbed starts per direction
// too (the claim tests' starts, seed 2012) and counts, per direction, the starts that walk (the
// summary's push_directions_from_starts: directions in which ceil(0.8 K) of them do). --effort
// picks J_M: the metabolic energy, or the ablations min_torque (w_M = 5) and min_act (w_M = 60000)
// of Sec. 6.2. --weaken GAS=0.25 scales both GAS units' F_max (the weakened muscles of Sec. 6.2). A
// saved controller records its effort, weights and weakness, and a replay uses them unless told
// otherwise; --init keeps its weakness and colliding legs (the body) unless told, not its effort or
// weights. --gait run starts from Sec. 6.3's running controller instead of the walking one;
// --iterations 0 checks the initial controller without optimizing it.
//
// --leg-collisions on (ours; default off, as the saved walkers were made): the left thigh and
// shin collide with the right shin and the right thigh and shin with the left shin
// (contact/self_contact.hpp's leg_capsule_pairs), so a walker can no longer swing one shin through
// the other, as most of the saved ones do (analysis/leg_overlap.hpp, the summary's leg_overlap).
// A saved controller records it as "leg_collisions"; a replay and --init follow it unless told.
//
// Every form takes the viewer flags (--html FILE, --filmstrip FILE, --csv FILE, ...) for the
// check rollout. Writes DIR/wang2012_walk.controller.json, .convergence.csv, .checkpoint, .csv
// (the check rollout) and prints a one-line JSON summary on stdout.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/analysis/flight_phases.hpp"
#include "gaitsynth/analysis/human_gait_comparison.hpp"
#include "gaitsynth/analysis/leg_overlap.hpp"
#include "gaitsynth/analysis/muscle_recording.hpp"
#include "gaitsynth/analysis/sagittal_gait_features.hpp"
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/io/csv.hpp"
#include "gaitsynth/io/normative_gait.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#include "gaitsynth/synthesis/wang2012_search_space.hpp"
#include "parallel_tasks.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

struct cli {
  double speed = 1.25;  // m/s, nwalk (Sec. 6.1)
  long long iterations = 3000;
  unsigned threads = 0;
  unsigned long long seed = 1;
  fs::path out;
  bool resume = false;
  std::string init, replay;
  std::string gait = "walk";  // the initial controller without --init: walk (Sec. 5) or run (6.3)
  std::map<std::string, double> weights;  // --weight TERM=W (ours: a continuation stage)
  std::string effort;  // metabolic (Sec. 5.1), torque or activation (Sec. 6.2); "": saved/metabolic
  std::map<std::string, double> weaken;  // --weaken MTU=F (Sec. 6.2): F_max x F, both legs
  int robust_pushes = 0;
  double push_force = 100.0;     // N (Sec. 6.4)
  int push_direction_step = -1;  // -1: robust_pushes (robust_variant_options::push_direction_step)
  std::vector<int> push_directions;  // --push-directions (robust_variant_options)
  bool keep_means = false;           // --keep-means: STEM.meanN.json at every checkpoint
  double push_period = 3.0;          // s between the training pushes' starts
  std::string push_phase = "fixed";  // fixed: first push at 2 s; random: redrawn per iteration
  double check_pushes = 0.0;         // N: the check's 40 s push protocol (0: none)
  int check_push_starts = 0;         // and from this many perturbed starts per direction (0: none)
  std::string leg_collisions = "off";  // on: the legs collide (ours; the saved walkers: off)
  bool leg_collisions_given = false;
  double check_seconds = 20.0;
  double horizon = 10.0;  // s, "not falling down for 10 seconds"
  double sigma = 0.005;   // Sec. 5
  int population = 50;    // Sec. 5
  int robust_starts = 0;
  double start_sigma = 0.05;   // rad/s, the claim tests' perturbation
  std::string muscle_svg;      // Figure 5: excitation, activation, force, fiber length
  std::string muscle = "GAS";  // the MTU --muscle-svg draws
  std::string command, out_arg;
  nlohmann::json options;
  viz_outputs viz;
};

cli parse(int argc, char** argv) {
  cli c;
  for (int i = 0; i < argc; ++i) c.command += (i ? " " : "") + std::string(argv[i]);
  CLI::App app{"Wang et al. 2012: optimize a muscle-driven walker, or replay a saved one.",
               "wang2012_walk"};
  app.option_defaults()->always_capture_default();
  std::string out, resume;
  app.add_option("--speed", c.speed, "target COM speed, m/s (nwalk 1.25)")
      ->check(example_cli::in_range(0.01, 10.0));
  app.add_option("--iterations", c.iterations,
                 "CMA-ES iterations (0: no optimization, check the initial controller)")
      ->check(example_cli::integer_in(0, 10000000));
  example_cli::add_threads(app, c.threads);
  example_cli::add_seed(app, c.seed);
  app.add_option("--out", out, "run folder (default out/wang2012_walk/<UTC time>/)");
  app.add_option("--resume", resume, "continue the run in this folder with its recorded options");
  app.add_option("--init", c.init, "start from this saved controller (JSON)")
      ->check(CLI::ExistingFile);
  app.add_option("--gait", c.gait,
                 "initial controller without --init: walk (Geyer & Herr, Sec. 5) or run (Sec. "
                 "6.3: start at 3.05 m/s, GAS and SOL force gains doubled, elbows bent)")
      ->check(CLI::IsMember({"walk", "run"}));
  app.add_option("--replay", c.replay, "replay this saved controller (JSON) instead")
      ->check(CLI::ExistingFile);
  app.add_option("--check-seconds", c.check_seconds, "length of the check rollout, s")
      ->check(example_cli::in_range(0.01, 10000.0));
  app.add_option("--horizon", c.horizon, "evaluation length, s (10)")
      ->check(example_cli::in_range(0.01, 1000.0));
  app.add_option("--sigma", c.sigma, "CMA-ES step size on [0, 1] (Sec. 5: 0.005)")
      ->check(example_cli::in_range(1e-9, 1.0));
  app.add_option("--population", c.population, "CMA-ES samples per iteration (Sec. 5: 50)")
      ->check(example_cli::integer_in(2, 100000));
  std::vector<std::string> weights;
  app.add_option("--weight", weights,
                 "TERM=W: a term's weight (E_user, E_vel, E_fail, E_head, E_posture, effort; "
                 "repeatable)")
      ->check(example_cli::name_equals_number());
  app.add_option("--robust-starts", c.robust_starts, "rollouts per candidate from perturbed starts")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--robust-pushes", c.robust_pushes, "rollouts per candidate with pushes")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--push-force", c.push_force, "force of those pushes, N (Sec. 6.4: 100)")
      ->check(example_cli::in_range(0.0, 100000.0));
  example_cli::add_push_schedule_flags(app, c.push_direction_step, c.push_period, c.push_phase,
                                       c.push_directions);
  example_cli::add_keep_means(app, c.keep_means);
  app.add_option("--check-pushes", c.check_pushes,
                 "also check Table 1's 40 s push protocol (a 0.4 s push to the torso every 4 s) "
                 "with this force, N, along each of its 8 directions (0: not checked)")
      ->check(example_cli::in_range(0.0, 100000.0));
  app.add_option("--check-push-starts", c.check_push_starts,
                 "with --check-pushes: also run the protocol from this many perturbed starts per "
                 "direction (joint velocities + N(0, 0.05 rad/s), seed 2012, the claim tests' "
                 "starts) and count the starts that walk (0: none)")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--effort", c.effort,
                 "J_M: metabolic (Sec. 5.1; default), torque (min_torque) or activation (min_act, "
                 "Sec. 6.2); a replay's default: the saved one")
      ->check(CLI::IsMember({"metabolic", "torque", "activation"}));
  std::vector<std::string> weaken;
  app.add_option("--weaken", weaken,
                 "MTU=F: the MTU's F_max times F in both legs (GAS, SOL, HAM, VAS, ...; Sec. 6.2; "
                 "repeatable; a replay's or --init's default: the saved weakness, which "
                 "--weaken MTU=1 undoes)")
      ->check(example_cli::name_equals_number());
  app.add_option("--start-sigma", c.start_sigma, "joint-velocity perturbation of those, rad/s")
      ->check(example_cli::in_range(0.0, 10.0));
  app.add_option("--muscle-svg", c.muscle_svg,
                 "write a left-leg MTU's (--muscle; Figure 5: GAS) excitation, activation, force "
                 "and fiber length over the gait cycle as SVG");
  app.add_option("--muscle", c.muscle, "the MTU --muscle-svg draws (left leg; Figure 5: GAS)")
      ->check(CLI::IsMember({"GLU", "HFL", "VAS", "TA", "SOL", "HAM", "RF", "GAS"}));
  app.add_option("--leg-collisions", c.leg_collisions,
                 "on: the thighs and shins of the two legs collide (ours; off: they pass through "
                 "each other, as the saved walkers were made; a replay or --init follows the saved "
                 "one)")
      ->check(CLI::IsMember({"off", "on"}));
  example_cli::add_viewer_flags(app, c.viz);
  example_cli::parse(app, argc, argv);
  c.leg_collisions_given = app.count("--leg-collisions") > 0;
  if (!resume.empty()) {
    example_cli::reparse_recorded(app, argv[0], resume, {"threads"});
    out = resume;
    c.resume = true;
  }
  for (const std::string& v : weights) {
    const std::size_t eq = v.find('=');
    check_argument(eq != std::string::npos, "--weight wants TERM=W, got '", v, "'");
    c.weights[v.substr(0, eq)] = std::stod(v.substr(eq + 1));
  }
  for (const std::string& v : weaken) {
    const std::size_t eq = v.find('=');
    check_argument(eq != std::string::npos, "--weaken wants MTU=F, got '", v, "'");
    c.weaken[v.substr(0, eq)] = std::stod(v.substr(eq + 1));
  }
  if (c.check_push_starts > 0 && c.check_pushes == 0.0)
    throw std::invalid_argument("--check-push-starts needs --check-pushes");
  example_cli::check_push_directions(c.push_directions, c.robust_pushes);
  c.threads = example_cli::resolve_threads(c.threads);
  c.out_arg = out;
  c.options = example_cli::effective_options(app);
  return c;
}

/// Sets the weight of term `name` (wang2012::objective_term_names, or "effort").
void set_weight(wang2012::task_weights& w, const std::string& name, double value) {
  check_argument(std::isfinite(value) && value >= 0.0, "--weight ", name,
                 ": must be finite and >= 0, got ", value);
  if (name == "E_user")
    w.user = value;
  else if (name == "E_vel")
    w.vel = value;
  else if (name == "E_fail")
    w.fail = value;
  else if (name == "E_head")
    w.head = value;
  else if (name == "E_posture")
    w.posture = value;
  else if (name == "effort")
    w.effort = value;
  else
    throw std::invalid_argument("--weight: no term '" + name +
                                "' (E_user, E_vel, E_fail, E_head, E_posture, effort)");
}

/// Geyer & Herr's MTUs with F_max scaled per --weaken ("GAS": both legs' units; "lGAS": one).
std::vector<musculotendon::unit> weakened_muscles(const floating_model& m,
                                                  const std::map<std::string, double>& weaken) {
  auto units = musculotendon::geyer_herr_leg_muscles(m);
  for (const auto& [name, f] : weaken) musculotendon::scale_max_isometric_force(units, name, f);
  return units;
}

/// The optimization (unless replaying), its check and summary for one effort term J_M (its type
/// fixes the objective's, so each --effort is its own instantiation).
template <class MetabolicTerm>
int run_with(const cli& c, const floating_model& m, const std::vector<musculotendon::unit>& units,
             const std::vector<double>& x0, double speed, MetabolicTerm j_m, double w_m) {
  const musculotendon_actuator act(units);
  const wang2012_reflex_controller ctrl(m);
  wang2012::objective_options oo{.target_speed = speed};
  oo.effort.metabolic = w_m;
  for (const auto& [t, w] : c.weights) set_weight(oo.weights, t, w);
  const auto obj = wang2012::objective(m, units, std::move(j_m), oo);
  rollout_options opt = wang2009_rollout_options(m);  // 2400 Hz, the Wang 2009 contact
  if (c.leg_collisions == "on") opt.self_contact.pairs = leg_capsule_pairs(m);
  const rollout_problem prob{m, act, ctrl, obj, flat_terrain{}, semi_implicit_euler{}, opt};
  const std::string stem = (c.out / "wang2012_walk").string();
  Eigen::VectorXd best = Eigen::Map<const Eigen::VectorXd>(x0.data(), std::ssize(x0));
  double best_cost = prob.cost(best, c.horizon);
  optimization_result res;
  auto save = [&](const Eigen::VectorXd& x, double cost,
                  const std::string& suffix = ".controller.json") {
    wang2012_saved_controller s;
    s.target_speed = speed;
    s.cost = cost;
    s.parameters.assign(x.data(), x.data() + x.size());
    s.info["command"] = c.command;
    s.info["weights"] = c.weights;
    s.info["effort"] = c.effort;
    if (!c.weaken.empty()) s.info["weaken"] = c.weaken;
    if (c.leg_collisions == "on") s.info["leg_collisions"] = true;
    save_wang2012_controller(stem + suffix, s);
  };
  // CMA-ES on `problem`'s cost at the horizon (the paper's problem, or one with robust variants).
  // before_iteration(i) runs before iteration i + 1 (from 0; after a resume, first with the
  // checkpoint's count): where --push-phase random redraws the pushes.
  auto optimize = [&](const auto& problem, auto&& before_iteration, bool save_mean) {
    save_mean = save_mean || c.keep_means;
    thread_pool_evaluator pool(c.threads);
    problem_contexts ctx(problem, pool.thread_count());
    problem_cost cost(problem, c.horizon, ctx);
    cmaes_options co;
    co.sigma0 = c.sigma;
    co.seed = c.seed;
    co.population_size = c.population;
    co.stop.max_iterations = c.iterations;
    co.stop.no_improvement_iterations = 300;
    cmaes cma(wang2012_search_space(x0), co);
    run_options ro;
    ro.progress = &std::cerr;
    ro.progress_interval = 10.0;
    ro.log_file = stem + ".convergence.csv";
    ro.checkpoint_file = stem + ".checkpoint";
    ro.checkpoint_every = 10;
    ro.resume = c.resume;
    std::int64_t done = 0;
    if (c.resume && fs::exists(ro.checkpoint_file)) {
      load_checkpoint(cma, ro.checkpoint_file);  // (minimize loads it again) its iteration count
      done = cma.status().iteration;
    }
    before_iteration(done);
    // The distribution's mean, clipped to the bounds (its cost is not evaluated: null).
    const parameter_space space = wang2012_search_space(x0);
    auto mean = [&] { return space.clamp_user(cma.mean_user()); };
    auto save_mean_now = [&] {
      save(mean(), std::numeric_limits<double>::quiet_NaN(), ".mean.json");
      if (c.keep_means)
        save(mean(), std::numeric_limits<double>::quiet_NaN(),
             example_cli::kept_mean_suffix(cma.status().iteration));
    };
    auto keep_best = [&](const optimizer_status& st) {
      if (st.iteration % 10 == 0 && std::isfinite(cma.best_value()))
        save(cma.best_x(), cma.best_value());
      if (save_mean && st.iteration % 10 == 0) save_mean_now();
      before_iteration(st.iteration);
    };
    res = minimize(cma, cost, pool, ro, keep_best);
    best = res.x;
    best_cost = res.value;
    save(best, best_cost);
    if (save_mean) save_mean_now();
  };
  if (c.replay.empty() && c.iterations > 0) {
    if (c.robust_starts == 0 && c.robust_pushes == 0) {
      optimize(
          prob, [](std::int64_t) {}, false);
    } else {
      // Seeded apart from the check's starts (2012 below), so the check judges unseen starts.
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
                                      .push_force_magnitude = true,
                                      .push_directions = c.push_directions};
      auto robust = make_problem_with_variants(prob, robust_variants(prob, vo));
      const bool random_phase = c.push_phase == "random";
      auto redraw = [&](std::int64_t i) {
        if (random_phase) redraw_push_phases(robust.variants, prob, vo, push_phase_seed(c.seed, i));
      };
      optimize(robust, redraw, random_phase);
    }
  }
  // Check: the walk for check_seconds, recorded, and from 10 perturbed starts.
  trajectory tr;
  rollout_options check = walk_options(opt);
  check.record = &tr;
  check.record_every = 40;
  check.duration = c.check_seconds;
  auto scratch = make_rollout_scratch(m);
  const std::span<const double> bx(best.data(), static_cast<std::size_t>(best.size()));
  muscle_recording muscles;
  const rollout_result r =
      rollout(m, act, prob.controller_with(best), obj, flat_terrain{}, semi_implicit_euler{}, bx,
              check, scratch, musculotendon_recorder(act, &muscles, check.record_every));
  save_csv(stem + ".csv", tr);
  // Gait cycles of the left leg (after the first 2 s): hip, knee and ankle angles and torques per
  // kg, against the adult data of data/normative_gait/ with their standard scores
  // (analysis/human_gait_comparison.hpp).
  const normative_gait human = load_normative_gait(
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv");
  gait_cycle_options go;
  go.channels = human_comparison_channels("l", m.total_mass());
  go.samples = 100;
  std::vector<gait_reference> references;
  std::vector<double> scored_cycle_starts;
  nlohmann::json scores = nlohmann::json::object(), differences = nlohmann::json::object(),
                 features = nlohmann::json::object();
  if (!tr.frames.empty() && tr.frames.back().t > 4.0) {
    const human_gait_comparison hc = compare_with_human(m, tr, human);
    if (hc.cycles.num_cycles() >= 1) scored_cycle_starts = hc.cycles.cycle_starts;
    for (std::size_t k = 0; k < hc.labels.size(); ++k) {
      const normative_curve& h = human.curve(hc.labels[k]);
      references.push_back({.channel = k,
                            .label = "human, 1.32 m/s (Falisse et al. 2019)",
                            .percent = h.percent,
                            .mean = h.mean,
                            .sd = h.sd});
      if (!hc.scores.empty()) {
        scores[hc.labels[k]] = hc.scores[k];
        differences[hc.labels[k]] = hc.mean_differences[k];
      }
    }
    // Sec. 6.2's comparisons (analysis/sagittal_gait_features.hpp).
    if (hc.cycles.num_cycles() >= 1) {
      const sagittal_gait_features f = sagittal_gait_features_of(hc.cycles);
      features["knee_flexion_mid_stance_min"] = f.knee_flexion_mid_stance_min;
      features["knee_flexion_mid_stance_mean"] = f.knee_flexion_mid_stance_mean;
      features["knee_flexion_swing_max"] = f.knee_flexion_swing_max;
      features["ankle_dorsiflexion_terminal_swing_mean"] = f.ankle_dorsiflexion_terminal_swing_mean;
    }
  }
  nlohmann::json gas = nlohmann::json::object();
  if (!tr.frames.empty() && tr.frames.back().t > 4.0) {
    // Figure 5: the left GAS over the gait cycle (after the first 2 s), and where its activation
    // peaks, how high, and its peak force.
    trajectory steady = tr;
    std::erase_if(steady.frames, [](const trajectory_frame& f) { return f.t < 2.0; });
    gait_plot_options gp;
    gp.cycles.channels = muscle_gait_channels(muscles, "lGAS");
    gp.cycles.samples = 101;
    gp.show_cycles = true;
    gp.title = "Wang et al. 2012, Figure 5: left GAS over the gait cycle";
    const gait_cycle_data g = gait_cycles(m, steady, gp.cycles);
    if (g.num_cycles() >= 1) {
      const auto& a = g.mean[1];
      const auto peak = std::max_element(a.begin(), a.end()) - a.begin();
      gas["peak_activation"] = a[static_cast<std::size_t>(peak)];
      gas["peak_activation_percent"] = g.percent[static_cast<std::size_t>(peak)];
      gas["peak_force"] = *std::max_element(g.mean[2].begin(), g.mean[2].end());
      gas["cycles"] = g.num_cycles();
    }
    if (!c.muscle_svg.empty()) {
      if (c.muscle != "GAS") {
        gp.cycles.channels = muscle_gait_channels(muscles, "l" + c.muscle);
        gp.title = "Wang et al. 2012: left " + c.muscle + " over the gait cycle";
      }
      std::ostringstream os;
      write_gait_plot_svg(c.muscle == "GAS" ? g : gait_cycles(m, steady, gp.cycles), os, gp,
                          m.name);
      viz_detail::save_text(c.muscle_svg, os.str(), "--muscle-svg");
    }
  }
  // Sec. 6.2's effort comparison: the left leg's mean activation per MTU after the first 2 s.
  nlohmann::json activation = nlohmann::json::object();
  if (!muscles.time.empty() && muscles.time.back() > 4.0) {
    const std::vector<double> a = mean_activation(muscles, 2.0);
    for (std::size_t i = 0; i < a.size(); ++i)
      if (muscles.names[i].starts_with("l")) activation[muscles.names[i].substr(1)] = a[i];
  }
  if (c.viz.any()) {
    viz_outputs v = c.viz;
    v.html_options.title = "Wang et al. 2012, muscle-driven walk";
    v.filmstrip.t_end = std::min(3.0, tr.frames.back().t);
    v.filmstrip.interval = 0.1;
    v.filmstrip.title = v.html_options.title;
    v.gait.cycles = go;
    // The cycles the standard scores use (after the first 2 s), not the start's transient.
    if (!scored_cycle_starts.empty()) v.gait.cycles.cycle_starts = scored_cycle_starts;
    v.gait.references = references;
    v.gait.show_cycles = false;
    v.gait.title = "Wang et al. 2012, muscle-driven walk: gait cycles (left leg)";
    write_viz_outputs(m, tr, v, &std::cerr);
  }
  int walking = 0;
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2012)) {
    rollout_options po = walk_options(opt);
    po.initial_velocity_offset = dv;
    po.duration = c.check_seconds;
    walking += walked(rollout(m, act, prob.controller_with(best), obj, flat_terrain{},
                              semi_implicit_euler{}, bx, po, scratch));
  }
  // --check-pushes F: Table 1's 40 s protocol (rollout/push_test.hpp) with F newtons along each
  // of its eight directions, the diagonals too (Sec. 6.4's "100 N pushes"), one walk each; with
  // --check-push-starts N also from N perturbed starts per direction, so that the count holds
  // beyond one rounding. Every (direction, start) walk is its own task on the threads.
  nlohmann::json pushes = nlohmann::json::array();
  int pushes_survived = 0;
  int push_directions_from_starts = 0;  // with at least `required` of the perturbed starts walking
  int push_starts_walked = 0;           // perturbed-start walks, all directions together
  const int required = static_cast<int>(std::ceil(0.8 * c.check_push_starts - 1e-9));  // 8 of 10
  if (c.check_pushes > 0.0) {
    const int torso = m.body_index("torso");
    const std::vector<Eigen::VectorXd> starts =
        joint_velocity_perturbations(m, c.check_push_starts, 0.05, 2012);
    const int per_direction = 1 + c.check_push_starts;  // the own start, then the perturbed ones
    std::vector<push_trial> trials(static_cast<std::size_t>(8 * per_direction));
    example_cli::run_tasks(8 * per_direction, c.threads, [&](int k) {
      const int d = k / per_direction, start = k % per_direction;
      rollout_options po = opt;
      if (start > 0) po.initial_velocity_offset = starts[static_cast<std::size_t>(start - 1)];
      const vec3 f = c.check_pushes * table1_directions()[static_cast<std::size_t>(d)].normalized();
      trials[static_cast<std::size_t>(k)] =
          push_trial_run(m, act, prob.controller_with(best), flat_terrain{}, semi_implicit_euler{},
                         bx, po, torso, f);
    });
    for (int d = 0; d < 8; ++d) {
      const vec3& dir = table1_directions()[static_cast<std::size_t>(d)];
      const push_trial& t = trials[static_cast<std::size_t>(d * per_direction)];
      pushes_survived += t.passed ? 1 : 0;
      nlohmann::json row = {{"direction", {dir.x(), dir.y()}},
                            {"walked", t.passed},
                            {"time", t.result.time},
                            {"final_speed", t.final_speed}};
      if (c.check_push_starts > 0) {
        int walked_starts = 0;
        nlohmann::json times = nlohmann::json::array();
        for (int k = 1; k < per_direction; ++k) {
          const push_trial& tk = trials[static_cast<std::size_t>(d * per_direction + k)];
          walked_starts += tk.passed ? 1 : 0;
          times.push_back(tk.result.time);
        }
        row["perturbed_starts_walked"] = walked_starts;
        row["perturbed_start_times"] = times;
        push_directions_from_starts += walked_starts >= required ? 1 : 0;
        push_starts_walked += walked_starts;
        std::cerr << "pushes " << c.check_pushes << " N (" << dir.x() << "," << dir.y()
                  << "): own start " << (t.passed ? "walks" : "falls") << ", " << walked_starts
                  << " of " << c.check_push_starts << " perturbed starts walk\n";
      }
      pushes.push_back(row);
    }
  }
  const walk_check w = judge_walk(r);
  nlohmann::json sum;
  sum["cost"] = best_cost;
  sum["check_cost"] = r.cost;
  sum["verdict"] = verdict(w);
  sum["time"] = w.seconds;
  sum["distance"] = w.distance;
  sum["speed"] = w.average_speed;
  sum["target_speed"] = speed;
  sum["perturbed_starts_walked"] = walking;
  if (c.check_pushes > 0.0) {
    sum["push_force"] = c.check_pushes;
    sum["pushes_survived"] = pushes_survived;
    if (c.check_push_starts > 0) {
      sum["push_starts"] = c.check_push_starts;
      sum["push_starts_required"] = required;
      sum["push_directions_from_starts"] = push_directions_from_starts;
      sum["push_starts_walked"] = push_starts_walked;  // of 8 x push_starts
    }
    sum["pushes"] = pushes;
  }
  sum["standard_scores"] = scores;
  sum["human_mean_differences"] = differences;
  sum["gas"] = gas;
  sum["gait_features_deg"] = features;
  // Sec. 6.3's runner has a flight phase in every cycle (analysis/flight_phases.hpp): the left
  // leg's cycles after the first 2 s, flights of 0.02 s or more (the check records at 60 Hz).
  const flight_phase_report flight = flight_phases(m, tr, {.t_begin = 2.0});
  // The legs do not collide in the simulation (analysis/leg_overlap.hpp): how far they overlap.
  const std::vector<self_collision_pair> leg_pairs = leg_capsule_pairs(m);
  const leg_overlap_report overlap = leg_overlap(m, tr, leg_pairs, 2.0);
  sum["leg_collisions"] = c.leg_collisions == "on";
  sum["leg_overlap"] = {{"max_depth_m", overlap.max_depth},
                        {"overlapping_fraction", overlap.overlapping_fraction},
                        {"worst_pair", leg_overlap_pair_name(m, leg_pairs, overlap.worst_pair)},
                        {"worst_time", overlap.worst_time}};
  sum["flight"] = {{"cycles", flight.cycles},
                   {"cycles_with_flight", flight.cycles_with_flight},
                   {"every_cycle", flight.every_cycle()},
                   {"mean_flight_s", flight.mean_flight},
                   {"airborne_fraction", flight.airborne_fraction}};
  sum["mean_activation"] = activation;
  sum["evaluations"] = res.evaluations;
  sum["iterations"] = res.iterations;
  example_cli::report_summary(sum, c.out);
  return 0;
}

int run(cli c) {
  const floating_model m = wang2012_humanoid();
  std::vector<double> x0 = c.gait == "run"
                               ? wang2012_reflex_controller::initial_running_parameters(m)
                               : wang2012_reflex_controller::initial_parameters(m);
  double speed = c.speed;
  if (!c.init.empty() || !c.replay.empty()) {
    const wang2012_saved_controller s =
        load_wang2012_controller(c.replay.empty() ? c.init : c.replay);
    x0 = s.parameters;
    // The body it was made for comes along with --init too (a continuation that silently dropped
    // a weakness or the colliding legs would optimize another character); the problem (speed,
    // weights, effort) does not, as each stage states its own.
    if (c.weaken.empty()) c.weaken = s.info.value("weaken", std::map<std::string, double>{});
    if (!c.leg_collisions_given && s.info.value("leg_collisions", false)) c.leg_collisions = "on";
    // options.json lists the effective values, so it shows the body the run optimizes.
    c.options["leg-collisions"] = c.leg_collisions;
    nlohmann::json weaken = nlohmann::json::array();
    for (const auto& [name, factor] : c.weaken) {
      std::ostringstream v;
      v << name << '=' << std::setprecision(17) << factor;
      weaken.push_back(v.str());
    }
    c.options["weaken"] = weaken;
    if (!c.replay.empty()) {
      // A replay is judged by the problem it was optimized for, unless told otherwise.
      speed = s.target_speed;
      if (c.weights.empty()) c.weights = s.info.value("weights", std::map<std::string, double>{});
      if (c.effort.empty()) c.effort = s.info.value("effort", std::string());
    }
  }
  if (c.effort.empty()) c.effort = "metabolic";
  if (!c.resume) example_cli::write_options(c.command, c.options, c.out);
  const auto units = weakened_muscles(m, c.weaken);
  if (c.effort == "torque")  // min_torque, w_M = 5 (Sec. 6.2)
    return run_with(c, m, units, x0, speed, wang2012::sagittal_joint_torque(units), 5.0);
  if (c.effort == "activation")  // min_act, w_M = 60000 (Sec. 6.2)
    return run_with(c, m, units, x0, speed, wang2012::mean_squared_activation{}, 60000.0);
  return run_with(c, m, units, x0, speed, wang2012::metabolic_energy(units), 100.0);
}

}  // namespace

int main(int argc, char** argv) try {
  cli c = parse(argc, argv);
  c.out = example_cli::run_folder("wang2012_walk", c.out_arg);
  return run(c);  // writes options.json once --init's or --replay's body is known
} catch (const std::exception& e) {
  std::cerr << "wang2012_walk: " << e.what() << "\n";
  return 1;
}
