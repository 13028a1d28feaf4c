// Draws the hand-authored keyframes of Sharon & van de Panne 2005 (Figures 5a, 5c, 6a, 6c, 7a) as
// SVG strips, the way the paper shows them, and checks that each file loads. The pictures in
// docs/reproductions/sharon2005/ are made by
//
//   ./sharon2005_keyframes --out docs/reproductions/sharon2005
//
// One SVG per keyframe file: the listed keyframes side by side (the step that the mirror image
// completes), with the ground under the stance foot.
//
//   sharon2005_keyframes [--out DIR]     (the folder of the SVGs, created; default out)
//
// Nothing is random: there is no --seed. --help lists the flags.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace {

template <gaitsynth::root_joint Root>
void draw(const gaitsynth::model<Root>& m, const std::string& file, const std::string& svg,
          const std::string& title, double slope_deg = 0.0) {
  using namespace gaitsynth;
  const auto motion =
      load_keyframes(m, std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + file);
  trajectory tr;
  // One frame per listed keyframe at its time, then the closing (mirrored) keyframe.
  for (const keyframe& k : motion.keyframes()) {
    trajectory_frame f;
    f.t = k.time;
    f.q = k.q;
    tr.frames.push_back(f);
  }
  {
    trajectory_frame f;
    f.t = motion.end_time();
    f.q.resize(m.nq());
    motion.pose(motion.end_time(), f.q);
    tr.frames.push_back(f);
  }
  if (slope_deg != 0.0) {
    // Terrain samples of the slope under the drawing (the filmstrip draws the profile).
    const slope_terrain ground(slope_deg * 3.14159265358979323846 / 180.0);
    tr.terrain.x0 = -2.0;
    tr.terrain.y0 = -1.0;
    tr.terrain.dx = 0.1;
    tr.terrain.dy = 1.0;
    tr.terrain.nx = 50;
    tr.terrain.ny = 3;
    for (int iy = 0; iy < tr.terrain.ny; ++iy)
      for (int ix = 0; ix < tr.terrain.nx; ++ix)
        tr.terrain.height.push_back(ground.height(tr.terrain.x0 + ix * tr.terrain.dx, 0.0));
  }
  fill_missing_kinematics(m, tr);
  filmstrip_options o;
  o.count = static_cast<int>(tr.frames.size());
  o.interval = 0.0;
  o.spread = 0.7;
  o.fade = false;
  o.show_com_path = false;
  o.show_contacts = false;
  o.show_times = true;
  o.width = 1000;
  o.title = title;
  save_filmstrip_svg(m, tr, svg, o);
  std::cerr << "wrote " << svg << " (" << motion.num_keyframes() << " keyframes, step "
            << motion.end_time() << " s, stride " << motion.advance()[0] << " m)\n";
}

}  // namespace

int main(int argc, char** argv) try {
  std::string out = "out";
  CLI::App app{
      "Draws the hand-authored keyframes of Sharon & van de Panne 2005 (Figures 5a, 5c, 6a, 6c, "
      "7a) as SVG strips.",
      "sharon2005_keyframes"};
  app.option_defaults()->always_capture_default();
  app.add_option("--out", out, "folder of the SVGs (created)");
  example_cli::parse(app, argc, argv);
  const std::filesystem::path dir = out;
  std::filesystem::create_directories(dir);
  using namespace gaitsynth;
  const planar_model h7 = sharon2005_human7();
  const planar_model h16 = sharon2005_human16();
  struct item {
    std::string file, svg, title;
    bool human16;
    double slope;
  };
  const std::vector<item> items = {
      {"normal_walk.keyframes.json", "fig5a_normal_walk.svg", "Fig. 5a: normal walk (7-link)",
       false, 0},
      {"human16_walk.keyframes.json", "fig5c_human16_walk.svg",
       "Fig. 5c: walk of the 16-link human", true, 0},
      {"high_knee.keyframes.json", "fig6a_high_knee.svg",
       "Fig. 6a: long double stance, high knee lift", false, 0},
      {"backswing.keyframes.json", "fig6c_backswing.svg",
       "Fig. 6c: extra back-swing of the swing leg", false, 0},
      {"uphill.keyframes.json", "fig7a_uphill.svg", "Fig. 7a: walk up a 10 degree slope", false,
       10},
  };
  for (const item& it : items) {
    if (!std::filesystem::exists(std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" +
                                 it.file)) {
      std::cerr << "skipping " << it.file << " (not there)\n";
      continue;
    }
    if (it.human16)
      draw(h16, it.file, (dir / it.svg).string(), it.title, it.slope);
    else
      draw(h7, it.file, (dir / it.svg).string(), it.title, it.slope);
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
