// leg_overlap (analysis/leg_overlap.hpp): two vertical capsules placed by hand at known distances
// (depth r_a + r_b - d, by hand), a crossing, the humanoid's legs in its neutral pose (apart) and
// crossed by the hips (overlapping), and bad input refused by name.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "gaitsynth/analysis/leg_overlap.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/viz/scene.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

const floating_model& humanoid() {
  static const floating_model m = wang2009_humanoid();
  return m;
}

/// A frame with every body at the origin, unrotated, but body b at `p` rotated by `R`.
trajectory_frame frame_with(double t, int b, const vec3& p,
                            const Eigen::Quaterniond& R = Eigen::Quaterniond::Identity()) {
  const auto nb = static_cast<std::size_t>(humanoid().num_bodies());
  trajectory_frame f;
  f.t = t;
  f.q = neutral_configuration(humanoid());
  f.body_position.assign(nb, vec3::Zero());
  f.body_orientation.assign(nb, Eigen::Quaterniond::Identity());
  f.body_position[static_cast<std::size_t>(b)] = p;
  f.body_orientation[static_cast<std::size_t>(b)] = R;
  return f;
}

}  // namespace

TEST_CASE("leg_overlap: the depth of two capsules at known distances", "[analysis]") {
  const floating_model& m = humanoid();
  const int a = m.body_index("lthigh"), b = m.body_index("rthigh");
  // Two vertical segments 0.4 m long, radii 0.06 and 0.04: touching below 0.1 m apart.
  const std::vector<self_collision_pair> pairs{
      {{a, vec3(0, 0, 0), vec3(0, 0, -0.4), 0.06}, {b, vec3(0, 0, 0), vec3(0, 0, -0.4), 0.04}}};
  trajectory tr;
  tr.frames.push_back(frame_with(0.0, b, vec3(0, 0.5, 0)));      // transient, left out
  tr.frames.push_back(frame_with(1.0, b, vec3(0, 0.15, 0)));     // apart by 0.05
  tr.frames.push_back(frame_with(1.1, b, vec3(0.03, 0.04, 0)));  // d 0.05: 0.05 deep
  tr.frames.push_back(frame_with(1.2, b, vec3(0, 0.08, 0.2)));   // d 0.08 (side by side): 0.02
  // Rotated 90 degrees about x so that it lies along y through a's axis: d 0 (crossing), 0.1 deep.
  tr.frames.push_back(frame_with(1.3, b, vec3(0, -0.2, -0.2),
                                 Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, vec3::UnitX()))));
  const leg_overlap_report r = leg_overlap(m, tr, pairs, 0.5);
  CHECK(r.frames == 4);
  CHECK_THAT(r.max_depth, WithinAbs(0.1, 1e-12));
  CHECK(r.worst_pair == 0);
  CHECK(r.worst_time == 1.3);
  CHECK(r.overlapping_fraction == 0.75);
  tr.frames.pop_back();
  const leg_overlap_report r2 = leg_overlap(m, tr, pairs, 0.5);
  CHECK_THAT(r2.max_depth, WithinAbs(0.05, 1e-12));
  CHECK(r2.worst_time == 1.1);
  CHECK(leg_overlap(m, tr, pairs, 1.05).frames == 2);  // from t_begin on
  // Nothing overlapping: depth 0, no worst pair.
  tr.frames.resize(2);
  const leg_overlap_report none = leg_overlap(m, tr, pairs, 0.5);
  CHECK(none.max_depth == 0.0);
  CHECK(none.worst_pair == -1);
  CHECK(none.overlapping_fraction == 0.0);
}

TEST_CASE("leg_overlap: the humanoid's legs apart when standing, overlapping when crossed",
          "[analysis]") {
  const floating_model& m = humanoid();
  const std::vector<self_collision_pair> pairs = leg_capsule_pairs(m);
  REQUIRE(pairs.size() == 3);
  trajectory tr;
  tr.frames.resize(2);
  tr.frames[0].t = 0.0;
  tr.frames[0].q = neutral_configuration(m);
  // Both hips adducted 0.2 rad (the left leg swung to the right about +x, the right to the
  // left): the knees meet in the middle and the shins pass through each other.
  tr.frames[1].t = 0.1;
  tr.frames[1].q = neutral_configuration(m);
  tr.frames[1].q[floating_root::nq + m.dof_index("lhip_x")] = -0.2;
  tr.frames[1].q[floating_root::nq + m.dof_index("rhip_x")] = 0.2;
  fill_missing_kinematics(m, tr);
  trajectory standing = tr;
  standing.frames.pop_back();
  CHECK(leg_overlap(m, standing, pairs).max_depth == 0.0);
  const leg_overlap_report crossed = leg_overlap(m, tr, pairs);
  CHECK(crossed.max_depth > 0.05);
  CHECK(crossed.overlapping_fraction == 0.5);
  CHECK(crossed.worst_time == 0.1);
  CHECK(crossed.worst_pair == 2);  // the shins
  CHECK(leg_overlap_pair_name(m, pairs, crossed.worst_pair) == "lshin-rshin");
  CHECK(leg_overlap_pair_name(m, pairs, 0) == "lthigh-rshin");
  CHECK(leg_overlap_pair_name(m, pairs, -1).empty());
  CHECK_THROWS_WITH(leg_overlap_pair_name(m, pairs, 3), Contains("pair 3 of 3"));
}

TEST_CASE("leg_overlap: bad input is refused by name", "[analysis][bad_input]") {
  const floating_model& m = humanoid();
  CHECK_THROWS_WITH(leg_capsule_pairs(m, "thigh", "shank"), Contains("shank'"));
  CHECK_THROWS_WITH(leg_capsule_pairs(m, "foot", "shin"), Contains("no capsule"));
  std::vector<self_collision_pair> pairs = leg_capsule_pairs(m);
  trajectory tr;
  tr.frames.push_back(frame_with(0.0, 0, vec3::Zero()));
  tr.frames.back().body_position.pop_back();
  CHECK_THROWS_WITH(leg_overlap(m, tr, pairs), Contains("record body poses"));
  CHECK_THROWS_WITH(leg_overlap(m, tr, pairs, NAN), Contains("t_begin"));
  pairs[0].a.radius = -1.0;
  CHECK_THROWS_WITH(leg_overlap(m, tr, pairs), Contains("radius"));
}
