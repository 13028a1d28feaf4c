// The objective terms of Wang, Fleet & Hertzmann 2009, Sec. 4.1 (objectives/wang2009/, eqs. 3-16)
// against hand-computed values on synthetic step views, and the complete objective through a
// short standing rollout of the humanoid (finite cost, recorded terms, report).
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;
namespace w9 = gaitsynth::wang2009;

namespace {

const floating_model& humanoid() {
  static const floating_model m = wang2009_humanoid();
  return m;
}

/// A step view filled by hand: every span points into this object's vectors.
struct synthetic {
  const floating_model& m;
  std::vector<int> count;
  std::vector<std::uint8_t> toe_top;
  std::vector<vec3> pos, lin, ang;
  std::vector<mat3> rot;
  Eigen::VectorXd q, v, tau, tau_passive;
  step_view<floating_root> view;

  explicit synthetic(const floating_model& model, double dt = 0.01)
      : m(model),
        count(model.num_bodies(), 0),
        toe_top(model.num_bodies(), 0),
        pos(model.num_bodies(), vec3::Zero()),
        lin(model.num_bodies(), vec3::Zero()),
        ang(model.num_bodies(), vec3::Zero()),
        rot(model.num_bodies(), mat3::Identity()),
        q(neutral_configuration(model)),
        v(Eigen::VectorXd::Zero(model.nv())),
        tau(Eigen::VectorXd::Zero(model.nv())),
        tau_passive(Eigen::VectorXd::Zero(model.nv())) {
    view.model_ptr = &m;
    view.dt = dt;
    view.q_ptr = &q;
    view.v_ptr = &v;
    view.tau_ptr = &tau;
    view.tau_passive_ptr = &tau_passive;
    view.body_rotation = rot;
    view.body_position = pos;
    view.body_angular_velocity = ang;
    view.body_linear_velocity = lin;
    view.contact_count = count;
    view.toe_top_touching = toe_top;
  }
  int body(const char* name) const { return m.body_index(name); }
  /// Feeds the view at step k to an objective.
  template <class O>
  void feed(const O& o, typename O::accumulator_type& a, std::int64_t k) {
    view.step = k;
    view.t = static_cast<double>(k) * view.dt;
    o.accumulate(a, view);
  }
};

rollout_outcome outcome(stop_reason reason, double time, double duration,
                        const vec3& com0 = vec3::Zero(), const vec3& com1 = vec3::Zero()) {
  rollout_outcome o;
  o.reason = reason;
  o.time = time;
  o.duration = duration;
  o.com_initial = com0;
  o.com_final = com1;
  return o;
}

}  // namespace

TEST_CASE("wang2009: the thresholded quadratic (eq. 3)", "[objectives][wang2009]") {
  CHECK(w9::thresholded_quadratic(0.0, 0.025) == 0.0);
  CHECK(w9::thresholded_quadratic(0.02, 0.025) == 0.0);
  CHECK(w9::thresholded_quadratic(0.025, 0.025) == 0.0);  // at the threshold: still 0
  CHECK(w9::thresholded_quadratic(0.03, 0.025) == Approx(0.0009));
  CHECK(w9::thresholded_quadratic(-0.03, 0.025) == Approx(0.0009));
  CHECK(w9::thresholded_quadratic(2.0, 0.0) == 4.0);
  CHECK(std::isnan(w9::thresholded_quadratic(NAN, 0.025)));  // never hides a NaN as 0
}

TEST_CASE("wang2009: E_user from the average speed and heel strikes (eq. 4)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const int lf = s.body("lfoot"), lt = s.body("ltoes"), rf = s.body("rfoot");
  // Strikes (dt = 0.01 s): both feet down at the start; left off 10..39, strikes at 40 (x 0.6,
  // no step yet: no earlier strike); right off 50..79, strikes at 80 (x 1.2: step 0.6); left
  // off 90..119, strikes at 120 on its toes only (x 1.9: step 0.7); left bounces off 125..126
  // (0.02 s < 0.05 s: no strike); right off 130..139, strikes at 140 (x 2.5: step 0.6) ...
  // then right again off 150..169, strikes at 170 (x 2.6: same foot, only the reference moves).
  const w9::user_gait both(m, {.target_speed = 1.0, .target_step_length = 0.65});
  auto a = both.make_accumulator(m);
  for (int k = 0; k < 180; ++k) {
    const bool left_down = !(k >= 10 && k < 40) && !(k >= 90 && k < 120) && !(k >= 125 && k < 127);
    const bool right_down =
        !(k >= 50 && k < 80) && !(k >= 130 && k < 140) && !(k >= 150 && k < 170);
    s.count[lf] = left_down && k != 120 ? 4 : 0;
    s.count[lt] = left_down && k >= 120 ? 2 : 0;
    s.count[rf] = right_down ? 3 : 0;
    s.pos[lf].x() = k == 40 ? 0.6 : k == 120 ? 1.9 : -5.0;
    s.pos[rf].x() = k == 80 ? 1.2 : k == 140 ? 2.5 : k == 170 ? 2.6 : -5.0;
    s.feed(both, a, k);
  }
  REQUIRE(w9::user_gait::step_count(a) == 3);
  CHECK(w9::user_gait::step_length(a) == Approx((0.6 + 0.7 + 0.6) / 3));
  CHECK(a.counter.strikes == 5);
  // Speed 1.2 m/s over 2 s: Q(0.2) = 0.04; step length 0.6333: |d| = 0.0167 < 0.025 -> 0.
  const rollout_outcome o = outcome(stop_reason::horizon, 2.0, 2.0, vec3::Zero(), {2.4, 0, 0.9});
  CHECK(both.finish(a, o) == Approx(0.04));
  const w9::user_gait longer(m, {.target_step_length = 0.7});
  CHECK(longer.finish(a, o) == Approx(std::pow(0.7 - 1.9 / 3, 2)));
  const w9::user_gait near(m, {.target_speed = 1.18});
  CHECK(near.finish(a, o) == 0.0);  // within eps_vel
  const w9::user_gait none(m);
  CHECK(none.finish(a, o) == 0.0);  // no target: no term

  // No step completed: s = 0, so a step target is fully penalized.
  auto still = longer.make_accumulator(m);
  synthetic s2(m);
  s2.count[lf] = s2.count[rf] = 4;
  for (int k = 0; k < 10; ++k) s2.feed(longer, still, k);
  CHECK(longer.finish(still, o) == Approx(0.49));

  // Recorded running values: E_user, speed and step length.
  std::array<double, 3> t{};
  both.terms(a, t);
  CHECK(t[2] == Approx(1.9 / 3));
  CHECK_THROWS_WITH(w9::user_gait(sharon2005_human7(), {.target_step_length = 0.6}),
                    Catch::Contains("no body named 'ltoes'"));
  CHECK_THROWS_WITH(w9::user_gait(m, {.target_step_length = -0.6}),
                    Catch::Contains("target_step_length"));
  CHECK_NOTHROW(w9::user_gait(sharon2005_human7(), {.target_speed = 1.0}));
}

TEST_CASE("wang2009: E_vel (eq. 5) with the start speed and footnote 2", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const w9::velocity vel;
  auto a = vel.make_accumulator(m);
  s.view.com_velocity = {1.0, 0.3, 0.0};  // v_0x = 1 (only the first step's counts)
  s.feed(vel, a, 0);
  s.view.com_velocity = {5.0, 5.0, 5.0};
  s.feed(vel, a, 1);
  // Average velocity over 2 s: (1.2, 0.05, -0.06) m/s.
  const rollout_outcome o =
      outcome(stop_reason::horizon, 2.0, 2.0, {0, 0, 1.0}, {2.4, 0.1, 1.0 - 0.12});
  // Q(0.05; 0.025) + 0.01 (Q(1 - 1.2; 0.025) + Q(-0.06; 0.05)).
  CHECK(vel.finish(a, o) == Approx(0.0025 + 0.01 * (0.04 + 0.0036)));
  const w9::velocity target({.target_speed = 1.0});  // v_x -> 1.0: Q(0) = 0
  auto b = target.make_accumulator(m);
  s.view.com_velocity = {1.0, 0, 0};
  s.feed(target, b, 0);
  CHECK(target.finish(b, o) == Approx(0.0025 + 0.01 * 0.0036));
  CHECK(vel.finish(vel.make_accumulator(m), outcome(stop_reason::fell, 0.0, 1.0)) == 0.0);
  CHECK_THROWS_WITH(w9::velocity({.lambda_vel = -1}), Catch::Contains("lambda_vel"));
}

TEST_CASE("wang2009: E_land counts unplanted toe-off and stubbed swing toes (eq. 6)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const int lf = s.body("lfoot"), lt = s.body("ltoes"), rf = s.body("rfoot"), rt = s.body("rtoes");
  const w9::landing land(m);
  auto a = land.make_accumulator(m);
  int k = 0;
  auto run = [&](int phase, int n) {
    s.view.controller_phase = phase;
    for (int i = 0; i < n; ++i) s.feed(land, a, k++);
  };
  s.count[rf] = 2, s.count[rt] = 2;
  run(1, 10);  // right stance, neither body with 3 points: 10 stance steps
  s.count[rf] = 3;
  run(1, 10);  // planted: 0
  s.count[lf] = 0, s.count[lt] = 4;
  run(3, 10);  // left stance planted on its toes: 0
  s.count[rf] = 0, s.count[rt] = 0;
  run(0, 10);  // phase 0: no stance test even with the stance foot off the ground
  s.toe_top[lt] = 1;
  run(0, 5);  // left swing toe stubbed: 5
  s.toe_top[lt] = 0, s.toe_top[rt] = 1;
  run(0, 5);  // the stance toe's top does not count
  run(2, 5);  // right is the swing toe now: 5
  s.toe_top[rt] = 0;
  s.view.toe_top_contact = true;
  run(-1, 5);  // no phases: any toe top counts: 5
  REQUIRE(k == 60);
  CHECK(a.stance == 10);
  CHECK(a.stubbed == 15);
  // T = horizon = 100 steps of 0.01 s: 25 / 100, also when the rollout fell after 60 steps.
  CHECK(land.finish(a, outcome(stop_reason::horizon, 1.0, 1.0)) == Approx(0.25));
  CHECK(land.finish(a, outcome(stop_reason::fell, 0.6, 1.0)) == Approx(0.25));
  std::array<double, 1> t{};
  land.terms(a, t);  // running: T = 60 steps so far
  CHECK(t[0] == Approx(25.0 / 60.0));
  // read_phase = false: every step as phase -1.
  const w9::landing blind(m, {.read_phase = false});
  auto b = blind.make_accumulator(m);
  s.view.controller_phase = 1;
  for (int i = 0; i < 4; ++i) s.feed(blind, b, i);
  CHECK(b.stance == 0);
  CHECK(b.stubbed == 4);
  CHECK(land.finish(land.make_accumulator(m), outcome(stop_reason::fell, 0, 1)) == 0.0);
  CHECK_THROWS_WITH(w9::landing(sharon2005_human7()), Catch::Contains("no body named 'ltoes'"));
}

TEST_CASE("wang2009: E_fail counts the unsimulated tail of a fall (eq. 7)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const w9::failure fail;
  auto a = fail.make_accumulator(m);
  for (int k = 0; k < 40; ++k) {
    s.view.com = {0, 0, k < 30 ? 0.9 : 0.6};  // the last 10 steps below 0.7 m
    s.feed(fail, a, k);
  }
  CHECK(a.failed == 10);
  // Horizon 100 steps; fell after 40: (10 + 60) / 100.
  CHECK(fail.finish(a, outcome(stop_reason::fell, 0.4, 1.0)) == Approx(0.7));
  CHECK(fail.finish(a, outcome(stop_reason::objective, 0.4, 1.0)) == Approx(0.7));
  CHECK(fail.finish(a, outcome(stop_reason::horizon, 0.4, 0.4)) == Approx(0.25));
  // Fallen before the first step: everything failed; a zero horizon costs nothing.
  const auto none = fail.make_accumulator(m);
  CHECK(fail.finish(none, outcome(stop_reason::fell, 0.0, 1.0)) == 1.0);
  CHECK(fail.finish(none, outcome(stop_reason::horizon, 0.0, 0.0)) == 0.0);
  // "long arm": 0.4 m; a ground at z = 0.25 m.
  const w9::failure low({.fail_height = 0.4, .ground_height = 0.25});
  auto b = low.make_accumulator(m);
  s.view.com = {0, 0, 0.6};  // 0.35 m above the ground: failed
  s.feed(low, b, 0);
  s.view.com = {0, 0, 0.7};
  s.feed(low, b, 1);
  CHECK(low.finish(b, outcome(stop_reason::horizon, 0.02, 0.02)) == Approx(0.5));
  CHECK_THROWS_WITH(w9::failure({.fail_height = 0.0}), Catch::Contains("fail_height"));
}

TEST_CASE("wang2009: E_sym from complete phase visits (eq. 8)", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const w9::symmetry sym;
  auto a = sym.make_accumulator(m);
  int k = 0;
  auto run = [&](int phase, int n) {
    s.view.controller_phase = phase;
    for (int i = 0; i < n; ++i) s.feed(sym, a, k++);
  };
  // Phase 0 at the start is incomplete; 1: 0.10 s; 2: 0.20 s; 3: 0.12 s; 0: 0.30 s; 1: 0.14 s;
  // 2 cut off at the end.
  run(0, 5), run(1, 10), run(2, 20), run(3, 12), run(0, 30), run(1, 14), run(2, 3);
  CHECK(w9::symmetry::average_duration(a, 0) == Approx(0.30));
  CHECK(w9::symmetry::average_duration(a, 1) == Approx(0.12));
  CHECK(w9::symmetry::average_duration(a, 2) == Approx(0.20));
  CHECK(w9::symmetry::average_duration(a, 3) == Approx(0.12));
  // Q(0.30 - 0.20; 0.025) + Q(0.12 - 0.12; 0.025).
  CHECK(sym.finish(a, {}) == Approx(0.01));
  // A pair with a phase never completed contributes 0: phase 3's visit is still in progress.
  auto b = sym.make_accumulator(m);
  k = 0;
  auto run_b = [&](int phase, int n) {
    s.view.controller_phase = phase;
    for (int i = 0; i < n; ++i) s.feed(sym, b, k++);
  };
  run_b(0, 1), run_b(1, 10), run_b(2, 30), run_b(0, 5), run_b(1, 20), run_b(3, 50);
  CHECK(w9::symmetry::average_duration(b, 3) < 0.0);
  CHECK(sym.finish(b, {}) == Approx(0.0625));  // Q(0.05 - 0.30) only
  run_b(0, 10), run_b(1, 1);                   // 3 completes (0.50 s); 0 averages (0.05 + 0.10) / 2
  CHECK(w9::symmetry::average_duration(b, 0) == Approx(0.075));
  CHECK(sym.finish(b, {}) == Approx(std::pow(0.075 - 0.30, 2) + std::pow(0.15 - 0.50, 2)));
  // No phases at all: 0.
  auto c = sym.make_accumulator(m);
  s.view.controller_phase = -1;
  for (int i = 0; i < 10; ++i) s.feed(sym, c, i);
  CHECK(sym.finish(c, {}) == 0.0);
}

TEST_CASE("wang2009: E_ang from a ramp of angular momentum (eqs. 9, 10)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  const double M = m.total_mass();
  // H = 1 m, V = 2 m/s: L = c t has Ldot = c, avgL = (c / (M V H))^2.
  const w9::angular_momentum ang(m, {.speed = 2.0, .height = 1.0});
  CHECK(ang.mass() == Approx(M));
  auto a = ang.make_accumulator(m);
  synthetic s(m, 0.001);
  const double c = 0.5 * M * 2.0;  // normalized Ldot = 0.5 /s: avgL = 0.25 > 0.05
  for (int k = 0; k < 50; ++k) {
    w9::angular_momentum::add_sample(a, c * k * 0.001 + 3.0, 0.001);
    a.track.add(s.view);
  }
  CHECK(a.diffs == 49);
  const rollout_outcome o = outcome(stop_reason::horizon, 0.05, 0.05);
  CHECK(ang.average_ldot_squared(a, o) == Approx(0.25));
  CHECK(ang.finish(a, o) == Approx(0.25));  // Q(0.5; sqrt(0.05))
  // A slower ramp, under the threshold: avgL = 0.04 < 0.05.
  auto b = ang.make_accumulator(m);
  for (int k = 0; k < 50; ++k) {
    w9::angular_momentum::add_sample(b, 0.2 * M * 2.0 * k * 0.001, 0.001);
    b.track.add(s.view);
  }
  CHECK(ang.average_ldot_squared(b, o) == Approx(0.04));
  CHECK(ang.finish(b, o) == 0.0);
  // Without a speed option V is the average forward speed, at least min_speed (0.1 m/s).
  const w9::angular_momentum own(m, {.height = 1.0});
  CHECK(own.normalization_speed(outcome(stop_reason::horizon, 2.0, 2.0, vec3::Zero(), {3, 0, 0})) ==
        1.5);
  CHECK(own.normalization_speed(
            outcome(stop_reason::horizon, 2.0, 2.0, vec3::Zero(), {-3, 0, 0})) == 0.1);
  CHECK(own.normalization_speed(outcome(stop_reason::fell, 0.0, 2.0)) == 0.1);
  // The default H: the standing COM height of the 1.65 m humanoid (about 55 % of its height).
  const w9::angular_momentum standing(m);
  CHECK(standing.height() > 0.8);
  CHECK(standing.height() < 1.0);
  CHECK(ang.finish(ang.make_accumulator(m), o) == 0.0);

  // Through a view: the body spinning at a constant rate about z has constant L_z (Ldot = 0),
  // read from the workspace's centroidal momentum.
  auto ws = make_workspace(m);
  Eigen::VectorXd q = neutral_configuration(m), v = Eigen::VectorXd::Zero(m.nv());
  v[5] = 1.5;  // pelvis angular velocity about z, rad/s
  forward_kinematics(m, ws, q, v);
  s.view.workspace_ptr = &ws;
  auto d = ang.make_accumulator(m);
  for (int k = 0; k < 3; ++k) s.feed(ang, d, k);
  const double L = centroidal_momentum(m, ws).angular.z();
  CHECK(L > 0.0);
  std::array<double, 2> t{};
  ang.terms(d, t);
  CHECK(t[1] == L);
  CHECK(d.sum_ldot2 == 0.0);
  CHECK_THROWS_WITH(w9::angular_momentum(m, {.speed = 0.0}), Catch::Contains("speed"));
}

TEST_CASE("wang2009: E_head from the head's velocity and orientation (eq. 11)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const int h = s.body("head");
  const w9::head head(m);
  auto a = head.make_accumulator(m);
  // x velocity alternating 1.0 and 1.6 m/s: sigma = 0.3 m/s; tilted 0.2 rad for 25 steps.
  for (int k = 0; k < 100; ++k) {
    s.lin[h] = {k % 2 == 0 ? 1.0 : 1.6, 0.0, 0.0};
    s.rot[h] = k < 25 ? mat3(Eigen::AngleAxisd(0.2, vec3::UnitY())) : mat3::Identity();
    s.feed(head, a, k);
  }
  CHECK(w9::head::velocity_std(a) == Approx(0.3));
  CHECK(a.oriented == 25);
  // Q(sqrt(0.3); sqrt(0.1)) + 0.012 * 25 / 200 (horizon 2 s).
  CHECK(head.finish(a, outcome(stop_reason::fell, 1.0, 2.0)) == Approx(0.3 + 0.012 * 0.125));
  // A steady head (sigma 0.05 < 0.1) and 0.05 rad of tilt (< 0.1): 0.
  auto b = head.make_accumulator(m);
  for (int k = 0; k < 100; ++k) {
    s.lin[h] = {k % 2 == 0 ? 1.0 : 1.1, 0.0, 0.0};
    s.rot[h] = mat3(Eigen::AngleAxisd(0.05, vec3::UnitZ()));
    s.feed(head, b, k);
  }
  CHECK(w9::head::velocity_std(b) == Approx(0.05));
  CHECK(head.finish(b, outcome(stop_reason::horizon, 1.0, 1.0)) == 0.0);
  // The velocity is the head COM's: a spin about y adds omega_y * c_z to its x velocity.
  auto c = head.make_accumulator(m);
  const double cz = m.bodies[h].com.z();
  s.rot[h] = mat3::Identity();
  s.lin[h] = {1.0, 0.0, 0.0};
  for (int k = 0; k < 10; ++k) {
    s.ang[h] = {0.0, k % 2 == 0 ? 0.0 : 1.0, 0.0};
    s.feed(head, c, k);
  }
  CHECK(w9::head::velocity_std(c) == Approx(0.5 * std::abs(cz)));
  CHECK_THROWS_WITH(w9::head(sharon2005_human7()), Catch::Contains("head"));
}

TEST_CASE("wang2009: E_posture from the torso's tilt (ours)", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const int t = s.body("torso");
  const w9::torso_posture posture(m);
  // The tilt is the up vector's angle from the vertical, whichever way it leans.
  for (const vec3& axis : {vec3(0, 1, 0), vec3(1, 0, 0), vec3(vec3(1, -1, 0).normalized())})
    CHECK(w9::torso_posture::tilt(mat3(Eigen::AngleAxisd(0.3, axis))) == Approx(0.3));
  CHECK(w9::torso_posture::tilt(mat3(Eigen::AngleAxisd(1.0, vec3::UnitZ()))) == 0.0);
  CHECK(w9::torso_posture::tilt(mat3(Eigen::AngleAxisd(2.5, vec3::UnitY()))) == Approx(2.5));
  // 0.4 rad forward for 30 steps, 0.1 rad (within eps = 0.15) for 70: Q = 0.16 on 30 of the
  // horizon's 200 steps.
  auto a = posture.make_accumulator(m);
  for (int k = 0; k < 100; ++k) {
    s.rot[t] = mat3(Eigen::AngleAxisd(k < 30 ? 0.4 : -0.1, vec3::UnitY()));
    s.feed(posture, a, k);
  }
  CHECK(posture.finish(a, outcome(stop_reason::fell, 1.0, 2.0)) == Approx(0.16 * 30 / 200));
  CHECK(w9::torso_posture::tilt(a.up) == Approx(0.1));
  // In eq. 16 its weight is 0 unless set: the paper's objective is unchanged.
  CHECK(wang2009_objective(m).weights()[wang2009_term::posture] == 0.0);
  CHECK(wang2009_term_names[wang2009_term::posture] == "E_posture");
  CHECK_THROWS_WITH(w9::torso_posture(m, {.eps_posture = -0.1}), Catch::Contains("eps_posture"));
  CHECK_THROWS_WITH(w9::torso_posture(m, {.body = "spine"}), Catch::Contains("spine"));
  CHECK(posture.term_names() == std::array<std::string, 2>{"E_posture", "torso_tilt_rad"});
}

TEST_CASE("wang2009: E_pelvis, the same measure on the pelvis (ours)", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const int t = s.body("torso"), p = s.body("pelvis");
  const auto obj = wang2009_objective(m);
  const w9::torso_posture& pelvis = obj.part<wang2009_term::pelvis>();
  const w9::torso_posture& torso = obj.part<wang2009_term::posture>();
  CHECK(pelvis.body() == p);
  CHECK(torso.body() == t);
  CHECK(pelvis.term_names() == std::array<std::string, 2>{"E_pelvis", "pelvis_tilt_rad"});
  CHECK(wang2009_term_names[wang2009_term::pelvis] == "E_pelvis");
  CHECK(obj.weights()[wang2009_term::pelvis] == 0.0);  // eq. 16 as published unless set
  // An upright torso over a pelvis tilted back 0.35 rad (the upright walkers' posture): E_posture
  // is 0, E_pelvis Q(0.35; 0.15) = 0.35^2 on every step.
  auto ap = pelvis.make_accumulator(m);
  auto at = torso.make_accumulator(m);
  for (int k = 0; k < 100; ++k) {
    s.rot[p] = mat3(Eigen::AngleAxisd(-0.35, vec3::UnitY()));
    s.rot[t] = mat3::Identity();
    s.feed(pelvis, ap, k);
    s.feed(torso, at, k);
  }
  const auto out = outcome(stop_reason::horizon, 1.0, 1.0);
  CHECK(pelvis.finish(ap, out) == Approx(0.35 * 0.35));
  CHECK(torso.finish(at, out) == 0.0);
  wang2009_objective_options o;
  o.weights.pelvis = 50.0;
  CHECK(wang2009_objective(m, o).weights()[wang2009_term::pelvis] == 50.0);
  o.weights.pelvis = -1.0;
  CHECK_THROWS_WITH(wang2009_objective(m, o), Catch::Contains("w_pelvis"));
}

TEST_CASE("wang2009: E_power and the cost of transport (eq. 12)", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const w9::power pw;
  auto a = pw.make_accumulator(m);
  s.tau.tail(m.num_joint_dofs()).setConstant(2.0);  // 30 DOFs * 4 = 120 (N m)^2
  s.tau_passive.setConstant(1000.0);                // passive torques are not effort
  s.feed(pw, a, 0);
  s.tau.setZero();
  s.feed(pw, a, 1);
  CHECK(w9::power::mean_squared_torque(a) == Approx(60.0));
  CHECK(pw.finish(a, outcome(stop_reason::horizon, 1, 1, vec3::Zero(), {1.2, 0, 0})) ==
        Approx(60.0));
  const w9::power cot({.cost_of_transport = true});
  auto b = cot.make_accumulator(m);
  s.tau.tail(m.num_joint_dofs()).setConstant(2.0);
  s.feed(cot, b, 0);
  s.tau.setZero();
  s.feed(cot, b, 1);
  CHECK(cot.finish(b, outcome(stop_reason::horizon, 1, 1, vec3::Zero(), {1.2, 0, 0})) ==
        Approx(50.0));
  // Below 0.1 m/s, the tangent of E/v at 0.1: 600 (2 - v / 0.1). Finite for any speed.
  CHECK(cot.finish(b, outcome(stop_reason::horizon, 1, 1, vec3::Zero(), {0.1, 0, 0})) ==
        Approx(600.0));
  CHECK(cot.finish(b, outcome(stop_reason::horizon, 1, 1, vec3::Zero(), {0.05, 0, 0})) ==
        Approx(900.0));
  CHECK(cot.finish(b, outcome(stop_reason::horizon, 1, 1)) == Approx(1200.0));
  CHECK(cot.finish(b, outcome(stop_reason::fell, 0, 1)) == Approx(1200.0));  // zero time
  CHECK(cot.finish(b, outcome(stop_reason::horizon, 1, 1, vec3::Zero(), {-1, 0, 0})) ==
        Approx(7200.0));
  CHECK(cot.finish(cot.make_accumulator(m), outcome(stop_reason::fell, 0, 1)) == 0.0);
  CHECK_THROWS_WITH(w9::power({.min_speed = -1}), Catch::Contains("min_speed"));
}

TEST_CASE("wang2009: E_ratio of hip, knee and ankle power (eqs. 13-15)", "[objectives][wang2009]") {
  const auto& m = humanoid();
  synthetic s(m);
  const w9::power_ratio ratio(m);
  auto j = [&](const char* name) { return 6 + m.dof_index(name); };
  // tau^2: hips 25 + 9 + 9 = 43, knee 4, ankles 49 + 4 = 53; toe, back and arms excluded.
  s.tau[j("lhip_y")] = 5, s.tau[j("rhip_y")] = -3, s.tau[j("lhip_x")] = 3;
  s.tau[j("lknee")] = 2;
  s.tau[j("lankle_y")] = 7, s.tau[j("rankle_y")] = -2;
  s.tau[j("ltoe")] = 100, s.tau[j("back_x")] = 50, s.tau[j("relbow_y")] = 30;
  auto a = ratio.make_accumulator(m);
  for (int k = 0; k < 3; ++k) s.feed(ratio, a, k);
  const auto r = w9::power_ratio::ratio(a);
  CHECK(r[0] == Approx(0.43));
  CHECK(r[1] == Approx(0.04));
  CHECK(r[2] == Approx(0.53));
  CHECK(w9::power_ratio::powers(a)[0] == Approx(43.0));
  CHECK(ratio.finish(a, {}) == Approx(0.0).margin(1e-15));
  // Knees only: r = [0, 1, 0].
  s.tau.setZero();
  s.tau[j("rknee")] = 1;
  auto b = ratio.make_accumulator(m);
  s.feed(ratio, b, 0);
  CHECK(ratio.finish(b, {}) == Approx(std::sqrt(0.43 * 0.43 + 0.96 * 0.96 + 0.53 * 0.53)));
  // No torque: r = 0, E = |r_walk|.
  auto c = ratio.make_accumulator(m);
  s.tau.setZero();
  s.feed(ratio, c, 0);
  CHECK(ratio.finish(c, {}) == Approx(std::sqrt(0.43 * 0.43 + 0.04 * 0.04 + 0.53 * 0.53)));
  std::array<double, 4> t{};
  ratio.terms(a, t);
  CHECK(t[3] == Approx(0.53));
  // The ratio as a constraint (ours): the largest excess over the tolerance, 0 inside. On the
  // target: 0 for any tolerance; knees only: the knee's |1 - 0.04| - 0.05.
  CHECK(ratio.violation(a, 0.05) == 0.0);
  CHECK(ratio.violation(a, 0.0) == Approx(0.0).margin(1e-15));
  CHECK(ratio.violation(b, 0.05) == Approx(0.96 - 0.05));
  CHECK(ratio.violation(b, 2.0) == 0.0);
  // r = [43 + 9, 4, 53] / 109 = [0.4771, 0.0367, 0.4862]: the hip is 0.0471 off, the ankle 0.0438.
  s.tau.setZero();
  s.tau[j("lhip_y")] = 5, s.tau[j("rhip_y")] = -3, s.tau[j("lhip_x")] = 3, s.tau[j("rhip_x")] = 3;
  s.tau[j("lknee")] = 2;
  s.tau[j("lankle_y")] = 7, s.tau[j("rankle_y")] = -2;
  auto d = ratio.make_accumulator(m);
  s.feed(ratio, d, 0);
  CHECK(ratio.violation(d, 0.05) == 0.0);
  CHECK(ratio.violation(d, 0.04) == Approx(52.0 / 109.0 - 0.43 - 0.04));
  CHECK_THROWS_WITH(ratio.violation(d, -0.01), Catch::Contains("-0.01"));
  CHECK_THROWS_WITH(ratio.violation(d, std::nan("")), Catch::Contains("tolerance"));
  CHECK_THROWS_WITH(w9::power_ratio(sharon2005_human7()), Catch::Contains("lhip_x"));
}

TEST_CASE("wang2009: the complete objective's weights and options (eq. 16)",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  const auto obj = wang2009_objective(m);
  const auto& w = obj.weights();
  CHECK(w[wang2009_term::user] == 100.0);
  CHECK(w[wang2009_term::fail] == 120000.0);
  CHECK(w[wang2009_term::land] == 1.2);
  CHECK(w[wang2009_term::power] == Approx(1e-5 * 70.0 / m.total_mass()));
  CHECK(obj.part<wang2009_term::power>().opts().cost_of_transport);  // no target speed
  const auto target = wang2009_objective(m, {.target_speed = 1.0, .target_step_length = 0.7});
  CHECK_FALSE(target.part<wang2009_term::power>().opts().cost_of_transport);
  CHECK(target.part<wang2009_term::vel>().opts().target_speed == 1.0);
  CHECK(target.part<wang2009_term::ang>().opts().speed == 1.0);
  // Fig. 3 without E_ratio: weight 0.
  wang2009_objective_options o;
  o.weights.ratio = 0.0;
  CHECK(wang2009_objective(m, o).weights()[wang2009_term::ratio] == 0.0);
  o.weights.ratio = -1.0;
  CHECK_THROWS_WITH(wang2009_objective(m, o), Catch::Contains("w_ratio"));
  CHECK_THROWS_WITH(wang2009_objective(m, {.fail_height = NAN}), Catch::Contains("fail_height"));
}

TEST_CASE("wang2009: a standing rollout of the humanoid under the complete objective",
          "[objectives][wang2009]") {
  const auto& m = humanoid();
  const auto obj = wang2009_objective(m);
  rollout_options opt;
  opt.duration = 0.2;
  trajectory tr;
  opt.record = &tr;
  opt.record_every = 48;
  const pd_actuator act = standing_pd(m, opt.dt);
  pose_hold ctrl(m);
  semi_implicit_euler integ;
  auto scratch = make_rollout_scratch(m);
  rollout_policy_states<pd_actuator, pose_hold, wang2009_objective_type> states;
  const Eigen::VectorXd params = Eigen::VectorXd::Zero(m.num_joint_dofs());
  const rollout_result r =
      rollout(m, act, ctrl, obj, flat_terrain{}, integ,
              std::span<const double>(params.data(), params.size()), opt, scratch, states);
  REQUIRE(r.reason == stop_reason::horizon);
  CHECK(std::isfinite(r.cost));
  CHECK(r.cost >= 0.0);
  // Recorded terms: every term's running values, one column each.
  REQUIRE(tr.objective_term_names == obj.term_names());
  const std::vector<std::string> names = {"E_user",         "speed_m_s",       "step_length_m",
                                          "E_vel",          "E_land",          "E_fail",
                                          "E_sym",          "E_ang",           "L_z",
                                          "E_head",         "head_vx_std_m_s", "E_power",
                                          "tau_squared",    "E_ratio",         "r_hip",
                                          "r_knee",         "r_ankle",         "E_posture",
                                          "torso_tilt_rad", "E_pelvis",        "pelvis_tilt_rad"};
  CHECK(tr.objective_term_names == names);
  REQUIRE(tr.frames.size() >= 2);
  for (const auto& f : tr.frames)
    for (double x : f.objective_terms) CHECK(std::isfinite(x));
  // Report: the rows add up to the cost; standing still: no fall, v_x ~ 0, no step.
  const wang2009_breakdown b = wang2009_report(obj, *states.objective, r, opt);
  double sum = 0.0;
  for (const auto& row : b.terms) sum += row.weighted;
  CHECK(b.total == Approx(r.cost));
  CHECK(sum == Approx(r.cost));
  CHECK(b.terms[wang2009_term::fail].raw == 0.0);
  CHECK(b.steps == 0);
  CHECK(std::abs(b.average_speed) < 0.05);
  CHECK(b.e_power > 0.0);
  CHECK(b.power_ratio[0] + b.power_ratio[1] + b.power_ratio[2] == Approx(1.0));
  std::ostringstream os;
  print_wang2009_report(os, b);
  CHECK(os.str().find("E_ratio") != std::string::npos);
  CHECK(os.str().find("E_pow/v_x") != std::string::npos);
  CHECK(os.str().find("power ratio") != std::string::npos);
}
