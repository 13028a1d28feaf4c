// Replays a saved Sharon & van de Panne 2005 controller (data/sharon2005/*.controller.json) in one
// of the paper's situations, without optimizing anything: the 70 s test, the Figure 8 robustness
// variants, the uphill slope. It writes what a person wants to look at: an HTML player, an SVG
// filmstrip, the CSV trajectory, and a one-line JSON summary on stdout.
//
//   ./sharon2005_replay --result NAME [--seconds S] [--controller FILE] [--out DIR]
//                       [--filmstrip-seconds S] [--filmstrip-from S]
//                       [--html FILE] [--filmstrip FILE] [--gait-svg FILE] ...
//
// NAME: normal_walk (Fig. 5a/b), human16 (5c/d), high_knee (6a/b), backswing (6c/d), uphill (7),
// torso_28kg (8a), shin_0.25_thigh_0.6 (8b), shin_0.8 (8c), bumpy (8d). The Figure 8 variants run
// the unmodified normal-walk controller on the changed body or terrain. The docs' filmstrips
// (docs/reproductions/sharon2005.md) are made with this program.
//
// --seconds: length of the rollout (default 70, in [0.01, 3600]); --filmstrip-seconds: length of
// the filmstrip (default 3, in [0.01, 3600]); --filmstrip-from: its start (default 0, in [0, 3600],
// before --seconds). The viewer flags (--html FILE, --filmstrip FILE, --filmstrip-front FILE,
// --gait-svg FILE, --bvh FILE, --csv FILE, --mjcf-replay FILE; examples/command_line.hpp) show
// the rollout; the CSV trajectory is always written to DIR/sharon2005_replay_NAME.csv (default
// out/). Nothing is random: there is no --seed. --help lists every flag with its default.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "command_line.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

namespace {

using namespace gaitsynth;

struct options {
  std::string result;
  double seconds = 70.0;
  std::string controller;  // empty: the result's saved controller
  std::filesystem::path out_dir = "out";
  viz_outputs viz;  // --html, --filmstrip, --gait-svg, --bvh, --csv, --mjcf-replay
  double filmstrip_seconds = 3.0;
  double filmstrip_from = 0.0;
};

const char* kResults =
    "normal_walk, human16, high_knee, backswing, uphill, torso_28kg, shin_0.25_thigh_0.6, "
    "shin_0.8, bumpy";

options parse(int argc, char** argv) {
  options o;
  std::string out = o.out_dir.string();
  CLI::App app{
      "Replays a saved Sharon & van de Panne 2005 controller in one of the paper's situations "
      "and writes the CSV trajectory, the viewer files asked for and a JSON summary.",
      "sharon2005_replay"};
  app.option_defaults()->always_capture_default();
  app.add_option("--result", o.result, "the result to replay (required)")
      ->check(CLI::IsMember({"normal_walk", "human16", "high_knee", "backswing", "uphill",
                             "torso_28kg", "shin_0.25_thigh_0.6", "shin_0.8", "bumpy"}));
  app.add_option("--seconds", o.seconds, "length of the rollout, s")
      ->check(example_cli::in_range(0.01, 3600.0));
  app.add_option("--controller", o.controller,
                 "controller JSON (default: the result's file in data/sharon2005)")
      ->check(CLI::ExistingFile);
  app.add_option("--out", out, "folder of the CSV trajectory (created)");
  app.add_option("--filmstrip-seconds", o.filmstrip_seconds, "length of the filmstrip, s")
      ->check(example_cli::in_range(0.01, 3600.0));
  app.add_option("--filmstrip-from", o.filmstrip_from, "start time of the filmstrip, s")
      ->check(example_cli::in_range(0.0, 3600.0));
  example_cli::add_viewer_flags(app, o.viz, "the rollout");
  // Checked once the command line is otherwise valid, so an unknown flag is named first.
  app.callback([&] {
    if (o.result.empty()) throw CLI::RequiredError("--result");
  });
  example_cli::parse(app, argc, argv);
  o.out_dir = out;
  if (!(o.filmstrip_from < o.seconds))
    throw std::invalid_argument("--filmstrip-from " +
                                app.get_option("--filmstrip-from")->as<std::string>() +
                                " must be before the end of the rollout, --seconds " +
                                app.get_option("--seconds")->as<std::string>());
  return o;
}

std::string data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

/// Simulates `controller_file` (made for controller_model) on model m and terrain `ground`, writes
/// the outputs and prints the summary. `place`: start from the keyframes' first state lowered onto
/// the ground (a changed body or terrain); otherwise exactly the keyframes' first state.
template <class Terrain>
int run(const options& o, const std::string& title, const planar_model& m,
        const planar_model& controller_model, const std::string& controller_file,
        const std::string& keyframes_file, const Terrain& ground, bool place) {
  const auto target = load_keyframes(controller_model, data(keyframes_file));
  const auto ctrl = load_nearest_neighbor(controller_model, controller_file);
  rollout_options ro;
  // As tests/sharon2005/claims.cpp: lowest foot point on z = 0 (every terrain here is level at the
  // start).
  ro.initial_state = place ? sharon_scenarios::start_state_for(m, target) : target.initial_state();
  const rollout_problem prob{
      m,      torque_actuator{},     ctrl, mass_distance<planar_root>(m, target),
      ground, semi_implicit_euler{}, ro};
  const auto p = ctrl.parameters();
  const Eigen::VectorXd x =
      Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size()));
  trajectory traj;
  const walk_check w =
      check_walk(prob, x, o.seconds, &traj, 40, sharon2005_walk_criteria);  // 60 fps

  std::filesystem::create_directories(o.out_dir);
  const auto csv = o.out_dir / ("sharon2005_replay_" + o.result + ".csv");
  save_trajectory_csv(traj, csv.string());
  viz_outputs v = o.viz;
  v.html_options.title = title;
  v.filmstrip.t_begin = std::min(o.filmstrip_from, traj.frames.back().t);
  v.filmstrip.t_end = std::min(o.filmstrip_from + o.filmstrip_seconds, traj.frames.back().t);
  v.filmstrip.interval = 0.1;
  v.filmstrip.title = title;
  write_viz_outputs(m, traj, v, &std::cerr);
  nlohmann::ordered_json j;
  j["result"] = o.result;
  j["controller"] = controller_file;
  j["seconds"] = o.seconds;
  j["seconds_walked"] = w.seconds;
  j["fell"] = w.fell;
  j["stalled"] = w.stalled;
  j["walked"] = w.walked;
  j["distance"] = std::round(w.distance * 1000) / 1000;
  j["average_speed"] = std::round(w.average_speed * 1000) / 1000;
  j["trajectory_csv"] = csv.string();
  if (!o.viz.html.empty()) j["html"] = o.viz.html;
  if (!o.viz.filmstrip_svg.empty()) j["filmstrip"] = o.viz.filmstrip_svg;
  std::cout << j.dump() << std::endl;
  std::cerr << title << ": " << verdict(w) << " (" << w.seconds << " s), " << w.distance << " m at "
            << w.average_speed << " m/s\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) try {
  const options o = parse(argc, argv);
  const planar_model human7 = sharon2005_human7();
  auto ctrl = [&](const std::string& f) { return o.controller.empty() ? data(f) : o.controller; };
  const flat_terrain flat;
  if (o.result == "normal_walk")
    return run(o, "Fig. 5b: normal walk", human7, human7, ctrl("normal_walk.controller.json"),
               "normal_walk.keyframes.json", flat, false);
  if (o.result == "human16") {
    const planar_model h16 = sharon2005_human16();
    return run(o, "Fig. 5d: 16-link human", h16, h16, ctrl("human16_walk.controller.json"),
               "human16_walk.keyframes.json", flat, false);
  }
  if (o.result == "high_knee")
    return run(o, "Fig. 6b: high knee, long double stance", human7, human7,
               ctrl("high_knee.controller.json"), "high_knee.keyframes.json", flat, false);
  if (o.result == "backswing")
    return run(o, "Fig. 6d: extra back swing", human7, human7, ctrl("backswing.controller.json"),
               "backswing.keyframes.json", flat, false);
  if (o.result == "uphill")
    return run(o, "Fig. 7b: 10 degree uphill", human7, human7, ctrl("uphill.controller.json"),
               "uphill.keyframes.json", slope_terrain(10.0 * std::numbers::pi / 180.0), false);
  if (o.result == "bumpy")
    return run(o, "Fig. 8d: bumpy terrain (up to 11 degrees), walked blindly", human7, human7,
               ctrl("normal_walk.controller.json"), "normal_walk.keyframes.json",
               sharon_scenarios::bumpy_terrain(), true);
  for (const auto& v : sharon_scenarios::figure8_bodies())
    if (o.result == v.name)
      return run(o, v.description, sharon2005_human7(v.params), human7,
                 ctrl("normal_walk.controller.json"), "normal_walk.keyframes.json", flat, true);
  throw std::invalid_argument("unknown --result '" + o.result + "' (one of: " + kResults + ")");
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
