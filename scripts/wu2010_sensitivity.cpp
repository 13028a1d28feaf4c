// How sensitive a saved Wu & Popovic 2010 forward walk is to its parameters
// (docs/reproductions/wu2010.md, "The walks are chaotic"): rolls out the controller (without the
// helper force) on flat ground for `seconds`, then COUNT - 1 samples around it, each normalized
// parameter (Table 1's bounds, synthesis/wu2010_search_space.hpp) moved by N(0, SIGMA^2) and
// clipped to [0, 1] as CMA-ES would sample them (seed 7), and prints how long each lasted: the
// quartiles and a histogram by whole seconds. For the first sample that falls within 2.5 s it
// prints when its configuration first differs from the unperturbed walk's by more than 1e-8, 1e-6,
// 1e-4, 1e-2 and 1e-1 (max-norm of q). Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_sensitivity.cpp -o /tmp/wu2010_sensitivity
//   /tmp/wu2010_sensitivity data/wu2010/runs/f5/wu2010_walk.mean.json 1e-6 40 8.8
//
// (one command line each).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/wu2010_search_space.hpp"

using namespace gaitsynth;

namespace {

/// Every step's time and configuration.
struct configurations {
  std::vector<double> t;
  std::vector<Eigen::VectorXd> q;
  template <class Ob>
  void observe(const Ob& ob) {
    t.push_back(ob.t);
    q.push_back(*ob.q_ptr);
  }
};

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 5)
    throw std::invalid_argument("usage: wu2010_sensitivity CONTROLLER.json SIGMA COUNT SECONDS");
  const char* file = argv[1];
  const double sigma = std::atof(argv[2]);
  const int count = std::atoi(argv[3]);
  const double seconds = std::atof(argv[4]);
  if (!(sigma >= 0.0) || count < 2 || !(seconds > 0.0))
    throw std::invalid_argument("SIGMA must be >= 0, COUNT >= 2, SECONDS > 0");
  const floating_model m = wu2010_biped();
  const planned_walk_saved saved = load_planned_walk(file);
  planned_walk_options po = saved_planned_walk_options(saved, file);
  po.helper_force = false;
  const planned_walk<> c(m, flat_terrain{}, po);
  const std::vector<double> x0 = planned_walk_values(saved, c.parameter_names(), file);
  const parameter_space space = wu2010_search_space(c, x0);
  const Eigen::VectorXd u0 =
      space.to_normalized(Eigen::Map<const Eigen::VectorXd>(x0.data(), std::ssize(x0)));

  auto scratch = make_rollout_scratch(m);
  rollout_options o;
  o.duration = seconds;
  o.initial_state = make_state(m);
  place_on_terrain(m, flat_terrain{}, o.initial_state.q);
  auto walk = [&](const Eigen::VectorXd& u, configurations& rec) {
    const Eigen::VectorXd x = space.to_user(u);
    return rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                   semi_implicit_euler{}, std::span<const double>(x.data(), std::size_t(x.size())),
                   o, scratch, rec);
  };
  configurations base;
  const rollout_result r0 = walk(u0, base);
  std::printf("unperturbed: %.2f s, %s\n", r0.time, std::string(to_string(r0.reason)).c_str());

  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::vector<double> times;
  bool traced = false;
  for (int k = 1; k < count; ++k) {
    Eigen::VectorXd u = u0;
    for (double& e : u) e = std::clamp(e + sigma * normal(rng), 0.0, 1.0);
    configurations rec;
    const rollout_result r = walk(u, rec);
    times.push_back(r.time);
    if (traced || r.time > 2.5) continue;
    traced = true;
    std::printf("sample %d falls at %.3f s; |q - q_unperturbed| first above", k, r.time);
    const double thresholds[] = {1e-8, 1e-6, 1e-4, 1e-2, 1e-1};
    std::size_t next = 0;
    for (std::size_t i = 0; i < std::min(rec.t.size(), base.t.size()) && next < 5; ++i)
      for (; next < 5 && (rec.q[i] - base.q[i]).lpNorm<Eigen::Infinity>() > thresholds[next];
           ++next)
        std::printf(" %.0e at %.4f s,", thresholds[next], rec.t[i]);
    std::printf("\n");
  }
  std::sort(times.begin(), times.end());
  const auto n = times.size();
  std::printf("%zu samples (sigma %g): quartiles %.2f %.2f %.2f s\n", n, sigma, times[n / 4],
              times[n / 2], times[3 * n / 4]);
  for (int s = 0; s < static_cast<int>(std::ceil(seconds)); ++s) {
    const auto in = std::count_if(times.begin(), times.end(), [&](double t) {
      return t >= s && (t < s + 1 || (t >= seconds - 1e-9 && s + 1 >= seconds));
    });
    std::printf("[%d, %d) s: %ld\n", s, s + 1, static_cast<long>(in));
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_sensitivity: %s\n", e.what());
  return 1;
}
