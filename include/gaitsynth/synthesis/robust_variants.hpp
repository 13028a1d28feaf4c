#pragma once
/// \file synthesis/robust_variants.hpp
/// The perturbed copies of a rollout problem that a robust optimization scores each candidate on
/// beside the problem itself (make_problem_with_variants): `starts` copies whose joint velocities
/// start perturbed by a seeded N(0, start_sigma^2) (rollout/start_perturbations.hpp), then
/// `pushes` copies pushed on one body for push_duration every push_period seconds from
/// first_push, with push_force newtons in the eight horizontal directions of Wang et al. 2009
/// Table 1 (variant k starting at direction k, each later push turning push_direction_step
/// directions on), as far as the horizon allows: with step = pushes, K variants of n pushes each
/// spread over the eight directions instead of the first K + n - 1 of them. push_directions, where
/// given, names each pushed variant's first direction instead, so that a direction listed twice
/// weighs twice in the cost (ours: to train a walker's weak directions). Every candidate meets
/// the same perturbations, so the cost stays a deterministic function of the parameters whatever
/// the thread count.
///
/// The robust stages of the Wang 2009 and Wang 2012 walkers (examples/wang2009_walk.cpp,
/// examples/wang2012_walk.cpp) use it; seed them apart from a claim test's perturbations, so the
/// test judges starts the optimization never saw.
///
/// Pushes at fixed times can be learned: a candidate that survives them because of where in its
/// gait cycle they land need not survive the same pushes a second later (Table 1's protocol
/// pushes at 4, 8, ... s). redraw_push_phases moves every pushed variant's pushes by its own
/// phase in [0, push_period), drawn from a seed: called between optimizer iterations with a seed
/// per iteration, as Wang et al. 2010 draw a problem's disturbances anew, every candidate of an
/// iteration still meets the same pushes.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "gaitsynth/detail/uniform01.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"

namespace gaitsynth {

struct robust_variant_options {
  int starts = 0;             ///< copies from perturbed starts
  double start_sigma = 0.05;  ///< rad/s (the claim tests' perturbation)
  std::uint64_t seed = 1001;  ///< of the start perturbations
  int pushes = 0;             ///< copies with pushes
  double push_force = 100.0;  ///< N
  std::string push_body = "torso";
  double first_push = 2.0;      ///< s
  double push_period = 3.0;     ///< s between push starts
  double push_duration = 0.4;   ///< s (Wang 2009 Sec. 5, Wang 2012 Sec. 6.4)
  double horizon = 10.0;        ///< s: pushes that would not end before it are left out
  int push_direction_step = 1;  ///< directions each later push of a variant turns on
  /// false: push_force per component, as Table 1 reports forces ((1, 1) at 100 N pushes 141 N);
  /// true: push_force newtons along every direction (Wang 2012 Sec. 6.4's "100 N pushes").
  bool push_force_magnitude = false;
  /// The first direction (an index into table1_directions) of each pushed variant, one per
  /// variant; empty: variant k starts at direction k mod 8.
  std::vector<int> push_directions = {};
};

namespace detail {
inline void check_push_directions(const robust_variant_options& o) {
  check_argument(o.push_directions.empty() || std::ssize(o.push_directions) == o.pushes,
                 "robust_variants: push_directions must name one direction per pushed variant (",
                 o.pushes, "), got ", o.push_directions.size());
  for (const int d : o.push_directions)
    check_argument(d >= 0 && d < 8, "robust_variants: push_directions must be in [0, 7], got ", d);
}
}  // namespace detail

/// Pushed variant k's pushes on `body` (k from 0 among the pushed variants), the first starting at
/// `first_push`: every push_period, as long as it ends before the horizon.
inline std::vector<push> variant_pushes(int body, const robust_variant_options& o, int k,
                                        double first_push) {
  std::vector<push> out;
  const int first = o.push_directions.empty() ? k : o.push_directions[static_cast<std::size_t>(k)];
  for (int i = 0; first_push + o.push_period * i + o.push_duration < o.horizon; ++i) {
    const vec3& t =
        table1_directions()[static_cast<std::size_t>((first + i * o.push_direction_step) % 8)];
    const vec3 d = o.push_force_magnitude ? vec3(t.normalized()) : t;
    out.push_back(push{body, o.push_force * d, first_push + o.push_period * i, o.push_duration});
  }
  return out;
}

/// The variants of `prob` (a rollout_problem: its `character` and `options` are read) that `o`
/// asks for, starts first. Throws std::invalid_argument for a negative count, a non-finite or
/// negative sigma, force or time, a non-positive period or duration, an unknown body, or
/// push_directions of another length than `pushes` or outside [0, 7].
template <class Problem>
std::vector<Problem> robust_variants(const Problem& prob, const robust_variant_options& o) {
  check_argument(o.starts >= 0 && o.pushes >= 0,
                 "robust_variants: starts and pushes must be >= 0, got ", o.starts, " and ",
                 o.pushes);
  check_argument(std::isfinite(o.push_force) && o.push_force >= 0.0,
                 "robust_variants: push_force must be finite and >= 0, got ", o.push_force);
  check_argument(std::isfinite(o.first_push) && o.first_push >= 0.0,
                 "robust_variants: first_push must be finite and >= 0, got ", o.first_push);
  check_argument(std::isfinite(o.push_period) && o.push_period > 0.0,
                 "robust_variants: push_period must be finite and > 0, got ", o.push_period);
  check_argument(std::isfinite(o.push_duration) && o.push_duration > 0.0,
                 "robust_variants: push_duration must be finite and > 0, got ", o.push_duration);
  check_argument(o.push_direction_step >= 0,
                 "robust_variants: push_direction_step must be >= 0, got ", o.push_direction_step);
  check_argument(std::isfinite(o.horizon) && o.horizon > 0.0,
                 "robust_variants: horizon must be finite and > 0, got ", o.horizon);
  detail::check_push_directions(o);
  std::vector<Problem> out;
  for (const Eigen::VectorXd& dv :
       joint_velocity_perturbations(prob.character, o.starts, o.start_sigma, o.seed)) {
    Problem v = prob;
    v.options.initial_velocity_offset = dv;
    out.push_back(std::move(v));
  }
  if (o.pushes == 0) return out;
  const int body = prob.character.body_index(o.push_body);  // throws naming an unknown body
  for (int k = 0; k < o.pushes; ++k) {
    Problem v = prob;
    for (const push& p : variant_pushes(body, o, k, o.first_push)) v.options.pushes.push_back(p);
    out.push_back(std::move(v));
  }
  return out;
}

/// The seed of iteration `iteration`'s push phases in a run seeded `run_seed`: distinct per
/// iteration and run, so a resumed run redraws exactly what the whole run drew.
inline std::uint64_t push_phase_seed(std::uint64_t run_seed, std::int64_t iteration) {
  return run_seed * 1000003ull + static_cast<std::uint64_t>(iteration);
}

/// The phases redraw_push_phases gives the o.pushes pushed variants for `seed`: each uniform in
/// [0, push_period), from its own stream (seed, k), so they do not depend on the variant count.
inline std::vector<double> push_phases(const robust_variant_options& o, std::uint64_t seed) {
  std::vector<double> out;
  for (int k = 0; k < o.pushes; ++k) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(k)};
    std::mt19937_64 rng(seq);
    out.push_back(o.push_period * detail::uniform01(rng));
  }
  return out;
}

/// Replaces the pushes of the pushed variants of `variants` (as robust_variants(prob, o) made
/// them: the o.starts start variants first) with the same pushes moved by push_phases(o, seed):
/// variant k's first push at first_push + phase_k. Pushes the problem had before
/// robust_variants are kept. Throws std::invalid_argument if `variants` is not o.starts +
/// o.pushes long.
template <class Problem>
void redraw_push_phases(std::vector<Problem>& variants, const Problem& prob,
                        const robust_variant_options& o, std::uint64_t seed) {
  check_argument(std::ssize(variants) == o.starts + o.pushes, "redraw_push_phases: expected ",
                 o.starts + o.pushes, " variants (starts + pushes), got ", variants.size());
  if (o.pushes == 0) return;
  detail::check_push_directions(o);
  const int body = prob.character.body_index(o.push_body);
  const std::vector<double> phase = push_phases(o, seed);
  for (int k = 0; k < o.pushes; ++k) {
    Problem& v = variants[static_cast<std::size_t>(o.starts + k)];
    v.options.pushes = prob.options.pushes;
    for (const push& p :
         variant_pushes(body, o, k, o.first_push + phase[static_cast<std::size_t>(k)]))
      v.options.pushes.push_back(p);
  }
}

}  // namespace gaitsynth
