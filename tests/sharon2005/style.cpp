// The style claims of Sharon & van de Panne 2005 on the saved 7-link controllers: each walk keeps
// its keyframed shape (eq. 2, the mass-distance error) through every cycle of the 70 s test, far
// closer to its target than the target is to itself on the wrong foot. Re-simulation only.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/rollout/problem.hpp"

using namespace gaitsynth;

namespace {

std::string data(const std::string& f) {
  return std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/" + f;
}

struct style_errors {
  double first = 0.0;       ///< eq. 2 as optimized over the first cycle, kg m^2
  double mean = 0.0;        ///< per cycle over 70 s, phase and progression aligned
  double worst = 0.0;       ///< the worst such cycle
  double wrong_step = 0.0;  ///< the target against itself half a cycle later (scale)
  double drift = 0.0;       ///< phase drift at the end, s
  std::size_t cycles = 0;
};

/// The 70 s walk of a saved 7-link controller from its keyframes' first state, scored against
/// those keyframes.
style_errors measure_style(const std::string& controller_file, const std::string& keyframes_file) {
  const planar_model m = sharon2005_human7();
  const auto target = load_keyframes(m, data(keyframes_file));
  const auto ctrl = load_nearest_neighbor(m, data(controller_file));
  rollout_options ro;
  ro.initial_state = target.initial_state();
  const rollout_problem prob{m,
                             torque_actuator{},
                             ctrl,
                             mass_distance<planar_root>(m, target),
                             flat_terrain{},
                             semi_implicit_euler{},
                             ro};
  const auto p = ctrl.parameters();
  trajectory tr;
  const rollout_result r = prob.evaluate(
      Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())), 70.0, &tr,
      48);  // 50 frames/s
  REQUIRE(r.reason == stop_reason::horizon);
  style_errors e;
  // Eq. 2 exactly as optimized, over the first cycle (target in phase and in place).
  const double P = target.period();
  int nf = 0;
  for (const auto& f : tr.frames)
    if (f.t < P) e.first += f.objective_terms[0], ++nf;
  e.first /= nf;
  // Every cycle of the 70 s: the style error with timing and progression drift removed.
  std::vector<double> per_cycle;
  for (double t0 = 0.0; t0 + P <= 70.0; t0 += P) {
    const auto [err, phi] = phase_aligned_style_error(m, target, tr, t0, t0 + P, 0.01);
    per_cycle.push_back(err);
    e.drift = phi;
  }
  e.cycles = per_cycle.size();
  for (double d : per_cycle)
    e.mean += d / static_cast<double>(per_cycle.size()), e.worst = std::max(e.worst, d);
  // Scale: the same metric between the target and itself half a cycle later (the left and right
  // legs swapped: the style on the wrong foot), averaged over a cycle.
  const auto pts = link_end_points(m);
  auto wa = make_workspace(m), wb = make_workspace(m);
  Eigen::VectorXd qa(m.nq()), qb(m.nq());
  const int n = 200;
  for (int k = 0; k < n; ++k) {
    target.pose(P * k / n, qa);
    target.pose(P * k / n + 0.5 * P, qb);
    qb[0] = qa[0];
    forward_kinematics(m, wa, qa);
    forward_kinematics(m, wb, qb);
    e.wrong_step += mass_distance_error(pts, wa.body_rotation, wa.body_position, wb.body_rotation,
                                        wb.body_position) /
                    n;
  }
  WARN(controller_file << " style (kg m^2): first cycle " << e.first
                       << " (eq. 2 as optimized); per cycle over 70 s with phase and progression "
                          "aligned: mean "
                       << e.mean << ", worst " << e.worst << " over " << e.cycles
                       << " cycles (phase drift at the end " << e.drift
                       << " s); the wrong step scores " << e.wrong_step);
  return e;
}

}  // namespace

TEST_CASE("Fig. 5a/b: the normal walk follows the keyframed style (mass-distance per cycle)",
          "[sharon2005][claims][style]") {
  const style_errors e = measure_style("normal_walk.controller.json", "normal_walk.keyframes.json");
  REQUIRE(e.cycles == 63);
  // The walk keeps the keyframed shape in every one of its 63 cycles: far closer to the target
  // than the target is to itself on the wrong foot.
  CHECK(e.worst < 0.25 * e.wrong_step);
  CHECK(e.first < 0.25 * e.wrong_step);
}

TEST_CASE("Fig. 6a/b, 6c/d: the high-knee and back-swing walks keep their styles",
          "[sharon2005][claims][style]") {
  for (const std::string s : {"high_knee", "backswing"}) {
    INFO(s);
    const style_errors e = measure_style(s + ".controller.json", s + ".keyframes.json");
    CHECK(e.worst < 0.25 * e.wrong_step);
    CHECK(e.first < 0.25 * e.wrong_step);
  }
}
