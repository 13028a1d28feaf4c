// Where Wu & Popovic 2010's helper force works in a saved forward-walk controller
// (docs/reproductions/wu2010.md, "Why the helper stays above zero"): replays the controller WITH
// its helper force (Sec. 8.2, clipped to h_max per entry of eq. 4's residual b - A f) on flat
// ground for `seconds` and prints, for each row group of eq. 4 (the upper body's force and
// torque, each action frame's force), the share of commands after the first second at which the
// helper sits at its clip and its mean magnitude, with the share of those commands at which the
// frame was pinned (Sec. 6.3: its rows leave the QP and get no helper) while its foot stood or
// swung. Then, for each warm-up length W, walks W seconds with the helper and continues from that
// state without it (the controller planning afresh), printing how long it lasts: whether the walk
// needs the helper only to start or all along. The legs collide when the saved controller says so
// (its "leg_collisions", as wu2010_walk --replay reads it; none recorded: they pass through).
// Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_helper_rows.cpp -o /tmp/helper_rows
//   /tmp/helper_rows data/wu2010/runs/f3/wu2010_walk.controller.json 10 2.2 4.4 8.8
//
// (one command line each; the warm-ups should be multiples of 2 t_h = 1.1 s, so that the
// continuation starts, as the controller does, with the left foot standing).
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

#include "wu2010_saved_rollout.hpp"

using namespace gaitsynth;

namespace {

/// Per row of eq. 4 (3N + 6): commands at the clip and the summed |h|; per action frame, the
/// commands at which it was pinned while its foot stood (the plan's stance foot) or swung.
struct helper_rows {
  double h_max = 0.0;
  Eigen::VectorXd at_clip, magnitude;
  Eigen::VectorXd pinned_standing, pinned_swinging;
  long commands = 0;
  std::int64_t last_command = -1;
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    if (ob.t < 1.0 || st.commands == last_command) return;
    last_command = st.commands;
    const Eigen::VectorXd& h = st.helper;
    if (at_clip.size() == 0) {
      at_clip = magnitude = Eigen::VectorXd::Zero(h.size());
      pinned_standing = pinned_swinging = Eigen::VectorXd::Zero(h.size() / 3 - 2);
    }
    ++commands;
    for (Eigen::Index i = 0; i < h.size(); ++i) {
      at_clip[i] += std::abs(h[i]) >= (1.0 - 1e-9) * h_max;
      magnitude[i] += std::abs(h[i]);
    }
    const int stance_link = st.stance == stance_side::left ? 1 : 2;
    for (Eigen::Index j = 0; j < pinned_standing.size(); ++j) {
      if (!st.lower.pinned[static_cast<std::size_t>(j)]) continue;
      const bool standing = link_of[static_cast<std::size_t>(j)] == stance_link;
      (standing ? pinned_standing : pinned_swinging)[j] += 1.0;
    }
  }
  std::vector<int> link_of;  ///< each action frame's link (1 left foot, 2 right foot)
};

struct last_state {
  sim_state s;
  template <class Ob>
  void observe(const Ob& ob) {
    s.q = *ob.q_ptr;
    s.v = *ob.v_ptr;
  }
};

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3)
    throw std::invalid_argument("usage: helper_rows CONTROLLER.json SECONDS [WARM ...]");
  const char* file = argv[1];
  const double seconds = std::atof(argv[2]);
  const floating_model m = wu2010_biped();
  const planned_walk_saved saved = load_planned_walk(file);
  planned_walk_options po = saved_planned_walk_options(saved, file);
  po.helper_force = true;
  const planned_walk<> helped(m, flat_terrain{}, po);
  const std::vector<double> xh = planned_walk_values(saved, helped.parameter_names(), file);
  po.helper_force = false;
  const planned_walk<> plain(m, flat_terrain{}, po);
  const std::vector<double> xp = planned_walk_values(saved, plain.parameter_names(), file);

  auto scratch = make_rollout_scratch(m);
  rollout_options o = gaitsynth_scripts::saved_rollout_options(m, saved, seconds);
  helper_rows rows;
  rows.h_max = xh.back();
  const end_effector_layout& L = helped.layout();
  for (const action_frame& a : L.action) rows.link_of.push_back(a.link);
  const rollout_result r = rollout(m, torque_actuator{}, helped, distance_objective(),
                                   flat_terrain{}, semi_implicit_euler{}, xh, o, scratch, rows);
  std::printf("with its helper (h_max %.2f N): %.2f s, %s; %ld commands after 1 s\n", rows.h_max,
              r.time, std::string(to_string(r.reason)).c_str(), rows.commands);
  std::printf("%-16s %-20s %-20s %s\n", "rows", "at the clip (x y z)", "mean |h| (x y z)",
              "pinned: standing, swinging");
  const double n = static_cast<double>(rows.commands);
  const auto print = [&](const std::string& name, Eigen::Index row, Eigen::Index frame) {
    std::printf("%-16s %.2f %.2f %.2f       %5.2f %5.2f %5.2f", name.c_str(), rows.at_clip[row] / n,
                rows.at_clip[row + 1] / n, rows.at_clip[row + 2] / n, rows.magnitude[row] / n,
                rows.magnitude[row + 1] / n, rows.magnitude[row + 2] / n);
    if (frame >= 0)
      std::printf("   %.2f %.2f", rows.pinned_standing[frame] / n, rows.pinned_swinging[frame] / n);
    std::printf("\n");
  };
  print("upper-body force", 0, -1);
  for (int j = 0; j < L.num_action(); ++j)
    print(L.action[static_cast<std::size_t>(j)].name, action_row(j), j);
  print("upper-body torque", wrench_rows(L) - 3, -1);

  for (int i = 3; i < argc; ++i) {
    const double warm = std::atof(argv[i]);
    rollout_options w = o;
    w.duration = warm;
    last_state ls;
    const rollout_result a = rollout(m, torque_actuator{}, helped, distance_objective(),
                                     flat_terrain{}, semi_implicit_euler{}, xh, w, scratch, ls);
    rollout_options c = o;
    c.duration = 20.0;
    c.initial_state = ls.s;
    const rollout_result b = rollout(m, torque_actuator{}, plain, distance_objective(),
                                     flat_terrain{}, semi_implicit_euler{}, xp, c, scratch);
    std::printf("%.2f s with the helper (%s), then without it: %.2f s more, %s, at x = %.2f m\n",
                warm, std::string(to_string(a.reason)).c_str(), b.time,
                std::string(to_string(b.reason)).c_str(), b.com_final.x());
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "helper_rows: %s\n", e.what());
  return 1;
}
