#pragma once
/// \file cmaes.hpp
/// CMA-ES, the (mu/mu_w, lambda) covariance matrix adaptation evolution strategy, as specified in
/// N. Hansen, "The CMA Evolution Strategy: A Tutorial", arXiv:1604.00772 (2016), referred to as
/// [T] below: default strategy parameters of [T] Table 1 including the negative ("active")
/// recombination weights, the update equations (Eqs. (39)-(47) of [T] Fig. 6), the h_sigma stall
/// of p_c, and the lazy eigendecomposition of C ([T] Sec. B.2). pycma (the reference
/// implementation) uses the same defaults with active covariance update on.
///
/// Deviations from [T], each taken from pycma:
///  - the change of log(sigma) per generation is capped at 1 (pycma's default), which only
///    matters when sigma0 is far too small;
///  - the eigendecomposition is refreshed every max(1, floor(g / ((c_1 + c_mu) n))) generations
///    with g = `eigen_gap` = 0.5 (purecma's gap; [T] suggests g = 0.1); sampling and the p_sigma
///    update use the last decomposition (which C^{-1/2} is consistently taken from).
///
/// The strategy works in the normalized coordinates of a parameter_space; `ask()` returns user
/// coordinates. Bounds are handled in normalized coordinates, by rejection sampling (Wu 2010:
/// redraw a candidate until it lies inside the bounds, at most `max_resamples` times), by
/// repair: the objective is evaluated at the projection onto the box and the ranking value is
/// f(projection) + penalty_weight * ||x - projection||^2, while the strategy keeps the unrepaired
/// sample (so its distribution update stays unbiased and the penalty pulls it back), or by
/// pycma's default, a transformation: the objective is evaluated at T(x), T the smooth map into the
/// box of bound_transform.hpp (the identity inside, away from the bounds), with no redraw and no
/// penalty, and the strategy again keeps x; the mean then starts at T^{-1}(initial point), so that
/// T(mean) is the initial point. The default is rejection sampling, falling back to repair for a
/// candidate that is still outside after `max_resamples` draws (e.g. when the optimum sits on a
/// bound).
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/bound_transform.hpp"
#include "gaitsynth/optimizers/checkpoint.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"
#include "gaitsynth/optimizers/random.hpp"

namespace gaitsynth {

enum class bound_handling {
  resample,  ///< rejection sampling (Wu 2010), repair after max_resamples failed draws (default)
  repair,    ///< projection onto the box plus a quadratic penalty on the distance
  /// pycma's default: the objective sees T(x), a smooth map into the box that is the identity
  /// inside it (bound_transform.hpp); no redraws, no penalty, the strategy keeps x
  transform,
};

struct cmaes_options {
  /// Initial step size, in normalized units (Wu 2010: 0.3 on [0, 1]; Wang 2009: 0.0025).
  double sigma0 = 0.3;
  /// Population size lambda; 0: 4 + floor(3 ln n) ([T] Eq. (48)). Must be >= 2 otherwise.
  int population_size = 0;
  /// Seed of the std::mt19937_64 that draws all samples. Every value (0 included) is a seed.
  std::uint64_t seed = 0;
  /// Initial mean in user coordinates; empty: the parameter space's initial values.
  Eigen::VectorXd x0;
  /// Active covariance matrix update (negative weights for the lambda - mu worst) as [T] and
  /// pycma do by default; false: the classic update with zero weights for them.
  bool active = true;
  bound_handling bounds = bound_handling::resample;
  int max_resamples = 100;
  /// Weight of the squared distance (normalized units) between sample and repaired point.
  double penalty_weight = 1.0;
  /// Lazy eigendecomposition gap factor g (see the file comment); 0: decompose every generation.
  double eigen_gap = 0.5;

  termination_options stop;
  /// Stop when the mean moves less than this (max-norm, normalized units) in one generation
  /// (Wu 2010: 1e-3). 0: off.
  double tol_mean_change = 0.0;
  /// pycma's defaults for the usual guards ([T] Sec. B.3). 0 (or inf for the last two) disables.
  double tol_fun = 1e-11;
  double tol_x = 1e-11;
  double max_condition = 1e14;
  double tol_up_sigma = 1e20;
  bool no_effect_axis = true;
  bool no_effect_coordinate = true;
};

/// Strategy parameters derived from n and lambda ([T] Table 1).
struct cmaes_parameters {
  int n = 0, lambda = 0, mu = 0;
  Eigen::VectorXd weights;  ///< lambda weights, sum of the mu positive ones = 1
  double mu_eff = 0, mu_eff_minus = 0;
  double c_sigma = 0, d_sigma = 0, c_c = 0, c_1 = 0, c_mu = 0, c_m = 1;
  double chi_n = 0;  ///< E||N(0, I)||
  std::int64_t eigen_gap_iterations = 1;

  static cmaes_parameters make(int n, int lambda, bool active, double eigen_gap) {
    cmaes_parameters p;
    p.n = n;
    p.lambda = lambda;
    p.mu = lambda / 2;
    const double N = n;
    // [T] Eq. (49): w'_i = ln((lambda + 1) / 2) - ln i, i = 1..lambda.
    Eigen::VectorXd wp(lambda);
    for (int i = 0; i < lambda; ++i) wp[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
    double sum_pos = 0, sum_pos2 = 0, sum_neg = 0, sum_neg2 = 0;
    for (int i = 0; i < lambda; ++i) {
      if (wp[i] > 0) {
        sum_pos += wp[i];
        sum_pos2 += wp[i] * wp[i];
      } else {
        sum_neg += -wp[i];
        sum_neg2 += wp[i] * wp[i];
      }
    }
    p.mu_eff = sum_pos * sum_pos / sum_pos2;
    p.mu_eff_minus = sum_neg2 > 0 ? sum_neg * sum_neg / sum_neg2 : 0.0;
    // [T] Eqs. (55)-(58).
    const double alpha_cov = 2.0;
    p.c_sigma = (p.mu_eff + 2.0) / (N + p.mu_eff + 5.0);
    p.d_sigma =
        1.0 + 2.0 * std::max(0.0, std::sqrt((p.mu_eff - 1.0) / (N + 1.0)) - 1.0) + p.c_sigma;
    p.c_c = (4.0 + p.mu_eff / N) / (N + 4.0 + 2.0 * p.mu_eff / N);
    p.c_1 = alpha_cov / ((N + 1.3) * (N + 1.3) + p.mu_eff);
    p.c_mu = std::min(1.0 - p.c_1, alpha_cov * (p.mu_eff - 2.0 + 1.0 / p.mu_eff) /
                                       ((N + 2.0) * (N + 2.0) + alpha_cov * p.mu_eff / 2.0));
    // [T] Eqs. (50)-(53): positive weights sum to 1; negative ones scaled by the smallest of
    // alpha_mu^- (no decay of C), alpha_mueff^- and alpha_posdef^- (C stays positive definite).
    const double alpha_mu_minus = 1.0 + p.c_1 / p.c_mu;
    const double alpha_mueff_minus = 1.0 + 2.0 * p.mu_eff_minus / (p.mu_eff + 2.0);
    const double alpha_posdef_minus = (1.0 - p.c_1 - p.c_mu) / (N * p.c_mu);
    const double neg_scale =
        std::min({alpha_mu_minus, alpha_mueff_minus, alpha_posdef_minus}) / sum_neg;
    p.weights.resize(lambda);
    for (int i = 0; i < lambda; ++i)
      p.weights[i] = wp[i] >= 0 ? wp[i] / sum_pos : (active ? neg_scale * wp[i] : 0.0);
    p.chi_n = std::sqrt(N) * (1.0 - 1.0 / (4.0 * N) + 1.0 / (21.0 * N * N));
    if (eigen_gap > 0)
      p.eigen_gap_iterations = std::max<std::int64_t>(
          1, static_cast<std::int64_t>(std::floor(eigen_gap / ((p.c_1 + p.c_mu) * N))));
    return p;
  }
};

/// CMA-ES with ask/tell; satisfies the `optimizer` concept. See the file comment.
class cmaes {
 public:
  /// Throws std::invalid_argument naming the value for: an empty space, sigma0 <= 0 (or not
  /// finite), population_size < 2 (other than 0 = default), a wrong-sized or out-of-bounds x0,
  /// max_resamples < 0, penalty_weight < 0, negative tolerances or budgets.
  cmaes(parameter_space space, cmaes_options options)
      : space_(std::move(space)), opt_(std::move(options)) {
    check_argument(space_.size() > 0, "cmaes: the parameter space is empty");
    check_positive(opt_.sigma0, "cmaes_options::sigma0");
    check_argument(opt_.population_size == 0 || opt_.population_size >= 2,
                   "cmaes_options::population_size (lambda) must be >= 2 (or 0 for the default), "
                   "got ",
                   opt_.population_size);
    check_argument(opt_.max_resamples >= 0, "cmaes_options::max_resamples must be >= 0, got ",
                   opt_.max_resamples);
    check_argument(std::isfinite(opt_.penalty_weight) && opt_.penalty_weight >= 0,
                   "cmaes_options::penalty_weight must be finite and >= 0, got ",
                   opt_.penalty_weight);
    check_argument(opt_.eigen_gap >= 0, "cmaes_options::eigen_gap must be >= 0, got ",
                   opt_.eigen_gap);
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
    for (auto [v, what] :
         {std::pair{opt_.tol_mean_change, "tol_mean_change"}, std::pair{opt_.tol_fun, "tol_fun"},
          std::pair{opt_.tol_x, "tol_x"}, std::pair{opt_.max_condition, "max_condition"},
          std::pair{opt_.tol_up_sigma, "tol_up_sigma"}})
      check_argument(v >= 0, "cmaes_options::", what, " must be >= 0, got ", v);
    if (opt_.x0.size() > 0) {
      check_size(opt_.x0.size(), space_.size(), "cmaes_options::x0");
      space_ = space_.with_initial(opt_.x0);
    }

    n_ = static_cast<int>(space_.size());
    const int lambda = opt_.population_size > 0
                           ? opt_.population_size
                           : 4 + static_cast<int>(std::floor(3.0 * std::log(n_)));
    // The samples (Z, Y and the candidates: 3 lambda n doubles) must fit in memory: a population
    // beyond any machine's would otherwise end in std::bad_alloc or the OOM killer, not a message.
    const double sample_bytes = 3.0 * 8.0 * lambda * static_cast<double>(n_);
    check_argument(sample_bytes <= 16e9, "cmaes_options::population_size ", lambda, " with ", n_,
                   " parameters needs ", sample_bytes / 1e9,
                   " GB for its samples; the limit is 16 GB");
    p_ = cmaes_parameters::make(n_, lambda, opt_.active, opt_.eigen_gap);
    max_iterations_ =
        opt_.stop.max_iterations > 0
            ? opt_.stop.max_iterations
            : static_cast<std::int64_t>(100.0 + 150.0 * (n_ + 3.0) * (n_ + 3.0) /
                                                    std::sqrt(static_cast<double>(lambda)));
    tolfun_window_ = 10 + static_cast<std::size_t>(std::ceil(30.0 * n_ / lambda));

    bounded_ = space_.bounded();
    rng_.seed(opt_.seed);
    lower_ = space_.normalized_lower();
    upper_ = space_.normalized_upper();
    mean_ = space_.initial_normalized();
    // Start where T(mean) is the initial point (as pycma's x0 under BoundTransform), not at a point
    // T would move (every point within the margins of a bound).
    if (transforms()) mean_ = bound_transform_inverse(mean_, lower_, upper_);
    sigma_ = opt_.sigma0;
    C_.setIdentity(n_, n_);
    B_.setIdentity(n_, n_);
    D_.setOnes(n_);
    pc_.setZero(n_);
    ps_.setZero(n_);
    Z_.setZero(n_, lambda);
    Y_.setZero(n_, lambda);
    penalty_.assign(static_cast<std::size_t>(lambda), 0.0);
    candidates_.assign(static_cast<std::size_t>(lambda), Eigen::VectorXd::Zero(n_));
    best_x_ = space_.initial();
    z_.resize(n_);
  }

  std::string_view name() const { return "cmaes"; }

  /// Samples lambda candidates x_k = m + sigma B D z_k ([T] Eqs. (38)-(40)) and returns them in
  /// user coordinates (repaired into the bounds where bound handling repairs, T(x_k) under
  /// bound_handling::transform). Calling ask twice without tell returns the same batch.
  const std::vector<Eigen::VectorXd>& ask() {
    if (asked_) return candidates_;
    const Eigen::Index lambda = p_.lambda;
    for (Eigen::Index k = 0; k < lambda; ++k) {
      Eigen::VectorXd x;
      int draws = 0;
      for (;;) {
        detail::fill_standard_normal(rng_, z_);
        Z_.col(k) = z_;
        Y_.col(k).noalias() = B_ * D_.cwiseProduct(z_);
        x = mean_ + sigma_ * Y_.col(k);
        ++draws;
        if (!bounded_ || opt_.bounds != bound_handling::resample || space_.contains_normalized(x) ||
            draws > opt_.max_resamples)
          break;
      }
      resamples_ += draws - 1;
      double pen = 0.0;
      if (transforms()) {
        x = bound_transform(x, lower_, upper_);  // inside the box: no repair, no penalty
      } else if (bounded_ && !space_.contains_normalized(x)) {
        const Eigen::VectorXd xp = space_.project_normalized(x);
        pen = opt_.penalty_weight * (x - xp).squaredNorm();
        x = xp;
        ++repairs_;
      }
      penalty_[static_cast<std::size_t>(k)] = pen;
      candidates_[static_cast<std::size_t>(k)] = space_.to_user(x);
    }
    asked_ = true;
    return candidates_;
  }

  /// Takes the objective values of the last ask's candidates (same order) and updates mean, step
  /// size, evolution paths and covariance matrix ([T] Fig. 6), then tests the stopping criteria.
  void tell(std::span<const double> values) {
    if (!asked_) throw std::logic_error("cmaes::tell called without a preceding ask");
    check_size(static_cast<std::ptrdiff_t>(values.size()), p_.lambda, "cmaes::tell values");
    asked_ = false;
    const int lambda = p_.lambda, n = n_;
    ++iteration_;
    evaluations_ += lambda;

    // Ranking value: f + penalty for finite f; non-finite values sort after every finite one, in
    // index order (deterministic), and are counted.
    std::vector<int> order(static_cast<std::size_t>(lambda));
    std::iota(order.begin(), order.end(), 0);
    fitness_.resize(static_cast<std::size_t>(lambda));
    bool improved = false;
    finite_values_.clear();
    for (int k = 0; k < lambda; ++k) {
      const double f = values[static_cast<std::size_t>(k)];
      const bool finite = std::isfinite(f);
      if (!finite) ++non_finite_;
      fitness_[static_cast<std::size_t>(k)] = finite ? f + penalty_[static_cast<std::size_t>(k)]
                                                     : std::numeric_limits<double>::infinity();
      if (finite) {
        finite_values_.push_back(f);
        if (!(f >= best_value_)) {  // also true while best_value_ is NaN (nothing yet)
          best_value_ = f;
          best_x_ = candidates_[static_cast<std::size_t>(k)];
          improved = true;
        }
      }
    }
    if (improved) last_improvement_ = iteration_;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      const double fa = fitness_[static_cast<std::size_t>(a)];
      const double fb = fitness_[static_cast<std::size_t>(b)];
      const bool ia = std::isfinite(values[static_cast<std::size_t>(a)]);
      const bool ib = std::isfinite(values[static_cast<std::size_t>(b)]);
      if (ia != ib) return ia;
      return ia && fa < fb;
    });
    std::sort(finite_values_.begin(), finite_values_.end());

    // Recombination: y_w = sum_{i<=mu} w_i y_{i:lambda}, z_w likewise ([T] Eq. (41)).
    Eigen::VectorXd y_w = Eigen::VectorXd::Zero(n), z_w = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < p_.mu; ++i) {
      y_w.noalias() += p_.weights[i] * Y_.col(order[static_cast<std::size_t>(i)]);
      z_w.noalias() += p_.weights[i] * Z_.col(order[static_cast<std::size_t>(i)]);
    }
    const Eigen::VectorXd old_mean = mean_;
    mean_.noalias() += p_.c_m * sigma_ * y_w;  // [T] Eq. (42)

    // Step-size path with C^{-1/2} y_w = B z_w ([T] Eq. (43)).
    ps_ = (1.0 - p_.c_sigma) * ps_ +
          std::sqrt(p_.c_sigma * (2.0 - p_.c_sigma) * p_.mu_eff) * (B_ * z_w);
    const double ps_norm = ps_.norm();
    // h_sigma stall ([T] p. 31 footnote): 1 unless ||p_sigma|| is large after correcting for its
    // initialization at zero.
    const double ps_corr =
        ps_norm /
        std::sqrt(1.0 - std::pow(1.0 - p_.c_sigma, 2.0 * static_cast<double>(iteration_)));
    const bool h_sigma = ps_corr < (1.4 + 2.0 / (n + 1.0)) * p_.chi_n;
    pc_ = (1.0 - p_.c_c) * pc_ +
          (h_sigma ? std::sqrt(p_.c_c * (2.0 - p_.c_c) * p_.mu_eff) : 0.0) * y_w;  // Eq. (45)

    // Covariance matrix update, [T] Eqs. (46)-(47): negative weights are rescaled by
    // n / ||C^{-1/2} y_i||^2 = n / ||z_i||^2.
    const double delta_h = h_sigma ? 0.0 : p_.c_c * (2.0 - p_.c_c);
    const double sum_w = p_.weights.sum();
    Eigen::VectorXd w_circ(lambda);
    for (int i = 0; i < lambda; ++i) {
      const double w = p_.weights[i];
      const double z2 = Z_.col(order[static_cast<std::size_t>(i)]).squaredNorm();
      w_circ[i] = w >= 0 ? w : (z2 > 0 ? w * n / z2 : 0.0);
    }
    Ysorted_.resize(n, lambda);
    for (int i = 0; i < lambda; ++i) Ysorted_.col(i) = Y_.col(order[static_cast<std::size_t>(i)]);
    C_ *= 1.0 + p_.c_1 * delta_h - p_.c_1 - p_.c_mu * sum_w;
    C_.noalias() += p_.c_1 * pc_ * pc_.transpose();
    C_.noalias() += p_.c_mu * (Ysorted_ * w_circ.asDiagonal()) * Ysorted_.transpose();

    // Step size, [T] Eq. (44), with pycma's cap of 1 on the change of log(sigma).
    sigma_ *= std::exp(std::min(1.0, p_.c_sigma / p_.d_sigma * (ps_norm / p_.chi_n - 1.0)));

    if (iteration_ - eigen_iteration_ >= p_.eigen_gap_iterations) decompose();

    // Bookkeeping for termination and status.
    mean_change_ = (mean_ - old_mean).cwiseAbs().maxCoeff();
    const double gen_best = fitness_[static_cast<std::size_t>(order[0])];
    best_history_.push_back(gen_best);
    if (best_history_.size() > tolfun_window_) best_history_.pop_front();
    check_stop();
  }

  stop_criterion stopped() const { return stopped_; }
  const Eigen::VectorXd& best_x() const { return best_x_; }
  double best_value() const { return best_value_; }
  const parameter_space& space() const { return space_; }
  const cmaes_options& options() const { return opt_; }
  const cmaes_parameters& parameters() const { return p_; }

  optimizer_status status() const {
    optimizer_status s;
    s.iteration = iteration_;
    s.evaluations = evaluations_;
    s.best_value = best_value_;
    if (!finite_values_.empty()) {
      s.iteration_best = finite_values_.front();
      s.iteration_worst = finite_values_.back();
      const std::size_t m = finite_values_.size();
      s.iteration_median =
          m % 2 ? finite_values_[m / 2] : 0.5 * (finite_values_[m / 2 - 1] + finite_values_[m / 2]);
    }
    s.step_size = sigma_;
    s.axis_ratio = D_.maxCoeff() / D_.minCoeff();
    s.non_finite = non_finite_;
    s.batch_size = p_.lambda;
    double frac = static_cast<double>(iteration_) / static_cast<double>(max_iterations_);
    if (opt_.stop.max_evaluations > 0)
      frac = std::max(
          frac, static_cast<double>(evaluations_) / static_cast<double>(opt_.stop.max_evaluations));
    s.budget_fraction = std::min(1.0, frac);
    s.stopped = stopped_;
    return s;
  }

  // ---- introspection (normalized coordinates) ----
  const Eigen::VectorXd& mean() const { return mean_; }
  /// The mean in user coordinates; under bound_handling::transform the transformed mean T(m) (the
  /// point the objective would see; m itself may lie outside the box, e.g. at a mirror point
  /// beyond a bound when the optimum is on that bound).
  Eigen::VectorXd mean_user() const {
    return space_.to_user(transforms() ? bound_transform(mean_, lower_, upper_) : mean_);
  }
  double sigma() const { return sigma_; }
  const Eigen::MatrixXd& covariance() const { return C_; }
  const Eigen::VectorXd& axis_lengths() const { return D_; }  ///< sqrt of eigenvalues of C
  int population_size() const { return p_.lambda; }
  int dimension() const { return n_; }
  std::int64_t iteration() const { return iteration_; }
  std::int64_t evaluations() const { return evaluations_; }
  std::int64_t non_finite_count() const { return non_finite_; }
  // Both counts stay 0 under bound_handling::transform.
  std::int64_t resample_count() const { return resamples_; }  ///< redraws by rejection sampling
  std::int64_t repair_count() const { return repairs_; }      ///< candidates projected
  std::int64_t max_iterations() const { return max_iterations_; }

  /// Writes the complete state (see checkpoint.hpp).
  void save(checkpoint_writer& w) const {
    w.integer("n", n_);
    w.integer("lambda", p_.lambda);
    w.integer("asked", asked_ ? 1 : 0);
    w.integer("iteration", iteration_);
    w.integer("evaluations", evaluations_);
    w.integer("non_finite", non_finite_);
    w.integer("resamples", resamples_);
    w.integer("repairs", repairs_);
    w.integer("eigen_iteration", eigen_iteration_);
    w.integer("last_improvement", last_improvement_);
    w.integer("stopped", static_cast<std::int64_t>(stopped_));
    w.rng("rng", rng_);
    w.vector("mean", mean_);
    w.real("sigma", sigma_);
    w.matrix("C", C_);
    w.matrix("B", B_);
    w.vector("D", D_);
    w.vector("pc", pc_);
    w.vector("ps", ps_);
    w.real("best_value", best_value_);
    w.vector("best_x", best_x_);
    w.real("mean_change", mean_change_);
    w.reals("best_history", std::vector<double>(best_history_.begin(), best_history_.end()));
    w.reals("finite_values", finite_values_);
    w.matrix("Z", Z_);
    w.matrix("Y", Y_);
    w.reals("penalty", penalty_);
    w.vectors("candidates", candidates_);
  }

  /// Restores a state written by save() from an optimizer built with the same space and options.
  void load(checkpoint_reader& r) {
    r.require("n", n_);
    r.require("lambda", p_.lambda);
    asked_ = r.integer("asked") != 0;
    iteration_ = r.integer("iteration");
    evaluations_ = r.integer("evaluations");
    non_finite_ = r.integer("non_finite");
    resamples_ = r.integer("resamples");
    repairs_ = r.integer("repairs");
    eigen_iteration_ = r.integer("eigen_iteration");
    last_improvement_ = r.integer("last_improvement");
    stopped_ = static_cast<stop_criterion>(r.integer("stopped"));
    r.rng("rng", rng_);
    mean_ = r.vector("mean", n_);
    for (int i = 0; i < n_; ++i)
      if (!std::isfinite(mean_[i]))
        r.error("mean component " + std::to_string(i) + " is " + std::to_string(mean_[i]) +
                ", not a finite number");
    sigma_ = r.real("sigma");
    if (!(std::isfinite(sigma_) && sigma_ > 0))
      r.error("sigma is " + std::to_string(sigma_) + ", not a finite number > 0");
    C_ = r.matrix("C", n_, n_);
    B_ = r.matrix("B", n_, n_);
    D_ = r.vector("D", n_);
    pc_ = r.vector("pc", n_);
    ps_ = r.vector("ps", n_);
    best_value_ = r.real("best_value");
    best_x_ = r.vector("best_x", n_);
    mean_change_ = r.real("mean_change");
    const auto h = r.reals("best_history");
    best_history_.assign(h.begin(), h.end());
    finite_values_ = r.reals("finite_values");
    Z_ = r.matrix("Z", n_, p_.lambda);
    Y_ = r.matrix("Y", n_, p_.lambda);
    penalty_ = r.reals("penalty");
    candidates_ = r.vectors("candidates");
    if (penalty_.size() != static_cast<std::size_t>(p_.lambda) ||
        candidates_.size() != static_cast<std::size_t>(p_.lambda))
      throw std::runtime_error("checkpoint: cmaes batch has the wrong size");
  }

 private:
  bool transforms() const { return bounded_ && opt_.bounds == bound_handling::transform; }

  void decompose() {
    // Symmetrize (the rank-mu product is symmetric only up to rounding) and decompose C = B D^2
    // B^T.
    C_ = 0.5 * (C_ + C_.transpose()).eval();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C_);
    Eigen::VectorXd ev = es.eigenvalues();
    if (!(ev.minCoeff() > 0.0) || !ev.allFinite()) {
      // Numerically lost positive definiteness (cannot happen in exact arithmetic with the
      // alpha_posdef^- limit): lift the spectrum, as pycma does.
      const double lift =
          -std::min(0.0, ev.minCoeff()) + std::max(1e-300, D_.minCoeff() * D_.minCoeff());
      C_.diagonal().array() += lift;
      ev.array() += lift;
    }
    B_ = es.eigenvectors();
    D_ = ev.cwiseSqrt();
    eigen_iteration_ = iteration_;
  }

  void check_stop() {
    using sc = stop_criterion;
    const auto& t = opt_.stop;
    auto set = [&](sc c) {
      if (stopped_ == sc::none) stopped_ = c;
    };
    if (best_value_ < t.target_value) set(sc::target_value);  // strict; false for NaN
    if (t.max_evaluations > 0 && evaluations_ >= t.max_evaluations) set(sc::max_evaluations);
    if (iteration_ >= max_iterations_) set(sc::max_iterations);
    if (t.no_improvement_iterations > 0 &&
        iteration_ - last_improvement_ >= t.no_improvement_iterations)
      set(sc::no_improvement);
    if (opt_.tol_mean_change > 0 && mean_change_ < opt_.tol_mean_change) set(sc::mean_change);
    if (opt_.tol_fun > 0 && best_history_.size() >= tolfun_window_ && !finite_values_.empty() &&
        finite_values_.size() == static_cast<std::size_t>(p_.lambda)) {
      const auto [lo, hi] = std::minmax_element(best_history_.begin(), best_history_.end());
      const double range =
          std::max(*hi, finite_values_.back()) - std::min(*lo, finite_values_.front());
      if (range < opt_.tol_fun) set(sc::tol_fun);
    }
    if (opt_.tol_x > 0) {
      const double sx = sigma_ * std::max(C_.diagonal().cwiseAbs().cwiseSqrt().maxCoeff(),
                                          pc_.cwiseAbs().maxCoeff());
      if (sx < opt_.tol_x) set(sc::tol_x);
    }
    const double cond = (D_.maxCoeff() / D_.minCoeff()) * (D_.maxCoeff() / D_.minCoeff());
    if (opt_.max_condition > 0 && !(cond <= opt_.max_condition)) set(sc::condition_number);
    if (opt_.tol_up_sigma > 0 && sigma_ * D_.maxCoeff() > opt_.tol_up_sigma * opt_.sigma0)
      set(sc::tol_up_sigma);
    if (opt_.no_effect_axis) {
      // [T] B.3 NoEffectAxis: axis i = g mod n, step 0.1 sigma sqrt(lambda_i) b_i.
      const Eigen::Index i = static_cast<Eigen::Index>(iteration_ % n_);
      const Eigen::VectorXd shifted = mean_ + 0.1 * sigma_ * D_[i] * B_.col(i);
      if ((shifted.array() == mean_.array()).all()) set(sc::no_effect_axis);
    }
    if (opt_.no_effect_coordinate) {
      const Eigen::VectorXd shifted = mean_ + 0.2 * sigma_ * C_.diagonal().cwiseAbs().cwiseSqrt();
      if ((shifted.array() == mean_.array()).any()) set(sc::no_effect_coordinate);
    }
  }

  parameter_space space_;
  cmaes_options opt_;
  cmaes_parameters p_;
  int n_ = 0;
  std::int64_t max_iterations_ = 0;
  std::size_t tolfun_window_ = 0;
  bool bounded_ = false;
  Eigen::VectorXd lower_, upper_;  ///< normalized bounds (for bound_handling::transform)

  std::mt19937_64 rng_;
  Eigen::VectorXd mean_, pc_, ps_, D_, z_;
  double sigma_ = 0;
  Eigen::MatrixXd C_, B_, Z_, Y_, Ysorted_;
  std::vector<double> penalty_, fitness_, finite_values_;
  std::vector<Eigen::VectorXd> candidates_;
  bool asked_ = false;
  std::int64_t iteration_ = 0, evaluations_ = 0, non_finite_ = 0, resamples_ = 0, repairs_ = 0;
  std::int64_t eigen_iteration_ = 0, last_improvement_ = 0;
  double best_value_ = std::numeric_limits<double>::quiet_NaN();
  Eigen::VectorXd best_x_;
  double mean_change_ = std::numeric_limits<double>::infinity();
  std::deque<double> best_history_;
  stop_criterion stopped_ = stop_criterion::none;
};

static_assert(optimizer<cmaes>);

}  // namespace gaitsynth
