#pragma once
/// \file problem_with_constraint.hpp
/// A problem whose candidates must also satisfy a constraint measured on its own rollout, ranked
/// by Deb's feasibility rules (K. Deb, "An efficient constraint handling method for genetic
/// algorithms", Comput. Methods Appl. Mech. Engrg. 186, 2000): a feasible candidate beats every
/// infeasible one, feasible ones compare by cost, infeasible ones by how far they violate the
/// constraint. CMA-ES and SDS use only the order of the costs, so the rules become one cost:
///
///   C'(x, T) = C(x, T)                               if v(x) == 0,
///              infeasible_cost * (1 + v(x))          if v(x) > 0,
///              +infinity                             if v(x) is NaN (as a diverged rollout),
///
/// with infeasible_cost above every feasible cost (checked: a feasible cost that reaches it is
/// an error, never a silent misranking). A penalty weight cannot do this when the cost's other
/// terms span orders of magnitude: a pushed rollout's fall costs 1e5-1e6 in Wang et al. 2009's
/// eq. 16, so any weight on a small violation either gives way to the falls or swamps the
/// ranking among feasible candidates.
///
///   auto violation = [](const auto& ctx) { return my_measure(*ctx.states.objective); };
///   auto constrained = make_problem_with_constraint(prob, violation);
///   auto robust = make_problem_with_variants(constrained, robust_variants(prob, vo));
///
/// v reads the main problem's context right after its cost (for a rollout_problem: the last
/// rollout's objective accumulator, ctx.states.objective), so it judges the main rollout alone,
/// not the variants a problem_with_variants adds around it. It must return a value >= 0, 0 when
/// the candidate is feasible.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <utility>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

template <class Main, class Violation>
struct problem_with_constraint : Main {
  using context_type = typename Main::context_type;

  Violation violation;            ///< v(const context_type&) -> double, after Main::cost
  double infeasible_cost = 1e15;  ///< above every feasible cost

  /// The main problem.
  const Main& main() const { return *this; }

  double cost(const Eigen::VectorXd& x, double horizon, context_type& ctx) const {
    const double c = Main::cost(x, horizon, ctx);
    const double v = violation(static_cast<const context_type&>(ctx));
    if (std::isnan(v)) return std::numeric_limits<double>::infinity();
    check_argument(v >= 0.0, "problem_with_constraint: the violation must be >= 0, got ", v);
    if (v > 0.0) return infeasible_cost * (1.0 + v);
    check_argument(!(c >= infeasible_cost) || c == std::numeric_limits<double>::infinity(),
                   "problem_with_constraint: a feasible candidate's cost ", c,
                   " reaches infeasible_cost ", infeasible_cost, "; raise infeasible_cost");
    return c;
  }
  double cost(const Eigen::VectorXd& x, double horizon) const {
    auto ctx = Main::make_context();
    return cost(x, horizon, ctx);
  }
};

/// Builds a problem_with_constraint; throws std::invalid_argument if infeasible_cost is not finite
/// and > 0.
template <class Main, class Violation>
problem_with_constraint<Main, Violation> make_problem_with_constraint(
    Main main, Violation violation, double infeasible_cost = 1e15) {
  check_argument(std::isfinite(infeasible_cost) && infeasible_cost > 0.0,
                 "make_problem_with_constraint: infeasible_cost must be finite and > 0, got ",
                 infeasible_cost);
  return {std::move(main), std::move(violation), infeasible_cost};
}

}  // namespace gaitsynth
