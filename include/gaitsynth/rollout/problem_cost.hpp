#pragma once
/// \file problem_cost.hpp
/// A problem's cost at one horizon as a worker-aware objective (optimizers/concept.hpp): one
/// context per worker, made once, reused for every candidate that worker evaluates.
///
///   thread_pool_evaluator pool(4);
///   problem_contexts ctx(prob, pool.thread_count());   // 4 contexts, made once
///   minimize(cmaes(space, o), problem_cost(prob, 10.0, ctx), pool);
///
/// The contexts outlive the objective, so a continuation (episodes of growing horizon) makes one
/// problem_cost per episode over the same contexts. An evaluator on another process (MPI) holds its
/// own problem and contexts; only x and the cost travel.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "gaitsynth/error.hpp"

namespace gaitsynth {

/// One context of `Problem` per worker.
template <class Problem>
class problem_contexts {
 public:
  problem_contexts(const Problem& p, std::size_t workers) {
    check_argument(workers >= 1, "problem_contexts: need at least one worker, got ", workers);
    contexts_.reserve(workers);
    for (std::size_t w = 0; w < workers; ++w) contexts_.push_back(p.make_context());
  }
  std::size_t size() const { return contexts_.size(); }
  typename Problem::context_type& operator[](std::size_t worker) {
    check_argument(worker < contexts_.size(), "problem_contexts: worker ", worker,
                   " out of range (", contexts_.size(), " contexts)");
    return contexts_[worker];
  }

 private:
  std::vector<typename Problem::context_type> contexts_;
};

/// x -> prob.cost(x, horizon, contexts[worker]).
template <class Problem>
class problem_cost {
 public:
  problem_cost(const Problem& p, double horizon, problem_contexts<Problem>& contexts)
      : prob_(&p), horizon_(horizon), contexts_(&contexts) {
    check_positive(horizon, "problem_cost: horizon (s)");
  }
  double operator()(const Eigen::VectorXd& x, std::size_t worker) const {
    return prob_->cost(x, horizon_, (*contexts_)[worker]);
  }

 private:
  const Problem* prob_;
  double horizon_;
  problem_contexts<Problem>* contexts_;
};

}  // namespace gaitsynth
