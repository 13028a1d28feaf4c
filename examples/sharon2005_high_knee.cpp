// Sharon & van de Panne 2005, Figure 6a/b: a stylized walk with a prolonged double stance and an
// exaggerated knee lift, 24 nodes (12 free x 12 = 144 parameters).
//
//   ./sharon2005_high_knee [--out DIR] [--threads N] ...
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "sharon2005_common.hpp"

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv, "optimize the high-knee style walk (Sharon & van de Panne 2005, Fig. 6a)",
      {.disturbances = true});
  const planar_model m = sharon2005_human7();
  const std::string kf_path = sharon_example::keyframes_path(c, "high_knee.keyframes.json");
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);
  nearest_neighbor_options o = sharon_example::human7_options();
  o.num_nodes = 24;
  const auto c0 = sharon_example::initial_controller(m, target, o, c);
  const auto prob = sharon_example::make_problem(m, target, c0, c);
  nn_synthesis_options so = sharon_example::synthesis_defaults();
  so.evaluations_per_episode = 700;  // 144 parameters: about 2.5 sweeps per episode
  return sharon_example::with_disturbance_training(prob, target, c, [&](const auto& p) {
    return sharon_example::synthesize_and_report(
        "sharon2005_high_knee", p, so, c,
        {{"keyframes", kf_path},
         {"figure", "6a"},
         {"disturbance_training", c.disturbance_training}});
  });
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
