// The contact broad phase (contact/penalty_contact.hpp): every terrain's height bound holds over
// its disc, and skipping the bodies above it changes no force, anchor or count of the full pass,
// bit for bit, on the Wang 2009 humanoid (63 points) tumbling near four terrains.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "support/contact_e1.hpp"

using namespace gaitsynth;

namespace {

/// The same terrain without its height bound: the broad phase then skips nothing.
template <terrain T>
struct unbounded {
  const T& t;
  double height(double x, double y) const { return t.height(x, y); }
  vec3 normal(double x, double y) const { return t.normal(x, y); }
  surface_contact penetration(const vec3& p) const { return terrain_penetration(t, p); }
};

template <terrain T>
void check_height_bound(const T& t, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double x = 3.0 * u(rng), y = 2.0 * u(rng), r = 0.5 * (1.0 + u(rng));
    const double bound = terrain_max_height(t, x, y, r);
    for (int k = 0; k < 20; ++k) {
      const double a = std::numbers::pi * u(rng), s = r * std::sqrt(0.5 * (1.0 + u(rng)));
      REQUIRE(t.height(x + s * std::cos(a), y + s * std::sin(a)) <= bound + 1e-12);
    }
  }
}

/// The humanoid dropped through a sequence of random poses and velocities near terrain `t`, with
/// and without the broad phase, on one contact state each (anchors carry over): identical.
template <terrain T>
void check_same_contacts(const T& t, std::uint32_t seed) {
  const floating_model m = wang2009_humanoid();
  auto ws_a = make_workspace(m), ws_b = make_workspace(m);
  auto cs_a = make_contact_state(m), cs_b = make_contact_state(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const contact_parameters p{.mu = 0.8};
  int skipped = 0, touched = 0;
  for (int step = 0; step < 300; ++step) {
    // A lying, tumbling or upright body; heights from sunk to well clear of the ground.
    const mat3 R =
        Eigen::AngleAxisd(std::numbers::pi * u(rng), vec3(u(rng), u(rng), u(rng)).normalized())
            .toRotationMatrix();
    Eigen::VectorXd q = test_e1::floating_q({0.5 * u(rng), 0.3 * u(rng), 0.6 + 0.6 * u(rng)}, R,
                                            m.num_joint_dofs());
    for (int j = 0; j < m.num_joint_dofs(); ++j) q[7 + j] = 0.8 * u(rng);
    Eigen::VectorXd v(m.nv());
    for (int j = 0; j < m.nv(); ++j) v[j] = 0.5 * u(rng);
    forward_kinematics(m, ws_a, q, v);
    forward_kinematics(m, ws_b, q, v);
    clear_external_wrenches(ws_a);
    clear_external_wrenches(ws_b);
    apply_contact_forces(m, ws_a, t, p, cs_a, 1.0 / 2400.0);
    apply_contact_forces(m, ws_b, unbounded<T>{t}, p, cs_b, 1.0 / 2400.0);
    for (int b = 0; b < m.num_bodies(); ++b) {
      REQUIRE(ws_a.f_ext[b] == ws_b.f_ext[b]);
      REQUIRE(cs_a.points_touching[b] == cs_b.points_touching[b]);
      REQUIRE(cs_a.toe_top_touching[b] == cs_b.toe_top_touching[b]);
      skipped += cs_a.reach[b] >= 0.0 && !cs_a.near[b];
    }
    REQUIRE(cs_a.total_points_touching == cs_b.total_points_touching);
    for (int k = 0; k < cs_a.num_points(); ++k) {
      REQUIRE(cs_a.active[k] == cs_b.active[k]);
      REQUIRE(cs_a.force[k] == cs_b.force[k]);
      REQUIRE(cs_a.normal_force[k] == cs_b.normal_force[k]);
      if (cs_b.active[k]) REQUIRE(cs_a.anchor[k] == cs_b.anchor[k]);
      // A touching point's depth is the full pass's; a skipped one's is negative.
      REQUIRE((cs_a.depth[k] > 0.0) == (cs_b.depth[k] > 0.0));
      if (cs_b.depth[k] > 0.0) REQUIRE(cs_a.depth[k] == cs_b.depth[k]);
      if (!cs_a.near[m.contact_points[k].body]) REQUIRE(cs_a.depth[k] < 0.0);
    }
    touched += cs_b.total_points_touching > 0;
  }
  // Not vacuous: the broad phase skipped bodies, and contacts happened.
  CHECK(skipped > 300);
  CHECK(touched > 30);
}

}  // namespace

TEST_CASE("contact broad phase: every terrain's height bound holds over its disc",
          "[contact][broad_phase]") {
  std::mt19937 rng(5);
  check_height_bound(flat_terrain(0.1), rng);
  check_height_bound(slope_terrain(0.2, 0.05, Eigen::Vector2d(1.0, 0.5)), rng);
  check_height_bound(slope_terrain(-0.3), rng);
  check_height_bound(random_height_field({}, 3), rng);
  check_height_bound(random_boxes({}, 4), rng);
  check_height_bound(steps_terrain::stairs(0.0, 0.3, 0.15, 5), rng);
  // A terrain that gives no bound: nothing is ever skipped.
  const flat_terrain flat;
  CHECK(std::isinf(terrain_max_height(unbounded<flat_terrain>{flat}, 0.0, 0.0, 1.0)));
}

TEST_CASE("contact broad phase: skipping bodies above the terrain changes nothing",
          "[contact][broad_phase]") {
  SECTION("flat") {
    check_same_contacts(flat_terrain(0.0), 1);
  }
  SECTION("slope") {
    check_same_contacts(slope_terrain(0.21), 2);
  }
  SECTION("height field") {
    check_same_contacts(random_height_field({}, 7), 3);
  }
  SECTION("boxes") {
    check_same_contacts(random_boxes({}, 8), 4);
  }
}
