#pragma once
/// \file objectives/wang2012/wang2012_objective.hpp
/// The optimization objective of Wang et al. 2012 Sec. 5, as a cost to minimize:
///     E = sum_i w_i K_i + w_e J_effort,
/// the task terms K_i "moving the COM forward at a target velocity while not falling down for 10
/// seconds, and maintaining head stability and upper body orientation", and the effort of Sec. 5.1
/// (effort_terms.hpp: w_e = 0.004 / mass, w_M J_M + w_R J_R + w_L J_L).
///
/// The paper defines its task terms in its supplement "based on Wang et al. [2010]", which we do
/// not have; ours are the Wang et al. 2009 terms of the same names (objectives/wang2009/), each its
/// own objective, with Wang 2009's weights:
///   E_user    the target speed (eq. 4 with a target speed only),          w = 100
///   E_vel     no sideways or vertical drift (eq. 5),                      w = 100
///   E_fail    the fraction of the 10 s horizon fallen (eq. 7),            w = 120000
///   E_head    head stability (eq. 11),                                    w = 100
///   E_posture the torso within 0.15 rad of the vertical (ours, Wang 2009), w = 100
/// "Unlike in previous work, we did not need to include human-like speed to step-length ratio and
/// minimal angular momentum about the COM": neither is here.
#include <array>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/wang2009/failure.hpp"
#include "gaitsynth/objectives/wang2009/head.hpp"
#include "gaitsynth/objectives/wang2009/torso_posture.hpp"
#include "gaitsynth/objectives/wang2009/user_gait.hpp"
#include "gaitsynth/objectives/wang2009/velocity.hpp"
#include "gaitsynth/objectives/wang2012/effort_terms.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"

namespace gaitsynth::wang2012 {

struct task_weights {
  double user = 100.0;
  double vel = 100.0;
  double fail = 120000.0;
  double head = 100.0;
  double posture = 100.0;
  double effort = 1.0;  ///< multiplies w_e J_effort (1: the paper's)
};

struct objective_options {
  double target_speed = 1.25;  ///< m/s (nwalk)
  double fail_height = 0.7;    ///< m
  task_weights weights;
  effort_weights effort;
};

inline constexpr std::array<std::string_view, 6> objective_term_names{
    "E_user", "E_vel", "E_fail", "E_head", "E_posture", "w_e J_effort"};

/// The objective for model m driven by `units`, with J_M = j_m (metabolic_energy(units), or an
/// ablation's term, with its w_M in o.effort.metabolic).
template <root_joint Root, class MetabolicTerm>
auto objective(const model<Root>& m, const std::vector<musculotendon::unit>& units,
               MetabolicTerm j_m, const objective_options& o = {}) {
  const task_weights& w = o.weights;
  const std::array<double, 6> weights{w.user, w.vel, w.fail, w.head, w.posture, w.effort};
  for (std::size_t i = 0; i < weights.size(); ++i)
    check_argument(std::isfinite(weights[i]) && weights[i] >= 0.0,
                   "wang2012::objective: weight of ", objective_term_names[i],
                   " must be finite and >= 0, got ", weights[i]);
  check_argument(std::isfinite(o.target_speed), "wang2012::objective: target_speed is not finite (",
                 o.target_speed, ")");
  auto e = effort(m.total_mass(), units, std::move(j_m), o.effort);
  return weighted_sum<wang2009::user_gait, wang2009::velocity, wang2009::failure, wang2009::head,
                      wang2009::torso_posture, decltype(e)>(
      weights, wang2009::user_gait(m, {.target_speed = o.target_speed}),
      wang2009::velocity({.target_speed = o.target_speed}),
      wang2009::failure({.fail_height = o.fail_height}), wang2009::head(m),
      wang2009::torso_posture(m), std::move(e));
}

}  // namespace gaitsynth::wang2012
