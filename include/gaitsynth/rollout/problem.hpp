#pragma once
/// \file problem.hpp
/// The "parameters -> cost" glue between a rollout and an optimizer, for any model, actuator,
/// controller, objective, terrain and integrator: what CMA-ES and SDS minimize.
///
///   rollout_problem prob{model, pd_actuator::capped(...), my_controller, my_objective,
///                        flat_terrain{}, semi_implicit_euler{}, options};
///   auto ctx = prob.make_context();                  // once per worker (thread, MPI rank)
///   double c = prob.cost(x, 10.0, ctx);              // allocates nothing when the policies don't
///   rollout_result r = prob.evaluate(x, 70.0, ctx);  // one rollout, with its stop reason
///
/// A problem is immutable during an optimizer's iteration and shared by all workers; everything a
/// rollout writes lives in the worker's context (rollout scratch, a copy of the controller to
/// bind, of the integrator, and of the options). Between iterations a program may change the
/// problem's start (options.initial_state) and pushes (options.pushes): every evaluation reads
/// those two from the problem (a new terrain or new pushes per iteration: wu2010_walk,
/// wang2012_walk --push-phase random); the rest of the options is the context's copy. Reusing a
/// context gives bit-identical results to a fresh one (tests/rollout/problem.cpp), so a value never
/// depends on which worker computed it, and an MPI evaluator can give every rank its own problem
/// instance and contexts. The overloads without a context make a temporary one (allocates; fine for
/// a check, not for an optimization loop).
///
/// The cost sums the objective over the start states (`starts`; empty: options.initial_state
/// alone). Other terrains, bodies or pushes come in as variants
/// (rollout/problem_with_variants.hpp). Parameters are validated with their names
/// (`node3.output.rknee`, not "index 37").
#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/rollout/rollout.hpp"

namespace gaitsynth {

/// Controllers that name their parameters (used in messages, logs and checkpoints).
template <class C>
concept controller_with_parameter_names = requires(const C& c) {
  { c.parameter_names() } -> std::convertible_to<std::vector<std::string>>;
};
/// Controllers that report their current (initial) parameter vector.
template <class C>
concept controller_with_parameters = requires(const C& c) {
  { c.parameters() } -> std::convertible_to<std::vector<double>>;
};

/// The names of c's parameters: its own (controller_with_parameter_names) or p0, p1, ...
template <class C>
std::vector<std::string> parameter_names_of(const C& c) {
  if constexpr (controller_with_parameter_names<C>) {
    return c.parameter_names();
  } else {
    std::vector<std::string> n;
    for (std::size_t i = 0; i < static_cast<std::size_t>(c.num_parameters()); ++i) {
      std::string s = "p";  // (not "p" + to_string: GCC 12 warns falsely, -Wrestrict)
      s += std::to_string(i);
      n.push_back(std::move(s));
    }
    return n;
  }
}

/// Per-worker memory of a rollout_problem: reused by every evaluation on that worker.
template <root_joint Root, class Actuator, class Controller, class Objective, class Integrator>
struct rollout_context {
  rollout_scratch<Root> scratch;
  Controller controller;    ///< bound to each candidate in turn
  Integrator integrator;    ///< steppers keep scratch of their own (RK4)
  rollout_options options;  ///< the problem's, with this evaluation's start, horizon, recorder
  rollout_policy_states<Actuator, Controller, Objective> states;  ///< reset for each rollout
};

template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator>
struct rollout_problem {
  using root_type = Root;
  using controller_type = Controller;
  using context_type = rollout_context<Root, Actuator, Controller, Objective, Integrator>;

  const model<Root>& character;  ///< must outlive the problem
  Actuator actuator;
  Controller controller;  ///< the initial controller: bind(x) must determine it from x alone
  Objective objective;
  Terrain ground;
  Integrator integrator;
  rollout_options options;  ///< its duration is replaced by the horizon of each evaluation
  /// Start states of the cost (empty: options.initial_state alone). Sharon 2005 evaluates from
  /// one state, the first keyframe; its section VII suggests "multiple states that are distributed
  /// along the desired trajectory" for robustness.
  std::vector<sim_state> starts = {};

  /// Memory for one worker (set-up: allocates).
  context_type make_context() const {
    context_type ctx{make_rollout_scratch(character), controller, integrator, options, {}};
    ctx.options.record = nullptr;
    return ctx;
  }

  std::size_t num_parameters() const {
    return static_cast<std::size_t>(controller.num_parameters());
  }
  std::vector<std::string> parameter_names() const { return parameter_names_of(controller); }

  /// The initial parameter vector (the controller's current parameters).
  Eigen::VectorXd initial_parameters() const requires controller_with_parameters<Controller> {
    const std::vector<double> p = controller.parameters();
    return Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size()));
  }

  /// The controller with parameter vector x bound.
  Controller controller_with(const Eigen::VectorXd& x) const {
    check_parameter_vector(x);
    Controller c = controller;
    c.bind(std::span<const double>(x.data(), static_cast<std::size_t>(x.size())));
    return c;
  }

  /// Throws std::invalid_argument for a wrong size or a non-finite entry, naming the parameter.
  /// Allocates only on the error path.
  void check_parameter_vector(const Eigen::VectorXd& x) const {
    check_size(static_cast<std::ptrdiff_t>(x.size()), static_cast<std::ptrdiff_t>(num_parameters()),
               "parameter vector");
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (!std::isfinite(x[i]))
        throw std::invalid_argument("parameter " + std::to_string(i) + " '" +
                                    parameter_names()[static_cast<std::size_t>(i)] +
                                    "' is not finite (" + std::to_string(x[i]) + ")");
  }

  /// One rollout of `horizon` seconds from options.initial_state (optionally recorded).
  rollout_result evaluate(const Eigen::VectorXd& x, double horizon, context_type& ctx,
                          trajectory* record = nullptr, int record_every = 1) const {
    return evaluate_from(options.initial_state, x, horizon, ctx, record, record_every);
  }
  rollout_result evaluate(const Eigen::VectorXd& x, double horizon, trajectory* record = nullptr,
                          int record_every = 1) const {
    auto ctx = make_context();
    return evaluate(x, horizon, ctx, record, record_every);
  }

  /// One rollout of `horizon` seconds from options.initial_state, watched by `observer`
  /// (rollout/observer.hpp: record, stream or plot).
  template <class Observer>
  requires(!std::is_convertible_v<Observer, trajectory*>) rollout_result
      evaluate(const Eigen::VectorXd& x, double horizon, context_type& ctx, Observer&& observer)
  const {
    return run_from(options.initial_state, x, horizon, ctx, nullptr, 1,
                    std::forward<Observer>(observer));
  }

  /// One rollout from start state s (its t is the target motion's time, for tracking costs).
  rollout_result evaluate_from(const sim_state& s, const Eigen::VectorXd& x, double horizon,
                               context_type& ctx, trajectory* record = nullptr,
                               int record_every = 1) const {
    return run_from(s, x, horizon, ctx, record, record_every, null_observer{});
  }
  rollout_result evaluate_from(const sim_state& s, const Eigen::VectorXd& x, double horizon,
                               trajectory* record = nullptr, int record_every = 1) const {
    auto ctx = make_context();
    return evaluate_from(s, x, horizon, ctx, record, record_every);
  }

  /// The optimization cost: the sum of the objective over the start states, each rollout
  /// `horizon` seconds long. A diverged rollout makes it +infinity.
  double cost(const Eigen::VectorXd& x, double horizon, context_type& ctx) const {
    if (starts.empty()) return evaluate(x, horizon, ctx).cost;
    double c = 0.0;
    for (const sim_state& s : starts) c += evaluate_from(s, x, horizon, ctx).cost;
    return c;
  }
  double cost(const Eigen::VectorXd& x, double horizon) const {
    auto ctx = make_context();
    return cost(x, horizon, ctx);
  }

 private:
  /// The one rollout every evaluation runs: start s, horizon, recorder and observer on ctx.
  template <class Observer>
  rollout_result run_from(const sim_state& s, const Eigen::VectorXd& x, double horizon,
                          context_type& ctx, trajectory* record, int record_every,
                          Observer&& observer) const {
    check_parameter_vector(x);
    check_argument(std::isfinite(horizon) && horizon >= 0.0,
                   "rollout_problem: horizon must be finite and >= 0 s, got ", horizon);
    rollout_options& o = ctx.options;
    o.initial_state.t = s.t;  // same sizes after the first call: no allocation
    o.initial_state.q = s.q;
    o.initial_state.v = s.v;
    o.pushes = options.pushes;  // reuses the copy's storage unless there are more pushes
    o.duration = horizon;
    o.record = record;
    o.record_every = record_every;
    return rollout(character, actuator, ctx.controller, objective, ground, ctx.integrator,
                   std::span<const double>(x.data(), static_cast<std::size_t>(x.size())), o,
                   ctx.scratch, ctx.states, std::forward<Observer>(observer));
  }
};

template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator>
rollout_problem(const model<Root>&, Actuator, Controller, Objective, Terrain, Integrator,
                rollout_options)
    -> rollout_problem<Root, Actuator, Controller, Objective, Terrain, Integrator>;
template <root_joint Root, class Actuator, class Controller, class Objective, terrain Terrain,
          class Integrator>
rollout_problem(const model<Root>&, Actuator, Controller, Objective, Terrain, Integrator,
                rollout_options, std::vector<sim_state>)
    -> rollout_problem<Root, Actuator, Controller, Objective, Terrain, Integrator>;

}  // namespace gaitsynth
