#pragma once
/// \file observer.hpp
/// The observer policy of a rollout (Boost.Odeint's integrate functions take one the same way):
/// something that watches every physics step without touching the loop, to record, stream or
/// plot. The default, null_observer, does nothing and compiles to nothing.
///
/// Valid expressions (O: observer type, o: O&, m: const model<Root>&, su: const observer_setup&,
/// ob: const observation<...>&, r: const rollout_result&):
///
///   o.observe(ob)      once per physics step k, after the objective's accumulate and before the
///                      integration step: the state at t_k with the torques and contact forces
///                      held over [t_k, t_k + dt). Must not allocate.
///   o.start(m, su)     optional: once at set-up, before step 0 (may allocate)
///   o.finish(ob, r)    optional: once after the loop, with the state the rollout stopped in
///                      (ob.step = r.steps; kinematics current; a fall ends on the ground) and
///                      the result. Not called for a diverged rollout (r.reason == non_finite)
///                      with ob, whose state is not finite: then ob.final_state_valid is false.
///
/// rollout_options::record is shorthand for the trajectory_observer of rollout/recorder.hpp.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/rollout/result.hpp"

namespace gaitsynth {

/// What an observer learns at set-up.
struct observer_setup {
  double dt = 0.0;  ///< physics timestep, s
  std::int64_t horizon_steps =
      0;  ///< steps to the horizon (a fall or the objective may stop it earlier)
  std::vector<std::string> objective_term_names;  ///< names of ob.objective_terms(), in order
  std::size_t max_pushes = 0;                     ///< number of pushes in the options
};

/// One physics step as an observer sees it: the objective's step view, plus the objective's
/// running terms, the controller's discrete state, the active pushes and the terrain.
/// Non-owning; valid during the call.
template <root_joint Root, class Objective, class Controller, class ActuatorState, class Terrain>
struct observation : step_view_with<Root, ActuatorState> {
  const Objective* objective_ptr = nullptr;
  const typename Objective::accumulator_type* accumulator_ptr = nullptr;
  const Controller* controller_ptr = nullptr;
  const typename Controller::state_type* controller_state_ptr = nullptr;
  const Terrain* terrain_ptr = nullptr;
  std::span<const push> pushes;   ///< every push of the options (see push::active)
  bool final_state_valid = true;  ///< false in finish() after a divergence

  const Terrain& terrain() const { return *terrain_ptr; }
  /// The objective's running terms (objective_with_terms), as many as setup's names.
  void objective_terms(std::span<double> out) const {
    if constexpr (objective_with_terms<Objective>) objective_ptr->terms(*accumulator_ptr, out);
  }
  /// The controller's discrete state (FSM phase, active node), -1 if it has none.
  int controller_state() const {
    if constexpr (controller_with_discrete_state<Controller>)
      return controller_ptr->discrete_state(*controller_state_ptr);
    else
      return -1;
  }
};

/// Observes nothing; the rollout's calls to it vanish.
struct null_observer {
  template <class Observation>
  void observe(const Observation&) const {}
};

template <class O, class Observation>
concept rollout_observer = requires(O& o, const Observation& ob) {
  o.observe(ob);
};

template <class O, class Model>
concept observer_with_start = requires(O& o, const Model& m, const observer_setup& su) {
  o.start(m, su);
};

template <class O, class Observation>
concept observer_with_finish = requires(O& o, const Observation& ob, const rollout_result& r) {
  o.finish(ob, r);
};

/// Two observers as one (the rollout's recorder and the user's).
template <class A, class B>
struct observer_pair {
  A& first;
  B& second;
  template <class Model>
  void start(const Model& m, const observer_setup& su) {
    if constexpr (observer_with_start<A, Model>) first.start(m, su);
    if constexpr (observer_with_start<B, Model>) second.start(m, su);
  }
  template <class Observation>
  void observe(const Observation& ob) {
    first.observe(ob);
    second.observe(ob);
  }
  template <class Observation>
  void finish(const Observation& ob, const rollout_result& r) {
    if constexpr (observer_with_finish<A, Observation>) first.finish(ob, r);
    if constexpr (observer_with_finish<B, Observation>) second.finish(ob, r);
  }
};

}  // namespace gaitsynth
