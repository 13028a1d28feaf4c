// Rounding probe (scripts/rounding_check.sh): prints, in hexfloat, the cost, step count and final
// COM of rollouts of every saved Sharon 2005 controller (flat ground, the 10 degree slope, the
// Figure 8 bodies, two bump profiles) and of pushed PD rollouts of the 7-link human, and of the
// saved 3D walkers of Wang et al. 2009 (10 s each, with the settings of their optimization).
// Built once against the headers of another revision and once against the working tree,
// identical outputs show that a change kept every floating-point operation of the simulation
// (the saved controllers depend on it; docs/performance.md, "Rounding").
//
//   rounding_probe REPO_ROOT
#include <cstdio>
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/keyframes_json.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"
#if __has_include("gaitsynth/synthesis/nearest_neighbor_synthesis.hpp")
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#else  // revisions before the synthesis/ folder
#include "gaitsynth/controllers/nearest_neighbor_synthesis.hpp"
#endif
#if __has_include("gaitsynth/synthesis/sharon2005_scenarios.hpp")
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"
#else  // revisions before 821fa71 kept it beside the examples
#include "sharon2005_scenarios.hpp"
#endif
using namespace gaitsynth;
static std::string data_dir;
static std::string D(const std::string& f) {
  return data_dir + "/data/sharon2005/" + f;
}
static void print(const char* name, const rollout_result& r, const sim_state* s = nullptr) {
  std::printf("%-22s steps=%lld cost=%a com=%a,%a", name, (long long)r.steps, r.cost,
              r.com_final.x(), r.com_final.z());
  if (s) {
    double h = 0;
    for (int i = 0; i < s->q.size(); ++i) h = h * 1.000001 + s->q[i];
    for (int i = 0; i < s->v.size(); ++i) h = h * 1.000001 + s->v[i];
    std::printf(" h=%a", h);
  }
  std::printf("\n");
}
template <class T>
void walk(const char* name, const planar_model& m, const std::string& cf, const std::string& kf,
          const T& ground, const planar_model* cm_ = nullptr, bool place = false,
          double secs = 15.0) {
  const planar_model& cm = cm_ ? *cm_ : m;
  const auto target = load_keyframes(cm, D(kf));
  const auto ctrl = load_nearest_neighbor(cm, D(cf));
  rollout_options ro;
  ro.initial_state = place ? sharon_scenarios::start_state_for(m, target) : target.initial_state();
  const rollout_problem prob{
      m,      torque_actuator{},     ctrl, mass_distance<planar_root>(m, target),
      ground, semi_implicit_euler{}, ro};
  const auto p = ctrl.parameters();
  Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(p.data(), p.size());
  auto w = check_walk(prob, x, secs);
  print(name, w.result);
}
int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: rounding_probe REPO_ROOT\n");
    return 2;
  }
  data_dir = argv[1];
  const planar_model h7 = sharon2005_human7();
  walk("normal flat", h7, "normal_walk.controller.json", "normal_walk.keyframes.json",
       flat_terrain{});
  walk("16-link", sharon2005_human16(), "human16_walk.controller.json",
       "human16_walk.keyframes.json", flat_terrain{});
  walk("high knee", h7, "high_knee.controller.json", "high_knee.keyframes.json", flat_terrain{});
  walk("backswing", h7, "backswing.controller.json", "backswing.keyframes.json", flat_terrain{});
  walk("uphill", h7, "uphill.controller.json", "uphill.keyframes.json",
       slope_terrain(10.0 * 3.14159265358979 / 180.0));
  for (const auto& v : sharon_scenarios::figure8_bodies()) {
    const planar_model m = sharon2005_human7(v.params);
    walk(v.name.c_str(), m, "normal_walk.controller.json", "normal_walk.keyframes.json",
         flat_terrain{}, &h7, true);
  }
  walk("bumps 2005", h7, "normal_walk.controller.json", "normal_walk.keyframes.json",
       sharon_scenarios::bumpy_terrain(), nullptr, true);
  walk("bumps 3003", h7, "normal_walk.controller.json", "normal_walk.keyframes.json",
       sharon_scenarios::bumpy_terrain(11.0, 3003), nullptr, true);
  // PD standing with a push (the benchmark's case), and a push-over fall.
  for (int k = 0; k < 2; ++k) {
    rollout_options ro;
    ro.dt = 1.0 / 2400.0;
    ro.duration = 3.0;
    ro.initial_state = make_state(h7);
    place_on_terrain(h7, flat_terrain(), ro.initial_state.q);
    ro.pushes.push_back(push{0, vec3(k ? 400.0 : 60.0, 0.0, 0.0), 0.5, 0.2});
    auto scr = make_rollout_scratch(h7);
    Eigen::VectorXd none = Eigen::VectorXd::Zero(h7.num_joint_dofs());
    auto r = rollout(h7, pd_actuator::uniform(h7, 300, 30), pose_hold(h7), distance_objective(),
                     flat_terrain{}, semi_implicit_euler{}, none, ro, scr);
    print(k ? "pd push fall" : "pd push", r, &scr.state);
  }
  // The 3D walkers of Wang et al. 2009 (world-frame servos, 63 contact points, implicit dampers):
  // 10 s of each saved walker below on flat ground.
  for (const char* file : {"stocky_table2", "stocky_ratio_constraint100", "short_cot"}) {
    const std::string path = data_dir + "/data/wang2009/walkers/" + file + ".controller.json";
    const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
    wang2009_controller c(m);
    const std::vector<double> p = load_wang2009_controller(path, c).parameters;
    const rollout_options opt = wang2009_rollout_options(m);
    auto scr = make_rollout_scratch(m);
    const auto r = rollout(m, mixed_pd_actuator{}, c, wang2009_objective(m), flat_terrain{},
                           semi_implicit_euler{}, std::span<const double>(p), opt, scr);
    print(file, r, &scr.state);
  }
}
