// How simbicon_walk_parameters() (controllers/fsm/simbicon.hpp) was set: Yin et al. 2007's walk,
// then a seeded random search (a (1+1) search with fixed steps) that maximizes the Table 1 push
// forces of Wang et al. 2009 on flat ground: the sum over the 8 directions of the largest force
// survived (25 N steps up to 300 N, 40 s with a push every 4 s) plus 4 times the smallest.
// Prints every improvement; the last one is what the library uses.
//
//   wang2009_simbicon_tune [--seed K] [--iterations N] [--from-yin]
//
// --seed: the search's std::mt19937_64 seed (default 1, in [0, 4294967295]); --iterations: search
// steps (default 400, in [0, 1000000]); --from-yin starts from Yin et al.'s walk as published
// instead of simbicon_walk_parameters(). --help lists every flag with its default.
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/detail/standard_normal.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"

using namespace gaitsynth;

int main(int argc, char** argv) try {
  unsigned long long seed = 1;
  int iterations = 400;
  bool from_yin = false;
  CLI::App app{
      "How simbicon_walk_parameters() was set: a seeded (1+1) random search from Yin et al. "
      "2007's walk that maximizes the Table 1 push forces of Wang et al. 2009.",
      "wang2009_simbicon_tune"};
  app.option_defaults()->always_capture_default();
  example_cli::add_seed(app, seed, 4294967295LL);  // the range of the first version's std::mt19937
  app.add_option("--iterations", iterations, "search steps")
      ->check(example_cli::integer_in(0, 1000000));
  app.add_flag("--from-yin", from_yin,
               "start from Yin et al.'s walk as published instead of simbicon_walk_parameters()");
  example_cli::parse(app, argc, argv);
  const auto m = wang2009_humanoid();
  const auto [kp, kd] = simbicon_walk_gains(m);
  const simbicon_controller c(m, kp, kd);
  rollout_options opt;
  opt.contact.mu = 10.0;
  opt.fall_height = 0.7;
  opt.initial_state = simbicon_start_state(m);
  push_protocol proto;
  proto.resolution = 25.0;
  proto.max_force = 300.0;
  const int torso = m.body_index("torso");
  auto score = [&](const std::vector<double>& p, std::array<double, 8>& f) {
    double sum = 0.0, least = 1e9;
    for (int k = 0; k < 8; ++k) {
      f[k] = max_push_force(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                            std::span<const double>(p), opt, torso, table1_directions()[k], proto);
      sum += f[k];
      least = std::min(least, f[k]);
    }
    return sum + 4.0 * least;
  };
  std::vector<double> best =
      from_yin ? simbicon_yin2007_walk_parameters() : simbicon_walk_parameters();
  std::array<double, 8> f{};
  double best_score = score(best, f);
  std::printf("start: score %g\n", best_score);
  // Step sizes (rad, s, or per m / per m/s for the feedback gains); s1.duration is unused.
  const std::vector<std::pair<int, double>> steps{
      {0, 0.025},  {2, 0.05},  {3, 0.1},   {4, 0.05},  {5, 0.025},  {6, 0.05}, {7, 0.1},
      {8, 0.05},   {9, 0.025}, {10, 0.05}, {12, 0.25}, {13, 0.05},  {14, 0.1}, {15, 0.05},
      {16, 0.025}, {17, 0.05}, {18, 0.05}, {19, 0.05}, {20, 0.025}, {21, 0.05}};
  // The library's own normal variates: std::normal_distribution's algorithm is the standard
  // library's choice, so a seed would search differently with libc++ (optimizers/random.hpp).
  std::mt19937_64 rng(seed);
  Eigen::VectorXd z(static_cast<Eigen::Index>(steps.size()));
  for (int it = 0; it < iterations; ++it) {
    std::vector<double> p = best;
    detail::fill_standard_normal(rng, z);
    for (std::size_t j = 0; j < steps.size(); ++j)
      p[steps[j].first] += steps[j].second * z[static_cast<Eigen::Index>(j)];
    p[0] = std::max(p[0], 0.15);
    const double s = score(p, f);
    if (s <= best_score) continue;
    best_score = s;
    best = p;
    std::printf("iteration %d: score %g, forces", it, s);
    for (double x : f) std::printf(" %g", x);
    std::printf("\n  parameters");
    for (double x : p) std::printf(" %.4f", x);
    std::printf("\n");
    std::fflush(stdout);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wang2009_simbicon_tune: %s\n", e.what());
  return 1;
}
