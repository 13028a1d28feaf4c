#pragma once
/// \file policy_states.hpp
/// The evolving states of one rollout's policies (actuator state and its rate, controller state,
/// objective accumulator), kept between rollouts so that a worker's context allocates nothing
/// per rollout (rollout/problem.hpp).
///
/// The first rollout makes each state (make_state / make_accumulator: set-up, may allocate).
/// Later rollouts on the same model reset it in place through an optional hook, or assign a new
/// one where the policy has none (which allocates only if that state owns heap memory):
///   a.reset_state(m, st)          actuator: st as make_state(m) would return it, no allocation
///   c.reset_state(m, st)          controller: the same
///   o.reset_accumulator(m, acc)   objective: the same for its accumulator
/// A change of model (by fingerprint, model/fingerprint.hpp) makes every state anew.
#include <cstdint>
#include <optional>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/model/fingerprint.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/objectives/concept.hpp"

namespace gaitsynth {

template <class Actuator, class Controller, class Objective>
struct rollout_policy_states {
  std::optional<typename Actuator::state_type> actuator;
  std::optional<typename Actuator::state_type> actuator_rate;  ///< for derivative() actuators
  std::optional<typename Controller::state_type> controller;
  std::optional<typename Objective::accumulator_type> objective;
  std::uint64_t model_fingerprint = 0;

  /// Makes or resets every state for a rollout of model m (fingerprint fp).
  template <root_joint Root>
  void prepare(const model<Root>& m, std::uint64_t fp, const Actuator& a, const Controller& c,
               const Objective& o) {
    if (fp != model_fingerprint) {
      actuator.reset();
      actuator_rate.reset();
      controller.reset();
      objective.reset();
      model_fingerprint = fp;
    }
    if (!actuator) {
      actuator.emplace(a.make_state(m));
    } else if constexpr (actuator_with_reset_state<Actuator, Root>) {
      a.reset_state(m, *actuator);
    } else {
      *actuator = a.make_state(m);
    }
    if (!actuator_rate) actuator_rate.emplace(*actuator);  // sized like the state (a copy)
    if (!controller) {
      controller.emplace(c.make_state(m));
    } else if constexpr (controller_with_reset_state<Controller, Root>) {
      c.reset_state(m, *controller);
    } else {
      *controller = c.make_state(m);
    }
    if (!objective) {
      objective.emplace(o.make_accumulator(m));
    } else if constexpr (objective_with_reset<Objective, Root>) {
      o.reset_accumulator(m, *objective);
    } else {
      *objective = o.make_accumulator(m);
    }
  }
};

}  // namespace gaitsynth
