// Sharon & van de Panne 2005, Figure 7: a controller optimized for, and walking up, a 10 degree
// slope (12 nodes, 72 parameters). Keyframes: data/sharon2005/uphill.keyframes.json, whose stride
// climbs with the slope.
//
//   ./sharon2005_uphill [--out DIR] [--threads N] ...
#include <numbers>

#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "sharon2005_common.hpp"

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv, "optimize a walk up a 10 degree slope (Sharon & van de Panne 2005, Fig. 7)");
  const planar_model m = sharon2005_human7();
  const std::string kf_path = sharon_example::keyframes_path(c, "uphill.keyframes.json");
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);
  const auto c0 =
      sharon_example::initial_controller(m, target, sharon_example::human7_options(), c);
  const slope_terrain hill(10.0 * std::numbers::pi / 180.0);
  const auto prob = sharon_example::make_problem(m, target, c0, c, hill);
  return sharon_example::synthesize_and_report(
      "sharon2005_uphill", prob, sharon_example::synthesis_defaults(), c,
      {{"keyframes", kf_path}, {"figure", "7a"}, {"slope_degrees", 10.0}});
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
