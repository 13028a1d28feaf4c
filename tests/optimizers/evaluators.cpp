#include <gaitsynth/optimizers/evaluators.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace gaitsynth;

namespace {
std::vector<Eigen::VectorXd> batch(int m) {
  std::vector<Eigen::VectorXd> xs;
  for (int k = 0; k < m; ++k) xs.push_back(Eigen::VectorXd::Constant(3, 0.1 * k));
  return xs;
}
}  // namespace

TEST_CASE("thread_pool_evaluator writes every value into its own slot", "[optimizers]") {
  auto f = [](const Eigen::VectorXd& x) { return x.squaredNorm() + std::sin(x[0]); };
  const auto xs = batch(37);
  std::vector<double> ref(xs.size()), out(xs.size());
  serial_evaluator{}.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(ref));
  for (unsigned threads : {1u, 2u, 3u, 8u}) {
    thread_pool_evaluator pool(threads);
    CHECK(pool.thread_count() == threads);
    for (int rep = 0; rep < 20; ++rep) {  // the pool is reused batch after batch
      std::fill(out.begin(), out.end(), -1.0);
      pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
      REQUIRE(out == ref);
    }
  }
}

TEST_CASE("thread_pool_evaluator uses several threads and all cores by default", "[optimizers]") {
  thread_pool_evaluator all;
  CHECK(all.thread_count() == std::max(1u, std::thread::hardware_concurrency()));
  thread_pool_evaluator pool(4);
  std::mutex m;
  std::set<std::thread::id> ids;
  std::atomic<int> inside{0}, max_inside{0};
  auto f = [&](const Eigen::VectorXd&) {
    const int now = ++inside;
    int prev = max_inside.load();
    while (now > prev && !max_inside.compare_exchange_weak(prev, now)) {
    }
    {
      std::lock_guard lock(m);
      ids.insert(std::this_thread::get_id());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    --inside;
    return 0.0;
  };
  const auto xs = batch(16);
  std::vector<double> out(xs.size());
  pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
  CHECK(ids.size() > 1);
  CHECK(max_inside.load() > 1);
}

TEST_CASE("evaluators propagate the objective's exception (lowest index first)", "[optimizers]") {
  auto f = [](const Eigen::VectorXd& x) -> double {
    if (x[0] > 0.45) throw std::runtime_error("fail at " + std::to_string(x[0]));
    return 0.0;
  };
  const auto xs = batch(10);  // x[0] = 0, 0.1, ..., 0.9: indices 5..9 throw
  std::vector<double> out(xs.size());
  thread_pool_evaluator pool(3);
  CHECK_THROWS_WITH(pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out)),
                    Catch::Matchers::Contains("0.5"));
  CHECK_THROWS_AS(
      serial_evaluator{}.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out)),
      std::runtime_error);
  // The pool still works afterwards.
  auto g = [](const Eigen::VectorXd& x) { return x[0]; };
  pool.evaluate(g, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
  CHECK(out[9] == Approx(0.9));
}

TEST_CASE("evaluators check the output size", "[optimizers]") {
  auto f = [](const Eigen::VectorXd&) { return 0.0; };
  const auto xs = batch(4);
  std::vector<double> out(3);
  thread_pool_evaluator pool(2);
  CHECK_THROWS_AS(pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out)),
                  std::invalid_argument);
}

TEST_CASE("a worker-aware objective gets each worker's index, never two calls at once on one",
          "[optimizers][evaluators]") {
  const auto xs = batch(64);
  for (unsigned threads : {1u, 2u, 4u}) {
    thread_pool_evaluator pool(threads);
    std::vector<std::atomic<int>> inside(threads);
    std::atomic<int> overlaps{0}, out_of_range{0};
    std::mutex m;
    std::set<std::size_t> seen;
    auto f = [&](const Eigen::VectorXd& x, std::size_t worker) {
      if (worker >= threads) {
        ++out_of_range;
        return 0.0;
      }
      if (++inside[worker] != 1) ++overlaps;
      {
        std::lock_guard lock(m);
        seen.insert(worker);
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      --inside[worker];
      return x.sum();  // the value does not depend on the worker
    };
    static_assert(worker_objective_function<decltype(f)>);
    std::vector<double> out(xs.size()), ref(xs.size());
    pool.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
    for (std::size_t k = 0; k < xs.size(); ++k) ref[k] = xs[k].sum();
    INFO(threads << " threads");
    CHECK(out == ref);
    CHECK(overlaps == 0);
    CHECK(out_of_range == 0);
    CHECK(seen.count(0) == 1);  // the calling thread is worker 0
  }
  std::size_t last = 99;
  auto g = [&](const Eigen::VectorXd&, std::size_t worker) {
    last = worker;
    return 1.0;
  };
  std::vector<double> out(xs.size());
  serial_evaluator{}.evaluate(g, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
  CHECK(last == 0);
}
