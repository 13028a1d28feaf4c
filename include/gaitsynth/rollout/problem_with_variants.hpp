#pragma once
/// \file problem_with_variants.hpp
/// A problem whose cost also counts rollouts of the same controller in situations it cannot sense:
/// other terrains, bodies, start states or pushes (Sharon & van de Panne 2005, section VII: "the
/// addition of disturbances during the controller evaluation may encourage robustness"). It is
/// the main problem (whose character, controller, starts and evaluate() it inherits: a long test
/// rollout runs on the main problem) with the cost
///
///   C(x, T) = C_main(x, T) + variant_weight * sum_k C_k(x, T),
///
/// each variant being a problem of its own (another Terrain or model type is fine). Only the main
/// problem's controller is optimized; the variants' controllers must take the same parameter
/// vector (checked by make_problem_with_variants). Problems with variants nest. Its context holds
/// one context per variant, so each scratch only ever serves one model.
#include <Eigen/Core>
#include <cmath>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

template <class Main, class Variant>
struct problem_with_variants : Main {
  struct context_type {
    typename Main::context_type main;
    std::vector<typename Variant::context_type> variants;
  };

  std::vector<Variant> variants;
  double variant_weight = 1.0;

  /// The main problem (itself possibly a problem with variants).
  const Main& main() const { return *this; }

  context_type make_context() const {
    context_type ctx{Main::make_context(), {}};
    ctx.variants.reserve(variants.size());
    for (const Variant& v : variants) ctx.variants.push_back(v.make_context());
    return ctx;
  }

  double cost(const Eigen::VectorXd& x, double horizon, context_type& ctx) const {
    double c = Main::cost(x, horizon, ctx.main);
    for (std::size_t k = 0; k < variants.size(); ++k)
      c += variant_weight * variants[k].cost(x, horizon, ctx.variants[k]);
    return c;
  }
  double cost(const Eigen::VectorXd& x, double horizon) const {
    auto ctx = make_context();
    return cost(x, horizon, ctx);
  }
};

/// Builds a problem_with_variants; throws std::invalid_argument if a variant's controller has a
/// different number of parameters or the weight is not finite and >= 0.
template <class Main, class Variant>
problem_with_variants<Main, Variant> make_problem_with_variants(Main main,
                                                                std::vector<Variant> variants,
                                                                double variant_weight = 1.0) {
  check_argument(std::isfinite(variant_weight) && variant_weight >= 0.0,
                 "make_problem_with_variants: variant_weight must be finite and >= 0, got ",
                 variant_weight);
  for (std::size_t k = 0; k < variants.size(); ++k)
    check_argument(variants[k].num_parameters() == main.num_parameters(),
                   "make_problem_with_variants: variant ", k, "'s controller has ",
                   variants[k].num_parameters(), " parameters, the main one ",
                   main.num_parameters());
  return {std::move(main), std::move(variants), variant_weight};
}

}  // namespace gaitsynth
