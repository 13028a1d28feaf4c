#pragma once
/// \file objectives/weighted_sum.hpp
/// cost = sum_i w_i cost_i over several objectives, each with its own accumulator, in one pass.
/// It stops early when any part's done() says so. Objectives composed this way stay independent,
/// so the biomechanical and metabolic terms of later issues are added without touching each other.
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"

namespace gaitsynth {

template <class... Os>
class weighted_sum {
  static_assert(sizeof...(Os) > 0, "weighted_sum needs at least one objective");

 public:
  static constexpr std::size_t size = sizeof...(Os);
  using accumulator_type = std::tuple<typename Os::accumulator_type...>;

  weighted_sum(const std::array<double, sizeof...(Os)>& weights, Os... parts)
      : weights_(weights), parts_(std::move(parts)...) {
    for (std::size_t i = 0; i < size; ++i)
      check_argument(std::isfinite(weights_[i]), "weighted_sum: weight ", i, " is not finite (",
                     weights_[i], ")");
  }

  const std::array<double, sizeof...(Os)>& weights() const { return weights_; }
  template <std::size_t I>
  const auto& part() const {
    return std::get<I>(parts_);
  }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    return std::apply([&](const auto&... p) { return accumulator_type{p.make_accumulator(m)...}; },
                      parts_);
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      std::get<I>(parts_).accumulate(std::get<I>(a), v);
    });
  }
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    double c = 0.0;
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      if (weights_[I] != 0.0) c += weights_[I] * std::get<I>(parts_).finish(std::get<I>(a), out);
    });
    return c;
  }
  bool done(const accumulator_type& a) const {
    bool d = false;
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      using O = std::tuple_element_t<I, std::tuple<Os...>>;
      if constexpr (objective_with_done<O>) d = d || std::get<I>(parts_).done(std::get<I>(a));
    });
    return d;
  }

 private:
  template <class F>
  static void each(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      (f(std::integral_constant<std::size_t, I>{}), ...);
    }
    (std::index_sequence_for<Os...>{});
  }

  std::array<double, sizeof...(Os)> weights_;
  std::tuple<Os...> parts_;
};

}  // namespace gaitsynth
