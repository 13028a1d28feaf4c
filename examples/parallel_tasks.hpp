#pragma once
// Independent tasks on a few threads, for the examples' checks (Table 1's directions, the
// perturbed starts of a push check): task k writes only its own result, so what the example
// prints does not depend on the thread count. The first exception, by task index, is rethrown
// after every thread has joined.
#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace example_cli {

/// Calls task(k) for k in [0, count) on min(threads, count) threads (the caller's among them).
template <class Task>
void run_tasks(int count, unsigned threads, Task&& task) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(count, 0)));
  std::atomic<int> next{0};
  const auto work = [&] {
    for (int k = next++; k < count; k = next++) {
      try {
        task(k);
      } catch (...) {
        errors[static_cast<std::size_t>(k)] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const unsigned n = std::min(threads, static_cast<unsigned>(std::max(count, 1)));
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace example_cli
