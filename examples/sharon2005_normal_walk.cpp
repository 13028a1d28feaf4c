// Sharon & van de Panne 2005, Figure 5a/b: a normal walk of the 7-link planar human.
//
// From the keyframes of data/sharon2005/normal_walk.keyframes.json (one step listed, the other is
// its mirror image), a 12-node nearest-neighbor controller (6 free nodes x 12 parameters = 72) is
// initialized along the target motion and optimized with SDS on the mass-distance cost over
// bootstrapped episodes of 0.2 s to 2 s. Each candidate is evaluated from the first keyframe's
// state and from three perturbed copies of it (velocities x0.9 and x1.1, 1 cm higher: the remedy
// the paper's section VII proposes; --single-start evaluates from the first state alone, as the
// paper did). The result is then simulated for 70 s (the paper's test).
//
//   ./sharon2005_normal_walk [--out DIR] [--threads N] [--single-start] ...
//
// Writes DIR/sharon2005_normal_walk.controller.json, .csv (70 s trajectory, 60 frames/s) and
// .convergence.csv; prints a one-line JSON summary on stdout, progress on stderr.
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/io/keyframes_json.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "sharon2005_common.hpp"

int main(int argc, char** argv) try {
  using namespace gaitsynth;
  const auto c = sharon_example::parse(
      argc, argv, "optimize a normal walk of the 7-link human (Sharon & van de Panne 2005, Fig. 5a)");
  const planar_model m = sharon2005_human7();
  const std::string kf_path =
      c.keyframes.empty() ? sharon_example::data_file("normal_walk.keyframes.json") : c.keyframes;
  const keyframe_motion<planar_root> target = load_keyframes(m, kf_path);

  const nearest_neighbor_controller<planar_root> c0(m, target, sharon_example::human7_options());
  rollout_options ro;
  ro.initial_state = target.initial_state();
  nn_problem prob{m, torque_actuator{}, c0, mass_distance<planar_root>(m, target),
                        flat_terrain{}, semi_implicit_euler{}, ro};
  sharon_example::set_starts(prob, c);
  return sharon_example::synthesize_and_report("sharon2005_normal_walk", prob,
                                               sharon_example::synthesis_defaults(), c,
                                               {{"keyframes", kf_path}, {"figure", "5a"}});
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
