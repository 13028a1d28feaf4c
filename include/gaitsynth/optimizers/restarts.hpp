#pragma once
/// \file restarts.hpp
/// Restart strategies for CMA-ES, as a wrapper that is itself an `optimizer`:
///  - IPOP (Auger & Hansen, CEC 2005): after each run that stops on a local criterion (tol_fun,
///    tol_x, no_improvement...), restart with the population size multiplied by
///    `population_factor` (2): the rounded default's multiples, or with
///    `unrounded_population_base` the unrounded default's (pycma's sequence);
///  - BIPOP (Hansen, GECCO BBOB 2009): interleave such "large population" runs (sigma0, lambda =
///    lambda_default * 2^i) with "small population" runs with lambda = floor(lambda_default *
///    max(1, lambda_large / lambda_default / 2)^(U^2)) and sigma = sigma0 * 10^(-2U), U ~ U(0, 1),
///    where lambda_large is the population of the latest large run, so lambda lies in
///    [lambda_default, max(lambda_default, lambda_large / 2)]. Before each restart the regime that
///    has used fewer evaluations so far runs. Run 0 is accounted with the small budget (as in
///    pycma), so the first restart is a large one and every small run follows a large run; a small
///    run may use at most half the evaluations of the last large run.
/// Run 0 is a plain CMA-ES run with the given options and seed, so `strategy = none` reproduces
/// `cmaes` exactly. Later runs get seeds drawn from the wrapper's own std::mt19937_64 (seeded with
/// the same seed), which is checkpointed with everything else.
///
/// Global stops (no restart): target_value, max_evaluations (over all runs), and running out of
/// restarts (`max_restarts`); the reported criterion is then the last run's. `runs()` (and
/// `optimization_result::runs`) lists every run with its population, evaluations and own criterion.
#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"
#include "gaitsynth/optimizers/random.hpp"

namespace gaitsynth {

enum class restart_strategy { none, ipop, bipop };

struct restart_options {
  restart_strategy strategy = restart_strategy::ipop;
  int max_restarts = 9;  ///< restarts after the first run (large-population runs for BIPOP)
  double population_factor = 2.0;  ///< lambda multiplier per (large) restart
  /// Large restart i gets floor((4 + 3 ln n) * factor^i), the unrounded default multiplied (21,
  /// 43, 87 at n = 10, as pycma's restarts), instead of the rounded default multiplied (20, 40,
  /// 80). Where cmaes_options::population_size is set, that value is the base either way.
  bool unrounded_population_base = false;
  /// Restart from a uniformly random mean in the initial region (the normalized bounds where
  /// finite, else initial mean +- 2 sigma0) instead of the initial mean.
  bool random_initial_mean = false;
};

class cmaes_restarts {
 public:
  cmaes_restarts(parameter_space space, cmaes_options options, restart_options restart = {})
      : base_(std::move(options)), ro_(restart) {
    check_argument(ro_.max_restarts >= 0, "restart_options::max_restarts must be >= 0, got ",
                   ro_.max_restarts);
    check_argument(std::isfinite(ro_.population_factor) && ro_.population_factor >= 1.0,
                   "restart_options::population_factor must be >= 1, got ", ro_.population_factor);
    run_opt_ = base_;
    run_ = std::make_unique<cmaes>(std::move(space), base_);  // validates the options
    space_ = run_->space();
    lambda0_ = run_->population_size();
    m0_ = space_.initial_normalized();
    rng_.seed(base_.seed);
    best_x_ = space_.initial();
  }

  std::string_view name() const { return "cmaes_restarts"; }

  const std::vector<Eigen::VectorXd>& ask() { return run_->ask(); }

  void tell(std::span<const double> values) {
    const std::int64_t before_nf = run_->non_finite_count();
    run_->tell(values);
    ++iteration_;
    evaluations_ += static_cast<std::int64_t>(values.size());
    non_finite_ += run_->non_finite_count() - before_nf;
    if (!std::isnan(run_->best_value()) && !(run_->best_value() >= best_value_)) {
      best_value_ = run_->best_value();
      best_x_ = run_->best_x();
    }
    const stop_criterion c = run_->stopped();
    if (c == stop_criterion::none) return;
    last_run_criterion_ = c;
    finished_runs_.push_back(current_run_record());
    const auto& t = base_.stop;
    const std::int64_t run_evals = run_->evaluations();
    if (large_regime_) {
      large_evals_ += run_evals;
      last_large_evals_ = run_evals;
    } else {
      small_evals_ += run_evals;
    }
    if (best_value_ < t.target_value) {  // strict, as in cmaes; false for NaN
      stopped_ = stop_criterion::target_value;
      return;
    }
    if (t.max_evaluations > 0 && evaluations_ >= t.max_evaluations) {
      stopped_ = stop_criterion::max_evaluations;
      return;
    }
    if (ro_.strategy == restart_strategy::none || large_restarts_ >= ro_.max_restarts) {
      stopped_ = c;
      return;
    }
    start_next_run();
  }

  stop_criterion stopped() const { return stopped_; }
  const Eigen::VectorXd& best_x() const { return best_x_; }
  double best_value() const { return best_value_; }
  const parameter_space& space() const { return space_; }
  int restarts() const { return restarts_; }
  const cmaes& current_run() const { return *run_; }
  /// Criterion that stopped the most recent finished run (none while run 0 is going).
  stop_criterion last_run_criterion() const { return last_run_criterion_; }
  /// Every run so far, in order (restarts() + 1 of them): the finished ones, then the current run
  /// while it is still going (its `stopped` is none).
  std::vector<run_record> runs() const {
    std::vector<run_record> all = finished_runs_;
    if (run_->stopped() == stop_criterion::none) all.push_back(current_run_record());
    return all;
  }

  optimizer_status status() const {
    optimizer_status s = run_->status();
    s.iteration = iteration_;
    s.evaluations = evaluations_;
    s.best_value = best_value_;
    s.non_finite = non_finite_;
    s.restart = restarts_;
    if (base_.stop.max_evaluations > 0)
      s.budget_fraction = std::min(
          1.0, static_cast<double>(evaluations_) / static_cast<double>(base_.stop.max_evaluations));
    else
      s.budget_fraction = std::numeric_limits<double>::quiet_NaN();
    s.stopped = stopped_;
    return s;
  }

  void save(checkpoint_writer& w) const {
    w.integer("restarts", restarts_);
    w.integer("large_restarts", large_restarts_);
    w.integer("large_regime", large_regime_ ? 1 : 0);
    w.integer("large_evals", large_evals_);
    w.integer("small_evals", small_evals_);
    w.integer("last_large_evals", last_large_evals_);
    w.integer("iteration", iteration_);
    w.integer("evaluations", evaluations_);
    w.integer("non_finite", non_finite_);
    w.integer("stopped", static_cast<std::int64_t>(stopped_));
    w.integer("last_run_criterion", static_cast<std::int64_t>(last_run_criterion_));
    w.integer("finished_runs", static_cast<std::int64_t>(finished_runs_.size()));
    for (const run_record& f : finished_runs_) {
      w.integer("finished_run_lambda", f.population_size);
      w.real("finished_run_sigma0", f.sigma0);
      w.integer("finished_run_small", f.small_population ? 1 : 0);
      w.integer("finished_run_iterations", f.iterations);
      w.integer("finished_run_evaluations", f.evaluations);
      w.real("finished_run_best", f.best_value);
      w.integer("finished_run_stopped", static_cast<std::int64_t>(f.stopped));
    }
    w.real("best_value", best_value_);
    w.vector("best_x", best_x_);
    w.rng("restart_rng", rng_);
    // Options of the current run, to rebuild it before loading its state.
    w.integer("run_lambda", run_opt_.population_size);
    w.real("run_sigma0", run_opt_.sigma0);
    w.integer("run_seed", static_cast<std::int64_t>(run_opt_.seed));
    w.integer("run_max_iterations", run_opt_.stop.max_iterations);
    w.integer("run_max_evaluations", run_opt_.stop.max_evaluations);
    w.vector("run_x0", run_opt_.x0);
    run_->save(w);
  }

  void load(checkpoint_reader& r) {
    restarts_ = static_cast<int>(r.integer("restarts"));
    large_restarts_ = static_cast<int>(r.integer("large_restarts"));
    large_regime_ = r.integer("large_regime") != 0;
    large_evals_ = r.integer("large_evals");
    small_evals_ = r.integer("small_evals");
    last_large_evals_ = r.integer("last_large_evals");
    iteration_ = r.integer("iteration");
    evaluations_ = r.integer("evaluations");
    non_finite_ = r.integer("non_finite");
    stopped_ = static_cast<stop_criterion>(r.integer("stopped"));
    last_run_criterion_ = static_cast<stop_criterion>(r.integer("last_run_criterion"));
    const std::int64_t num_finished = r.integer("finished_runs");
    if (num_finished < 0) throw std::runtime_error("checkpoint: 'finished_runs' is negative");
    // One record at a time: a corrupt count fails as a short file rather than allocating first.
    finished_runs_.clear();
    for (std::int64_t k = 0; k < num_finished; ++k) {
      run_record& f = finished_runs_.emplace_back();
      f.population_size = static_cast<int>(r.integer("finished_run_lambda"));
      f.sigma0 = r.real("finished_run_sigma0");
      f.small_population = r.integer("finished_run_small") != 0;
      f.iterations = r.integer("finished_run_iterations");
      f.evaluations = r.integer("finished_run_evaluations");
      f.best_value = r.real("finished_run_best");
      f.stopped = static_cast<stop_criterion>(r.integer("finished_run_stopped"));
    }
    best_value_ = r.real("best_value");
    best_x_ = r.vector("best_x", space_.size());
    r.rng("restart_rng", rng_);
    cmaes_options o = base_;
    o.population_size = static_cast<int>(r.integer("run_lambda"));
    o.sigma0 = r.real("run_sigma0");
    o.seed = static_cast<std::uint64_t>(r.integer("run_seed"));
    o.stop.max_iterations = r.integer("run_max_iterations");
    o.stop.max_evaluations = r.integer("run_max_evaluations");
    o.x0 = r.vector("run_x0");
    run_opt_ = o;
    run_ = std::make_unique<cmaes>(space_, run_opt_);
    run_->load(r);
  }

 private:
  void start_next_run() {
    cmaes_options o = base_;
    o.seed = rng_();
    const auto& t = base_.stop;
    bool large = true;
    int lambda = 0;
    if (ro_.strategy == restart_strategy::bipop && small_evals_ < large_evals_) {
      // Small-population regime ([Hansen 2009]): lambda in [lambda_default, lambda_large / 2] for
      // the latest large run's lambda_large (run 0 counts as small, so there is one), sigma0 scaled
      // by 10^(-2U). The ratio is at least 1 so a population_factor below 2 cannot push lambda
      // below the default.
      large = false;
      const double u = detail::uniform01(rng_);
      const double ratio = std::max(1.0, 0.5 * large_run_lambda(large_restarts_) / lambda0_);
      lambda = static_cast<int>(std::floor(lambda0_ * std::pow(ratio, u * u)));
      o.sigma0 = base_.sigma0 * std::pow(10.0, -2.0 * detail::uniform01(rng_));
      const std::int64_t cap = std::max<std::int64_t>(1, last_large_evals_ / 2);
      o.stop.max_iterations = std::max<std::int64_t>(1, cap / lambda);
      if (base_.stop.max_iterations > 0)
        o.stop.max_iterations = std::min(o.stop.max_iterations, base_.stop.max_iterations);
    } else {
      ++large_restarts_;
      lambda = large_run_lambda(large_restarts_);
    }
    large_regime_ = large;
    o.population_size = std::max(2, lambda);
    if (t.max_evaluations > 0) o.stop.max_evaluations = t.max_evaluations - evaluations_;
    // The target and no-improvement tests stay per run (they are in base_.stop).
    if (ro_.random_initial_mean) {
      const Eigen::VectorXd lo = space_.normalized_lower(), hi = space_.normalized_upper();
      Eigen::VectorXd m(space_.size());
      for (Eigen::Index i = 0; i < m.size(); ++i) {
        const double a = std::isfinite(lo[i]) ? lo[i] : m0_[i] - 2.0 * base_.sigma0;
        const double b = std::isfinite(hi[i]) ? hi[i] : m0_[i] + 2.0 * base_.sigma0;
        m[i] = a + (b - a) * detail::uniform01(rng_);
      }
      o.x0 = space_.to_user(m);
    } else {
      o.x0 = space_.initial();
    }
    run_opt_ = o;
    run_ = std::make_unique<cmaes>(space_, run_opt_);
    ++restarts_;
  }

  /// Population of the i-th large-population restart (i = 0: the default lambda of run 0).
  int large_run_lambda(int i) const {
    if (i > 0 && ro_.unrounded_population_base && base_.population_size == 0) {
      const double unrounded = 4.0 + 3.0 * std::log(static_cast<double>(space_.size()));
      return static_cast<int>(std::floor(unrounded * std::pow(ro_.population_factor, i)));
    }
    return static_cast<int>(std::lround(lambda0_ * std::pow(ro_.population_factor, i)));
  }

  run_record current_run_record() const {
    run_record rec;
    rec.population_size = run_->population_size();
    rec.sigma0 = run_opt_.sigma0;
    rec.small_population = restarts_ > 0 && !large_regime_;
    rec.iterations = run_->iteration();
    rec.evaluations = run_->evaluations();
    rec.best_value = run_->best_value();
    rec.stopped = run_->stopped();
    return rec;
  }

  cmaes_options base_;
  restart_options ro_;
  parameter_space space_;
  std::unique_ptr<cmaes> run_;
  cmaes_options run_opt_;
  int lambda0_ = 0;
  Eigen::VectorXd m0_;
  std::mt19937_64 rng_;
  int restarts_ = 0, large_restarts_ = 0;
  // Run 0 is accounted with the small-population budget (pycma: it is the large population
  // before the first doubling), so BIPOP's first restart is a large one.
  bool large_regime_ = false;
  std::int64_t large_evals_ = 0, small_evals_ = 0, last_large_evals_ = 0;
  std::int64_t iteration_ = 0, evaluations_ = 0, non_finite_ = 0;
  double best_value_ = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd best_x_;
  stop_criterion stopped_ = stop_criterion::none, last_run_criterion_ = stop_criterion::none;
  std::vector<run_record> finished_runs_;
};

static_assert(optimizer<cmaes_restarts>);

}  // namespace gaitsynth
