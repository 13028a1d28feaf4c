#pragma once
/// \file sds.hpp
/// SDS, the simple deterministic search (coordinate search) of Sharon & van de Panne 2005,
/// Sec. IV and Fig. 2: for each free parameter i in turn, evaluate C(theta + alpha Delta_i e_i)
/// and C(theta - alpha Delta_i e_i); if the better of the two improves on C(theta), move theta
/// there at once (greedy hill climbing, the next coordinate starts from the new theta). When a
/// whole sweep over the parameters finds no improvement, shrink alpha (coarse to fine: alpha *=
/// shrink) and sweep again; stop when alpha < min_step or a budget is used up. Torczon 1997 (their
/// reference [17]) gives the convergence theory of this class of pattern searches.
///
/// Conventions shared with CMA-ES: the search runs in the normalized coordinates of a
/// parameter_space (alpha and Delta_i in normalized units; candidates outside the bounds are
/// projected onto them, and a candidate that projects onto theta itself is skipped); `ask()`
/// returns user coordinates; non-finite values never win; one iteration is one ask/tell, i.e. one
/// coordinate probe of at most two evaluations, which an evaluator may compute in parallel.
/// SDS draws no random numbers: its results are deterministic.
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"

namespace gaitsynth {

struct sds_options {
  /// Initial perturbation size alpha (normalized units).
  double initial_step = 0.1;
  /// Factor applied to alpha after a sweep without improvement, in (0, 1).
  double shrink = 0.5;
  /// Stop when alpha drops below this.
  double min_step = 1e-6;
  /// Per-parameter perturbation directions' lengths Delta_i (normalized units); empty: all 1.
  Eigen::VectorXd deltas;
  /// Initial point in user coordinates; empty: the parameter space's initial values.
  Eigen::VectorXd x0;
  termination_options stop;
};

class sds {
 public:
  /// Throws std::invalid_argument naming the value for: an empty space, initial_step <= 0,
  /// shrink outside (0, 1), min_step < 0, wrong-sized or negative deltas, wrong-sized x0,
  /// negative budgets.
  sds(parameter_space space, sds_options options)
      : space_(std::move(space)), opt_(std::move(options)) {
    check_argument(space_.size() > 0, "sds: the parameter space is empty");
    check_positive(opt_.initial_step, "sds_options::initial_step");
    check_argument(opt_.shrink > 0 && opt_.shrink < 1,
                   "sds_options::shrink must be in (0, 1), got ", opt_.shrink);
    check_argument(opt_.min_step >= 0 && std::isfinite(opt_.min_step),
                   "sds_options::min_step must be finite and >= 0, got ", opt_.min_step);
    check_argument(opt_.stop.max_iterations >= 0,
                   "termination_options::max_iterations must be >= 0, got ",
                   opt_.stop.max_iterations);
    check_argument(opt_.stop.max_evaluations >= 0,
                   "termination_options::max_evaluations must be >= 0, got ",
                   opt_.stop.max_evaluations);
    check_argument(opt_.stop.no_improvement_iterations >= 0,
                   "termination_options::no_improvement_iterations must be >= 0, got ",
                   opt_.stop.no_improvement_iterations);
    check_argument(!std::isnan(opt_.stop.target_value),
                   "termination_options::target_value must not be NaN");
    if (opt_.x0.size() > 0) {
      check_size(opt_.x0.size(), space_.size(), "sds_options::x0");
      space_ = space_.with_initial(opt_.x0);
    }
    const Eigen::Index n = space_.size();
    if (opt_.deltas.size() == 0) opt_.deltas = Eigen::VectorXd::Ones(n);
    check_size(opt_.deltas.size(), n, "sds_options::deltas");
    check_finite(opt_.deltas, "sds_options::deltas");
    check_argument((opt_.deltas.array() >= 0).all(), "sds_options::deltas must be >= 0");
    theta_ = space_.initial_normalized();
    alpha_ = opt_.initial_step;
    best_x_ = space_.initial();
    // The first batch is the initial point itself.
    points_ = {theta_};
    candidates_ = {space_.to_user(theta_)};
  }

  std::string_view name() const { return "sds"; }

  const std::vector<Eigen::VectorXd>& ask() { return candidates_; }

  void tell(std::span<const double> values) {
    check_size(static_cast<std::ptrdiff_t>(values.size()),
               static_cast<std::ptrdiff_t>(candidates_.size()), "sds::tell values");
    ++iteration_;
    evaluations_ += static_cast<std::int64_t>(values.size());
    batch_values_.clear();
    int winner = -1;
    double winner_f = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < values.size(); ++k) {
      const double f = values[k];
      if (!std::isfinite(f)) {
        ++non_finite_;
        continue;
      }
      batch_values_.push_back(f);
      if (f < winner_f) {
        winner_f = f;
        winner = static_cast<int>(k);
      }
    }
    std::sort(batch_values_.begin(), batch_values_.end());
    if (!initialized_) {
      initialized_ = true;
      f_theta_ = winner >= 0 ? winner_f : std::numeric_limits<double>::infinity();
      if (winner >= 0) {
        best_value_ = winner_f;
        best_x_ = candidates_[0];
        last_improvement_ = iteration_;
      }
      coordinate_ = 0;
    } else {
      if (winner >= 0 && winner_f < f_theta_) {  // greedy acceptance (strict improvement)
        theta_ = points_[static_cast<std::size_t>(winner)];
        f_theta_ = winner_f;
        best_value_ = winner_f;
        best_x_ = candidates_[static_cast<std::size_t>(winner)];
        sweep_improved_ = true;
        last_improvement_ = iteration_;
      }
      ++coordinate_;
    }
    prepare_batch();
    check_stop();
  }

  stop_criterion stopped() const { return stopped_; }
  const Eigen::VectorXd& best_x() const { return best_x_; }
  double best_value() const { return best_value_; }
  const parameter_space& space() const { return space_; }
  const sds_options& options() const { return opt_; }
  double step() const { return alpha_; }
  /// Current point theta (normalized coordinates).
  const Eigen::VectorXd& theta() const { return theta_; }
  std::int64_t sweeps() const { return sweeps_; }

  optimizer_status status() const {
    optimizer_status s;
    s.iteration = iteration_;
    s.evaluations = evaluations_;
    s.best_value = best_value_;
    if (!batch_values_.empty()) {
      s.iteration_best = batch_values_.front();
      s.iteration_worst = batch_values_.back();
      const std::size_t m = batch_values_.size();
      s.iteration_median =
          m % 2 ? batch_values_[m / 2] : 0.5 * (batch_values_[m / 2 - 1] + batch_values_[m / 2]);
    }
    s.step_size = alpha_;
    s.axis_ratio = 1.0;
    s.non_finite = non_finite_;
    s.batch_size = static_cast<int>(candidates_.size());
    double frac = std::numeric_limits<double>::quiet_NaN();
    if (opt_.stop.max_evaluations > 0)
      frac = static_cast<double>(evaluations_) / static_cast<double>(opt_.stop.max_evaluations);
    if (opt_.stop.max_iterations > 0) {
      const double fi =
          static_cast<double>(iteration_) / static_cast<double>(opt_.stop.max_iterations);
      frac = std::isnan(frac) ? fi : std::max(frac, fi);
    }
    if (opt_.min_step > 0 && alpha_ > 0) {
      // Shrinks left until min_step, as a fraction of the total number of shrinks.
      const double total = std::log(opt_.min_step / opt_.initial_step) / std::log(opt_.shrink);
      const double done = std::log(alpha_ / opt_.initial_step) / std::log(opt_.shrink);
      if (total > 0) {
        const double fa = std::clamp(done / total, 0.0, 1.0);
        frac = std::isnan(frac) ? fa : std::max(frac, fa);
      }
    }
    s.budget_fraction = std::isnan(frac) ? frac : std::min(1.0, frac);
    s.stopped = stopped_;
    return s;
  }

  void save(checkpoint_writer& w) const {
    w.integer("n", space_.size());
    w.integer("initialized", initialized_ ? 1 : 0);
    w.integer("iteration", iteration_);
    w.integer("evaluations", evaluations_);
    w.integer("non_finite", non_finite_);
    w.integer("sweeps", sweeps_);
    w.integer("coordinate", coordinate_);
    w.integer("sweep_improved", sweep_improved_ ? 1 : 0);
    w.integer("min_step_reached", min_step_reached_ ? 1 : 0);
    w.integer("last_improvement", last_improvement_);
    w.integer("stopped", static_cast<std::int64_t>(stopped_));
    w.vector("theta", theta_);
    w.real("f_theta", f_theta_);
    w.real("alpha", alpha_);
    w.real("best_value", best_value_);
    w.vector("best_x", best_x_);
    w.reals("batch_values", batch_values_);
    w.vectors("points", points_);
    w.vectors("candidates", candidates_);
  }

  void load(checkpoint_reader& r) {
    const Eigen::Index n = space_.size();
    r.require("n", n);
    initialized_ = r.integer("initialized") != 0;
    iteration_ = r.integer("iteration");
    evaluations_ = r.integer("evaluations");
    non_finite_ = r.integer("non_finite");
    sweeps_ = r.integer("sweeps");
    coordinate_ = r.integer("coordinate");
    sweep_improved_ = r.integer("sweep_improved") != 0;
    min_step_reached_ = r.integer("min_step_reached") != 0;
    last_improvement_ = r.integer("last_improvement");
    stopped_ = static_cast<stop_criterion>(r.integer("stopped"));
    theta_ = r.vector("theta", n);
    for (Eigen::Index i = 0; i < n; ++i)
      if (!std::isfinite(theta_[i]))
        r.error("theta component " + std::to_string(i) + " is " + std::to_string(theta_[i]) +
                ", not a finite number");
    f_theta_ = r.real("f_theta");
    alpha_ = r.real("alpha");
    if (!(std::isfinite(alpha_) && alpha_ >= 0))
      r.error("alpha is " + std::to_string(alpha_) + ", not a finite number >= 0");
    best_value_ = r.real("best_value");
    best_x_ = r.vector("best_x", n);
    batch_values_ = r.reals("batch_values");
    points_ = r.vectors("points");
    candidates_ = r.vectors("candidates");
    if (points_.size() != candidates_.size())
      throw std::runtime_error("checkpoint: sds batch is inconsistent");
  }

 private:
  // Builds the next coordinate's batch, ending sweeps (and shrinking alpha) as needed.
  void prepare_batch() {
    const Eigen::Index n = space_.size();
    points_.clear();
    candidates_.clear();
    // Skips coordinates with no admissible move; ends the sweep (maybe shrinking alpha) at n.
    for (;;) {
      if (coordinate_ >= n) {
        ++sweeps_;
        coordinate_ = 0;
        if (!sweep_improved_) {
          alpha_ *= opt_.shrink;
          if (alpha_ < opt_.min_step || alpha_ == 0.0) {
            min_step_reached_ = true;
            return;
          }
        }
        sweep_improved_ = false;
      }
      const Eigen::Index i = static_cast<Eigen::Index>(coordinate_);
      for (const double sign : {1.0, -1.0}) {
        Eigen::VectorXd p = theta_;
        p[i] += sign * alpha_ * opt_.deltas[i];
        p = space_.project_normalized(p);
        if (p[i] == theta_[i]) continue;  // no move (at a bound, or Delta_i = 0)
        points_.push_back(p);
        candidates_.push_back(space_.to_user(p));
      }
      if (!points_.empty()) return;
      ++coordinate_;
    }
  }

  void check_stop() {
    using sc = stop_criterion;
    const auto& t = opt_.stop;
    auto set = [&](sc c) {
      if (stopped_ == sc::none) stopped_ = c;
    };
    if (best_value_ < t.target_value) set(sc::target_value);  // strict; false for NaN
    if (t.max_evaluations > 0 && evaluations_ >= t.max_evaluations) set(sc::max_evaluations);
    if (t.max_iterations > 0 && iteration_ >= t.max_iterations) set(sc::max_iterations);
    if (t.no_improvement_iterations > 0 &&
        iteration_ - last_improvement_ >= t.no_improvement_iterations)
      set(sc::no_improvement);
    if (min_step_reached_) set(sc::min_step);
  }

  parameter_space space_;
  sds_options opt_;
  Eigen::VectorXd theta_;
  double f_theta_ = std::numeric_limits<double>::infinity();
  double alpha_ = 0;
  std::int64_t coordinate_ = 0, sweeps_ = 0;
  bool sweep_improved_ = false, initialized_ = false, min_step_reached_ = false;
  std::vector<Eigen::VectorXd> points_, candidates_;
  std::vector<double> batch_values_;
  std::int64_t iteration_ = 0, evaluations_ = 0, non_finite_ = 0, last_improvement_ = 0;
  double best_value_ = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd best_x_;
  stop_criterion stopped_ = stop_criterion::none;
};

static_assert(optimizer<sds>);

}  // namespace gaitsynth
