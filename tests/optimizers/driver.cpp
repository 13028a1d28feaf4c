// The minimize driver (CSV log, progress line, callbacks) and continuation.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "optimizers/helpers.hpp"

using namespace gaitsynth;
using namespace gaitsynth::testing;
using Catch::Matchers::Contains;
namespace tf = gaitsynth::test_functions;

namespace {
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

/// CMA-ES on a 4-D sphere with a budget of 20 iterations.
cmaes twenty_iterations() {
  cmaes_options o;
  o.stop.max_iterations = 20;
  return cmaes(parameter_space::unbounded(Eigen::VectorXd::Ones(4)), o);
}

/// A run in the fresh folder `dir` (log and checkpoint every 5 iterations, resume on) whose first
/// call stopped after 10 of its 20 iterations: what the resume tests start from.
run_options interrupted_at_ten(const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  run_options ro;
  ro.log_file = dir / "log.csv";
  ro.checkpoint_file = dir / "run.ckpt";
  ro.checkpoint_every = 5;
  ro.resume = true;
  cmaes first = twenty_iterations();
  minimize(first, tf::sphere, ro, [](const optimizer_status& s) { return s.iteration < 10; });
  return ro;
}
}  // namespace

TEST_CASE("minimize writes one CSV row per iteration", "[optimizers]") {
  const auto dir = scratch_dir("csv");
  parameter_space space(
      {{"kp", 0.0, 10.0, 5.0}, {"kd", 0.0, 1.0, 0.5}, {"name,with,commas", -1, 1, 0}});
  cmaes_options o;
  o.stop.max_iterations = 25;
  run_options ro;
  ro.log_file = dir / "log.csv";
  ro.log_parameters = true;
  cmaes es(space, o);
  std::vector<optimizer_status> seen;
  const auto r = minimize(
      es, [](const Eigen::VectorXd& x) { return x.squaredNorm(); }, ro,
      [&](const optimizer_status& s) { seen.push_back(s); });
  const auto rows = read_csv(ro.log_file);
  REQUIRE(rows.size() == 26);
  CHECK(rows[0][0] == "stage");
  CHECK(rows[0][2] == "iteration");
  CHECK(rows[0][13] == "kp");
  CHECK(rows[0][15] == "\"name");  // quoted because of its commas
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& s = seen[i - 1];
    CHECK(std::stoll(rows[i][2]) == s.iteration);
    CHECK(std::stoll(rows[i][3]) == s.evaluations);
    CHECK(std::stod(rows[i][4]) == s.best_value);  // %.17g round-trips
    CHECK(std::stod(rows[i][8]) == s.step_size);
  }
  CHECK(std::stod(rows.back()[13]) == r.x[0]);
  CHECK(r.iterations == 25);
}

TEST_CASE("minimize prints a compact progress line", "[optimizers]") {
  std::ostringstream os;
  run_options ro;
  ro.progress = &os;
  ro.progress_interval = 1e9;  // first and last iterations only
  cmaes_options o;
  o.stop.max_iterations = 40;
  minimize(cmaes(parameter_space::unbounded(Eigen::VectorXd::Ones(4)), o), tf::sphere, ro);
  const std::string out = os.str();
  CHECK(std::count(out.begin(), out.end(), '\n') == 2);
  CHECK_THAT(out, Contains("cmaes it 1 ") && Contains("it 40 ") && Contains("best ") &&
                      Contains("med ") && Contains("step ") && Contains("axis ") &&
                      Contains("left ~") && Contains("stop: max_iterations"));
}

TEST_CASE("the progress line's time left extrapolates this call's pace, also after a resume",
          "[optimizers]") {
  optimizer_status s;
  s.iteration = 300;
  s.budget_fraction = 0.75;
  // A fresh run: 0.75 of the budget in 30 s, 10 s left.
  CHECK_THAT(progress_line("cmaes", s, 30.0), Contains("left ~10.0s"));
  // Resumed at 0.5: this call did 0.25 in 10 s, so 10 s left (not 3.3 s: the pace of the whole
  // budget fraction over this call's time).
  CHECK_THAT(progress_line("cmaes", s, 10.0, 0.5), Contains("left ~10.0s"));
  // Nothing done yet in this call: unknown.
  CHECK_THAT(progress_line("cmaes", s, 1.0, 0.75), Contains("left ~?"));
}

TEST_CASE("a resumed run's log drops the row a kill tore", "[optimizers]") {
  const auto dir = std::filesystem::temp_directory_path() / "gaitsynth_torn_log";
  const run_options ro = interrupted_at_ten(dir);
  // The process dies in the middle of writing a row (no newline).
  {
    std::ofstream torn(ro.log_file, std::ios::app);
    torn << "0,0,11,110,0.0012";
  }
  cmaes second = twenty_iterations();
  REQUIRE(minimize(second, tf::sphere, ro).resumed);
  const auto rows = read_csv(ro.log_file);
  REQUIRE(rows.size() == 21);  // the header and iterations 1-20 (the checkpoint is at 10)
  for (const auto& r : rows) CHECK(r.size() == rows.front().size());
  CHECK(rows[11][2] == "11");
  CHECK(rows[20][2] == "20");
  // A torn header alone is cut away and written again.
  {
    std::ofstream torn(ro.log_file, std::ios::trunc);
    torn << "stage,restart,iter";
  }
  cmaes third = twenty_iterations();
  minimize(third, tf::sphere, ro);
  CHECK(read_csv(ro.log_file).front().size() == rows.front().size());
  std::filesystem::remove_all(dir);
}

TEST_CASE("a resumed run's elapsed_s counts on from the log's last row", "[optimizers]") {
  const auto dir = std::filesystem::temp_directory_path() / "gaitsynth_elapsed_log";
  const run_options ro = interrupted_at_ten(dir);
  // The first call had run 1000 s by its last row (the log is rewritten to say so).
  auto rows = read_csv(ro.log_file);
  REQUIRE(rows.size() == 11);
  rows.back()[12] = "1000.000";
  {
    std::ofstream out(ro.log_file, std::ios::trunc);
    for (const auto& r : rows) {
      for (std::size_t i = 0; i < r.size(); ++i) out << (i ? "," : "") << r[i];
      out << '\n';
    }
  }
  cmaes second = twenty_iterations();
  const optimization_result res = minimize(second, tf::sphere, ro);
  REQUIRE(res.resumed);
  rows = read_csv(ro.log_file);
  REQUIRE(rows.size() == 21);
  for (std::size_t i = 11; i < rows.size(); ++i) {
    INFO("row " << i << ": elapsed_s " << rows[i][12]);
    CHECK(std::stod(rows[i][12]) >= 1000.0);
    CHECK(std::stod(rows[i][12]) >= std::stod(rows[i - 1][12]));
  }
  CHECK(res.elapsed_seconds < 1000.0);  // the result's is this call's alone
  std::filesystem::remove_all(dir);
}

TEST_CASE("continuation starts each stage from the previous result", "[optimizers]") {
  // Stage k: minimum at c_k = 1, 2, 3 (like a horizon or slope that grows by stages).
  const std::vector<double> centers = {1.3, 2.1, 3.7};
  auto make_objective = [&](std::size_t k) { return tf::shifted_sphere{centers[k]}; };
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(4);
  const auto space = parameter_space::unbounded(x0);
  std::vector<Eigen::VectorXd> starts;

  SECTION("with CMA-ES") {
    auto make_optimizer = [&](std::size_t, const Eigen::VectorXd& start) {
      starts.push_back(start);
      cmaes_options o;
      o.sigma0 = 0.5;
      o.x0 = start;
      o.stop.target_value = 1e-10;
      return cmaes(space, o);
    };
    serial_evaluator e;
    const auto r = continuation(3, x0, make_optimizer, make_objective, e);
    REQUIRE(r.stages.size() == 3);
    CHECK(identical(starts[0], x0));
    CHECK(identical(starts[1], r.stages[0].x));
    CHECK(identical(starts[2], r.stages[1].x));
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(r.stages[k].stopped == stop_criterion::target_value);
      CHECK((r.stages[k].x.array() - centers[k]).abs().maxCoeff() < 1e-4);
    }
    CHECK(identical(r.x, r.stages[2].x));
  }
  SECTION("with SDS, checkpointed and resumed") {
    const auto dir = scratch_dir("continuation");
    auto make_optimizer = [&](std::size_t, const Eigen::VectorXd& start) {
      starts.push_back(start);
      sds_options o;
      o.x0 = start;
      o.initial_step = 0.5;
      o.stop.target_value = 1e-10;
      return sds(space, o);
    };
    run_options ro;
    ro.checkpoint_file = dir / "cont.ckpt";
    ro.checkpoint_every = 5;
    ro.log_file = dir / "cont.csv";
    ro.resume = true;
    serial_evaluator e;
    const auto ref = continuation(3, x0, make_optimizer, make_objective, e, ro);
    CHECK((ref.x.array() - 3.7).abs().maxCoeff() < 1e-4);
    // The log holds all three stages.
    const auto rows = read_csv(ro.log_file);
    CHECK(rows[1][0] == "0");
    CHECK(rows.back()[0] == "2");
    // Kill during stage 1, then resume: finished stage 0 is not run again.
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::int64_t calls = 0;
    auto dying_objective = [&](std::size_t k) {
      return [&, k](const Eigen::VectorXd& x) {
        if (k == 1 && ++calls > 40) throw std::runtime_error("killed");
        return tf::shifted_sphere{centers[k]}(x);
      };
    };
    CHECK_THROWS(continuation(3, x0, make_optimizer, dying_objective, e, ro));
    starts.clear();
    const auto resumed = continuation(3, x0, make_optimizer, make_objective, e, ro);
    CHECK(starts.size() == 2);  // stages 1 and 2 only
    CHECK(std::filesystem::exists(dir / "cont.ckpt.stage1"));
    REQUIRE(resumed.stages.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(identical(resumed.stages[k].x, ref.stages[k].x));
      CHECK(resumed.stages[k].evaluations == ref.stages[k].evaluations);
    }
  }
}
