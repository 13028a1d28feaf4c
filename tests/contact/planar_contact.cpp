// The planar path of penalty contact (penalty_contact.hpp, apply_contact_forces_planar) against
// the general path on the same kinematics: random planar trees with contact points off the x-z
// plane and COMs off it, flat ground, a slope, and a height field that also slopes across y (its
// normal leaves the plane, so some points take the general formula inside the planar path). Over
// a sequence of states the two must produce the same forces, anchors, flags and external wrenches.
// The planar path only drops terms that are exact zeros of the general one, so in the test build
// (no FMA contraction) the results are identical; the tolerance only leaves room for a compiler
// that contracts the two paths' products differently.
#include <catch2/catch.hpp>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;
using gaitsynth::testing::random_inertia;
using gaitsynth::testing::random_vec3;
using gaitsynth::testing::random_vector;

namespace {

/// A random planar tree (hinges about +-y) with two contact points per body, some off the plane.
model<planar_root> random_planar_model_with_contacts(std::mt19937& rng, int nb) {
  model_builder<planar_root> b("random_planar_contacts");
  std::uniform_real_distribution<double> mass(0.2, 5.0);
  std::bernoulli_distribution flip(0.5), off_plane(0.3);
  auto com = [&] {
    vec3 c = random_vec3(rng, 0.1);
    if (!off_plane(rng)) c.y() = 0.0;
    return c;
  };
  b.add_body({.name = "b0", .mass = mass(rng), .com = com(), .inertia = random_inertia(rng)});
  for (int i = 1; i < nb; ++i) {
    const int parent = std::uniform_int_distribution<int>(0, i - 1)(rng);
    b.add_body({.name = detail::concat("b", i),
                .parent = detail::concat("b", parent),
                .joint_offset = random_vec3(rng, 0.3),
                .mass = mass(rng),
                .com = com(),
                .inertia = random_inertia(rng),
                .dofs = {{.name = detail::concat("j", i),
                          .axis = vec3(0.0, flip(rng) ? 1.0 : -1.0, 0.0)}}});
  }
  for (int i = 0; i < nb; ++i)
    for (int k = 0; k < 2; ++k) {
      vec3 p = random_vec3(rng, 0.2);
      if (!off_plane(rng)) p.y() = 0.0;
      b.add_contact_point(
          {.name = detail::concat("c", i, "_", k),
           .body = detail::concat("b", i),
           .position = p,
           .role = k == 0 ? contact_point::kind::sole : contact_point::kind::toe_top});
    }
  return b.build();
}

/// a: the planar path; b: the general path, whose broad phase may skip a body far above the
/// terrain (its points' positions are then not computed, and their depth is only negative).
void require_same_contacts(const model<planar_root>& m, const contact_state& a,
                           const contact_state& b, const workspace<planar_root>& wa,
                           const workspace<planar_root>& wb) {
  REQUIRE(a.total_points_touching == b.total_points_touching);
  REQUIRE(a.any_toe_top_touching == b.any_toe_top_touching);
  REQUIRE(a.points_touching == b.points_touching);
  REQUIRE(a.toe_top_touching == b.toe_top_touching);
  REQUIRE(a.active == b.active);
  REQUIRE(a.sliding == b.sliding);
  for (int k = 0; k < a.num_points(); ++k) {
    CAPTURE(k);
    if (b.near[m.contact_points[k].body]) {
      REQUIRE_THAT(Eigen::MatrixXd(a.position[k]), is_approx(b.position[k], 1e-14, 1e-14));
      REQUIRE(a.depth[k] == Approx(b.depth[k]).epsilon(1e-13).margin(1e-15));
    } else {
      REQUIRE(a.depth[k] < 0.0);
      REQUIRE(b.depth[k] < 0.0);
    }
    REQUIRE_THAT(Eigen::MatrixXd(a.force[k]), is_approx(b.force[k], 1e-12, 1e-12));
    if (a.active[k])
      REQUIRE_THAT(Eigen::MatrixXd(a.anchor[k]), is_approx(b.anchor[k], 1e-14, 1e-14));
  }
  for (std::size_t i = 0; i < wa.f_ext.size(); ++i)
    REQUIRE_THAT(Eigen::MatrixXd(wa.f_ext[i]), is_approx(wb.f_ext[i], 1e-12, 1e-12));
}

/// Moves a random model through a sequence of states that press it into terrain t, and compares
/// the planar and general contact paths on identical kinematics at every state.
template <class Terrain>
void compare_paths(const Terrain& t, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const contact_parameters params;
  const double dt = 1.0 / 2400.0;
  int touching_seen = 0, sliding_seen = 0;
  for (int trial = 0; trial < 20; ++trial) {
    CAPTURE(trial);
    const auto m = random_planar_model_with_contacts(rng, 2 + trial % 6);
    auto ws = make_workspace(m);
    REQUIRE(ws.scratch.planar.enabled);
    auto fast = make_contact_state(m), ref = make_contact_state(m);
    Eigen::VectorXd q = random_vector(rng, m.nq(), 1.0);
    Eigen::VectorXd v = random_vector(rng, m.nv(), 1.0);
    q[1] = 0.05;  // the root near the ground: some points below it, some above
    for (int step = 0; step < 30; ++step) {
      CAPTURE(step);
      forward_kinematics(m, ws, q, v);
      workspace<planar_root> general = ws;  // the same kinematics, general contact path
      general.scratch.planar.enabled = false;
      clear_external_wrenches(ws);
      clear_external_wrenches(general);
      apply_contact_forces(m, ws, t, params, fast, dt);
      apply_contact_forces(m, general, t, params, ref, dt);
      require_same_contacts(m, fast, ref, ws, general);
      touching_seen += fast.total_points_touching;
      for (auto s : fast.sliding) sliding_seen += s;
      q += 0.02 * v + random_vector(rng, m.nq(), 0.002);  // drift, so anchors stretch and slide
      v += random_vector(rng, m.nv(), 0.3);
    }
  }
  // The comparison covered touching and sliding points.
  REQUIRE(touching_seen > 50);
  REQUIRE(sliding_seen > 5);
}

}  // namespace

TEST_CASE("planar contact path equals the general path: flat ground", "[contact][planar]") {
  compare_paths(flat_terrain(0.0), 11);
}

TEST_CASE("planar contact path equals the general path: 10 degree slope", "[contact][planar]") {
  compare_paths(slope_terrain(10.0 * 3.14159265358979 / 180.0), 12);
}

TEST_CASE("planar contact path equals the general path: height field sloping across y",
          "[contact][planar]") {
  // Heights vary along y too, so the normal at y = 0 has a y component: those points take the
  // general formula inside the planar path.
  std::mt19937 rng(13);
  const Eigen::VectorXd values = random_vector(rng, 40 * 3, 0.05);
  const Eigen::MatrixXd h = Eigen::Map<const Eigen::MatrixXd>(values.data(), 40, 3);
  compare_paths(height_field_terrain(Eigen::Vector2d(-10.0, -1.0), 0.5, h), 13);
}
