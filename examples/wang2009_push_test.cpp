// Table 1 of Wang, Fleet & Hertzmann 2009: the largest push (force components, N) a walker
// survives from each of 8 directions, with a 0.4 s push to the torso COM every 4 s for 40 s
// (rollout/push_test.hpp). Without arguments it tests the SIMBICON baseline
// (controllers/fsm/simbicon.hpp) and prints its column next to the paper's.
//
//   wang2009_push_test [--resolution N] [--max-force N] [--from-yin] [--paper COLUMN]
//   wang2009_push_test --controller FILE [--paper COLUMN] [--resolution N] [--max-force N]
//                      [--slope DEG] [--mu MU]
//   either with [--perturbed N [--required K]] [--threads T]
//
// --resolution: step of the force components tried, N (default 5, in [0.01, 10000]);
// --max-force: the largest tried, N (default 500, in [0, 10000]). --from-yin tests Yin et al.'s
// walk as published (simbicon_yin2007_walk_parameters) instead of the library's adjusted one.
// --controller tests an optimized Wang 2009 walker saved by wang2009_walk, with the settings of
// its optimization (synthesis/wang2009_simulation.hpp), next to Table 1's column COLUMN (short,
// overweight, tall, short2, stocky, simbicon; default: SIMBICON's), on the slope and friction it
// was optimized for (its file's info; --slope and --mu override them: a walker made for mu = 0.3
// or 12 degrees is pushed where it walks, not on level ground at mu = 10). SIMBICON walks on
// level ground at mu = 10 unless told otherwise. --perturbed N adds a column that holds beyond
// one rounding: the largest force that K of N perturbed starts (the claim tests' starts: joint
// velocities + N(0, 0.05 rad/s), seed 2009; K default ceil(0.8 N)) survive at every force up to
// it (rollout/push_test.hpp, max_push_force_from_starts), with each start's own largest force.
// The eight directions run on --threads threads (default all); the table does not depend on it.
// Nothing is random: there is no --seed. --help lists every flag with its default.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#include "parallel_tasks.hpp"

using namespace gaitsynth;

namespace {

/// Table 1's columns (N).
std::array<double, 8> paper_column(const std::string& name) {
  if (name == "short") return {75, 75, 100, 50, 60, 40, 100, 75};
  if (name == "overweight") return {1, 1, 25, 50, 75, 40, 20, 1};
  if (name == "tall") return {20, 20, 200, 70, 120, 70, 200, 20};
  if (name == "short2") return {10, 10, 50, 40, 75, 40, 75, 10};
  if (name == "stocky") return {50, 65, 125, 75, 50, 50, 125, 50};
  check_argument(name == "simbicon", "--paper: unknown column '", name,
                 "' (short, overweight, tall, short2, stocky, simbicon)");
  return {225, 150, 250, 100, 120, 100, 275, 125};
}

/// One direction's row: the own start's largest force and, with perturbed starts, their scan.
struct table_row {
  double own = 0.0;
  push_scan perturbed;
};

/// Runs `row(direction)` for Table 1's eight directions on `threads` threads (each direction is
/// deterministic, so the table does not depend on the thread count) and prints the rows next to
/// the paper's column; `required` of `perturbed` starts (0: only the own start).
template <class Row>
void print_table(const std::string& column, double slope_deg, double mu, int perturbed,
                 int required, unsigned threads, Row&& row) {
  const std::array<double, 8> paper = paper_column(column);
  std::printf("ground: slope %g deg, mu %g\n", slope_deg, mu);
  if (perturbed == 0) {
    std::printf("direction  max force (N)  paper %s (N)\n", column.c_str());
  } else {
    std::printf(
        "direction  own start (N)  %d of %d perturbed (N)  paper %s (N)  perturbed "
        "starts' own (N; + still passing)\n",
        required, perturbed, column.c_str());
  }
  std::fflush(stdout);  // the ground line first, before the progress lines on stderr
  std::array<table_row, 8> rows;
  example_cli::run_tasks(8, threads, [&](int k) {
    const auto ks = static_cast<std::size_t>(k);
    rows[ks] = row(table1_directions()[ks]);
    const vec3& d = table1_directions()[ks];
    std::fprintf(stderr, "(%2.0f,%2.0f) done\n", d.x(), d.y());
  });
  for (std::size_t k = 0; k < 8; ++k) {
    const vec3& d = table1_directions()[k];
    if (perturbed == 0) {
      std::printf("(%2.0f,%2.0f)    %8.0f       %8.0f\n", d.x(), d.y(), rows[k].own, paper[k]);
      continue;
    }
    std::printf("(%2.0f,%2.0f)    %8.0f       %14.0f         %8.0f        ", d.x(), d.y(),
                rows[k].own, rows[k].perturbed.force, paper[k]);
    std::vector<std::size_t> order(rows[k].perturbed.per_start.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const push_scan& s = rows[k].perturbed;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return s.per_start[a] > s.per_start[b]; });
    for (std::size_t i : order) std::printf(" %g%s", s.per_start[i], s.censored[i] ? "+" : "");
    std::printf("\n");
  }
}

/// Table 1 on the ground the walker walks on: level (flat_terrain, which lets the contact skip
/// the points above it) or the uphill slope along +x. `test(direction, ground)` gives the row.
template <class Test>
void print_table_on(const std::string& column, double slope_deg, double mu, int perturbed,
                    int required, unsigned threads, Test&& test) {
  if (slope_deg == 0.0)
    return print_table(column, slope_deg, mu, perturbed, required, threads,
                       [&](const vec3& d) { return test(d, flat_terrain{}); });
  const slope_terrain ground(slope_deg * std::numbers::pi / 180.0);
  print_table(column, slope_deg, mu, perturbed, required, threads,
              [&](const vec3& d) { return test(d, ground); });
}

/// The row for `direction`: the own start's scan, then the perturbed starts' (if any).
template <class Controller, class Ground>
table_row scan_row(const floating_model& m, const Controller& c, const Ground& ground,
                   const std::vector<double>& p, const rollout_options& opt, int torso,
                   const vec3& direction, const std::vector<Eigen::VectorXd>& starts, int required,
                   const push_protocol& proto) {
  table_row r;
  r.own = max_push_force(m, mixed_pd_actuator{}, c, ground, semi_implicit_euler{},
                         std::span<const double>(p), opt, torso, direction, proto);
  if (!starts.empty())
    r.perturbed = max_push_force_from_starts(m, mixed_pd_actuator{}, c, ground,
                                             semi_implicit_euler{}, std::span<const double>(p), opt,
                                             torso, direction, starts, required, proto);
  return r;
}

}  // namespace

int main(int argc, char** argv) try {
  push_protocol proto;
  bool from_yin = false;
  std::string controller, column = "simbicon";
  double slope_deg = 0.0, mu = 10.0;  // SIMBICON's ground; a saved walker's comes from its file
  int perturbed = 0, required = 0;
  unsigned threads = 0;
  CLI::App app{
      "Table 1 of Wang, Fleet & Hertzmann 2009: the largest push a walker survives from each of 8 "
      "directions (the SIMBICON baseline, or a saved controller).",
      "wang2009_push_test"};
  app.option_defaults()->always_capture_default();
  app.add_option("--resolution", proto.resolution, "step of the force components tried, N")
      ->check(example_cli::in_range(0.01, 10000.0));
  app.add_option("--max-force", proto.max_force, "largest force component tried, N")
      ->check(example_cli::in_range(0.0, 10000.0));
  app.add_flag("--from-yin", from_yin,
               "test Yin et al.'s walk as published instead of the library's adjusted one");
  app.add_option("--controller", controller, "test this saved Wang 2009 controller (JSON)")
      ->check(CLI::ExistingFile);
  app.add_option("--paper", column, "Table 1's column printed next to it")
      ->check(CLI::IsMember({"short", "overweight", "tall", "short2", "stocky", "simbicon"}));
  app.add_option("--slope", slope_deg,
                 "uphill slope along +x, degrees (default: the controller's own, else 0)")
      ->check(example_cli::in_range(-44.9, 44.9));
  app.add_option("--mu", mu, "ground friction (default: the controller's own, else Sec. 4.2's 10)")
      ->check(example_cli::in_range(1e-6, 1e6));
  app.add_option("--perturbed", perturbed,
                 "also scan from this many perturbed starts (joint velocities + N(0, 0.05 rad/s), "
                 "seed 2009, the claim tests' starts)")
      ->check(example_cli::integer_in(0, 1000));
  app.add_option("--required", required,
                 "with --perturbed: how many of them must pass (default: 8 of 10, i.e. "
                 "ceil(0.8 x perturbed))")
      ->check(example_cli::integer_in(1, 1000))
      ->default_str("ceil(0.8 x perturbed)");
  example_cli::add_threads(app, threads);
  example_cli::parse(app, argc, argv);
  if (app.get_option("--required")->count() == 0)
    required = static_cast<int>(std::ceil(0.8 * perturbed - 1e-9));
  if (perturbed > 0 && required > perturbed)
    throw std::invalid_argument("--required " + std::to_string(required) +
                                " is more than --perturbed " + std::to_string(perturbed));
  if (perturbed == 0 && app.get_option("--required")->count() > 0)
    throw std::invalid_argument("--required needs --perturbed");
  threads = example_cli::resolve_threads(threads);
  const bool slope_given = app.get_option("--slope")->count() > 0;
  const bool mu_given = app.get_option("--mu")->count() > 0;
  if (from_yin && !controller.empty())
    throw std::invalid_argument("--from-yin cannot be given with --controller " + controller +
                                " (it tests the SIMBICON baseline)");
  if (!controller.empty()) {
    const std::string shape = wang2009_saved_shape(controller);
    const floating_model m = wang2009_humanoid(wang2009_preset(shape));
    wang2009_controller c(m);
    const wang2009_saved_controller saved = load_wang2009_controller(controller, c);
    const std::vector<double>& p = saved.parameters;
    c.bind(p);
    if (!slope_given) slope_deg = saved.info.value("slope_deg", 0.0);
    if (!mu_given) mu = saved.info.value("mu", 10.0);
    rollout_options opt = wang2009_rollout_options(m, wang2009_fail_height(shape));
    opt.contact.mu = mu;
    const int torso = m.body_index("torso");
    const std::vector<Eigen::VectorXd> starts =
        joint_velocity_perturbations(m, perturbed, 0.05, 2009);
    print_table_on(column, slope_deg, mu, perturbed, required, threads,
                   [&](const vec3& d, const auto& ground) {
                     return scan_row(m, c, ground, p, opt, torso, d, starts, required, proto);
                   });
    return 0;
  }
  const floating_model m = wang2009_humanoid();
  const auto [kp, kd] = simbicon_walk_gains(m);
  const simbicon_controller c(m, kp, kd);
  const std::vector<double> p =
      from_yin ? simbicon_yin2007_walk_parameters() : simbicon_walk_parameters();
  rollout_options opt;
  opt.contact.mu = mu;    // Wang et al. 2009 Sec. 4.2: 10
  opt.fall_height = 0.7;  // E_fail's height
  opt.initial_state = simbicon_start_state(m);
  const int torso = m.body_index("torso");
  const std::vector<Eigen::VectorXd> starts =
      joint_velocity_perturbations(m, perturbed, 0.05, 2009);
  print_table_on(column, slope_deg, mu, perturbed, required, threads,
                 [&](const vec3& d, const auto& ground) {
                   return scan_row(m, c, ground, p, opt, torso, d, starts, required, proto);
                 });
  return 0;
} catch (const std::exception& e) {
  std::cerr << "wang2009_push_test: " << e.what() << "\n";
  return 1;
}
