#pragma once
/// \file concept.hpp
/// Vocabulary shared by every optimizer of gaitsynth (CMA-ES, its IPOP/BIPOP restarts, SDS):
/// the objective and evaluator concepts, the optimizer concept (ask / tell, as in libcmaes'
/// ask-tell loop), the stopping criteria, the termination options they all honour and the status
/// a driver prints, logs and passes to callbacks.
///
/// Conventions common to all optimizers:
///  - They search a `parameter_space` in *normalized* coordinates (each bounded parameter mapped to
///    [0, 1], as Wu 2010 and Wang 2009 do); `ask()` returns the candidates in *user* coordinates,
///    ready to be passed to the objective.
///  - The objective is minimized. A non-finite value (NaN, +-inf: e.g. a simulation that blew up)
///    is ranked worse than every finite value, counted in `optimizer_status::non_finite`, and never
///    enters the strategy's arithmetic.
///  - An iteration is one ask/tell cycle (a CMA-ES generation; one SDS coordinate probe).
#include <Eigen/Core>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

namespace gaitsynth {

class checkpoint_writer;
class checkpoint_reader;

/// Something callable as `double(const Eigen::VectorXd& x)` with x in user (unnormalized)
/// coordinates. Evaluators may call it from several threads at once: making concurrent calls safe
/// (no shared mutable state, or per-thread workspaces) is the caller's responsibility.
///
/// A *worker-aware* objective is callable as `double(const Eigen::VectorXd& x, std::size_t
/// worker)`: the evaluator passes the index of the worker (thread) making the call, in
/// [0, thread_count()), and never runs two calls with the same index at once. The objective keeps
/// one context (rollout scratch, controller copy) per worker and reuses it for every call on that
/// worker, so an optimization allocates nothing per evaluation (rollout/problem_cost.hpp). The
/// value must not depend on which worker computed it: that is what keeps results independent of
/// the thread count. Evaluators call f(x, worker) when that is valid, f(x) otherwise.
// (clang-format 14 mangles concept definitions)
// clang-format off
template <class F>
concept plain_objective_function = std::invocable<F&, const Eigen::VectorXd&> &&
    std::convertible_to<std::invoke_result_t<F&, const Eigen::VectorXd&>, double>;

template <class F>
concept worker_objective_function = std::invocable<F&, const Eigen::VectorXd&, std::size_t> &&
    std::convertible_to<std::invoke_result_t<F&, const Eigen::VectorXd&, std::size_t>, double>;

template <class F>
concept objective_function = plain_objective_function<F> || worker_objective_function<F>;

/// f(x) evaluated by worker `worker` (see worker_objective_function).
template <objective_function F>
double call_objective(F& f, const Eigen::VectorXd& x, std::size_t worker) {
  if constexpr (worker_objective_function<F>)
    return static_cast<double>(f(x, worker));
  else
    return static_cast<double>(f(x));
}

/// An evaluator computes `out[k] = f(xs[k])` for a batch of candidates. It must write each value
/// into its own slot (never depend on the completion order), so that results are independent of
/// how the work is spread: the serial and thread-pool evaluators here, an MPI evaluator that ships
/// the batch to other processes later. An exception thrown by `f` propagates to the caller.
template <class E, class F>
concept evaluator = objective_function<F> &&
    requires(E& e, F& f, std::span<const Eigen::VectorXd> xs, std::span<double> out) {
      e.evaluate(f, xs, out);
    };
// clang-format on

/// Why an optimizer stopped (checked after every tell, in the order listed in the documentation).
enum class stop_criterion : std::uint8_t {
  none = 0,          ///< still running
  max_iterations,    ///< iteration budget used up
  max_evaluations,   ///< evaluation budget used up
  target_value,      ///< best value < target, strictly (e.g. 1e-8 for the benchmark functions)
  no_improvement,    ///< best value not improved for N iterations (Wang 2009: 300)
  mean_change,       ///< mean moved less than a tolerance in one iteration (Wu 2010: 1e-3)
  tol_fun,           ///< CMA-ES: range of recent best values and of the last generation < tol_fun
  tol_x,             ///< CMA-ES: sigma * max(sqrt(diag C), |p_c|) < tol_x in every coordinate
  condition_number,  ///< CMA-ES: condition number of C above its limit
  tol_up_sigma,      ///< CMA-ES: sigma * max(D) grew by more than a factor (divergence)
  no_effect_axis,    ///< CMA-ES: a 0.1-sigma step along a principal axis leaves the mean unchanged
  no_effect_coordinate,  ///< CMA-ES: a 0.2-sigma step in a coordinate leaves the mean unchanged
  min_step,              ///< SDS: step size alpha shrank below its minimum
  callback,              ///< the per-iteration callback asked to stop
};

/// Stable lower-case name of a criterion (used in logs, the progress line and checkpoints).
constexpr std::string_view to_string(stop_criterion c) {
  switch (c) {
    case stop_criterion::none:
      return "none";
    case stop_criterion::max_iterations:
      return "max_iterations";
    case stop_criterion::max_evaluations:
      return "max_evaluations";
    case stop_criterion::target_value:
      return "target_value";
    case stop_criterion::no_improvement:
      return "no_improvement";
    case stop_criterion::mean_change:
      return "mean_change";
    case stop_criterion::tol_fun:
      return "tol_fun";
    case stop_criterion::tol_x:
      return "tol_x";
    case stop_criterion::condition_number:
      return "condition_number";
    case stop_criterion::tol_up_sigma:
      return "tol_up_sigma";
    case stop_criterion::no_effect_axis:
      return "no_effect_axis";
    case stop_criterion::no_effect_coordinate:
      return "no_effect_coordinate";
    case stop_criterion::min_step:
      return "min_step";
    case stop_criterion::callback:
      return "callback";
  }
  return "unknown";
}

/// Termination options shared by all optimizers. Zero (or -inf for the target) disables a test.
struct termination_options {
  /// Iterations (ask/tell cycles). 0: CMA-ES uses pycma's default 100 + 150 (n+3)^2 / sqrt(lambda)
  /// per run; SDS is unlimited.
  std::int64_t max_iterations = 0;
  /// Objective evaluations in total (over all restarts); 0: unlimited.
  std::int64_t max_evaluations = 0;
  /// Stop as soon as a value strictly below target_value has been seen (best < target_value; a
  /// value equal to the target does not stop). -inf, the default, never stops.
  double target_value = -std::numeric_limits<double>::infinity();
  /// Stop when the best value has not improved for this many iterations (Wang 2009 uses 300).
  std::int64_t no_improvement_iterations = 0;
};

/// Snapshot of an optimizer after a tell; what the progress line, the CSV log and callbacks see.
struct optimizer_status {
  std::int64_t iteration = 0;    ///< iterations done (over all restarts)
  std::int64_t evaluations = 0;  ///< objective evaluations done (over all restarts)
  double best_value = std::numeric_limits<double>::quiet_NaN();        ///< best so far (NaN: none)
  double iteration_best = std::numeric_limits<double>::quiet_NaN();    ///< of the last batch
  double iteration_median = std::numeric_limits<double>::quiet_NaN();  ///< finite values only
  double iteration_worst = std::numeric_limits<double>::quiet_NaN();   ///< finite values only
  double step_size = std::numeric_limits<double>::quiet_NaN();  ///< sigma (CMA-ES) / alpha (SDS)
  double axis_ratio = 1.0;      ///< sqrt(condition number of C) (CMA-ES); 1 for SDS
  std::int64_t non_finite = 0;  ///< non-finite objective values seen so far
  int restart = 0;              ///< index of the current run (0: first run)
  int batch_size = 0;           ///< candidates per ask in the current run (lambda for CMA-ES)
  /// Fraction of the budget used, in [0, 1], for the time-left estimate; NaN when unknown.
  double budget_fraction = std::numeric_limits<double>::quiet_NaN();
  stop_criterion stopped = stop_criterion::none;
};

/// One run of a restarting optimizer (cmaes_restarts): what it started with and why it ended, so a
/// result says more than the whole sequence's stop reason.
struct run_record {
  int population_size = 0;        ///< lambda of this run
  double sigma0 = 0;              ///< its initial step size, normalized units
  bool small_population = false;  ///< BIPOP's small-population regime (run 0 and IPOP: false)
  std::int64_t iterations = 0;    ///< of this run alone
  std::int64_t evaluations = 0;   ///< of this run alone
  double best_value = std::numeric_limits<double>::quiet_NaN();  ///< best of this run (NaN: none)
  /// Why this run ended; none for a run still going (or cut short by the driver's callback).
  stop_criterion stopped = stop_criterion::none;

  friend bool operator==(const run_record&, const run_record&) = default;
};

/// The optimizer policy: a strategy with an ask/tell interface, a stop test, the best point seen,
/// a status, and a complete serializable state (checkpoint/resume).
///  - `ask()` returns the batch of candidates (user coordinates) to evaluate next;
///  - `tell(values)` takes their objective values, in the same order;
///  - `stopped()` is stop_criterion::none while the optimizer wants to continue;
///  - `save`/`load` write and read the full state, including random number generators, so a run
///    resumed from a checkpoint continues bit-identically.
// clang-format off
template <class O>
concept optimizer = requires(O& o, const O& co, std::span<const double> values,
                             checkpoint_writer& w, checkpoint_reader& r) {
  { o.ask() } -> std::same_as<const std::vector<Eigen::VectorXd>&>;
  o.tell(values);
  { co.stopped() } -> std::same_as<stop_criterion>;
  { co.best_x() } -> std::convertible_to<const Eigen::VectorXd&>;
  { co.best_value() } -> std::convertible_to<double>;
  { co.status() } -> std::same_as<optimizer_status>;
  { co.name() } -> std::convertible_to<std::string_view>;
  { co.space() };
  co.save(w);
  o.load(r);
};
// clang-format on

}  // namespace gaitsynth
