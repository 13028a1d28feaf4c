// Sharon & van de Panne 2005, Figure 5c/d: the 16-link planar human walks.
//
// As in the paper, only the hips, knees and ankles are optimized (6 free nodes x 12 = 72
// parameters); the upper body (back, chest, neck, arms) follows the target poses stored in the
// nodes. Keyframes: data/sharon2005/human16_walk.keyframes.json. The torso servo drives the pelvis
// (the root, which carries the hips) to the target's orientation.
//
//   ./sharon2005_human16 [--out DIR] [--threads N] ...
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "sharon2005_common.hpp"

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv, "optimize a walk of the 16-link human (Sharon & van de Panne 2005, Fig. 5c)");
  const planar_model m = sharon2005_human16();
  const std::string kf_path = sharon_example::keyframes_path(c, "human16_walk.keyframes.json");
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);
  const nearest_neighbor_options o = sharon_example::human16_options(m);
  const auto c0 = sharon_example::initial_controller(m, target, o, c);
  const auto prob = sharon_example::make_problem(m, target, c0, c);
  return sharon_example::synthesize_and_report("sharon2005_human16", prob,
                                               sharon_example::synthesis_defaults(), c,
                                               {{"keyframes", kf_path}, {"figure", "5c"}});
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
