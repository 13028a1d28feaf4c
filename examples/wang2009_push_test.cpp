// Table 1 of Wang, Fleet & Hertzmann 2009: the largest push (force components, N) a walker
// survives from each of 8 directions, with a 0.4 s push to the torso COM every 4 s for 40 s
// (rollout/push_test.hpp). Without arguments it tests the SIMBICON baseline
// (controllers/fsm/simbicon.hpp) and prints its column next to the paper's.
//
//   wang2009_push_test [--resolution N] [--max-force N] [--from-yin] [--paper COLUMN]
//   wang2009_push_test --controller FILE [--paper COLUMN] [--resolution N] [--max-force N]
//                      [--slope DEG] [--mu MU]
//
// --resolution: step of the force components tried, N (default 5, in [0.01, 10000]);
// --max-force: the largest tried, N (default 500, in [0, 10000]). --from-yin tests Yin et al.'s
// walk as published (simbicon_yin2007_walk_parameters) instead of the library's adjusted one.
// --controller tests an optimized Wang 2009 walker saved by wang2009_walk, with the settings of
// its optimization (synthesis/wang2009_simulation.hpp), next to Table 1's column COLUMN (short,
// overweight, tall, short2, stocky, simbicon; default: SIMBICON's), on the slope and friction it
// was optimized for (its file's info; --slope and --mu override them: a walker made for mu = 0.3
// or 12 degrees is pushed where it walks, not on level ground at mu = 10). SIMBICON walks on
// level ground at mu = 10 unless told otherwise. Nothing is random: there is no --seed. --help
// lists every flag with its default.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>

#include "command_line.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

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

/// Prints the largest force per direction for the walker `test(direction)` next to the column.
template <class Test>
void print_table(const std::string& column, double slope_deg, double mu, Test&& test) {
  const std::array<double, 8> paper = paper_column(column);
  std::printf("ground: slope %g deg, mu %g\n", slope_deg, mu);
  std::printf("direction  max force (N)  paper %s (N)\n", column.c_str());
  for (int k = 0; k < 8; ++k) {
    const vec3& d = table1_directions()[static_cast<std::size_t>(k)];
    std::printf("(%2.0f,%2.0f)    %8.0f       %8.0f\n", d.x(), d.y(), test(d),
                paper[static_cast<std::size_t>(k)]);
    std::fflush(stdout);
  }
}

/// Table 1 on the ground the walker walks on: level (flat_terrain, which lets the contact skip
/// the points above it) or the uphill slope along +x.
template <class Test>
void print_table_on(const std::string& column, double slope_deg, double mu, Test&& test) {
  if (slope_deg == 0.0)
    return print_table(column, slope_deg, mu,
                       [&](const vec3& d) { return test(d, flat_terrain{}); });
  const slope_terrain ground(slope_deg * std::numbers::pi / 180.0);
  print_table(column, slope_deg, mu, [&](const vec3& d) { return test(d, ground); });
}

}  // namespace

int main(int argc, char** argv) try {
  push_protocol proto;
  bool from_yin = false;
  std::string controller, column = "simbicon";
  double slope_deg = 0.0, mu = 10.0;  // SIMBICON's ground; a saved walker's comes from its file
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
  example_cli::parse(app, argc, argv);
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
    print_table_on(column, slope_deg, mu, [&](const vec3& d, const auto& ground) {
      return max_push_force(m, mixed_pd_actuator{}, c, ground, semi_implicit_euler{},
                            std::span<const double>(p), opt, torso, d, proto);
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
  print_table_on(column, slope_deg, mu, [&](const vec3& d, const auto& ground) {
    return max_push_force(m, mixed_pd_actuator{}, c, ground, semi_implicit_euler{},
                          std::span<const double>(p), opt, torso, d, proto);
  });
  return 0;
} catch (const std::exception& e) {
  std::cerr << "wang2009_push_test: " << e.what() << "\n";
  return 1;
}
