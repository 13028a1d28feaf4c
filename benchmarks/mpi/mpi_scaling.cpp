// What docs/scaling.md's figures and model are made of: the MPI evaluator's throughput on real
// Wang 2009 rollouts and rank 0's per-generation overhead. Run under mpirun; rank 0 prints one
// JSON line.
//
//   mpirun -np R bench_mpi_scaling throughput GENERATIONS [THREADS_PER_RANK]
//       CMA-ES (sigma 0.0025 on [0, 1], default population 19) around the saved stocky walker
//       (data/wang2009/walkers/stocky_push_off) with eq. 16's objective, 10 s evaluations: wall
//       time per generation, evaluations per second, and each rollout's own wall time
//       (mean, 90th percentile, max) gathered from every rank.
//   mpirun -np R bench_mpi_scaling overhead N LAMBDA GENERATIONS
//       rank 0's own work per generation with an objective that costs nothing: ask, tell, and
//       the evaluate call (scatter and gather; rank 0 evaluates nothing when R > 1).
#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include <gaitsynth/actuators/mixed_pd.hpp>
#include <gaitsynth/contact/flat_terrain.hpp>
#include <gaitsynth/controllers/fsm/wang2009_controller.hpp>
#include <gaitsynth/controllers/fsm/wang2009_json.hpp>
#include <gaitsynth/integrators/semi_implicit_euler.hpp>
#include <gaitsynth/models/wang2009.hpp>
#include <gaitsynth/objectives/wang2009/wang2009_objective.hpp>
#include <gaitsynth/optimizers/cmaes.hpp>
#include <gaitsynth/optimizers/mpi_evaluator.hpp>
#include <gaitsynth/rollout/problem.hpp>
#include <gaitsynth/rollout/problem_cost.hpp>
#include <gaitsynth/synthesis/wang2009_search_space.hpp>
#include <gaitsynth/synthesis/wang2009_simulation.hpp>

using namespace gaitsynth;
using seconds = std::chrono::duration<double>;
using clock_type = std::chrono::steady_clock;

namespace {

double since(clock_type::time_point t0) {
  return seconds(clock_type::now() - t0).count();
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

int throughput(int generations, unsigned threads, int argc, char** argv) {
  const std::string path =
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/wang2009/walkers/stocky_push_off.controller.json";
  const floating_model m = wang2009_humanoid(wang2009_preset(wang2009_saved_shape(path)));
  wang2009_controller c(m);
  const std::vector<double> p = load_wang2009_controller(path, c).parameters;
  c.bind(p);
  const rollout_problem prob{m,
                             mixed_pd_actuator{},
                             c,
                             wang2009_objective(m),
                             flat_terrain{},
                             semi_implicit_euler{},
                             wang2009_rollout_options(m)};
  mpi_environment env(argc, argv);
  mpi_evaluator eval(MPI_COMM_WORLD, {.threads = threads});
  problem_contexts ctx(prob, eval.thread_count());
  problem_cost cost(prob, 10.0, ctx);
  std::vector<std::vector<double>> per_thread(eval.thread_count());  // rollouts' wall times
  auto timed = [&](const Eigen::VectorXd& x, std::size_t worker) {
    const auto t0 = clock_type::now();
    const double v = cost(x, worker);
    per_thread[worker].push_back(since(t0));
    return v;
  };
  auto durations_here = [&] {
    std::vector<double> d;
    for (const auto& t : per_thread) d.insert(d.end(), t.begin(), t.end());
    return d;
  };
  if (eval.is_root()) {
    cmaes_options co;
    co.sigma0 = 0.0025;
    co.seed = 2009;
    cmaes es(wang2009_search_space(m, c, p), co);
    std::vector<double> values(static_cast<std::size_t>(es.population_size()));
    const auto t0 = clock_type::now();
    for (int g = 0; g < generations; ++g) {
      const auto& xs = es.ask();
      eval.evaluate(timed, std::span<const Eigen::VectorXd>(xs), std::span<double>(values));
      es.tell(values);
    }
    const double wall = since(t0);
    eval.release();
    // Every rank's rollout times, gathered on rank 0.
    const std::vector<double> durations = durations_here();
    std::vector<double> all = durations;
    for (int r = 1; r < eval.size(); ++r) {
      MPI_Status st;
      MPI_Probe(r, 5, MPI_COMM_WORLD, &st);
      int n = 0;
      MPI_Get_count(&st, MPI_DOUBLE, &n);
      std::vector<double> theirs(static_cast<std::size_t>(n));
      MPI_Recv(theirs.data(), n, MPI_DOUBLE, r, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      all.insert(all.end(), theirs.begin(), theirs.end());
    }
    const double evaluations = static_cast<double>(generations * es.population_size());
    std::printf(
        "{\"mode\": \"throughput\", \"ranks\": %d, \"threads_per_rank\": %u, \"lambda\": %d, "
        "\"generations\": %d, "
        "\"wall_s\": %.3f, \"s_per_generation\": %.4f, \"evaluations_per_s\": %.3f, "
        "\"rollout_s_mean\": %.4f, \"rollout_s_p90\": %.4f, \"rollout_s_max\": %.4f, "
        "\"rollout_s_sum\": %.3f, \"rollouts_on_rank0\": %zu}\n",
        eval.size(), eval.thread_count(), es.population_size(), generations, wall,
        wall / generations, evaluations / wall,
        std::accumulate(all.begin(), all.end(), 0.0) / all.size(), percentile(all, 0.9),
        percentile(all, 1.0), std::accumulate(all.begin(), all.end(), 0.0), durations.size());
  } else {
    eval.serve(timed);
    const std::vector<double> durations = durations_here();
    MPI_Send(durations.data(), static_cast<int>(durations.size()), MPI_DOUBLE, 0, 5,
             MPI_COMM_WORLD);
  }
  return 0;
}

int overhead(int n, int lambda, int generations, int argc, char** argv) {
  mpi_environment env(argc, argv);
  mpi_evaluator eval(MPI_COMM_WORLD, {.root_evaluates = false});
  auto nothing = [](const Eigen::VectorXd& x) { return x[0]; };
  if (!eval.is_root()) {
    eval.serve(nothing);
    return 0;
  }
  cmaes_options co;
  co.seed = 1;
  co.population_size = lambda;
  cmaes es(parameter_space::box(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Ones(n),
                                Eigen::VectorXd::Constant(n, 0.5)),
           co);
  std::vector<double> values(static_cast<std::size_t>(lambda));
  double ask = 0, evaluate = 0, tell = 0;
  for (int g = 0; g < generations; ++g) {
    auto t0 = clock_type::now();
    const auto& xs = es.ask();
    ask += since(t0);
    t0 = clock_type::now();
    eval.evaluate(nothing, std::span<const Eigen::VectorXd>(xs), std::span<double>(values));
    evaluate += since(t0);
    t0 = clock_type::now();
    es.tell(values);
    tell += since(t0);
  }
  eval.release();
  std::printf(
      "{\"mode\": \"overhead\", \"ranks\": %d, \"n\": %d, \"lambda\": %d, \"generations\": %d, "
      "\"ask_us\": %.1f, \"scatter_gather_us\": %.1f, \"tell_us\": %.1f}\n",
      eval.size(), n, lambda, generations, 1e6 * ask / generations, 1e6 * evaluate / generations,
      1e6 * tell / generations);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> a(argv + 1, argv + argc);
  try {
    if ((a.size() == 2 || a.size() == 3) && a[0] == "throughput")
      return throughput(std::stoi(a[1]), a.size() == 3 ? std::stoul(a[2]) : 1u, argc, argv);
    if (a.size() == 4 && a[0] == "overhead")
      return overhead(std::stoi(a[1]), std::stoi(a[2]), std::stoi(a[3]), argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "bench_mpi_scaling: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "usage: bench_mpi_scaling throughput GENERATIONS [THREADS] | overhead N LAMBDA "
               "GENERATIONS\n";
  return 2;
}
