#pragma once
/// \file nearest_neighbor_synthesis.hpp
/// The controller synthesis of Sharon & van de Panne 2005 (sections IV-V) as one call: optimize the
/// free parameters of a nearest-neighbor controller (controllers/nearest_neighbor.hpp) with SDS
/// (optimizers/sds.hpp) over bootstrapped episodes of growing simulation horizon (section V.C,
/// "typically we begin with T_sim = 0.2 s and finish with T_sim = 2 s"), each episode started
/// from the previous one's result (optimizers/continuation.hpp). The cost is any objective; the
/// paper's is the mass-distance metric (objectives/mass_distance.hpp, eqs. 2-3).
///
///   rollout_problem prob{model, torque_actuator{}, controller0, mass_distance(model, target),
///                        flat_terrain{}, semi_implicit_euler{},
///                        rollout_options_with_initial_state};
///
/// (The type is an nn_problem. Deduce it through rollout_problem, as above: deduction through an
/// alias template is C++20, but clang 14 and older do not implement it.)
///   nn_synthesis_result r = synthesize_nearest_neighbor(prob, nn_synthesis_options{});
///   auto c = prob.controller_with(r.x);           // the optimized controller
///   rollout_result check = prob.evaluate(r.x, 70.0);  // the paper's 70 s test
///
/// Everything here is deterministic (SDS draws no random numbers and the evaluator writes each
/// value into its own slot), so a synthesis gives the same controller on any thread count.
#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gaitsynth/controllers/nearest_neighbor.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/motion/keyframes.hpp"
#include "gaitsynth/optimizers/continuation.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"
#include "gaitsynth/optimizers/sds.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/rollout/problem_with_variants.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/rollout/walk_check.hpp"

namespace gaitsynth {

/// A rollout_problem (rollout/problem.hpp) whose controller is a nearest-neighbor controller: the
/// character, actuator, the initial controller (its non-free node coordinates stay fixed), the
/// objective, terrain, integrator and the rollout settings (initial state, dt, contact, falls).
template <root_joint Root, class Actuator, class Objective, terrain Terrain, class Integrator>
using nn_problem = rollout_problem<Root, Actuator, nearest_neighbor_controller<Root>, Objective,
                                   Terrain, Integrator>;

/// The nearest-neighbor name of problem_with_variants (rollout/problem_with_variants.hpp).
template <class Main, class Variant>
using nn_problem_with_variants = problem_with_variants<Main, Variant>;

struct nn_synthesis_options {
  /// Episode horizons T_sim (s), in order. Empty: 0.2, 0.4, ..., 2.0 (section V.C).
  std::vector<double> horizons;
  /// SDS per episode (angles in rad: parameters are node coordinates): initial step alpha,
  /// shrink factor, minimum step, and an evaluation budget (0: until min_step).
  double initial_step = 0.1;
  double shrink = 0.5;
  double min_step = 0.0125;
  std::int64_t evaluations_per_episode = 400;
  /// Each parameter may move at most this far (rad) from its initial value.
  double parameter_range = 1.5;
  /// Evaluation threads (the calling thread included).
  unsigned threads = 2;
  /// Progress line, CSV log, checkpoints (optimizers/minimize.hpp). The `stage` column of the log
  /// is the episode index.
  run_options run{};
};

struct nn_synthesis_result {
  Eigen::VectorXd x;             ///< optimized parameters
  double value = 0.0;            ///< cost of x on the last episode
  continuation_result episodes;  ///< one optimization_result per episode
  std::vector<double> horizons;  ///< T_sim of each episode, s
  std::int64_t evaluations = 0;  ///< cost function evaluations over all episodes
  double wall_seconds = 0.0;     ///< wall time of the whole synthesis
};

/// The default bootstrapping schedule: 0.2, 0.4, ..., 2.0 s.
inline std::vector<double> default_episode_horizons() {
  std::vector<double> h;
  for (int k = 1; k <= 10; ++k) h.push_back(k / 5.0);  // 0.2, 0.4, ..., 2 (exact decimals)
  return h;
}

/// Runs the bootstrapped SDS synthesis of section V. Throws std::invalid_argument for bad options.
template <class Problem>
nn_synthesis_result synthesize_nearest_neighbor(const Problem& prob, nn_synthesis_options o = {}) {
  if (o.horizons.empty()) o.horizons = default_episode_horizons();
  for (std::size_t k = 0; k < o.horizons.size(); ++k)
    check_argument(std::isfinite(o.horizons[k]) && o.horizons[k] > 0,
                   "nn_synthesis_options: horizon ", k, " must be finite and > 0, got ",
                   o.horizons[k]);
  check_positive(o.parameter_range, "nn_synthesis_options::parameter_range (rad)");
  check_argument(o.threads >= 1, "nn_synthesis_options::threads must be >= 1");
  const Eigen::VectorXd x0 = prob.initial_parameters();
  const std::vector<std::string> names = prob.parameter_names();
  parameter_space space;
  for (Eigen::Index i = 0; i < x0.size(); ++i)
    space.add({names[static_cast<std::size_t>(i)], x0[i] - o.parameter_range,
               x0[i] + o.parameter_range, x0[i], 1.0});
  thread_pool_evaluator pool(o.threads);
  problem_contexts<Problem> contexts(prob, pool.thread_count());  // one per worker, all episodes
  const auto t0 = std::chrono::steady_clock::now();
  nn_synthesis_result res;
  res.horizons = o.horizons;
  res.episodes = continuation(
      o.horizons.size(), x0,
      [&](std::size_t k, const Eigen::VectorXd& start) {
        if (o.run.progress)
          *o.run.progress << "episode " << k + 1 << "/" << o.horizons.size()
                          << ": T_sim = " << o.horizons[k] << " s\n";
        sds_options so;
        so.initial_step = o.initial_step;
        so.shrink = o.shrink;
        so.min_step = o.min_step;
        so.x0 = start;
        so.stop.max_evaluations = o.evaluations_per_episode;
        return sds(space, so);
      },
      [&](std::size_t k) { return problem_cost<Problem>(prob, o.horizons[k], contexts); }, pool,
      o.run);
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.x = res.episodes.x;
  res.value = res.episodes.value;
  for (const auto& s : res.episodes.stages) res.evaluations += s.evaluations;
  return res;
}

/// States on the target motion at the given times (pose and velocity of the keyframe motion, with
/// s.t = time so the objective compares against the target from there on), each lowered or raised
/// so that its lowest contact point touches the terrain.
template <root_joint Root, terrain Terrain>
std::vector<sim_state> target_start_states(const model<Root>& m,
                                           const keyframe_motion<Root>& target,
                                           const Terrain& ground,
                                           const std::vector<double>& times) {
  std::vector<sim_state> out;
  auto ws = make_workspace(m);
  for (double t : times) {
    sim_state s;
    s.q.resize(m.nq());
    s.v.resize(m.nv());
    target.pose(t, s.q);
    target.velocity(t, s.v);
    s.t = t;
    forward_kinematics(m, ws, s.q);
    double gap = std::numeric_limits<double>::infinity();
    for (const auto& c : m.contact_points) {
      const vec3 p = point_position(m, ws, c.body, c.position);
      gap = std::min(gap, p.z() - ground.height(p.x(), p.y()));
    }
    if (std::isfinite(gap)) s.q[std::is_same_v<Root, planar_root> ? 1 : 2] -= gap;
    out.push_back(std::move(s));
  }
  return out;
}

/// A start state and perturbed copies of it, for a cost that rewards robustness (section VII: "The
/// addition of disturbances during the controller evaluation may encourage robustness"): s itself,
/// then s with its velocity scaled by each of `velocity_scales`, then s lifted by each of `lifts`
/// (m; the character drops onto the ground).
template <root_joint Root>
std::vector<sim_state> perturbed_starts(const model<Root>&, const sim_state& s,
                                        const std::vector<double>& velocity_scales = {0.9, 1.1},
                                        const std::vector<double>& lifts = {0.01}) {
  std::vector<sim_state> out{s};
  for (double k : velocity_scales) {
    check_argument(std::isfinite(k), "perturbed_starts: velocity scale is not finite (", k, ")");
    sim_state p = s;
    p.v *= k;
    out.push_back(std::move(p));
  }
  for (double h : lifts) {
    check_argument(std::isfinite(h), "perturbed_starts: lift is not finite (", h, ")");
    sim_state p = s;
    p.q[std::is_same_v<Root, planar_root> ? 1 : 2] += h;
    out.push_back(std::move(p));
  }
  return out;
}

/// Sharon & van de Panne's test of a walk (their 70 s rollouts; check_walk with these criteria):
/// run to the horizon without falling or stalling, at 0.3 m/s or more on average.
inline constexpr walk_criteria sharon2005_walk_criteria{
    .stall = {.window = 5.0, .min_progress = 0.1}, .min_average_speed = 0.3};

}  // namespace gaitsynth
