// The mass-distance objective (objectives/mass_distance.hpp, eqs. 2-3) against hand-computed values
// on the small biped: two point masses per link at its ends, each half the link's mass.
#include <catch2/catch.hpp>
#include <cmath>

#include "gaitsynth/objectives/mass_distance.hpp"
#include "support/sharon2005.hpp"

using namespace gaitsynth;
using sharon_test::small_biped;
using sharon_test::vec;

namespace {
// A constant "motion": every keyframe is pose q0 (no advance).
keyframe_motion<planar_root> still(const planar_model& m, const Eigen::VectorXd& q0) {
  return keyframe_motion<planar_root>(m, {{0.0, q0}}, 1.0, false);
}
// delta between configurations qa and qb, through the library's forward kinematics.
double delta(const planar_model& m, const Eigen::VectorXd& qa, const Eigen::VectorXd& qb) {
  auto wa = make_workspace(m), wb = make_workspace(m);
  forward_kinematics(m, wa, qa);
  forward_kinematics(m, wb, qb);
  const auto pts = link_end_points(m);
  return mass_distance_error(pts, wa.body_rotation, wa.body_position, wb.body_rotation,
                             wb.body_position);
}
}  // namespace

TEST_CASE("mass distance: point masses at the link ends", "[objectives][mass_distance]") {
  const auto m = small_biped();
  const auto pts = link_end_points(m);
  REQUIRE(pts.size() == 10);
  CHECK(pts[0].mass == 5.0);  // torso 10 kg: 5 at the hip joint, 5 at the top
  CHECK(pts[1].position.z() == 0.5);
  CHECK(pts[2].mass == 1.0);  // thigh 2 kg
  CHECK(pts[3].position.z() == -0.4);
  double total = 0;
  for (const auto& p : pts) total += p.mass;
  CHECK(total == Approx(m.total_mass()));
}

TEST_CASE("mass distance: eq. 2 against hand-computed values", "[objectives][mass_distance]") {
  const auto m = small_biped();
  const Eigen::VectorXd q0 = vec({0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  CHECK(delta(m, q0, q0) == 0.0);
  // A pure translation by d moves every point by d: delta = M |d|^2 = 16 kg * (0.3^2 + 0.4^2).
  Eigen::VectorXd q = q0;
  q[0] = 0.3;
  q[1] = 1.4;
  CHECK(delta(m, q, q0) == Approx(16.0 * 0.25));
  // Left knee bent by th: only the left shin's end (0.5 kg) moves, along a chord 2 l sin(th/2).
  const double th = 0.7;
  q = q0;
  q[4] = th;
  const double chord = 2 * 0.4 * std::sin(th / 2);
  CHECK(delta(m, q, q0) == Approx(0.5 * chord * chord));
  // Left hip by th: thigh end (1 kg) and shin origin (0.5 kg) move along a 0.4 m chord, shin end
  // (0.5 kg) along a 0.8 m chord.
  q = q0;
  q[3] = th;
  const double c4 = 2 * 0.4 * std::sin(th / 2), c8 = 2 * 0.8 * std::sin(th / 2);
  CHECK(delta(m, q, q0) == Approx(1.0 * c4 * c4 + 0.5 * c4 * c4 + 0.5 * c8 * c8));
}

TEST_CASE("mass distance: eq. 3 integrates delta over time, falls and stalls pay for the time left",
          "[objectives][mass_distance]") {
  const auto m = small_biped();
  const Eigen::VectorXd q0 = vec({0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  mass_distance_options o;
  o.fall_rate = 50.0;
  const mass_distance<planar_root> obj(m, still(m, q0), o);
  auto acc = obj.make_accumulator(m);
  // Simulated pose: translated up by 0.1 m, so delta = 16 * 0.01 = 0.16 kg m^2 at every step.
  Eigen::VectorXd q = q0, v = Eigen::VectorXd::Zero(m.nv());
  q[1] += 0.1;
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, q, v);
  step_view<planar_root> sv;
  sv.model_ptr = &m;
  sv.q_ptr = &q;
  sv.v_ptr = &v;
  sv.body_rotation = ws.body_rotation;
  sv.body_position = ws.body_position;
  sv.dt = 0.01;
  for (int k = 0; k < 150; ++k) {
    sv.t = k * sv.dt;
    sv.step = k;
    obj.accumulate(acc, sv);
  }
  rollout_outcome out;
  out.duration = 2.0;
  out.time = 1.5;
  out.reason = stop_reason::horizon;
  CHECK(obj.finish(acc, out) == Approx(0.16 * 1.5));
  out.reason = stop_reason::fell;  // 0.5 s left at max(0.16, 50) kg m^2
  CHECK(obj.finish(acc, out) == Approx(0.16 * 1.5 + 0.5 * 50.0));
  out.reason = stop_reason::stalled;  // standing still is no cheaper than falling
  CHECK(obj.finish(acc, out) == Approx(0.16 * 1.5 + 0.5 * 50.0));
  double terms[2];
  obj.terms(acc, terms);
  CHECK(terms[0] == Approx(0.16));
  CHECK(terms[1] == Approx(0.24));

  // Default fall rate: the first target pose against itself collapsed to z = 0:
  // torso points at z = 1 and 1.5 (5 kg each), thighs' ends and shins' origins at 0.6 (1 + 0.5 kg
  // per leg), thighs' origins at 1 (1 kg per leg), shins' ends at 0.2 (0.5 kg per leg).
  const mass_distance<planar_root> od(m, still(m, q0));
  const double expect = 5 * 1.0 + 5 * 2.25 + 2 * (1.0 * 1.0 + 1.5 * 0.36 + 0.5 * 0.04);
  CHECK(od.fall_rate() == Approx(expect));
}

TEST_CASE("mass distance: the target moves with the keyframe motion",
          "[objectives][mass_distance]") {
  const auto m = small_biped();
  const auto walk = sharon_test::small_walk(m);
  const mass_distance<planar_root> obj(m, walk);
  auto acc = obj.make_accumulator(m);
  auto ws = make_workspace(m);
  Eigen::VectorXd q(m.nq()), v = Eigen::VectorXd::Zero(m.nv());
  step_view<planar_root> sv;
  sv.model_ptr = &m;
  sv.q_ptr = &q;
  sv.v_ptr = &v;
  sv.dt = 0.001;
  // A character exactly on the target motion has zero error at every time.
  for (int k = 0; k < 2000; k += 37) {
    sv.t = k * sv.dt;
    walk.pose(sv.t, q);
    forward_kinematics(m, ws, q, v);
    sv.body_rotation = ws.body_rotation;
    sv.body_position = ws.body_position;
    obj.accumulate(acc, sv);
    CHECK(acc.delta < 1e-20);
  }
  CHECK_THROWS_WITH(mass_distance<planar_root>(m, walk, {.time_offset = NAN}),
                    Catch::Contains("time_offset is not finite"));
}
