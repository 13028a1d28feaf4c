// A short simulation demo: the fused rollout loop (docs/architecture.md) on the built-in
// characters, printing what happened.
//
//   1. The 3D humanoid of Wang et al. 2009 holds a standing pose with PD servos on flat ground and
//      is pushed forward at the pelvis (60 N for 0.2 s, t = 1 s); it absorbs the push.
//   2. The same character without actuation (zero torques) collapses; the rollout stops at the
//   fall.
//   3. The 7-link planar human of Sharon & van de Panne 2005 stands on a 5 degree uphill slope,
//      its ankles dorsiflexed by the slope angle so that its feet lie flat with the body upright.
//
// Nothing is random: every run prints the same.
//
// Usage: simulation_demo [--html FILE] [--filmstrip FILE] [--filmstrip-front FILE]
//                        [--gait-svg FILE] [--bvh FILE] [--csv FILE] [--mjcf-replay FILE]
// The viewer flags (examples/command_line.hpp, docs/viewer.md) write the first rollout, the
// pushed humanoid. --help lists them.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "command_line.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

namespace {

constexpr double dt = 1.0 / 2400.0;  // the papers' 2400 Hz

/// Prints a few frames of a recorded rollout: time, COM, contact points touching, peak torque.
void print_frames(const trajectory& tr, double every_s) {
  std::printf("     t [s]   COM x [m]   COM y [m]   COM z [m]   contacts   max |tau| [N m]\n");
  double next = 0.0;
  for (const trajectory_frame& f : tr.frames) {
    if (f.t + 1e-9 < next && &f != &tr.frames.back()) continue;
    next += every_s;
    int touching = 0;
    for (unsigned char a : f.contact_active) touching += a;
    std::printf("  %8.3f  %10.4f  %10.4f  %10.4f  %9d  %16.1f\n", f.t, f.com.x(), f.com.y(),
                f.com.z(), touching, f.tau.cwiseAbs().maxCoeff());
  }
}

template <class F>
double wall_seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void print_result(const rollout_result& r, double wall) {
  std::printf("  stopped: %s at t = %.3f s after %lld steps (%lld controller calls)\n",
              std::string(to_string(r.reason)).c_str(), r.time, static_cast<long long>(r.steps),
              static_cast<long long>(r.controller_calls));
  std::printf("  COM moved (%.3f, %.3f, %.3f) m; cost %.4f; %.0f x real time (%.2f us/step)\n",
              r.com_final.x() - r.com_initial.x(), r.com_final.y() - r.com_initial.y(),
              r.com_final.z() - r.com_initial.z(), r.cost, r.time / wall,
              1e6 * wall / static_cast<double>(r.steps));
}

}  // namespace

int main(int argc, char** argv) try {
  viz_outputs views;
  CLI::App app{
      "A short simulation demo: a pushed standing humanoid, the same without actuation, and the "
      "7-link human standing on a slope.",
      "simulation_demo"};
  app.option_defaults()->always_capture_default();
  example_cli::add_viewer_flags(app, views, "the first rollout, the pushed humanoid");
  example_cli::parse(app, argc, argv);

  // ---- 1. standing humanoid, pushed -------------------------------------------------------------
  const floating_model humanoid = wang2009_humanoid();
  std::printf(
      "1. %s (%d bodies, %d joint DOFs, %.0f kg, %zu contact points): PD pose hold on\n"
      "   flat ground at 2400 Hz, pushed forward at the pelvis with 60 N for 0.2 s at 1 s\n",
      humanoid.name.c_str(), humanoid.num_bodies(), humanoid.num_joint_dofs(),
      humanoid.total_mass(), humanoid.contact_points.size());
  auto scratch = make_rollout_scratch(humanoid);
  trajectory tr;
  rollout_options opt;
  opt.dt = dt;
  opt.duration = 3.0;
  opt.record = &tr;
  opt.record_every = 24;  // 100 frames per second
  opt.pushes = {push{humanoid.body_index("pelvis"), vec3(60.0, 0.0, 0.0), 1.0, 0.2}};
  const Eigen::VectorXd upright = Eigen::VectorXd::Zero(humanoid.num_joint_dofs());
  rollout_result r;
  double wall = wall_seconds([&] {
    r = rollout(humanoid, standing_pd(humanoid, dt), pose_hold(humanoid), distance_objective(),
                flat_terrain(), semi_implicit_euler(), upright, opt, scratch);
  });
  print_frames(tr, 0.25);
  print_result(r, wall);
  if (views.any()) {
    views.html_options.title = "gaitsynth demo: standing humanoid pushed at 1 s";
    write_viz_outputs(humanoid, tr, views, &std::cerr);
  }

  // ---- 2. the same character, unactuated ------------------------------------------------------
  std::printf("\n2. the same character with zero joint torques (torque actuator, no gains)\n");
  opt.pushes.clear();
  opt.record_every = 120;  // 20 frames per second
  wall = wall_seconds([&] {
    r = rollout(humanoid, torque_actuator{},
                pose_hold(humanoid, {.output = command_kind::joint_torque}), distance_objective(),
                flat_terrain(), semi_implicit_euler(), upright, opt, scratch);
  });
  print_frames(tr, 0.1);
  print_result(r, wall);
  std::printf(
      "  (a fall: the COM dropped below %.3f m, half its standing height; the distance\n"
      "   objective adds 10 per second lost, so the cost ranks falling worst)\n",
      r.fall_height);

  // ---- 3. planar human on a slope ---------------------------------------------------------------
  const planar_model human7 = sharon2005_human7();
  const double angle = 5.0 * 3.14159265358979 / 180.0;
  const slope_terrain slope(angle);
  std::printf(
      "\n3. %s (planar, %d joint DOFs) standing upright on a 5 degree uphill slope,\n"
      "   ankles dorsiflexed by 5 degrees\n",
      human7.name.c_str(), human7.num_joint_dofs());
  // Plantarflexion is positive (models/sharon2005.hpp): dorsiflex to put the feet on the slope.
  Eigen::VectorXd pose7 = Eigen::VectorXd::Zero(human7.num_joint_dofs());
  pose7[human7.dof_index("lankle")] = -angle;
  pose7[human7.dof_index("rankle")] = -angle;
  auto scratch7 = make_rollout_scratch(human7);
  rollout_options opt7;
  opt7.dt = dt;
  opt7.duration = 2.0;
  opt7.record = &tr;
  opt7.record_every = 240;
  opt7.initial_state = make_state(human7);
  opt7.initial_state.q.tail(human7.num_joint_dofs()) = pose7;
  place_on_terrain(human7, slope, opt7.initial_state.q);
  wall = wall_seconds([&] {
    r = rollout(human7, standing_pd(human7, dt), pose_hold(human7), distance_objective(), slope,
                semi_implicit_euler(), pose7, opt7, scratch7);
  });
  print_frames(tr, 0.5);
  print_result(r, wall);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "simulation_demo: %s\n", e.what());
  return 1;
}
