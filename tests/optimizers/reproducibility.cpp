// Thread-count independence and checkpoint/resume equivalence.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
namespace tf = gaitsynth::test_functions;

namespace {

struct fingerprint {
  Eigen::VectorXd x;
  double value = 0;
  std::int64_t evaluations = 0, iterations = 0;
  stop_criterion stopped = stop_criterion::none;
  std::vector<double> trace;  // best value after every iteration
  std::vector<run_record> runs;
};

bool same(const fingerprint& a, const fingerprint& b) {
  return identical(a.x, b.x) && a.value == b.value && a.evaluations == b.evaluations &&
         a.iterations == b.iterations && a.stopped == b.stopped && a.trace == b.trace &&
         a.runs == b.runs;
}

template <class O, class F, class E>
fingerprint run(O& opt, F f, E& eval, const run_options& ro = {}) {
  fingerprint fp;
  const auto r = minimize(opt, f, eval, ro,
                          [&](const optimizer_status& s) { fp.trace.push_back(s.best_value); });
  fp.x = r.x;
  fp.value = r.value;
  fp.evaluations = r.evaluations;
  fp.iterations = r.iterations;
  fp.stopped = r.stopped;
  fp.runs = r.runs;
  return fp;
}

cmaes make_cmaes() {
  cmaes_options o;
  o.seed = 42;
  o.stop.max_iterations = 120;
  return cmaes(parameter_space::unbounded(uniform_x0(12, -3, 3, 42)), o);
}
cmaes_restarts make_bipop() {
  cmaes_options o;
  o.sigma0 = 2.0;
  o.seed = 9;
  o.tol_fun = 1e-4;  // short runs: several restarts within the budget
  o.stop.max_evaluations = 12000;
  restart_options ro;
  ro.strategy = restart_strategy::bipop;
  return cmaes_restarts(parameter_space::unbounded(uniform_x0(6, -3, 3, 9)), o, ro);
}
sds make_sds() {
  sds_options o;
  o.initial_step = 0.5;
  o.stop.max_evaluations = 3000;
  return sds(parameter_space::unbounded(Eigen::VectorXd::Zero(6)), o);
}
// A bounded problem so that resampling and repair are part of the reproduced state.
cmaes make_bounded() {
  cmaes_options o;
  o.seed = 3;
  o.stop.max_iterations = 80;
  const int n = 8;
  return cmaes(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                    Eigen::VectorXd::Constant(n, 0.5)),
               o);
}

struct crash {};

}  // namespace

TEST_CASE("Results are bit-identical whatever the thread count", "[optimizers]") {
  auto check_all = [](auto make, auto f) {
    serial_evaluator serial;
    auto o0 = make();
    const auto ref = run(o0, f, serial);
    for (unsigned threads : {1u, 2u, 3u, 5u}) {
      thread_pool_evaluator pool(threads);
      auto o = make();
      const auto fp = run(o, f, pool);
      INFO("threads " << threads);
      CHECK(same(fp, ref));
    }
  };
  check_all(make_cmaes, tf::rosenbrock);
  check_all(make_bipop, tf::rastrigin);
  check_all(make_sds, tf::rosenbrock);
  check_all(make_bounded, tf::shifted_sphere{0.95});
}

TEST_CASE("A run killed and resumed from its checkpoint continues exactly", "[optimizers]") {
  const auto dir = scratch_dir("resume");
  auto check_resume = [&](auto make, auto f, const std::string& name, std::int64_t kill_at) {
    serial_evaluator serial;
    auto uninterrupted = make();
    const auto ref = run(uninterrupted, f, serial);

    run_options ro;
    ro.checkpoint_file = dir / (name + ".ckpt");
    ro.checkpoint_every = 7;
    ro.log_file = dir / (name + ".csv");
    ro.resume = true;
    // First attempt: the process "dies" inside the objective after kill_at evaluations.
    std::int64_t calls = 0;
    auto dying = [&](const Eigen::VectorXd& x) {
      if (++calls > kill_at) throw crash{};
      return f(x);
    };
    {
      auto first = make();
      CHECK_THROWS_AS(run(first, dying, serial, ro), crash);
    }
    REQUIRE(std::filesystem::exists(ro.checkpoint_file));
    // Second attempt: a fresh optimizer object (new process) resumes from the checkpoint.
    thread_pool_evaluator pool(2);  // and may use another evaluator
    auto second = make();
    fingerprint resumed;
    const auto r = minimize(second, f, pool, ro, [&](const optimizer_status& s) {
      resumed.trace.push_back(s.best_value);
    });
    CHECK(r.resumed);
    CHECK(identical(r.x, ref.x));
    CHECK(r.value == ref.value);
    CHECK(r.evaluations == ref.evaluations);
    CHECK(r.iterations == ref.iterations);
    CHECK(r.stopped == ref.stopped);
    CHECK(r.runs == ref.runs);  // the finished runs' records survive the checkpoint
    // The resumed trace is the tail of the uninterrupted one.
    REQUIRE(resumed.trace.size() < ref.trace.size());
    CHECK(std::equal(resumed.trace.begin(), resumed.trace.end(),
                     ref.trace.end() - static_cast<std::ptrdiff_t>(resumed.trace.size())));
    // The log has one row per iteration, with the iterations after the checkpoint repeated.
    std::ifstream log(ro.log_file);
    std::string line;
    std::int64_t rows = 0;
    std::getline(log, line);
    CHECK(line.rfind("stage,restart,iteration,evaluations,best", 0) == 0);
    while (std::getline(log, line)) ++rows;
    CHECK(rows >= ref.iterations);
  };
  check_resume(make_cmaes, tf::rosenbrock, "cmaes", 12 * 53 + 5);
  check_resume(make_bipop, tf::rastrigin, "bipop", 7777);
  check_resume(make_sds, tf::rosenbrock, "sds", 1234);
  check_resume(make_bounded, tf::shifted_sphere{0.95}, "bounded", 333);
}

TEST_CASE("Checkpoints: exact state round trip and clear errors", "[optimizers]") {
  const auto dir = scratch_dir("checkpoint");
  auto a = make_cmaes();
  minimize(a, tf::ellipsoid, run_options{},
           [](const optimizer_status& s) { return s.iteration < 33; });
  save_checkpoint(a, dir / "a.ckpt");
  auto b = make_cmaes();
  load_checkpoint(b, dir / "a.ckpt");
  CHECK(identical(a.mean(), b.mean()));
  CHECK(a.sigma() == b.sigma());
  CHECK(identical(a.covariance(), b.covariance()));
  CHECK(a.iteration() == b.iteration());
  // Same next samples (the random engine was restored).
  const auto xa = a.ask();
  const auto xb = b.ask();
  for (std::size_t k = 0; k < xa.size(); ++k) CHECK(identical(xa[k], xb[k]));

  // Another dimension or another optimizer kind is refused.
  cmaes other(parameter_space::unbounded(Eigen::VectorXd::Zero(3)), {});
  // (the parameter list, checked before the optimizer's own state, sees the dimension first)
  CHECK_THROWS_WITH(load_checkpoint(other, dir / "a.ckpt"),
                    Catch::Matchers::Contains("'parameters' is"));
  auto s = make_sds();
  CHECK_THROWS_WITH(load_checkpoint(s, dir / "a.ckpt"), Catch::Matchers::Contains("cmaes"));
  CHECK_THROWS_AS(load_checkpoint(b, dir / "missing.ckpt"), std::runtime_error);
  // A truncated file is refused too.
  {
    std::ifstream in(dir / "a.ckpt");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(dir / "cut.ckpt");
    out << content.substr(0, content.size() / 2);
  }
  auto c = make_cmaes();
  CHECK_THROWS_AS(load_checkpoint(c, dir / "cut.ckpt"), std::runtime_error);
}

TEST_CASE("Checkpoints carry the parameter names and refuse another search space", "[optimizers]") {
  const auto dir = scratch_dir("checkpoint_names");
  auto a = make_cmaes();
  minimize(a, tf::ellipsoid, run_options{},
           [](const optimizer_status& s) { return s.iteration < 5; });
  save_checkpoint(a, dir / "a.ckpt");
  std::ifstream in(dir / "a.ckpt");
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto& ps = a.space().parameters();
  REQUIRE(ps.size() >= 2);
  CHECK(content.find("parameter " + std::to_string(ps[1].name.size()) + " " + ps[1].name + "\n") !=
        std::string::npos);
  // Same dimension, other names: refused, naming both.
  std::vector<parameter_spec> renamed = ps;
  renamed[1].name = "rknee_target[state 1]";
  cmaes other(parameter_space(renamed), a.options());
  CHECK_THROWS_WITH(load_checkpoint(other, dir / "a.ckpt"),
                    Catch::Matchers::Contains("parameter 1 '" + ps[1].name + "'") &&
                        Catch::Matchers::Contains("'rknee_target[state 1]'"));
  // A version 1 file (no names) still resumes exactly.
  std::string v1 = content;
  const auto at = v1.find("version 2\n");
  REQUIRE(at != std::string::npos);
  v1.replace(at, 10, "version 1\n");
  std::string stripped;
  {
    std::istringstream lines(v1);
    std::string line;
    while (std::getline(lines, line))
      if (line.rfind("parameters ", 0) != 0 && line.rfind("parameter ", 0) != 0)
        stripped += line + "\n";
  }
  {
    std::ofstream out(dir / "v1.ckpt");
    out << stripped;
  }
  auto b = make_cmaes();
  load_checkpoint(b, dir / "v1.ckpt");
  CHECK(identical(a.mean(), b.mean()));
}
