#pragma once
// Shared plumbing of the examples/sharon2005_*.cpp programs (Sharon & van de Panne 2005): command
// line, the synthesis run with progress, the paper's 70 s check, and the outputs every example
// writes: the optimized controller (JSON), the 70 s trajectory (CSV) and a one-line JSON summary
// on stdout. Everything else goes to stderr.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/controllers/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"

namespace sharon_example {

struct cli {
  std::filesystem::path out_dir = "out";
  unsigned threads = 2;
  long long evaluations_per_episode = -1;  // -1: the example's default
  double check_seconds = 70.0;
  std::string keyframes;  // empty: the example's data file
};

inline void usage(const char* name, const char* what) {
  std::cerr << name << ": " << what << "\n\n"
            << "usage: " << name << " [options]\n"
            << "  --out DIR                  output folder (default out/)\n"
            << "  --threads N                evaluation threads (default 2)\n"
            << "  --evaluations-per-episode N  SDS budget per bootstrapping episode\n"
            << "  --check-seconds S          length of the final test rollout (default 70)\n"
            << "  --keyframes FILE           target motion (default: the data/sharon2005 file)\n";
}

inline cli parse(int argc, char** argv, const char* what) {
  cli c;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--out") c.out_dir = value();
    else if (a == "--threads") c.threads = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--evaluations-per-episode") c.evaluations_per_episode = std::stoll(value());
    else if (a == "--check-seconds") c.check_seconds = std::stod(value());
    else if (a == "--keyframes") c.keyframes = value();
    else if (a == "--help" || a == "-h") {
      usage(argv[0], what);
      std::exit(0);
    } else {
      usage(argv[0], what);
      throw std::invalid_argument("unknown option '" + a + "'");
    }
  }
  if (c.threads < 1) throw std::invalid_argument("--threads must be >= 1");
  return c;
}

inline std::string data_file(const std::string& name) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + name;
}

/// Runs the synthesis, the check rollout, writes the outputs and prints the summary line.
/// Returns the process exit code (0 also when the controller falls: that is a result, reported).
template <class Problem>
int synthesize_and_report(const std::string& name, const Problem& prob,
                          gaitsynth::nn_synthesis_options so, const cli& c,
                          nlohmann::ordered_json extra = nlohmann::ordered_json::object()) {
  using namespace gaitsynth;
  so.threads = c.threads;
  if (c.evaluations_per_episode >= 0) so.evaluations_per_episode = c.evaluations_per_episode;
  so.run.progress = &std::cerr;
  so.run.progress_interval = 2.0;
  std::filesystem::create_directories(c.out_dir);
  so.run.log_file = c.out_dir / (name + ".convergence.csv");
  const std::size_t n_params = prob.controller.num_parameters();
  std::cerr << name << ": optimizing " << n_params << " parameters of a "
            << prob.controller.num_nodes() << "-node controller ("
            << prob.controller.num_free_nodes() << " free) with SDS on " << so.threads
            << " thread(s)\n";
  const nn_synthesis_result r = synthesize_nearest_neighbor(prob, so);
  std::cerr << name << ": " << r.evaluations << " evaluations in " << r.wall_seconds
            << " s; checking the controller over " << c.check_seconds << " s\n";

  trajectory traj;
  const walk_check w = check_walk(prob, r.x, c.check_seconds, &traj, 40);
  const auto ctrl = prob.controller_with(r.x);

  nlohmann::ordered_json info;
  info["example"] = name;
  info["evaluations"] = r.evaluations;
  info["wall_seconds"] = r.wall_seconds;
  info["threads"] = so.threads;
  info["episodes"] = r.horizons;
  nlohmann::ordered_json ev = nlohmann::ordered_json::array();
  for (const auto& s : r.episodes.stages) ev.push_back(s.evaluations);
  info["evaluations_per_episode"] = ev;
  info["cost"] = r.value;
  info["check_seconds"] = c.check_seconds;
  info["seconds_walked"] = w.seconds;
  info["fell"] = w.fell;
  info["distance"] = w.distance;
  info["average_speed"] = w.average_speed;
  for (auto it = extra.begin(); it != extra.end(); ++it) info[it.key()] = it.value();

  const auto ctrl_path = c.out_dir / (name + ".controller.json");
  const auto csv_path = c.out_dir / (name + ".csv");
  save_nearest_neighbor(ctrl_path, prob.character, ctrl, info);
  save_trajectory_csv(traj, csv_path.string());

  nlohmann::ordered_json summary;
  summary["example"] = name;
  summary["evaluations"] = r.evaluations;
  summary["wall_seconds"] = std::round(r.wall_seconds * 100) / 100;
  summary["cost"] = r.value;
  summary["seconds_walked"] = w.seconds;
  summary["fell"] = w.fell;
  summary["average_speed"] = std::round(w.average_speed * 1000) / 1000;
  summary["controller"] = ctrl_path.string();
  summary["trajectory_csv"] = csv_path.string();
  summary["convergence_csv"] = so.run.log_file.string();
  std::cerr << name << ": " << (w.fell ? "FELL after " : "walked ") << w.seconds << " s, "
            << w.distance << " m at " << w.average_speed << " m/s\n"
            << name << ": controller  " << ctrl_path.string() << "\n"
            << name << ": trajectory  " << csv_path.string() << "\n"
            << name << ": convergence " << so.run.log_file.string() << "\n";
  std::cout << summary.dump() << std::endl;
  return 0;
}

}  // namespace sharon_example
