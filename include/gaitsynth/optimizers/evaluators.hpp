#pragma once
/// \file evaluators.hpp
/// Evaluator policies: how a batch of candidates gets its objective values.
///
/// - serial_evaluator: one after the other, in the calling thread (worker 0).
/// - thread_pool_evaluator: a persistent pool; workers (and the calling thread) take candidates
///   by index from an atomic counter and write `out[k]` only, so the values, and therefore the
///   whole optimization, are bit-identical whatever the thread count. The calling thread is
///   worker 0, pool thread t is worker t; a worker-aware objective (optimizers/concept.hpp) gets
///   that index and uses its own context on each.
///
/// An evaluator that spreads a batch over processes (MPI) fits the same concept: rank 0's
/// `evaluate` scatters `xs`, the other ranks call the objective, rank 0 gathers into `out`. The
/// optimizers never see how the values were obtained. Objectives evaluated by the pool must be
/// safe to call concurrently (the caller's responsibility: e.g. one simulation workspace per call
/// or per thread, no shared mutable state).
#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/concept.hpp"

namespace gaitsynth {

/// Evaluates the batch in order in the calling thread.
struct serial_evaluator {
  template <objective_function F>
  void evaluate(F& f, std::span<const Eigen::VectorXd> xs, std::span<double> out) const {
    check_size(static_cast<std::ptrdiff_t>(out.size()), static_cast<std::ptrdiff_t>(xs.size()),
               "evaluator output");
    for (std::size_t k = 0; k < xs.size(); ++k) out[k] = call_objective(f, xs[k], 0);
  }
  unsigned thread_count() const { return 1; }
};

/// Evaluates a batch on `threads` threads (the calling thread included). 0 = all cores
/// (std::thread::hardware_concurrency()). Not copyable; one batch at a time (evaluate is not
/// reentrant). If the objective throws, the remaining candidates of the batch are still
/// evaluated and the exception of the lowest-index failing candidate is rethrown by `evaluate`.
class thread_pool_evaluator {
 public:
  explicit thread_pool_evaluator(unsigned threads = 0) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads_ = threads;
    workers_.reserve(threads - 1);
    for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this, t] { worker_loop(t); });
  }
  thread_pool_evaluator(const thread_pool_evaluator&) = delete;
  thread_pool_evaluator& operator=(const thread_pool_evaluator&) = delete;
  ~thread_pool_evaluator() {
    {
      std::lock_guard lock(mutex_);
      shutdown_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }

  unsigned thread_count() const { return threads_; }

  template <objective_function F>
  void evaluate(F& f, std::span<const Eigen::VectorXd> xs, std::span<double> out) {
    check_size(static_cast<std::ptrdiff_t>(out.size()), static_cast<std::ptrdiff_t>(xs.size()),
               "evaluator output");
    if (xs.empty()) return;
    if (workers_.empty() || xs.size() == 1) {
      serial_evaluator{}.evaluate(f, xs, out);
      return;
    }
    // Type-erased job without allocation: a context pointer and a function pointer.
    struct context {
      F* f;
      std::span<const Eigen::VectorXd> xs;
      std::span<double> out;
    } ctx{&f, xs, out};
    errors_.assign(xs.size(), nullptr);
    {
      std::lock_guard lock(mutex_);
      job_ctx_ = &ctx;
      job_fn_ = [](void* c, std::size_t k, std::size_t worker) {
        auto* cx = static_cast<context*>(c);
        cx->out[k] = call_objective(*cx->f, cx->xs[k], worker);
      };
      job_size_ = xs.size();
      next_.store(0, std::memory_order_relaxed);
      busy_ = workers_.size();
      ++epoch_;
    }
    wake_.notify_all();
    run_items(0);  // the calling thread works too, as worker 0
    {
      std::unique_lock lock(mutex_);
      done_.wait(lock, [this] { return busy_ == 0; });
      job_ctx_ = nullptr;
    }
    for (auto& e : errors_)
      if (e) std::rethrow_exception(e);
  }

 private:
  void run_items(std::size_t worker) {
    for (;;) {
      const std::size_t k = next_.fetch_add(1, std::memory_order_relaxed);
      if (k >= job_size_) return;
      try {
        job_fn_(job_ctx_, k, worker);
      } catch (...) {
        errors_[k] = std::current_exception();
      }
    }
  }
  void worker_loop(std::size_t worker) {
    std::uint64_t seen = 0;
    for (;;) {
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return shutdown_ || epoch_ != seen; });
        if (shutdown_) return;
        seen = epoch_;
      }
      run_items(worker);
      {
        std::lock_guard lock(mutex_);
        if (--busy_ == 0) done_.notify_one();
      }
    }
  }

  unsigned threads_ = 1;
  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  bool shutdown_ = false;
  std::uint64_t epoch_ = 0;
  std::size_t busy_ = 0;
  void* job_ctx_ = nullptr;
  void (*job_fn_)(void*, std::size_t, std::size_t) = nullptr;
  std::size_t job_size_ = 0;
  std::atomic<std::size_t> next_{0};
  std::vector<std::exception_ptr> errors_;
};

}  // namespace gaitsynth
