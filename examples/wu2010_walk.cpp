// Wu & Popovic 2010, Sec. 8: the offline optimization of the cyclical forward-walk controller
// (planned_walk, Sec. 7; Sec. 8.3's forward walk: t_h = 0.55 s, r = 0.65 m) on the Table 3 biped.
// CMA-ES (Sec. 8.3): lambda = 32, parameters normalized to [0, 1] by Table 1's bounds
// (synthesis/wu2010_search_space.hpp), initial mean 0.5 in every normalized coordinate (the middle
// of every bound; --init FILE starts from a saved controller instead), sigma 0.3, rejection
// sampling at the bounds, stop when the mean moves less than 1e-3 (max-norm, normalized) in one
// iteration or after 4000 iterations. Cost per candidate: one rollout of 4 locomotion cycles
// (8 half-cycles, 4.4 s) with the helper force on (h_max the last parameter, [-200, 1000] N),
// under eq. 6 + eq. 7 (objectives/wu2010/wu2010_objective.hpp) plus a fall guard (below). A new
// random terrain every CMA iteration, the same for all 32 samples of it (Sec. 8.3: a height field
// on a 1 m grid with node heights U[0, 0.2] m, or "terrain with vertical drops created with
// boxes", heights U[0, 0.2] m, which the forward walk is also optimized on): iteration i (counted
// from 0) walks on random_height_field({}, seed * 1000003 + i) or, --terrain mixed (the default)
// on odd iterations or --terrain boxes on all, random_boxes({}, seed * 1000003 + i); --resume
// regenerates it (runs that did not record --terrain used height fields only); --flat optimizes
// on flat ground instead.
//
//   wu2010_walk [--iterations N] [--threads N] [--seed K] [--out DIR] [--init FILE]
//               [--horizon S] [--flat] [--fall-penalty W] [--check-seconds S]
//               [--controller-rate HZ] [--sigma S] [--cost-timestep S]
//               [--stance-target planned_landing|touchdown|first_contact]
//               [--pin-by frame_geometry|link] [--half-cycle fixed|touchdown]
//               [--no-helper]
//               [--divergence fall|infinite] [--robust-starts K] [--start-sigma S]
//               [--leg-collisions on|off] [--task f|b|l|r|s] [--h-max-cap N]
//               [--implicit-damping on|off]
//   wu2010_walk --resume DIR [--threads N] [--helper-weight W]
//   wu2010_walk --replay FILE [--check-seconds S] [--out DIR]
//               [--body normal|inverted_knees|frozen_left_knee] [--push-force N]
//               [--terrain-blind] [--helper-weight W]
//
// --helper-weight (eq. 7's w_h, default Sec. 8.3's 5e-3 per N per timestep): Sec. 8.2's
// continuation, "restart the optimization with a larger value for w_h after the optimization
// approximately converges to an infeasible solution" (h_max > 0): either a new run from that
// run's best or mean with --init, or that run itself continued, --resume DIR --helper-weight W,
// which keeps CMA's state (mean, step size, covariance) and records the change in options.json
// ("continuations": the iteration, the command, the new value; later resumes keep it).
//
// --h-max-cap N (ours; default Sec. 8.3's upper bound, 1000 N): a continuation on the bound
// instead of the weight. h_max's upper bound becomes N, and an --init controller whose h_max is
// above it starts at N; stages with a falling cap (e.g. 10, 5, 2, 0 N, each from the previous
// stage's mean) take the help away step by step, where a larger w_h (the paper's continuation)
// let CMA drop it at once and lose the helped walk (run f6, docs/reproductions/wu2010.md).
//
// --terrain-blind (Sec. 4, issue 12's claim 3): plan without sampling the terrain (the swing
// path over the stance foot's ground plane, planner_setup::terrain_awareness = false; recorded
// in the saved controller, which --replay follows unless given). The
// check reports each field's swing clearance (analysis/swing_clearance.hpp: the median of the
// swings' peak heights of the lowest sole point over the terrain), so a controller replayed with
// and without it shows what the sampling changes.
//
// --body (Sec. 9, Fig. 4): the character, Table 3's biped or one of its variants (models/
// wu2010.hpp): both knees inverted, or the left knee frozen straight. With --replay it runs the
// unaltered controller on the changed body, as the paper does.
//
// Fall guard (ours; the paper's cost has no fall term): a fall ends the rollout early (the
// rollout's terrain-aware fall test, COM below half its initial height above the terrain under
// it), which would lower every sum of eq. 6, so each timestep of eq. 6 (--cost-timestep) of the
// horizon left unsimulated costs --fall-penalty (default 100, in eq. 6's units; no timestep of a
// walk costs that much: the helper penalty at h_max = 1000 N is 5 per timestep).
//
// Eq. 6's timestep (--cost-timestep, default 1/64 s, the paper's: objectives/wu2010/common.hpp):
// the per-timestep terms weight each physics step by dt / timestep; 0 counts physics steps (the
// runs f1 and f2 of data/wu2010/ did, 37.5 times the paper's weight against the COM term; a
// --resume of a run that did not record this option keeps 0).
//
// Stance target (--stance-target, ours; default the paper's planned_landing): touchdown re-targets
// the stance foot to where it landed once the previous swing's tail is over, first_contact from
// its first ground contact, tail or not (planned_walk_options::stance_target).
//
// Half-cycle timing (--half-cycle, ours; default the paper's fixed t_h): touchdown ends a
// half-cycle t_h or more after it began, once the swing foot touches the ground (at most 0.3 s
// later), so that the new stance foot stands as its half-cycle starts
// (planned_walk_options::timing). A saved controller records it; a replay follows it.
//
// --pin-by (Sec. 6.3's contact test, ours to choose: the paper says "the geometry to which a
// stationary action frame is attached"; default frame_geometry, the frame's own box): link pins
// every stationary frame of a foot that touches anywhere, so a stance foot rolled onto its toes
// does not ask eq. 5 to pull its heel down (scripts/wu2010_qp_residuals.cpp measures what the
// default leaves: docs/reproductions/wu2010.md, "Where eq. 5 falls short"). Recorded in the saved
// controller ("pin_by"), which --init and --replay follow unless given.
//
// Divergence (--divergence, ours): a candidate whose simulation diverges (most often while it
// falls) is scored like a fall at its last sane step (fall, the default: rollout_options::
// score_divergence, the fall guard charging the rest), or costs +infinity (infinite: the
// library's default, which f1, f2 and f3 used and a --resume of a run that did not record the
// option keeps). With +infinity a helper-free stage whose candidates mostly diverge cannot rank
// them.
//
// --leg-collisions (Sec. 9: "benign inter-leg collisions ... are allowed to happen" in the paper's
// PhysX; default on): the thighs, shanks and feet of the two legs collide (wu2010_leg_collisions,
// contact/self_contact.hpp); off lets them pass through each other, as runs f1-f8 did (a --resume
// of a run that did not record the option keeps off; --replay follows the saved controller's
// "leg_collisions", false when it has none).
//
// --implicit-damping (ours; default on): the soft joint limits' dampers taken by backward Euler
// (rollout_options::implicit_joint_damping). The ankle is three Euler angles; its 400 N m (Table
// 3) pushes it past its range's soft limit toward ankle_y = +-pi/2, where the x and z axes align
// and the joint-space inertia has a vanishing mode, so explicit dampers diverge (the walks of
// f9, f13 and f14 that read "diverged" did so there; docs/reproductions/wu2010.md). Off is the
// explicit step of runs f1-f14 (a --resume of a run that did not record the option keeps it;
// --replay follows the saved controller's "implicit_damping", false when it has none).
//
// --task (Table 2's cyclical controllers; Sec. 8.3: r = 0.65 m forward and backward, 0.5 m side
// steps, 0 standing): f, the forward walk (the default); b, the backward walk, started facing -x
// so that it moves along +x, the training terrain's long axis (the planner is orientation
// invariant, appendix A); l and r, the side steps, started facing -y and +y, with the asymmetric
// planner (each half-cycle its own Omega: 74 parameters, 75 with the helper's h_max; Table 1:
// "except for symmetric controllers"); s, the stand, judged by
// not falling (no stall rule; its pushes pass while it stands). The check's push directions are
// world axes, +x the movement (for b, behind the character). Recorded in the saved controller,
// which --replay follows.
//
// --robust-starts K (ours, as wang2009_walk's and wang2012_walk's): K more rollouts per candidate
// on the iteration's terrain from starts whose joint velocities are perturbed by a seeded
// N(0, S^2) (--start-sigma, 0.05 rad/s; synthesis/robust_variants.hpp), the cost the sum. These
// walks are chaotic: a candidate 1e-6 (normalized) from a mean that walks can fall within 1.5 s, so
// one rollout per candidate ranks luck as much as a gait's stability.
//
// --no-helper (ours): optimize without the helper force (no h_max parameter, no penalty), e.g. a
// second stage from a helped run's best (--init FILE drops its h_max) when that run ends with
// h_max > 0. The saved controller records "helper_force": false, which --replay follows.
// wang2009::failure is not used: its per-step test is the COM below a fixed height above a fixed
// ground height, which the 0-0.2 m height fields shift.
//
// Controller rate (--controller-rate, ours): the paper commands at 64 Hz with the torques held
// (Appendix C); here that diverges within 0.1 s (docs/reproductions/wu2010.md, "Controller
// rate"), so the default is a command every physics step (2400 Hz). 600 Hz (a command held over 4
// steps) is stable with the gains of the middle of Table 1's bounds and costs a third as much; a
// candidate whose gains diverge at that rate is a failed rollout like any other.
//
// The check (after the optimization, or of --replay FILE / --init FILE with --iterations 0): the
// controller WITHOUT the helper force (Sec. 8.2: the paper's controller after the optimization;
// h_max is dropped) walks --check-seconds (20 s) on flat ground and on 10 unseen random height
// fields (seeds 9001..9010) and 10 unseen grids of boxes (9101..9110), with the library's stall
// rule (rollout/walk_check.hpp), from 10 perturbed starts on flat ground (joint velocities
// N(0, 0.05^2) rad/s, seed 2010), and on flat
// ground with pushes (Sec. 9: "it can sustain sideways or forward pushes of 350 N with 0.1 s
// durations"): --push-force newtons (350; 0 skips them) for 0.1 s on the upper body's COM every 4 s
// from 4 s on, one trial per direction (forward, backward, left, right), passed when it is still
// walking forward at the end (rollout/push_test.hpp).
//
// Writes DIR/wu2010_walk.controller.json (parameter names and values, h_max, cost, command),
// .mean.json (CMA-ES's mean, clipped to the bounds, in the same format: --replay takes it),
// .convergence.csv, .checkpoint (every 10 iterations), .csv (the flat check rollout), options.json
// and summary.json, and prints a one-line JSON summary on stdout.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/analysis/swing_clearance.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/contact/terrain_choice.hpp"
#include "gaitsynth/contact/terrain_ref.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_names.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/csv.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"
#include "gaitsynth/objectives/wu2010/wu2010_objective.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/rollout/walk_check.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"
#include "gaitsynth/synthesis/wu2010_search_space.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

/// A height field or a grid of boxes (Sec. 8.3 trains the forward walk on both).
using field_or_boxes = terrain_choice<height_field_terrain, steps_terrain>;
using field_ref = terrain_ref<field_or_boxes>;
using walk_controller = planned_walk<field_ref>;

struct cli {
  long long iterations = 4000;  // Sec. 8.3
  unsigned threads = 0;
  unsigned long long seed = 1;
  fs::path out;
  bool resume = false;
  bool keep_means = false;  // --keep-means: STEM.meanN.json at every checkpoint
  bool flat = false;
  std::string init, replay;
  double horizon = 8 * 0.55;  // s: 4 locomotion cycles of 2 t_h (Sec. 8.3)
  double fall_penalty = 100.0;
  double check_seconds = 20.0;
  double controller_rate = 0.0;  // Hz; 0: a command every physics step
  double sigma = 0.3;            // Sec. 8.3, on the [0, 1] scale
  bool controller_rate_given = false;
  std::string stance_target = "planned_landing";  // planned_walk_options::stance_target
  std::string half_cycle = "fixed";               // planned_walk_options::timing
  bool half_cycle_given = false;
  double cost_timestep = wu2010::paper_timestep;  // s; 0: eq. 6 summed per physics step
  bool no_helper = false;
  std::string divergence = "fall";  // rollout_options::score_divergence (ours)
  bool stance_target_given = false;
  std::string pin_by = "frame_geometry";  // lower_level_options::pin_by (Sec. 6.3)
  bool pin_by_given = false;
  std::string body = "normal";  // Sec. 9's variants: inverted_knees, frozen_left_knee
  double push_force = 350.0;    // N, Sec. 9
  bool terrain_blind = false;   // planner_setup::terrain_awareness = false
  bool terrain_blind_given = false;
  std::string leg_collisions = "on";    // Sec. 9: PhysX collides the legs
  std::string implicit_damping = "on";  // rollout_options::implicit_joint_damping (ours)
  bool implicit_damping_given = false;
  std::string task = "f";  // Table 2's cyclical controllers: f, b, l, r, s
  bool task_given = false;
  bool leg_collisions_given = false;
  double helper_weight = 5e-3;                    // eq. 7's w_h (Sec. 8.3)
  double h_max_cap = wu2010_h_max_bounds.second;  // N: h_max's upper bound (ours: continuation)
  std::string terrain = "mixed";                  // Sec. 8.3: height fields and boxes
  int robust_starts = 0;      // ours: more rollouts per candidate from perturbed starts
  double start_sigma = 0.05;  // rad/s, their joint velocities' perturbation
  std::string command, out_arg;
  nlohmann::json options;
  std::vector<std::string> continued;  // options changed by this --resume (record_continuation)
};

cli parse(int argc, char** argv) {
  cli c;
  for (int i = 0; i < argc; ++i) c.command += (i ? " " : "") + std::string(argv[i]);
  CLI::App app{
      "Wu & Popovic 2010, Sec. 8: optimize the cyclical forward-walk controller with "
      "CMA-ES on random height fields, or replay a saved one.",
      "wu2010_walk"};
  app.option_defaults()->always_capture_default();
  std::string out, resume;
  app.add_option("--iterations", c.iterations,
                 "CMA-ES iterations (Sec. 8.3: 4000; 0: no optimization, check the initial "
                 "controller)")
      ->check(example_cli::integer_in(0, 10000000));
  example_cli::add_threads(app, c.threads);
  example_cli::add_seed(app, c.seed);
  example_cli::add_keep_means(app, c.keep_means);
  app.add_option("--out", out, "run folder (default out/wu2010_walk/<UTC time>/)");
  app.add_option("--resume", resume, "continue the run in this folder with its recorded options");
  app.add_option("--init", c.init,
                 "start from this saved controller (JSON) instead of the middle of every bound")
      ->check(CLI::ExistingFile);
  app.add_option("--replay", c.replay, "check this saved controller (JSON) instead")
      ->check(CLI::ExistingFile);
  app.add_option("--horizon", c.horizon, "evaluation length, s (Sec. 8.3: 4 cycles, 4.4 s)")
      ->check(example_cli::in_range(0.01, 1000.0));
  app.add_flag("--flat", c.flat, "optimize on flat ground instead of random height fields");
  app.add_option("--fall-penalty", c.fall_penalty,
                 "cost per timestep of eq. 6 (--cost-timestep) of the horizon left unsimulated "
                 "by a fall (ours)")
      ->check(example_cli::in_range(0.0, 1e12));
  app.add_option("--check-seconds", c.check_seconds, "length of each check rollout, s")
      ->check(example_cli::in_range(0.01, 10000.0));
  app.add_option("--controller-rate", c.controller_rate,
                 "controller commands per second, held between physics steps (0: every step, "
                 "2400 Hz; a saved controller's own rate when replaying; ours, see the file "
                 "comment)")
      ->check(example_cli::in_range(0.0, 2400.0));
  app.add_option("--sigma", c.sigma,
                 "CMA-ES step size on [0, 1] (Sec. 8.3: 0.3; smaller to search near an --init "
                 "controller)")
      ->check(example_cli::in_range(1e-9, 1.0));
  app.add_option("--stance-target", c.stance_target,
                 "the stance foot's stationary target: planned_landing (the paper, Fig. 5), "
                 "touchdown (ours: where it landed, after the previous swing's tail) or "
                 "first_contact (ours: from its first contact, tail or not); a saved "
                 "controller's own when replaying")
      ->check(CLI::IsMember(names_of(stance_foot_target_names)));
  app.add_option("--half-cycle", c.half_cycle,
                 "when a half-cycle ends: fixed (the paper: every t_h) or touchdown (ours: t_h or "
                 "more after it began, once the swing foot touches); a saved controller's own "
                 "when replaying")
      ->check(CLI::IsMember(names_of(half_cycle_end_names)));
  app.add_option("--pin-by", c.pin_by,
                 "Sec. 6.3's contact test for pinning a stationary frame: its own geometry "
                 "(frame_geometry: the heel box for the heel frame) or any of its foot's (link); "
                 "a saved controller's own when replaying or starting from it")
      ->check(CLI::IsMember(names_of(pin_contact_names)));
  app.add_flag("--no-helper", c.no_helper,
               "optimize without Sec. 8.2's helper force (no h_max parameter; ours: a second "
               "stage from a helped run's --init)");
  app.add_option("--divergence", c.divergence,
                 "a diverged candidate: scored as a fall at its last sane step (fall, ours) or "
                 "+infinity (infinite)")
      ->check(CLI::IsMember({"fall", "infinite"}));
  app.add_option("--cost-timestep", c.cost_timestep,
                 "eq. 6's timestep, s: each physics step counts dt / this (the paper's 64 Hz "
                 "step); 0: each physics step counts once")
      ->check(example_cli::in_range(0.0, 1.0));
  app.add_option("--body", c.body,
                 "the character: Table 3's biped (normal) or Sec. 9's variants, both knees "
                 "inverted or the left knee frozen straight")
      ->check(CLI::IsMember({"normal", "inverted_knees", "frozen_left_knee"}));
  app.add_option("--push-force", c.push_force,
                 "the check's pushes, N for 0.1 s every 4 s, each direction its own walk (Sec. 9: "
                 "350; 0: none)")
      ->check(example_cli::in_range(0.0, 1e5));
  app.add_option("--helper-weight", c.helper_weight,
                 "eq. 7's w_h, per N of h_max per timestep (Sec. 8.3: 5e-3; larger for Sec. "
                 "8.2's continuation)")
      ->check(example_cli::in_range(0.0, 1e6));
  app.add_option("--h-max-cap", c.h_max_cap,
                 "h_max's upper bound, N (Sec. 8.3: 1000; lower for a continuation that takes the "
                 "helper away in stages, ours); an --init controller above it starts at it")
      ->check(example_cli::in_range(-199.0, wu2010_h_max_bounds.second));
  app.add_option("--terrain", c.terrain,
                 "the training terrain per iteration: random height fields, random boxes, or both "
                 "(mixed: boxes on odd iterations; Sec. 8.3's forward walk)")
      ->check(CLI::IsMember({"fields", "boxes", "mixed"}));
  app.add_option("--robust-starts", c.robust_starts,
                 "more rollouts per candidate on the same terrain from seeded perturbed starts "
                 "(ours: the cost sums them)")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--start-sigma", c.start_sigma,
                 "the perturbed starts' joint velocity perturbation, rad/s (N(0, sigma^2))")
      ->check(example_cli::in_range(0.0, 100.0));
  app.add_option("--task", c.task,
                 "the cyclical controller (Table 2): f forward, b backward (r = 0.65 m), l, r "
                 "side steps (0.5 m), s stand (r = 0); a saved controller's own when replaying")
      ->check(CLI::IsMember({"f", "b", "l", "r", "s"}));
  app.add_option("--leg-collisions", c.leg_collisions,
                 "the legs collide with each other (on: Sec. 9's PhysX) or pass through (off; a "
                 "saved controller's own when replaying)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--implicit-damping", c.implicit_damping,
                 "the joint-limit dampers taken implicitly (on; ours: an ankle pushed past its "
                 "range toward the Euler angles' gimbal lock otherwise diverges) or explicitly "
                 "(off, as runs f1-f14 did; a saved controller's own when replaying)")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_flag("--terrain-blind", c.terrain_blind,
               "plan without sampling the terrain (the stance foot's ground plane)");
  example_cli::parse(app, argc, argv);
  c.controller_rate_given = app.count("--controller-rate") > 0;
  c.stance_target_given = app.count("--stance-target") > 0;
  c.half_cycle_given = app.count("--half-cycle") > 0;
  c.pin_by_given = app.count("--pin-by") > 0;
  c.terrain_blind_given = app.count("--terrain-blind") > 0;
  c.leg_collisions_given = app.count("--leg-collisions") > 0;
  c.implicit_damping_given = app.count("--implicit-damping") > 0;
  c.task_given = app.count("--task") > 0;
  if (!resume.empty()) {
    // --helper-weight with --resume: Sec. 8.2's continuation on the run's own CMA state.
    c.continued =
        example_cli::reparse_recorded(app, argv[0], resume, {"threads"}, {"helper-weight"});
    // Runs from before --cost-timestep existed summed eq. 6 per physics step.
    const auto recorded = example_cli::recorded_arguments(resume, {});
    if (std::find(recorded.begin(), recorded.end(), "--cost-timestep") == recorded.end())
      c.cost_timestep = 0.0;
    if (std::find(recorded.begin(), recorded.end(), "--divergence") == recorded.end())
      c.divergence = "infinite";
    if (std::find(recorded.begin(), recorded.end(), "--terrain") == recorded.end())
      c.terrain = "fields";  // runs from before --terrain trained on height fields only
    if (std::find(recorded.begin(), recorded.end(), "--leg-collisions") == recorded.end())
      c.leg_collisions = "off";  // runs from before --leg-collisions had none
    if (std::find(recorded.begin(), recorded.end(), "--implicit-damping") == recorded.end())
      c.implicit_damping = "off";  // runs from before --implicit-damping integrated explicitly
    out = resume;
    c.resume = true;
  }
  check_argument(c.replay.empty() || c.init.empty(), "--replay and --init exclude each other");
  check_argument(c.controller_rate == 0.0 || c.controller_rate > 2.0,
                 "--controller-rate must be 0 (every physics step) or above 2 Hz (a command per "
                 "half-cycle at least), got ",
                 c.controller_rate);
  c.threads = example_cli::resolve_threads(c.threads);
  c.out_arg = out;
  c.options = example_cli::effective_options(app);
  return c;
}

/// The fall guard (ours, see the file comment): `weight` per timestep (each physics step counts
/// dt / timestep, 1 with timestep 0) of the requested horizon that a rollout stopped early (a
/// fall) did not simulate; 0 for a rollout that reached it.
class unfinished_steps {
 public:
  explicit unfinished_steps(double timestep = 0.0) : timestep_(timestep) {}
  struct accumulator_type {
    std::int64_t steps = 0;
    double dt = 0.0;
  };
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    ++a.steps;
    a.dt = v.dt;
  }
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    if (out.reason == stop_reason::horizon || !(out.duration > out.time)) return 0.0;
    if (!(a.dt > 0.0)) return out.duration > 0.0 ? 1.0 : 0.0;  // stopped before its first step
    const auto total = static_cast<std::int64_t>(std::llround(out.duration / a.dt));
    return wu2010::timestep_weight(a.dt, timestep_) *
           static_cast<double>(std::max<std::int64_t>(total - a.steps, 0));
  }

 private:
  double timestep_ = 0.0;
};

using cost_objective = weighted_sum<wu2010_objective_type, unfinished_steps>;

/// Wu's training terrain (random_height_field's defaults: x in [-5, 45] m, y in [-5, 5] m), or the
/// same grid at height 0 (flat ground).
height_field_terrain training_field(std::uint64_t seed, bool flat) {
  random_height_field_options o;
  if (flat) o.min_height = o.max_height = 0.0;
  return random_height_field(o, seed);
}

/// Wu's boxes (random_boxes' defaults: 1 m boxes over the same area, heights U[0, 0.2] m).
steps_terrain training_boxes(std::uint64_t seed) {
  return random_boxes({}, seed);
}

/// --terrain's ground for seed `seed` of iteration i: a height field, boxes, or (mixed) boxes on
/// odd iterations; flat ground with --flat.
field_or_boxes training_terrain(std::uint64_t seed, std::int64_t i, const std::string& kind,
                                bool flat) {
  const bool boxes = !flat && (kind == "boxes" || (kind == "mixed" && i % 2 == 1));
  return boxes ? field_or_boxes(training_field(0, true), training_boxes(seed), true)
               : field_or_boxes(training_field(seed, flat), training_boxes(0), false);
}

/// The neutral pose standing on `ground`.
template <terrain T>
sim_state start_on(const floating_model& m, const T& ground, double facing) {
  sim_state s = make_state(m);
  s.q.segment<4>(3) << std::cos(0.5 * facing), 0.0, 0.0,
      std::sin(0.5 * facing);  // yaw (w, x, y, z)
  place_on_terrain(m, ground, s.q);
  return s;
}

/// --task's goal G = (psi_f, psi_m, r) (Sec. 8.3: r = 0.65 m forward and backward, 0 standing).
/// Every task moves along +x, the training terrain's long axis: the backward walk starts facing
/// -x (psi_f = pi), which the planner's orientation invariance (appendix A) allows.
task_goal task_goal_of(const std::string& task) {
  if (task == "b") return {std::numbers::pi, 0.0, 0.65};
  if (task == "l") return {-0.5 * std::numbers::pi, 0.0, 0.5};  // facing -y: +x on its left
  if (task == "r") return {0.5 * std::numbers::pi, 0.0, 0.5};
  if (task == "s") return {0.0, 0.0, 0.0};
  return {0.0, 0.0, 0.65};
}

/// The rollouts' options (2400 Hz, penalty contact): the library's defaults, with the legs
/// colliding when `legs` and the joint-limit dampers implicit when `implicit`.
rollout_options base_options(const floating_model& m, bool legs, bool implicit) {
  rollout_options o;
  if (legs) o.self_contact = wu2010_leg_collisions(m);
  o.implicit_joint_damping = implicit;
  return o;
}

/// The median of `x` (m), null when empty (a walk that fell before a complete swing).
nlohmann::ordered_json median_or_null(std::vector<double> x) {
  if (x.empty()) return nullptr;
  std::sort(x.begin(), x.end());
  const std::size_t h = x.size() / 2;
  return x.size() % 2 ? x[h] : 0.5 * (x[h - 1] + x[h]);
}

/// --body's character.
floating_model character(const std::string& body) {
  wu2010_biped_options o;
  if (body == "inverted_knees") o.knees = wu2010_knees::inverted;
  if (body == "frozen_left_knee") o.frozen_left_knee = true;
  return wu2010_biped(o);
}

int run(const cli& c) {
  const floating_model m = character(c.body);
  const std::string stem = (c.out / "wu2010_walk").string();
  // The training terrain: one field, replaced between CMA iterations, read by the problem's
  // contact and by every controller copy through terrain_ref.
  const std::uint64_t field_base = c.seed * 1000003ull;
  field_or_boxes field = training_terrain(field_base, 0, c.terrain, c.flat);
  const field_ref ground(field);

  // How the controller runs: the command line's options, else (--init, --replay) what the saved
  // controller records (controllers/end_effector/planned_walk_json.hpp): its rate and stance
  // target, and when replaying its helper force.
  const std::string from = c.replay.empty() ? c.init : c.replay;
  double rate = c.controller_rate;  // Hz; 0: every physics step
  planned_walk_options po;          // Sec. 8.3's forward walk (r = 0.65 m, t_h = 0.55 s)
  bool terrain_blind = c.terrain_blind;
  bool legs = c.leg_collisions == "on";
  bool implicit = c.implicit_damping == "on";
  std::string task = c.task;
  po.helper_force = !c.no_helper;
  // The command line checked each name against its table (planned_walk_names.hpp).
  po.stance_target = *value_of(stance_foot_target_names, c.stance_target);
  po.lower.pin_by = *value_of(pin_contact_names, c.pin_by);
  po.timing = *value_of(half_cycle_end_names, c.half_cycle);
  if (!from.empty()) {
    const planned_walk_saved s = load_planned_walk(from);
    const planned_walk_options saved = saved_planned_walk_options(s, from, po);  // validates
    if (!c.controller_rate_given && s.info.contains("controller_rate"))
      rate = s.info["controller_rate"].get<double>();
    if (!c.stance_target_given) po.stance_target = saved.stance_target;
    if (!c.pin_by_given) po.lower.pin_by = saved.lower.pin_by;
    if (!c.half_cycle_given) po.timing = saved.timing;
    if (!c.terrain_blind_given && s.info.contains("terrain_blind") &&
        s.info["terrain_blind"].is_boolean())
      terrain_blind = s.info["terrain_blind"].get<bool>();
    // Replaying: the saved controller's legs (none recorded: from before the option, no
    // collisions).
    if (!c.replay.empty() && !c.leg_collisions_given)
      legs = s.info.contains("leg_collisions") && s.info["leg_collisions"].is_boolean() &&
             s.info["leg_collisions"].get<bool>();
    // Replaying: the saved controller's integration (none recorded: explicit dampers).
    if (!c.replay.empty() && !c.implicit_damping_given)
      implicit = s.info.contains("implicit_damping") && s.info["implicit_damping"].is_boolean() &&
                 s.info["implicit_damping"].get<bool>();
    if (!c.replay.empty()) po.helper_force = saved.helper_force;
    // Replaying: the saved controller's task (none recorded: the forward walk).
    if (!c.replay.empty() && !c.task_given && s.info.contains("task")) {
      const nlohmann::json& t = s.info["task"];
      check_argument(t == "f" || t == "b" || t == "l" || t == "r" || t == "s", from,
                     ": task must be \"f\", \"b\", \"l\", \"r\" or \"s\", got ", t.dump());
      task = t.get<std::string>();
    }
  }
  {  // options.json lists the effective values, those taken from --init or --replay included.
    nlohmann::json options = c.options;
    std::ostringstream hz;
    hz << std::setprecision(17) << rate;
    options["controller-rate"] = hz.str();
    options["stance-target"] = std::string(name_of(stance_foot_target_names, po.stance_target));
    options["pin-by"] = std::string(name_of(pin_contact_names, po.lower.pin_by));
    options["half-cycle"] = std::string(name_of(half_cycle_end_names, po.timing));
    options["terrain-blind"] = terrain_blind;
    options["leg-collisions"] = legs ? "on" : "off";
    options["implicit-damping"] = implicit ? "on" : "off";
    options["task"] = task;
    if (!c.resume) example_cli::write_options(c.command, options, c.out);
  }
  po.goal = task_goal_of(task);
  // The side steps' half-cycles are not mirror images: each has its own Omega (Table 1's caption:
  // "except for symmetric controllers").
  po.symmetry = task == "l" || task == "r" ? planned_walk_symmetry::asymmetric
                                           : planned_walk_symmetry::mirrored_planner;
  // The stand (--task s) is judged by not falling: no stall rule, any speed.
  walk_criteria criteria;
  if (task == "s") criteria = {.stall = {.window = 0.0}, .min_average_speed = -1e9};
  auto word = [&](const walk_check& w) -> std::string {
    return task == "s" && w.walked ? "stood" : verdict(w);
  };
  po.period = rate > 0.0 ? 1.0 / rate : 0.0;
  po.setup.terrain_awareness = !terrain_blind;
  const bool helper = po.helper_force;
  const std::string stance_target(name_of(stance_foot_target_names, po.stance_target));
  const std::string pin_by(name_of(pin_contact_names, po.lower.pin_by));
  const std::string half_cycle(name_of(half_cycle_end_names, po.timing));
  const walk_controller ctrl(m, ground, po);
  const std::vector<std::string> names = ctrl.parameter_names();

  // x0: the middle of every bound (Sec. 8.3: 0.5 normalized), or --init / --replay's controller.
  const parameter_space bounds = wu2010_search_space(ctrl, ctrl.default_parameters());
  std::vector<double> x0;
  for (const parameter_spec& p : bounds.parameters()) x0.push_back(0.5 * (p.lower + p.upper));
  nlohmann::json saved_info = nlohmann::json::object();
  if (!from.empty()) {
    const planned_walk_saved s = load_planned_walk(from);
    x0 = planned_walk_values(s, names, from);
    saved_info = s.info;
  }
  // --h-max-cap: h_max's upper bound lowered, an initial value above it moved down to it.
  if (helper) x0[ctrl.helper_offset()] = std::min(x0[ctrl.helper_offset()], c.h_max_cap);
  auto make_space = [&] {
    try {
      parameter_space s = wu2010_search_space(ctrl, x0);  // throws naming an x0 outside its bounds
      if (!helper || c.h_max_cap >= wu2010_h_max_bounds.second) return s;
      std::vector<parameter_spec> specs = s.parameters();
      specs[ctrl.helper_offset()].upper = c.h_max_cap;
      return parameter_space(std::move(specs));
    } catch (const std::invalid_argument& e) {
      if (from.empty()) throw;
      throw std::invalid_argument(from + ": " + e.what());
    }
  };
  const parameter_space space = make_space();

  wu2010_objective_options cost_options;
  cost_options.timestep = c.cost_timestep;
  cost_options.helper.w_h = c.helper_weight;
  rollout_options opt = base_options(m, legs, implicit);
  opt.initial_state = start_on(m, ground, po.goal.facing);
  opt.score_divergence = c.divergence == "fall";
  const auto obj =
      cost_objective({1.0, c.fall_penalty}, wu2010_objective(ctrl.report_layout(), cost_options),
                     unfinished_steps(c.cost_timestep));
  rollout_problem prob{m, torque_actuator{}, ctrl, obj, ground, semi_implicit_euler{}, opt};
  // --robust-starts: the copies from perturbed starts (none by default: the cost is prob's).
  // Seeded apart from the check's perturbed starts (2010), so the check judges unseen ones.
  auto robust =
      make_problem_with_variants(prob, robust_variants(prob, {.starts = c.robust_starts,
                                                              .start_sigma = c.start_sigma,
                                                              .seed = 1000 + c.seed,
                                                              .horizon = c.horizon}));

  Eigen::VectorXd best = Eigen::Map<const Eigen::VectorXd>(x0.data(), std::ssize(x0));
  double best_cost = std::numeric_limits<double>::quiet_NaN();
  std::int64_t iterations = saved_info.value("iterations", std::int64_t{0});
  std::int64_t evaluations = saved_info.value("evaluations", std::int64_t{0});
  if (c.replay.empty() && c.iterations > 0) {
    cmaes_options co;
    co.sigma0 = c.sigma;  // Sec. 8.3: 0.3
    co.population_size = 32;
    co.seed = c.seed;
    co.stop.max_iterations = c.iterations;
    co.tol_mean_change = 1e-3;
    co.bounds = bound_handling::resample;
    cmaes cma(space, co);
    run_options ro;
    ro.progress = &std::cerr;
    ro.progress_interval = 10.0;
    ro.log_file = stem + ".convergence.csv";
    ro.checkpoint_file = stem + ".checkpoint";
    ro.checkpoint_every = 10;
    ro.resume = c.resume;
    // The terrain of iteration i (from 0): seed * 1000003 + i, the start state placed on it.
    auto use_field = [&](std::int64_t i) {
      field = training_terrain(field_base + static_cast<std::uint64_t>(i), i, c.terrain, c.flat);
      robust.options.initial_state = start_on(m, ground, po.goal.facing);
      for (auto& v : robust.variants) v.options.initial_state = robust.options.initial_state;
    };
    if (c.resume && fs::exists(ro.checkpoint_file)) {
      load_checkpoint(cma, ro.checkpoint_file);  // (minimize loads it again) its iteration count
      use_field(cma.status().iteration);
    }
    if (!c.continued.empty()) {
      std::map<std::string, std::string> changed;
      for (const std::string& n : c.continued) changed[n] = c.options[n].get<std::string>();
      example_cli::record_continuation(c.out, c.command, c.resume ? cma.status().iteration : 0,
                                       changed);
    }
    auto save = [&](const Eigen::VectorXd& x, double cost, const optimizer_status& st,
                    const std::string& suffix = ".controller.json") {
      nlohmann::ordered_json info;
      info["h_max"] = helper ? x[static_cast<Eigen::Index>(ctrl.helper_offset())] : 0.0;
      info["helper_force"] = helper;
      if (std::isfinite(cost)) info["cost"] = cost;
      info["iterations"] = st.iteration;
      info["evaluations"] = st.evaluations;
      info["seed"] = c.seed;
      info["horizon"] = c.horizon;
      info["flat"] = c.flat;
      info["fall_penalty"] = c.fall_penalty;
      info["controller_rate"] = rate;
      info["stance_target"] = stance_target;
      info["pin_by"] = pin_by;
      info["half_cycle_timing"] = half_cycle;
      info["terrain_blind"] = terrain_blind;
      info["leg_collisions"] = legs;
      info["implicit_damping"] = implicit;
      info["task"] = task;
      info["helper_weight"] = c.helper_weight;
      info["terrain"] = c.terrain;
      info["cost_timestep"] = c.cost_timestep;
      info["divergence"] = c.divergence;
      info["command"] = c.command;
      save_planned_walk(stem + suffix, names,
                        std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), info,
                        po.symmetry);
    };
    // The distribution's mean, clipped to the bounds: on a new field every iteration the best
    // single sample is partly luck (an easy field), the mean what the search has settled on.
    auto save_mean = [&](const optimizer_status& st) {
      save(space.clamp_user(cma.mean_user()), std::numeric_limits<double>::quiet_NaN(), st,
           ".mean.json");
      if (c.keep_means)
        save(space.clamp_user(cma.mean_user()), std::numeric_limits<double>::quiet_NaN(), st,
             example_cli::kept_mean_suffix(st.iteration));
    };
    thread_pool_evaluator pool(c.threads);
    problem_contexts ctx(robust, pool.thread_count());
    problem_cost cost(robust, c.horizon, ctx);
    auto per_iteration = [&](const optimizer_status& st) {
      if (st.iteration % 10 == 0 && std::isfinite(cma.best_value()))
        save(cma.best_x(), cma.best_value(), st);
      if (st.iteration % 10 == 0) save_mean(st);
      use_field(st.iteration);  // Sec. 8.3: a new height field for the next iteration
    };
    const optimization_result res = minimize(cma, cost, pool, ro, per_iteration);
    best = res.x;
    best_cost = res.value;
    iterations = res.iterations;
    evaluations = res.evaluations;
    save(best, best_cost, cma.status());
    save_mean(cma.status());
    std::cerr << "wu2010_walk: " << res.iterations << " iterations, " << res.evaluations
              << " evaluations; this call: " << res.elapsed_seconds
              << " s; stop: " << to_string(res.stopped) << "\n";
  } else if (c.replay.empty()) {
    // --iterations 0: the initial controller's cost on iteration 0's field, as the run would
    // score it first (not a saved value from another field).
    problem_contexts ctx(prob, 1);
    best_cost = problem_cost(prob, c.horizon, ctx)(best, 0);
  } else if (saved_info.contains("cost") && saved_info["cost"].is_number()) {
    best_cost = saved_info["cost"].get<double>();
  }

  // The check: the controller without the helper force (h_max dropped), check_seconds on flat
  // ground (recorded) and on 10 unseen random height fields.
  planned_walk_options check_po = po;
  check_po.helper_force = false;
  const walk_controller plain(m, ground, check_po);
  const std::vector<std::string> plain_names = plain.parameter_names();
  Eigen::VectorXd plain_x(static_cast<Eigen::Index>(plain_names.size()));
  for (std::size_t i = 0; i < plain_names.size(); ++i) {
    const auto at = std::find(names.begin(), names.end(), plain_names[i]) - names.begin();
    plain_x[static_cast<Eigen::Index>(i)] = best[at];
  }
  const double h_max = helper ? best[static_cast<Eigen::Index>(ctrl.helper_offset())] : 0.0;
  const auto check_obj = wu2010_objective(plain.report_layout(), cost_options);
  rollout_options check = walk_options(base_options(m, legs, implicit), criteria);
  check.duration = c.check_seconds;
  auto scratch = make_rollout_scratch(m);
  const std::span<const double> px(plain_x.data(), static_cast<std::size_t>(plain_x.size()));
  auto walk_on = [&](const field_or_boxes& terrain, trajectory* record) {
    field = terrain;
    check.initial_state = start_on(m, ground, po.goal.facing);
    check.record = record;
    check.record_every = 40;
    return judge_walk(rollout(m, torque_actuator{}, plain, check_obj, ground, semi_implicit_euler{},
                              px, check, scratch),
                      criteria);
  };
  // For comparison, the same walk on flat ground with the helper force of the optimization.
  field = training_terrain(0, 0, "fields", true);
  check.initial_state = start_on(m, ground, po.goal.facing);
  check.record = nullptr;
  std::optional<walk_check> helped;
  if (helper)
    helped = judge_walk(
        rollout(m, torque_actuator{}, ctrl, obj, ground, semi_implicit_euler{},
                std::span<const double>(best.data(), static_cast<std::size_t>(best.size())), check,
                scratch),
        criteria);
  trajectory tr;
  const walk_check flat = walk_on(training_terrain(0, 0, "fields", true), &tr);
  save_csv(stem + ".csv", tr);
  // 10 perturbed starts on flat ground (joint velocities N(0, 0.05^2) rad/s, seed 2010: starts
  // that --robust-starts never trains on): does the walk survive a small difference at its start?
  int perturbed_walked = 0;
  nlohmann::ordered_json per_start = nlohmann::ordered_json::array();
  for (const Eigen::VectorXd& dv : joint_velocity_perturbations(m, 10, 0.05, 2010)) {
    check.initial_velocity_offset = dv;
    const walk_check w = walk_on(training_terrain(0, 0, "fields", true), nullptr);
    perturbed_walked += w.walked ? 1 : 0;
    per_start.push_back({{"verdict", word(w)}, {"time", w.seconds}, {"distance", w.distance}});
  }
  check.initial_velocity_offset.resize(0);
  // 10 unseen height fields (seeds 9001..9010) and 10 unseen box grids (9101..9110).
  std::vector<double> clearances;  // every field's swings, both feet
  auto walk_unseen = [&](std::uint64_t first_seed, bool boxes, int& walked) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::uint64_t s = first_seed; s < first_seed + 10; ++s) {
      trajectory field_tr;
      const walk_check w =
          walk_on(training_terrain(s, 0, boxes ? "boxes" : "fields", false), &field_tr);
      walked += w.walked ? 1 : 0;
      std::vector<double> peaks;
      for (const char* foot : {"lfoot", "rfoot"})
        for (const foot_swing& sw : swing_clearance(m, field_tr, ground, foot).swings)
          peaks.push_back(sw.peak_clearance);
      if (!boxes) clearances.insert(clearances.end(), peaks.begin(), peaks.end());
      out.push_back({{"seed", s},
                     {"verdict", word(w)},
                     {"time", w.seconds},
                     {"distance", w.distance},
                     {"swings", peaks.size()},
                     {"median_swing_clearance", median_or_null(peaks)}});
    }
    return out;
  };
  int fields_walked = 0, boxes_walked = 0;
  const nlohmann::ordered_json per_field = walk_unseen(9001, false, fields_walked);
  const nlohmann::ordered_json per_box_grid = walk_unseen(9101, true, boxes_walked);
  // Sec. 9's pushes on flat ground, one walk per direction.
  nlohmann::ordered_json pushes = nlohmann::ordered_json::array();
  if (c.push_force > 0.0) {
    field = training_terrain(0, 0, "fields", true);
    rollout_options pushed = check;
    pushed.initial_state = start_on(m, ground, po.goal.facing);
    pushed.record = nullptr;
    // Passed: still moving along +x at the end (the stand: still standing).
    const push_protocol proto{.duration = c.check_seconds,
                              .period = 4.0,
                              .push_duration = 0.1,
                              .min_forward_speed = task == "s" ? -1e9 : 0.1};
    const std::pair<const char*, vec3> directions[] = {{"forward", vec3(1, 0, 0)},
                                                       {"backward", vec3(-1, 0, 0)},
                                                       {"left", vec3(0, 1, 0)},
                                                       {"right", vec3(0, -1, 0)}};
    for (const auto& [name, d] : directions) {
      const push_trial t =
          push_trial_run(m, torque_actuator{}, plain, ground, semi_implicit_euler{}, px, pushed,
                         m.body_index("upper_body"), c.push_force * d, proto);
      pushes.push_back({{"direction", name},
                        {"force", c.push_force},
                        {"passed", t.passed},
                        {"time", t.result.time},
                        {"final_speed", t.final_speed}});
    }
  }
  nlohmann::ordered_json sum;
  sum["cost"] = best_cost;
  sum["task"] = task;
  sum["flat_verdict"] = word(flat);
  sum["flat_time"] = flat.seconds;
  sum["flat_distance"] = flat.distance;
  sum["flat_speed"] = flat.average_speed;
  sum["flat_check_cost"] = flat.cost;
  sum["perturbed_walked"] = perturbed_walked;  // of 10 perturbed starts on flat ground
  sum["perturbed_checks"] = per_start;
  sum["fields_walked"] = fields_walked;
  sum["median_swing_clearance"] = median_or_null(clearances);  // m, over the fields' swings
  sum["terrain_blind"] = terrain_blind;
  sum["leg_collisions"] = legs;
  sum["implicit_damping"] = implicit;
  sum["fields"] = 10;
  sum["field_checks"] = per_field;
  sum["boxes_walked"] = boxes_walked;  // of 10 unseen grids of boxes
  sum["box_checks"] = per_box_grid;
  sum["terrain"] = c.terrain;
  sum["pushes"] = pushes;
  sum["check_seconds"] = c.check_seconds;
  sum["controller_rate"] = rate;
  sum["stance_target"] = stance_target;
  sum["pin_by"] = pin_by;
  sum["half_cycle_timing"] = half_cycle;
  sum["body"] = c.body;
  sum["cost_timestep"] = c.cost_timestep;
  sum["h_max"] = h_max;
  sum["helper_force"] = helper;
  if (helped) {
    sum["helper_flat_verdict"] = word(*helped);  // with the helper force, as optimized
    sum["helper_flat_time"] = helped->seconds;
    sum["helper_flat_distance"] = helped->distance;
  }
  sum["evaluations"] = evaluations;
  sum["iterations"] = iterations;
  example_cli::report_summary(sum, c.out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) try {
  cli c = parse(argc, argv);
  c.out = example_cli::run_folder("wu2010_walk", c.out_arg);
  return run(c);  // writes options.json once --init's or --replay's settings are known
} catch (const std::exception& e) {
  std::cerr << "wu2010_walk: " << e.what() << "\n";
  return 1;
}
