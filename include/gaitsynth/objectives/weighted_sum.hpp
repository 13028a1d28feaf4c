#pragma once
/// \file objectives/weighted_sum.hpp
/// cost = sum_i w_i cost_i over several objectives, each with its own accumulator, in one pass.
/// It stops early when any part's done() says so. Objectives composed this way stay independent,
/// so the biomechanical and metabolic terms of later issues are added without touching each other.
///
/// Recorded terms: the parts' own terms (term_names / terms), in part order, so the player shows
/// every term of a composite objective. A name that an earlier part already used gets "#I"
/// appended (I: the part's index). Parts without terms add none.
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

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
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      using O = std::tuple_element_t<I, std::tuple<Os...>>;
      if constexpr (objective_with_terms<O>) {
        for (const auto& n : std::get<I>(parts_).term_names()) {
          std::string name(n);
          for (const std::string& earlier : term_names_)
            if (earlier == name) {
              name += '#';
              name += std::to_string(I);
              break;
            }
          term_names_.push_back(std::move(name));
          ++term_counts_[I];
        }
      }
    });
  }

  /// The parts' term names (see the file comment).
  const std::vector<std::string>& term_names() const { return term_names_; }
  /// The parts' current term values, in term_names() order. No allocation.
  void terms(const accumulator_type& a, std::span<double> out) const {
    std::size_t at = 0;
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      using O = std::tuple_element_t<I, std::tuple<Os...>>;
      if constexpr (objective_with_terms<O>) {
        std::get<I>(parts_).terms(std::get<I>(a), out.subspan(at, term_counts_[I]));
        at += term_counts_[I];
      }
    });
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
  /// Resets each part's accumulator in place (its reset hook) or makes it anew.
  template <root_joint Root>
  void reset_accumulator(const model<Root>& m, accumulator_type& a) const {
    each([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
      using O = std::tuple_element_t<I, std::tuple<Os...>>;
      if constexpr (objective_with_reset<O, Root>)
        std::get<I>(parts_).reset_accumulator(m, std::get<I>(a));
      else
        std::get<I>(a) = std::get<I>(parts_).make_accumulator(m);
    });
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
  std::vector<std::string> term_names_;
  std::array<std::size_t, sizeof...(Os)> term_counts_{};
};

}  // namespace gaitsynth
