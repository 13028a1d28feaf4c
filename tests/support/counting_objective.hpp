#pragma once
// An objective wrapper for the allocation tests: counts heap allocations (operator new and
// Eigen's, tests/support/counting_allocations.hpp, which must be included first) between a
// rollout's first and last accumulate, and forbids Eigen's in between, so a test can show that
// the step loop allocates nothing after set-up.
#include <Eigen/Core>

#include "gaitsynth/objectives/concept.hpp"

namespace gaitsynth::test_alloc {

/// What counting_objective saw: the counters at the first and last step, and the steps.
struct region {
  long news_at_start = -1, news_at_end = -1, eigen_at_start = -1, eigen_at_end = -1;
  long views = 0;
};

template <class Inner>
struct counting_objective {
  Inner inner;
  region* r;
  using accumulator_type = typename Inner::accumulator_type;
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    return inner.make_accumulator(m);
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    if (v.step == 0) {
      r->news_at_start = g_news.load();
      r->eigen_at_start = g_eigen_asserts.load();
      Eigen::internal::set_is_malloc_allowed(false);
    }
    inner.accumulate(a, v);
    ++r->views;
    r->news_at_end = g_news.load();
    r->eigen_at_end = g_eigen_asserts.load();
  }
  double finish(const accumulator_type& a, const rollout_outcome& out) const {
    Eigen::internal::set_is_malloc_allowed(true);
    return inner.finish(a, out);
  }
};

}  // namespace gaitsynth::test_alloc
