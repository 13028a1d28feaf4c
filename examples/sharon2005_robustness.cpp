// Sharon & van de Panne 2005, Figure 8: the unmodified normal-walk controller (Fig. 5a/b) on
// (a) a torso of 28 kg instead of 40 kg, (b) shins of 0.25 m with thighs of 0.6 m, (c) shins of
// 0.8 m, (d) bumpy terrain with gradients up to 11 degrees that the controller cannot see. No
// re-optimization: each variant is simulated for 70 s from the first keyframe's state (the root
// placed so the lowest foot point touches the ground).
// With --disturbances test it runs, instead, the conditions no figure shows (slopes of -5 and +3
// degrees, friction 0.5, 50 N pushes forward and backward, torso mass -/+20 %;
// synthesis/sharon2005_disturbances.hpp) for any 7-link controller with its keyframes
// (--disturbances training: the conditions that --disturbance-training puts in a cost).
//
//   ./sharon2005_robustness [--controller FILE] [--keyframes FILE] [--disturbances test|training]
//                           [--out DIR] [--seconds S] [--html FILE] [--filmstrip FILE] ...
//
// Default controller: data/sharon2005/normal_walk.controller.json (written by
// sharon2005_normal_walk), default keyframes (start state and style): the normal walk's. Writes
// DIR/sharon2005_robustness_<variant>.csv (--seconds, default 70, in [0.01, 3600]; 60 frames/s) and
// .svg (strobe picture of the first 3 s) into DIR (default out, created) and prints one JSON line
// per variant, then a summary line, on stdout. The viewer flags
// (--html FILE, --filmstrip FILE, --filmstrip-front FILE, --gait-svg FILE, --bvh FILE, --csv FILE,
// --mjcf-replay FILE; examples/command_line.hpp) are each written once per variant, the variant's
// name inserted before the file's extension (--html out/r.html gives out/r_torso_28kg.html, ...).
// Nothing is random: there is no --seed. --help lists every flag with its default.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "command_line.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "gaitsynth/synthesis/sharon2005_disturbances.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  std::string data = std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/";
  std::string ctrl_path = data + "normal_walk.controller.json";
  std::string kf_path = data + "normal_walk.keyframes.json";
  std::string disturbances;  // empty: Figure 8
  std::string out_arg = "out";
  double seconds = 70.0;
  // Viewer flags: each is written once per variant, the variant's name inserted before the file's
  // extension (--html out/r.html gives out/r_torso_28kg.html, ...).
  viz_outputs views;
  CLI::App app{
      "Sharon & van de Panne 2005, Figure 8: the unmodified normal-walk controller on a changed "
      "body or bumpy terrain, simulated without re-optimization.",
      "sharon2005_robustness"};
  app.option_defaults()->always_capture_default();
  app.add_option("--controller", ctrl_path, "controller JSON")->check(CLI::ExistingFile);
  app.add_option("--keyframes", kf_path, "the controller's keyframes (start state, style)")
      ->check(CLI::ExistingFile);
  app.add_option("--disturbances", disturbances,
                 "run the slopes, low friction, pushes and torso masses of "
                 "synthesis/sharon2005_disturbances.hpp instead of Figure 8: the test set, or the "
                 "training set of --disturbance-training")
      ->check(CLI::IsMember({"test", "training"}));
  app.add_option("--out", out_arg, "folder of the CSV trajectories and SVG pictures (created)");
  app.add_option("--seconds", seconds, "length of each rollout, s")
      ->check(example_cli::in_range(0.01, 3600.0));
  example_cli::add_viewer_flags(app, views,
                                "each variant (one file per variant, its name before the "
                                "extension)");
  example_cli::parse(app, argc, argv);
  const std::filesystem::path out = out_arg;
  std::filesystem::create_directories(out);
  const planar_model nominal = sharon2005_human7();
  const auto target = load_keyframes(nominal, kf_path);
  const auto ctrl = load_nearest_neighbor(nominal, ctrl_path);
  const Eigen::VectorXd x = [&] {
    const auto p = ctrl.parameters();
    return Eigen::VectorXd(
        Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())));
  }();

  int walked = 0, total = 0;
  auto summary = [&](int n_walked, int n) {
    nlohmann::ordered_json s;
    s["example"] = "sharon2005_robustness";
    s["controller"] = ctrl_path;
    s["keyframes"] = kf_path;
    s["variants_walking"] = n_walked;
    s["variants"] = n;
    std::cout << s.dump() << std::endl;
    return 0;
  };
  auto report = [&](const std::string& name, const std::string& what, const auto& m,
                    const auto& ground, rollout_options ro = {}) {
    ro.initial_state = sharon_scenarios::start_state_for(m, target, ground);
    const rollout_problem prob{
        m,      torque_actuator{},     ctrl, mass_distance<planar_root>(m, target),
        ground, semi_implicit_euler{}, ro};
    trajectory traj;
    const walk_check w = check_walk(prob, x, seconds, &traj, 40, sharon2005_walk_criteria);
    const auto csv = out / ("sharon2005_robustness_" + name + ".csv");
    save_trajectory_csv(traj, csv.string());
    // A strobe picture of the first 3 s, like the paper's Figures 5b and 8.
    const auto svg = out / ("sharon2005_robustness_" + name + ".svg");
    filmstrip_options fo;
    fo.t_begin = 0.0;
    fo.t_end = std::min(3.0, w.seconds);
    fo.interval = 0.1;
    fo.title = what;
    save_filmstrip_svg(m, traj, svg.string(), fo);
    if (views.any()) {
      auto per_variant = [&](const std::string& f) {
        if (f.empty()) return f;
        const std::filesystem::path p(f);
        return (p.parent_path() / (p.stem().string() + "_" + name + p.extension().string()))
            .string();
      };
      viz_outputs v = views;
      for (std::string* f :
           {&v.html, &v.filmstrip_svg, &v.gait_svg, &v.bvh, &v.trajectory_csv, &v.mjcf_replay})
        *f = per_variant(*f);
      v.html_options.title = what;
      v.filmstrip = fo;
      write_viz_outputs(m, traj, v, &std::cerr);
    }
    const bool ok = w.walked;  // rollout/walk_check.hpp: no fall, no stall, >= 0.3 m/s
    walked += ok;
    ++total;
    nlohmann::ordered_json j;
    j["variant"] = name;
    j["description"] = what;
    j["seconds_walked"] = w.seconds;
    j["fell"] = w.fell;
    j["stalled"] = w.stalled;
    j["distance"] = std::round(w.distance * 1000) / 1000;
    j["average_speed"] = std::round(w.average_speed * 1000) / 1000;
    j["walks"] = ok;
    j["trajectory_csv"] = csv.string();
    j["filmstrip_svg"] = svg.string();
    std::cout << j.dump() << std::endl;
    std::cerr << name << ": " << verdict(w) << " (" << w.seconds << " s), " << w.distance << " m ("
              << what << ")\n";
  };
  report("nominal", "the 7-link human of Table I on flat ground", nominal, flat_terrain{});
  if (!disturbances.empty()) {
    for (const auto& d : disturbances == "test" ? sharon_scenarios::test_disturbances()
                                                : sharon_scenarios::training_disturbances())
      report(d.name, d.description, sharon2005_human7(d.body()), d.ground(),
             d.apply(rollout_options{}, seconds));
    return summary(walked, total);
  }
  for (const auto& v : sharon_scenarios::figure8_bodies())
    report(v.name, v.description, sharon2005_human7(v.params), flat_terrain{});
  const auto bumps = sharon_scenarios::bumpy_terrain();
  report("bumpy_terrain",
         "Fig. 8d: bumpy terrain, steepest gradient " +
             std::to_string(sharon_scenarios::max_gradient_deg(bumps, -5.0, 110.0)) + " deg",
         nominal, bumps);
  return summary(walked, total);
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
