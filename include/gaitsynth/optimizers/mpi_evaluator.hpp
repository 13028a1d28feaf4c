#pragma once
/// \file mpi_evaluator.hpp
/// An evaluator (optimizers/concept.hpp) that spreads each batch over the processes of an MPI
/// communicator, for optimizations that outgrow one machine (Wang 2009 used 19 CPUs, Wu 2010 32
/// cores, Wang 2012 50 cores for 10 hours). Needs MPI (CMake: `gaitsynth::mpi`); nothing else in
/// the library includes it.
///
/// Every rank runs the same program and builds the same objective; rank 0 runs the optimizer and
/// hands candidates out, the other ranks evaluate them:
///
///   gaitsynth::mpi_environment env(argc, argv);
///   gaitsynth::mpi_evaluator eval;               // MPI_COMM_WORLD, one thread per rank
///   problem_contexts ctx(prob, eval.thread_count());
///   problem_cost f(prob, 10.0, ctx);
///   if (eval.is_root()) {
///     result = minimize(opt, f, eval, ...);
///     eval.release();                            // the others' serve() returns
///   } else {
///     eval.serve(f);
///   }
///
/// Work is handed out dynamically, `chunk` candidates at a time (default: the receiving rank's
/// thread count), to whichever rank is free, because rollouts that fall end early and lengths
/// vary; each rank has two chunks in flight, so it never waits for rank 0 between chunks. Rank 0
/// evaluates chunks too (`root_evaluates`), on a thread of its own, while its main thread
/// dispatches (polling every 0.1 ms). Each value is written by candidate index, so an
/// optimization is bit-identical for any number of ranks and threads per rank, provided every
/// rank computes the same f (same binary, same inputs).
///
/// Failures: a candidate whose objective throws on any rank makes `evaluate` throw, after the
/// whole batch is in, a std::runtime_error naming the lowest failing candidate, its rank and the
/// original message (the exception's type does not cross processes), as the thread pool
/// rethrows the lowest failing candidate's exception. A non-finite value travels as a value: the
/// optimizers rank it worst. The evaluator stays usable after a failed batch.
///
/// Shutdown: `release()` (also run by rank 0's destructor, so an exception that unwinds rank 0's
/// main still lets the others finish), then MPI_Finalize in mpi_environment's destructor. On
/// Ctrl-C, mpirun ends every rank; the run's checkpoint is where to resume from.
///
/// Only the main thread of each rank calls MPI (MPI_THREAD_FUNNELED); the pool's threads and rank
/// 0's evaluation thread only evaluate.
// The C API only: the deprecated C++ bindings (removed in MPI-3) warn under -Wextra.
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#ifndef MPICH_SKIP_MPICXX
#define MPICH_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/concept.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"

namespace gaitsynth {

namespace detail {
inline void mpi_check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(concat("mpi_evaluator: ", call, " failed: ", std::string(text, length)));
}
}  // namespace detail

/// MPI_Init_thread (funneled) on construction, MPI_Finalize on destruction: one per process, in
/// main(). Throws if MPI cannot give the thread support the evaluator needs.
class mpi_environment {
 public:
  mpi_environment(int& argc, char**& argv) {
    int initialized = 0;
    MPI_Initialized(&initialized);
    check_argument(!initialized, "mpi_environment: MPI is already initialized");
    int provided = 0;
    detail::mpi_check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided),
                      "MPI_Init_thread");
    if (provided < MPI_THREAD_FUNNELED) {
      MPI_Finalize();
      throw std::runtime_error(
          detail::concat("mpi_environment: MPI gives thread support ", provided,
                         ", the evaluator needs MPI_THREAD_FUNNELED (", MPI_THREAD_FUNNELED, ")"));
    }
  }
  mpi_environment(const mpi_environment&) = delete;
  mpi_environment& operator=(const mpi_environment&) = delete;
  ~mpi_environment() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
  static int rank(MPI_Comm comm = MPI_COMM_WORLD) {
    int r = 0;
    MPI_Comm_rank(comm, &r);
    return r;
  }
  static int size(MPI_Comm comm = MPI_COMM_WORLD) {
    int s = 1;
    MPI_Comm_size(comm, &s);
    return s;
  }
};

struct mpi_evaluator_options {
  /// Threads of each rank's own pool (the calling thread included); 0 = all cores of the host.
  /// One rank per core and one thread per rank is the usual MPI layout, hence the default.
  unsigned threads = 1;
  /// Candidates handed to a rank at once; 0 = that rank's thread count.
  std::size_t chunk = 0;
  /// Rank 0 evaluates chunks too, on its own thread (otherwise it only hands out and collects).
  bool root_evaluates = true;
};

/// See the file comment. Construction is collective: every rank of `comm` constructs one.
class mpi_evaluator {
 public:
  explicit mpi_evaluator(MPI_Comm comm = MPI_COMM_WORLD, mpi_evaluator_options o = {})
      : comm_(comm), options_(o), pool_(o.threads) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
    // Rank 0 learns each rank's chunk size (its threads, unless set).
    const double mine = static_cast<double>(o.chunk > 0 ? o.chunk : pool_.thread_count());
    chunks_.assign(static_cast<std::size_t>(size_), 0.0);
    detail::mpi_check(MPI_Gather(&mine, 1, MPI_DOUBLE, chunks_.data(), 1, MPI_DOUBLE, 0, comm_),
                      "MPI_Gather");
    sends_.resize(2 * static_cast<std::size_t>(size_));
    sent_.assign(static_cast<std::size_t>(size_), 0);
  }
  mpi_evaluator(const mpi_evaluator&) = delete;
  mpi_evaluator& operator=(const mpi_evaluator&) = delete;
  ~mpi_evaluator() {
    if (is_root() && !released_) {
      try {
        release();
      } catch (...) {  // a destructor must not throw; MPI aborts the job on real failures
      }
    }
  }

  bool is_root() const { return rank_ == 0; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// This rank's threads: the number of worker contexts a worker-aware objective needs here.
  unsigned thread_count() const { return pool_.thread_count(); }

  /// Rank 0: out[k] = f(xs[k]) over all ranks. See the file comment for failures.
  template <objective_function F>
  void evaluate(F& f, std::span<const Eigen::VectorXd> xs, std::span<double> out) {
    check_argument(is_root(),
                   "mpi_evaluator::evaluate: only rank 0 evaluates batches (this is rank ", rank_,
                   "; the others call serve)");
    check_argument(!released_, "mpi_evaluator::evaluate: the workers were released");
    check_size(static_cast<std::ptrdiff_t>(out.size()), static_cast<std::ptrdiff_t>(xs.size()),
               "evaluator output");
    const std::size_t n = xs.size();
    if (n == 0) return;
    const Eigen::Index dim = xs[0].size();
    for (const auto& x : xs) check_size(x.size(), dim, "mpi_evaluator: candidate dimension");
    failure_ = {};
    ++batch_;
    // Candidates are taken in chunks from one counter, by the dispatcher (this thread) for the
    // other ranks and by rank 0's own evaluation thread.
    std::atomic<std::size_t> next{0};
    auto take = [&](std::size_t want) -> std::pair<std::size_t, std::size_t> {
      const std::size_t first = next.fetch_add(want);
      return {first, first < n ? std::min(want, n - first) : 0};
    };
    const bool root_works = options_.root_evaluates || size_ == 1;
    auto evaluate_here = [&] {
      for (auto [first, count] = take(chunk_of(0)); count > 0;
           std::tie(first, count) = take(chunk_of(0)))
        evaluate_locally(f, xs.subspan(first, count), out.subspan(first, count), first);
    };
    if (size_ == 1) {
      evaluate_here();
    } else {
      // Two chunks in flight per rank, so that a rank finds its next chunk waiting when it sends
      // a result, instead of idling while rank 0 answers.
      int outstanding = 0;
      for (int depth = 0; depth < 2; ++depth)
        for (int w = 1; w < size_; ++w)
          if (send_chunk(w, xs, take(chunk_of(w)))) ++outstanding;
      std::atomic<bool> here_done{!root_works};
      std::exception_ptr here_error;
      std::thread here;
      if (root_works)
        here = std::thread([&] {
          try {
            evaluate_here();
          } catch (...) {
            here_error = std::current_exception();
          }
          here_done = true;
        });
      while (outstanding > 0) {
        MPI_Status status;
        if (!here_done) {  // poll, leaving the core to rank 0's own evaluations in between
          int arrived = 0;
          detail::mpi_check(MPI_Iprobe(MPI_ANY_SOURCE, tag_result, comm_, &arrived, &status),
                            "MPI_Iprobe");
          if (!arrived) {
            std::this_thread::sleep_for(std::chrono::microseconds(100));
            continue;
          }
        } else {
          detail::mpi_check(MPI_Probe(MPI_ANY_SOURCE, tag_result, comm_, &status), "MPI_Probe");
        }
        receive_result(status, out);
        --outstanding;
        if (send_chunk(status.MPI_SOURCE, xs, take(chunk_of(status.MPI_SOURCE)))) ++outstanding;
      }
      if (here.joinable()) here.join();
      complete_sends();
      if (here_error) std::rethrow_exception(here_error);
    }
    if (failure_.index != no_failure)
      throw std::runtime_error(detail::concat("mpi_evaluator: candidate ", failure_.index,
                                              " failed on rank ", failure_.rank, ": ",
                                              failure_.message));
  }

  /// Ranks other than 0: evaluate what rank 0 sends until it calls release(). `f` must compute
  /// what rank 0's would (same problem, same horizon).
  template <objective_function F>
  void serve(F& f) {
    check_argument(!is_root(), "mpi_evaluator::serve: rank 0 runs the optimizer, not serve");
    std::vector<Eigen::VectorXd> xs;
    std::vector<double> values;
    for (;;) {
      MPI_Status status;
      detail::mpi_check(MPI_Probe(0, MPI_ANY_TAG, comm_, &status), "MPI_Probe");
      int length = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &length);
      buffer_.resize(static_cast<std::size_t>(std::max(length, 1)));
      detail::mpi_check(
          MPI_Recv(buffer_.data(), length, MPI_DOUBLE, 0, status.MPI_TAG, comm_, MPI_STATUS_IGNORE),
          "MPI_Recv");
      if (status.MPI_TAG == tag_release) return;
      // [batch, first, count, dim, x_first..., x_last...]
      const auto first = static_cast<std::size_t>(buffer_[1]);
      const auto count = static_cast<std::size_t>(buffer_[2]);
      const auto dim = static_cast<Eigen::Index>(buffer_[3]);
      xs.resize(count);
      for (std::size_t k = 0; k < count; ++k)
        xs[k] = Eigen::Map<const Eigen::VectorXd>(
            buffer_.data() + 4 + static_cast<std::ptrdiff_t>(k) * dim, dim);
      values.resize(count);
      failure_ = {};
      evaluate_locally(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(values), first);
      // [batch, first, count, failed, values...]; then the failure's text when failed.
      buffer_.resize(4 + count);
      buffer_[2] = static_cast<double>(count);
      buffer_[3] = failure_.index == no_failure ? -1.0 : static_cast<double>(failure_.index);
      std::copy(values.begin(), values.end(), buffer_.begin() + 4);
      detail::mpi_check(MPI_Send(buffer_.data(), static_cast<int>(buffer_.size()), MPI_DOUBLE, 0,
                                 tag_result, comm_),
                        "MPI_Send");
      if (failure_.index != no_failure)
        detail::mpi_check(
            MPI_Send(failure_.message.data(), static_cast<int>(failure_.message.size()), MPI_CHAR,
                     0, tag_error, comm_),
            "MPI_Send");
    }
  }

  /// Rank 0: ends every other rank's serve(). Called by rank 0's destructor if not before.
  void release() {
    check_argument(is_root(), "mpi_evaluator::release: only rank 0 releases the workers");
    if (released_) return;
    released_ = true;
    const double none = 0.0;
    for (int w = 1; w < size_; ++w)
      detail::mpi_check(MPI_Send(&none, 0, MPI_DOUBLE, w, tag_release, comm_), "MPI_Send");
  }

 private:
  static constexpr int tag_work = 71, tag_result = 72, tag_error = 73, tag_release = 74;
  static constexpr std::size_t no_failure = std::numeric_limits<std::size_t>::max();
  struct failure {
    std::size_t index = no_failure;  // lowest failing candidate of the batch
    int rank = 0;
    std::string message;
  };

  std::size_t chunk_of(int r) const {
    return std::max<std::size_t>(1, static_cast<std::size_t>(chunks_[static_cast<std::size_t>(r)]));
  }

  /// Sends candidates [first, first + count) to rank w without waiting for it to receive them;
  /// false when there is nothing to send. Each rank has two send buffers, one per chunk in
  /// flight: the one reused was sent two chunks ago, whose result is in, so its send is done.
  bool send_chunk(int w, std::span<const Eigen::VectorXd> xs,
                  std::pair<std::size_t, std::size_t> chunk) {
    const auto [first, count] = chunk;
    if (count == 0) return false;
    const auto dim = static_cast<std::size_t>(xs[0].size());
    pending_send& slot =
        sends_[2 * static_cast<std::size_t>(w) + (sent_[static_cast<std::size_t>(w)]++ & 1u)];
    detail::mpi_check(MPI_Wait(&slot.request, MPI_STATUS_IGNORE), "MPI_Wait");
    slot.buffer.resize(4 + count * dim);
    slot.buffer[0] = static_cast<double>(batch_);
    slot.buffer[1] = static_cast<double>(first);
    slot.buffer[2] = static_cast<double>(count);
    slot.buffer[3] = static_cast<double>(dim);
    for (std::size_t k = 0; k < count; ++k)
      std::copy(xs[first + k].data(), xs[first + k].data() + dim,
                slot.buffer.begin() + static_cast<std::ptrdiff_t>(4 + k * dim));
    detail::mpi_check(MPI_Isend(slot.buffer.data(), static_cast<int>(slot.buffer.size()),
                                MPI_DOUBLE, w, tag_work, comm_, &slot.request),
                      "MPI_Isend");
    return true;
  }

  void complete_sends() {
    for (auto& s : sends_) detail::mpi_check(MPI_Wait(&s.request, MPI_STATUS_IGNORE), "MPI_Wait");
  }

  void receive_result(const MPI_Status& status, std::span<double> out) {
    int length = 0;
    MPI_Get_count(&status, MPI_DOUBLE, &length);
    result_.resize(static_cast<std::size_t>(length));
    detail::mpi_check(MPI_Recv(result_.data(), length, MPI_DOUBLE, status.MPI_SOURCE, tag_result,
                               comm_, MPI_STATUS_IGNORE),
                      "MPI_Recv");
    const auto first = static_cast<std::size_t>(result_[1]);
    const auto count = static_cast<std::size_t>(result_[2]);
    std::copy(result_.begin() + 4, result_.begin() + 4 + static_cast<std::ptrdiff_t>(count),
              out.begin() + static_cast<std::ptrdiff_t>(first));
    if (result_[3] >= 0.0) {  // the text follows from the same rank (MPI keeps the order)
      MPI_Status text_status;
      detail::mpi_check(MPI_Probe(status.MPI_SOURCE, tag_error, comm_, &text_status), "MPI_Probe");
      int chars = 0;
      MPI_Get_count(&text_status, MPI_CHAR, &chars);
      std::string text(static_cast<std::size_t>(chars), '\0');
      detail::mpi_check(MPI_Recv(text.data(), chars, MPI_CHAR, status.MPI_SOURCE, tag_error, comm_,
                                 MPI_STATUS_IGNORE),
                        "MPI_Recv");
      note_failure(static_cast<std::size_t>(result_[3]), status.MPI_SOURCE, std::move(text));
    }
  }

  void note_failure(std::size_t index, int rank, std::string message) {
    std::lock_guard lock(failure_mutex_);  // rank 0's evaluation thread and its dispatcher
    if (index < failure_.index) failure_ = {index, rank, std::move(message)};
  }

  /// Values of one chunk on this rank's pool; candidate k of the chunk is `first + k` of the
  /// batch. Failures are recorded, not thrown, so the rest of the batch still completes.
  template <objective_function F>
  void evaluate_locally(F& f, std::span<const Eigen::VectorXd> xs, std::span<double> out,
                        std::size_t first) {
    errors_.assign(xs.size(), nullptr);
    auto guarded = [&](const Eigen::VectorXd& x, std::size_t worker) -> double {
      const auto k = static_cast<std::size_t>(&x - xs.data());
      try {
        return call_objective(f, x, worker);
      } catch (...) {
        errors_[k] = std::current_exception();
        return std::numeric_limits<double>::quiet_NaN();
      }
    };
    pool_.evaluate(guarded, xs, out);
    for (std::size_t k = 0; k < xs.size(); ++k) {
      if (!errors_[k]) continue;
      std::string message = "unknown exception";
      try {
        std::rethrow_exception(errors_[k]);
      } catch (const std::exception& e) {
        message = e.what();
      } catch (...) {
      }
      note_failure(first + k, rank_, std::move(message));
      break;  // the lowest of this chunk; later ones cannot be the batch's lowest
    }
  }

  MPI_Comm comm_;
  mpi_evaluator_options options_;
  thread_pool_evaluator pool_;
  int rank_ = 0, size_ = 1;
  std::vector<double> chunks_;  // rank 0: each rank's chunk size
  struct pending_send {
    std::vector<double> buffer;
    MPI_Request request = MPI_REQUEST_NULL;
  };
  std::vector<pending_send> sends_;  // rank 0: two per rank
  std::vector<std::uint64_t> sent_;  // rank 0: chunks sent to each rank
  std::vector<double> buffer_, result_;
  std::vector<std::exception_ptr> errors_;  // rank 0: used by its evaluation thread only
  std::mutex failure_mutex_;
  failure failure_;
  std::uint64_t batch_ = 0;
  bool released_ = false;
};

}  // namespace gaitsynth
