// How a saved Wu & Popovic 2010 forward walk fails without its helper force
// (docs/reproductions/wu2010.md, "Taking the helper away"): walks the controller WITHOUT the
// helper on flat ground for up to SECONDS, the legs colliding when the saved controller did, every
// physics step recorded, and prints the COM every 0.25 s, then for the last 30 steps the COM, the
// fastest joint (rad/s), the sole contact points touching and the three angles (x y z, rad) of the
// ankle on the fastest joint's side (a blow-up at the ankle's Euler gimbal lock, ankle_y -> pi/2,
// docs/reproductions/wu2010.md, "Where eq. 5 falls short"). Two knobs rule out other causes:
// NULL_SPACE_OFF=1 in the environment switches the lower level's null-space spring-damper off,
// FOOT_INERTIA=k multiplies both feet's inertia by k. Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_divergence.cpp -o /tmp/wu2010_divergence
//   /tmp/wu2010_divergence data/wu2010/runs/f9/wu2010_walk.mean.json 20
//
// (one command line each).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/walk_check.hpp"

#include "wu2010_saved_rollout.hpp"

using namespace gaitsynth;

int main(int argc, char** argv) try {
  if (argc != 3) throw std::invalid_argument("usage: wu2010_divergence CONTROLLER.json SECONDS");
  const char* file = argv[1];
  const double seconds = std::atof(argv[2]);
  if (!(seconds > 0.0)) throw std::invalid_argument("SECONDS must be > 0");
  floating_model m = wu2010_biped();
  if (const char* k = std::getenv("FOOT_INERTIA"))
    for (body& b : m.bodies)
      if (b.name == "lfoot" || b.name == "rfoot") b.inertia *= std::atof(k);
  const planned_walk_saved saved = load_planned_walk(file);
  planned_walk_options po = saved_planned_walk_options(saved, file);
  po.helper_force = false;
  if (std::getenv("NULL_SPACE_OFF")) po.lower.null_space_kp = po.lower.null_space_kd = 0.0;
  const planned_walk<> c(m, flat_terrain{}, po);
  const std::vector<double> x = planned_walk_values(saved, c.parameter_names(), file);
  rollout_options o = walk_options(gaitsynth_scripts::saved_rollout_options(m, saved, seconds));
  trajectory tr;
  o.record = &tr;
  o.record_every = 1;
  auto scratch = make_rollout_scratch(m);
  const rollout_result r = rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                                   semi_implicit_euler{}, x, o, scratch);
  std::printf("%s without its helper: %s after %.4f s\n", file,
              std::string(to_string(r.reason)).c_str(), r.time);
  const std::size_t n = tr.frames.size();
  const std::size_t every = static_cast<std::size_t>(std::lround(0.25 * 2400.0));
  auto line = [&](const trajectory_frame& f) {
    Eigen::Index j = 0;
    const double fastest = f.v.tail(f.v.size() - 6).cwiseAbs().maxCoeff(&j);
    int touching = 0;
    for (const unsigned char a : f.contact_active) touching += a;
    // The ankle of the fastest joint's side (DOFs 4-6 left, 11-13 right; the waist's: left).
    const Eigen::Index ankle = (j >= 7 && j < 14 ? 11 : 4) + (f.q.size() - f.v.size() + 6);
    std::printf(
        "t %.4f  COM (%6.3f %6.3f %5.3f) m  fastest joint %-9s %7.1f rad/s  touching %d"
        "  ankle %5.2f %5.2f %5.2f\n",
        f.t, f.com.x(), f.com.y(), f.com.z(), m.dofs[static_cast<std::size_t>(j)].name.c_str(),
        fastest, touching, f.q[ankle], f.q[ankle + 1], f.q[ankle + 2]);
  };
  for (std::size_t k = 0; k + 30 < n; k += every) line(tr.frames[k]);
  std::printf("the last steps:\n");
  for (std::size_t k = n > 30 ? n - 30 : 0; k < n; ++k) line(tr.frames[k]);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_divergence: %s\n", e.what());
  return 1;
}
