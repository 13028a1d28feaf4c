// synthesis/sharon2005_scenarios.hpp's start_state_for: the first keyframe's pose, its lowest
// contact point on the ground under it, on every kind of terrain.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/synthesis/sharon2005_scenarios.hpp"

using namespace gaitsynth;

namespace {

/// The smallest height of m's contact points above `ground` (under each point) in configuration q.
template <class T>
double lowest_gap(const planar_model& m, const Eigen::VectorXd& q, const T& ground) {
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, q);
  double gap = 1e300;
  for (const auto& c : m.contact_points) {
    const vec3 p = point_position(m, ws, c.body, c.position);
    gap = std::min(gap, p.z() - ground.height(p.x(), p.y()));
  }
  return gap;
}

}  // namespace

TEST_CASE("start_state_for: the keyframed start stands on flat ground, slopes, bumps and steps",
          "[synthesis][sharon2005]") {
  const planar_model m = sharon2005_human7();
  const auto target = load_keyframes(
      m, std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/normal_walk.keyframes.json");
  const sim_state keyed = target.initial_state();

  const sim_state flat = sharon_scenarios::start_state_for(m, target);
  CHECK(std::abs(lowest_gap(m, flat.q, flat_terrain{})) < 1e-12);
  // Only the root height moves; the pose and the velocities are the keyframe's.
  CHECK(flat.q[0] == keyed.q[0]);
  CHECK(flat.q.tail(flat.q.size() - 2) == keyed.q.tail(keyed.q.size() - 2));
  CHECK(flat.v == keyed.v);

  const slope_terrain up(5.0 * std::numbers::pi / 180.0, 0.3);
  const sim_state on_slope = sharon_scenarios::start_state_for(m, target, up);
  CHECK(std::abs(lowest_gap(m, on_slope.q, up)) < 1e-12);

  const height_field_terrain bumps = sharon_scenarios::training_terrains(1)[0];
  const sim_state on_bumps = sharon_scenarios::start_state_for(m, target, bumps);
  CHECK(std::abs(lowest_gap(m, on_bumps.q, bumps)) < 1e-12);

  // A step edge under the feet: the contact point above the higher tread decides.
  const steps_terrain step({{keyed.q[0], 0.1}}, 0.0);
  const sim_state on_step = sharon_scenarios::start_state_for(m, target, step);
  CHECK(std::abs(lowest_gap(m, on_step.q, step)) < 1e-12);
  CHECK(on_step.q[1] > flat.q[1] - 1e-12);
}
