// The MPI evaluator (optimizers/mpi_evaluator.hpp), run under mpirun by
// tests/support/run_mpi_test.sh with 1, 2 and 4 ranks:
//   optimize PROBLEM FILE THREADS [--reference]
//       a short CMA-ES optimization of a real rollout problem (sharon2005: the saved normal walk's
//       nearest-neighbor controller on the 7-link human, mass-distance cost; wang2009: Table 2's
//       controller on the 30-DOF humanoid, eq. 16's objective), its fingerprint (best point,
//       value, counts, best value after every iteration, as exact hex) written by rank 0 to FILE;
//       with --reference the same on a thread pool in one process, without MPI; with
//       --skew-workers the ranks other than 0 add 1e-12 to each cost (the negative control: the
//       comparison must see that). The script compares the files byte for byte.
//   failures
//       a worker's exception reaches rank 0 naming the lowest failing candidate and the message;
//       NaN travels as a value; the evaluator is usable afterwards; without rank 0's help every
//       candidate is evaluated exactly once by the other ranks; misuse is refused.
//   forever FILE
//       an optimization that does not end (for the Ctrl-C test); rank 0 writes FILE once the
//       first batch is in.
// Prints "FAIL: ..." and exits 1 on a failed check.
#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/optimizers/cmaes.hpp"
#include "gaitsynth/optimizers/evaluators.hpp"
#include "gaitsynth/optimizers/minimize.hpp"
#include "gaitsynth/optimizers/mpi_evaluator.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/problem_cost.hpp"
#include "gaitsynth/synthesis/wang2009_search_space.hpp"
#include "gaitsynth/synthesis/wang2009_simulation.hpp"

using namespace gaitsynth;

namespace {

int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    std::cerr << "FAIL: " << what << "\n";
    ++failures;
  }
}

std::string hex(double v) {
  char s[64];
  std::snprintf(s, sizeof s, "%a", v);
  return s;
}

// (a problem refers to its model, which the caller keeps)
auto sharon2005_problem(const planar_model& m) {
  const std::string dir = std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/";
  const auto target = load_keyframes(m, dir + "normal_walk.keyframes.json");
  rollout_options ro;
  ro.initial_state = target.initial_state();
  return rollout_problem{m,
                         torque_actuator{},
                         load_nearest_neighbor(m, dir + "normal_walk.controller.json"),
                         mass_distance<planar_root>(m, target),
                         flat_terrain{},
                         semi_implicit_euler{},
                         ro};
}

auto wang2009_problem(const floating_model& m) {
  wang2009_controller c(m);
  c.bind(wang2009_table2_parameters(m, c));
  return rollout_problem{m,
                         mixed_pd_actuator{},
                         c,
                         wang2009_objective(m),
                         flat_terrain{},
                         semi_implicit_euler{},
                         wang2009_rollout_options(m)};
}

parameter_space space_around(const Eigen::VectorXd& x0, const std::vector<std::string>& names) {
  parameter_space space;
  for (Eigen::Index i = 0; i < x0.size(); ++i)
    space.add({names[static_cast<std::size_t>(i)], x0[i] - 1.0, x0[i] + 1.0, x0[i], 1.0});
  return space;
}

/// Rank 0 (or the reference process) writes the fingerprint; the other ranks serve.
template <class Problem>
int optimize(const Problem& prob, parameter_space space, double sigma0, double horizon,
             const std::string& file, unsigned threads, const std::string& mode, int argc,
             char** argv) {
  cmaes_options co;
  co.sigma0 = sigma0;
  co.seed = 17;
  co.stop.max_iterations = 4;
  std::vector<double> trace;
  optimization_result r;
  auto record = [&](const optimizer_status& s) { trace.push_back(s.best_value); };
  if (mode == "--reference") {
    thread_pool_evaluator pool(threads);
    problem_contexts ctx(prob, pool.thread_count());
    problem_cost f(prob, horizon, ctx);
    cmaes opt(space, co);
    r = minimize(opt, f, pool, run_options{}, record);
  } else {
    mpi_environment env(argc, argv);
    // (the skewed run leaves all the work to the skewed ranks, so every cost is off)
    mpi_evaluator eval(MPI_COMM_WORLD,
                       {.threads = threads, .root_evaluates = mode != "--skew-workers"});
    problem_contexts ctx(prob, eval.thread_count());
    problem_cost f(prob, horizon, ctx);
    if (!eval.is_root()) {
      if (mode == "--skew-workers") {
        auto skewed = [&](const Eigen::VectorXd& x, std::size_t worker) {
          return f(x, worker) + 1e-12;
        };
        eval.serve(skewed);
      } else {
        eval.serve(f);
      }
      return 0;
    }
    cmaes opt(space, co);
    r = minimize(opt, f, eval, run_options{}, record);
    eval.release();
  }
  std::ofstream out(file);
  out << "value " << hex(r.value) << "\nevaluations " << r.evaluations << "\niterations "
      << r.iterations << "\nnon_finite " << r.non_finite << "\nx";
  for (double v : r.x) out << ' ' << hex(v);
  out << "\ntrace";
  for (double v : trace) out << ' ' << hex(v);
  out << "\n";
  // A real search: the batches were rollouts with finite, differing costs.
  check(std::isfinite(r.value) &&
            r.evaluations == 4 * static_cast<std::int64_t>(cmaes(space, co).population_size()),
        "the optimization ran its 4 full iterations with a finite best value");
  return failures ? 1 : 0;
}

/// f(x) = |x|^2, except x[0] == 3 or 7: throws; x[0] == 5: NaN. Counts its calls.
struct marked_objective {
  long calls = 0;
  double operator()(const Eigen::VectorXd& x) {
    ++calls;
    if (x[0] == 3.0 || x[0] == 7.0)
      throw std::runtime_error("bad candidate " + std::to_string(static_cast<int>(x[0])));
    if (x[0] == 5.0) return std::numeric_limits<double>::quiet_NaN();
    return x.squaredNorm();
  }
};

int failures_mode(int argc, char** argv) {
  mpi_environment env(argc, argv);
  std::vector<Eigen::VectorXd> xs;
  for (int k = 0; k < 10; ++k) xs.push_back(Eigen::Vector3d(k, 0.5 * k, -1.0));
  std::vector<Eigen::VectorXd> good(xs);
  good[3][0] = good[7][0] = 30.0;
  good[5][0] = 50.0;
  std::vector<double> out(xs.size(), -1.0);
  for (bool root_evaluates : {true, false}) {
    marked_objective f;
    mpi_evaluator eval(MPI_COMM_WORLD, {.root_evaluates = root_evaluates});
    if (!eval.is_root()) {
      bool refused = false;
      try {
        eval.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
      } catch (const std::invalid_argument&) {
        refused = true;
      }
      check(refused, "a rank other than 0 cannot evaluate batches");
      eval.serve(f);
    } else {
      bool refused = false;
      try {
        eval.serve(f);
      } catch (const std::invalid_argument&) {
        refused = true;
      }
      check(refused, "rank 0 cannot serve");
      std::string message;
      try {
        eval.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
      } catch (const std::runtime_error& e) {
        message = e.what();
      }
      check(message.find("candidate 3 failed on rank") != std::string::npos &&
                message.find("bad candidate 3") != std::string::npos,
            "the lowest failing candidate and its message reach rank 0, got '" + message + "'");
      check(std::isnan(out[5]), "a NaN value travels as a value");
      check(out[9] == xs[9].squaredNorm(), "the other values of a failed batch are filled in");
      // The evaluator is usable after a failed batch.
      std::vector<double> out2(good.size());
      eval.evaluate(f, std::span<const Eigen::VectorXd>(good), std::span<double>(out2));
      for (std::size_t k = 0; k < good.size(); ++k)
        check(out2[k] == good[k].squaredNorm(), "value of candidate " + std::to_string(k));
      eval.release();
    }
    // Every candidate evaluated exactly once over all ranks; rank 0 none when it only hands out.
    long total = 0;
    MPI_Reduce(&f.calls, &total, 1, MPI_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
    if (eval.is_root()) {
      check(total == 20, "20 evaluations in all, got " + std::to_string(total));
      if (!root_evaluates && eval.size() > 1)
        check(f.calls == 0, "rank 0 evaluated " + std::to_string(f.calls) +
                                " candidates with root_evaluates = false");
    }
  }
  int all = 0;
  MPI_Allreduce(&failures, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return all ? 1 : 0;
}

int forever_mode(const std::string& file, int argc, char** argv) {
  mpi_environment env(argc, argv);
  mpi_evaluator eval;
  auto slow = [](const Eigen::VectorXd& x) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return x.squaredNorm();
  };
  if (!eval.is_root()) {
    eval.serve(slow);
    return 0;
  }
  cmaes_options co;
  co.seed = 1;
  co.stop.max_iterations = 1000000;
  cmaes opt(parameter_space::unbounded(Eigen::VectorXd::Ones(4)), co);
  minimize(opt, slow, eval, run_options{}, [&](const optimizer_status& s) {
    if (s.iteration == 1) std::ofstream(file) << "running\n";
  });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() >= 4 && args[0] == "optimize") {
      const std::string mode = args.size() >= 5 ? args[4] : "";
      const auto threads = static_cast<unsigned>(std::stoul(args[3]));
      if (args[1] == "sharon2005") {
        const planar_model m = sharon2005_human7();
        const auto prob = sharon2005_problem(m);
        const Eigen::VectorXd x0 = prob.initial_parameters();
        return optimize(prob, space_around(x0, prob.parameter_names()), 0.02, 0.4, args[2], threads,
                        mode, argc, argv);
      }
      if (args[1] == "wang2009") {
        const floating_model m = wang2009_humanoid();
        const auto prob = wang2009_problem(m);
        const Eigen::VectorXd x0 = prob.initial_parameters();
        wang2009_controller c(m);
        const std::vector<double> p(x0.data(), x0.data() + x0.size());
        return optimize(prob, wang2009_search_space(m, c, p), 0.0025, 0.3, args[2], threads, mode,
                        argc, argv);
      }
    }
    if (args.size() == 1 && args[0] == "failures") return failures_mode(argc, argv);
    if (args.size() == 2 && args[0] == "forever") return forever_mode(args[1], argc, argv);
    std::cerr << "usage: optimize sharon2005|wang2009 FILE THREADS [--reference|--skew-workers] | "
                 "failures | "
                 "forever FILE\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "FAIL: " << e.what() << "\n";
    return 1;
  }
}
