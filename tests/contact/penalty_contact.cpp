// Penalty contact: resting height against the spring's prediction, sticking and sliding on slopes
// near atan(mu) against Coulomb's law, the friction cone, forces from hand-computed formulas,
// contact counts and toe-top flags, vertical faces of steps, and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "support/contact_e1.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_e1;
using Catch::Matchers::Contains;

namespace {
constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 2400.0;          // the papers' simulation rate
const Eigen::Vector3d kHalf(0.2, 0.2, 0.05);  // a flat block: does not tip below 76 degrees
constexpr double kMass = 10.0;

/// A foot (root) with a toe on a hinge at its front bottom edge; 4 sole corners on the foot, 4
/// bottom corners and 2 top points on the toe (a light body, like the humanoids' toes).
model<floating_root> foot_with_toe(double toe_mass = 0.15) {
  model_builder<floating_root> b("foot");
  const Eigen::Vector3d fh(0.1, 0.05, 0.03), th(0.03, 0.05, 0.015);
  b.add_body({.name = "foot", .mass = 1.0, .inertia = box_inertia(1.0, fh)});
  b.add_body({.name = "toe",
              .parent = "foot",
              .joint_offset = {fh.x(), 0.0, -fh.z()},
              .mass = toe_mass,
              .com = {th.x(), 0.0, th.z()},
              .inertia = box_inertia(toe_mass, th),
              .dofs = {{.name = "toe_y", .axis = {0, 1, 0}}}});
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      b.add_contact_point({.name = indexed_name("foot", 3 * sx + sy),
                           .body = "foot",
                           .position = {sx * fh.x(), sy * fh.y(), -fh.z()}});
      b.add_contact_point({.name = indexed_name("toe", 3 * sx + sy),
                           .body = "toe",
                           .position = {th.x() + sx * th.x(), sy * th.y(), 0.0},
                           .role = contact_point::kind::toe});
    }
  for (int sy : {-1, 1})
    b.add_contact_point({.name = indexed_name("toetop", sy),
                         .body = "toe",
                         .position = {2 * th.x(), sy * th.y(), 2 * th.z()},
                         .role = contact_point::kind::toe_top});
  return b.build();
}
}  // namespace

TEST_CASE("a box dropped on a plane rests at the depth the springs predict", "[contact][penalty]") {
  const auto m = box_model<floating_root>(kMass, kHalf);
  contact_parameters p;
  const bool implicit = GENERATE(true, false);
  const double kp = GENERATE(75000.0, 20000.0);
  p.implicit_damping = implicit;
  p.kp = kp;
  const double h0 = 0.3;
  const flat_terrain ground(h0);
  sim_state s{floating_q({0.1, -0.2, h0 + kHalf.z() + 0.05}, mat3::Identity()),
              Eigen::VectorXd::Zero(6), 0.0};
  simulate(m, ground, p, s, kDt, 2 * 2400);  // 2 s: drop, bounce, settle
  // Four bottom corners share the weight: m g = 4 kp d.
  const double d = kMass * kG / (4.0 * kp);
  INFO("implicit damping " << implicit << ", kp " << kp);
  CHECK(s.q[2] == Approx(h0 + kHalf.z() - d).margin(1e-7));  // 1e-7 m: <0.1% of d
  CHECK(s.v.norm() < 1e-5);
  CHECK(std::abs(s.q[3]) == Approx(1.0).margin(1e-9));  // still level
  CHECK(s.q[0] == Approx(0.1).margin(1e-6));            // no lateral drift
  CHECK(s.q[1] == Approx(-0.2).margin(1e-6));
}

TEST_CASE("a planar box rests at the predicted depth on a step's tread", "[contact][penalty]") {
  const auto m = box_model<planar_root>(kMass, kHalf);
  const steps_terrain stairs({{-1.0, 0.1}, {1.0, 0.25}});
  sim_state s{Eigen::Vector3d(0.0, 0.1 + kHalf.z() + 0.01, 0.0), Eigen::VectorXd::Zero(3), 0.0};
  simulate(m, stairs, contact_parameters{}, s, kDt, 2400);
  CHECK(s.q[1] == Approx(0.1 + kHalf.z() - kMass * kG / (4 * 75000.0)).margin(1e-7));
  CHECK(s.q[0] == Approx(0.0).margin(1e-9));
}

TEST_CASE("a block on a slope sticks below atan(mu) and slides above it", "[contact][penalty]") {
  const auto m = box_model<floating_root>(kMass, kHalf);
  const double mu = GENERATE(1.0, 0.5);
  const double sign = GENERATE(-1.0, 1.0);  // 5 degrees below / above the friction angle
  const double angle = std::atan(mu) + sign * 5.0 * std::numbers::pi / 180.0;
  contact_parameters p;
  p.mu = mu;
  const slope_terrain slope(angle);
  const vec3 n = slope.normal(0, 0), up = slope.uphill();
  // Block aligned with the slope, resting at the spring's static normal penetration.
  const mat3 R = Eigen::AngleAxisd(-angle, vec3::UnitY()).toRotationMatrix();
  REQUIRE((R * vec3::UnitZ() - n).norm() < 1e-14);
  const double d0 = kMass * kG * std::cos(angle) / (4.0 * p.kp);
  const vec3 x0 = n * (kHalf.z() - d0);  // the slope passes through the origin
  sim_state s{floating_q(x0, R), Eigen::VectorXd::Zero(6), 0.0};

  const double T = 1.5, T1 = 0.5 * T;
  double worst_cone = 0.0;  // max over steps and points of |f_t| - mu f_n
  double min_fn = 0.0;
  double along1 = 0.0, speed1 = 0.0;  // at T1
  int sliding_at_end = 0;
  simulate(m, slope, p, s, kDt, static_cast<int>(T * 2400), {},
           [&](const sim_state& st, const contact_state& cs) {
             for (int k = 0; k < cs.num_points(); ++k) {
               const double fn = cs.force[k].dot(cs.normal[k]);
               const vec3 ft = cs.force[k] - fn * cs.normal[k];
               worst_cone = std::max(worst_cone, ft.norm() - mu * fn);
               min_fn = std::min(min_fn, fn);
               CHECK(fn == Approx(cs.normal_force[k]).margin(1e-9));
             }
             if (std::abs(st.t - T1) < 0.5 * kDt) {
               along1 = (st.q.head<3>() - x0).dot(up);
               speed1 = st.v.head<3>().dot(up);
             }
             sliding_at_end = cs.sliding[0] + cs.sliding[2] + cs.sliding[4] + cs.sliding[6];
           });
  const double along = (s.q.head<3>() - x0).dot(up);  // displacement up the slope
  const double speed = s.v.head<3>().dot(up);
  INFO("mu " << mu << ", angle " << angle * 180 / std::numbers::pi << " deg, moved " << along);
  CHECK(worst_cone <= 1e-9);
  CHECK(min_fn >= 0.0);
  if (sign < 0) {
    // Sticks: the anchor springs deflect by about m g sin(a) / (4 kt) ~ 0.2 mm (the loading
    // transient may briefly reach the cone), then nothing moves.
    const double deflection = kMass * kG * std::sin(angle) / (4.0 * p.kt);
    CHECK(std::abs(along) < 3.0 * deflection);
    CHECK(std::abs(along - along1) < 1e-7);  // no creep over the second half
    CHECK(s.v.norm() < 1e-6);
    CHECK(sliding_at_end == 0);
  } else {
    // Slides with Coulomb's acceleration g (sin a - mu cos a). Measured over [T1, T] to leave out
    // the loading of the anchor springs at the start (a few mm/s of extra speed).
    const double acc = kG * (std::sin(angle) - mu * std::cos(angle));
    const double dt1 = T - T1;
    CHECK(-(speed - speed1) == Approx(acc * dt1).epsilon(2e-3));
    CHECK(-(along - along1) == Approx(-speed1 * dt1 + 0.5 * acc * dt1 * dt1).epsilon(2e-3));
    // and over the whole time, from rest, within the start-up slip
    CHECK(-along == Approx(0.5 * acc * T * T).epsilon(0.02));
    CHECK(sliding_at_end == 4);
    // Moving along the surface, not into it or off it.
    CHECK(std::abs((s.q.head<3>() - x0).dot(n)) < 1e-4);
  }
}

TEST_CASE("contact forces follow the documented formulas", "[contact][penalty]") {
  // One body with one contact point at its COM (so the free-body effective mass is the mass).
  model_builder<floating_root> b("ball");
  b.add_body({.name = "ball",
              .mass = 2.0,
              .com = {0.0, 0.0, -0.1},
              .inertia = Eigen::Matrix3d::Identity() * 0.01});
  b.add_contact_point({.name = "p", .body = "ball", .position = {0.0, 0.0, -0.1}});
  const auto m = b.build();
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  contact_parameters p;
  p.mu = 0.8;
  const flat_terrain ground(0.0);
  const double d = 0.002;
  Eigen::VectorXd q = floating_q({0.3, 0.4, 0.1 - d}, mat3::Identity());
  Eigen::VectorXd v = Eigen::VectorXd::Zero(6);
  v.head<3>() << 0.01, -0.02, -0.05;  // moving into the ground and sideways

  const auto step = [&](bool implicit) {
    p.implicit_damping = implicit;
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, ground, p, cs, kDt);
  };
  SECTION("explicit damping") {
    step(false);
    const double fn = p.kp * d - p.kd * v[2];
    CHECK(cs.normal_force[0] == Approx(fn));
    REQUIRE(cs.active[0] == 1);
    CHECK(cs.anchor[0].isApprox(vec3(0.3, 0.4, -d)));  // anchor set at first touch
    // First touch: no anchor displacement, tangential force is the damper, inside the cone.
    const vec3 ft(-p.bt * v[0], -p.bt * v[1], 0.0);
    CHECK(cs.force[0].isApprox(vec3(ft.x(), ft.y(), fn)));
    CHECK(cs.sliding[0] == 0);
    // The wrench about the body origin: force at the point (0.3, 0.4, -d).
    const vec3 r(0.0, 0.0, -0.1);
    CHECK(ws.f_ext[0].tail<3>().isApprox(cs.force[0]));
    CHECK(ws.f_ext[0].head<3>().isApprox(r.cross(cs.force[0])));

    // Move 1 mm along x with no velocity: the anchor spring pulls back with kt * 1 mm.
    q[0] += 0.001;
    v.setZero();
    step(false);
    CHECK(cs.force[0].x() == Approx(-p.kt * 0.001));
    CHECK(cs.force[0].y() == Approx(0.0).margin(1e-9));
    CHECK(cs.sliding[0] == 0);
    CHECK(cs.anchor[0].isApprox(vec3(0.3, 0.4, -d)));

    // Move 5 mm more: kt * 6 mm = 450 N > mu f_n = 120 N: slides, force on the cone, anchor moves
    // so that kt * (p - anchor) = mu f_n.
    q[0] += 0.005;
    step(false);
    const double limit = p.mu * p.kp * d;
    CHECK(cs.sliding[0] == 1);
    CHECK(cs.force[0].x() == Approx(-limit));
    CHECK(cs.force[0].z() == Approx(p.kp * d));
    CHECK(cs.anchor[0].x() == Approx(0.306 - limit / p.kt));
    // Back to rest at that position: the spring force is exactly at the cone and sticks.
    step(false);
    CHECK(cs.sliding[0] == 0);
    CHECK(cs.force[0].x() == Approx(-limit));

    // Leaving the ground forgets the anchor and the force.
    q[2] = 0.2;
    step(false);
    CHECK(cs.active[0] == 0);
    CHECK(cs.force[0].isZero());
    CHECK(ws.f_ext[0].isZero());
    // Separating fast while still penetrating: the damper does not pull (f_n = 0).
    q[2] = 0.1 - d;
    v[2] = 1.0;
    step(false);
    CHECK(cs.active[0] == 1);
    CHECK(cs.normal_force[0] == 0.0);
    CHECK(cs.force[0].isZero());
  }
  SECTION("implicit damping: kd / (1 + n kd dt / m_eff)") {
    step(true);
    const double kd = p.kd / (1.0 + p.kd * kDt / 2.0);  // one point at the COM: m_eff = m
    const double bt = p.bt / (1.0 + p.bt * kDt / 2.0);
    CHECK(cs.normal_force[0] == Approx(p.kp * d - kd * v[2]));
    CHECK(cs.force[0].x() == Approx(-bt * v[0]));
    CHECK(cs.force[0].y() == Approx(-bt * v[1]));
  }
}

TEST_CASE("no contact force above the ground", "[contact][penalty]") {
  const auto m = box_model<floating_root>(kMass, kHalf);
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  Eigen::VectorXd v(6);
  v << 0.5, -0.3, -2.0, 1.0, 2.0, -1.0;
  const mat3 R = Eigen::AngleAxisd(0.7, vec3(1, 2, 3).normalized()).toRotationMatrix();
  const auto field = random_height_field({}, 5);
  forward_kinematics(m, ws, floating_q({0.2, 0.1, 0.2 + 0.3 + 1e-3}, R), v);
  clear_external_wrenches(ws);
  apply_contact_forces(m, ws, field, contact_parameters{}, cs, kDt);  // heights <= 0.2, corners
  for (const auto& f : ws.f_ext) CHECK(f.isZero());                   // at most 0.3 from centre
  CHECK(cs.total_points_touching == 0);
  CHECK(cs.points_touching[0] == 0);
  for (int k = 0; k < 8; ++k) {
    CHECK(cs.active[k] == 0);
    CHECK(cs.force[k].isZero());
    CHECK(cs.depth[k] < 0.0);
  }
}

TEST_CASE("contact counts per body and toe-top flags", "[contact][penalty]") {
  const auto m = foot_with_toe();
  const Eigen::Vector3d fh(0.1, 0.05, 0.03);
  const int foot = m.body_index("foot"), toe = m.body_index("toe");
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(m.nv());
  const auto eval = [&](double ground, double root_z, double toe_angle) {
    Eigen::VectorXd q = floating_q({0, 0, root_z}, mat3::Identity(), 1);
    q[7] = toe_angle;
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, flat_terrain(ground), contact_parameters{}, cs, kDt);
  };
  // Flat foot 1 mm into the ground: 4 + 4 points, no toe top.
  eval(0.0, fh.z() - 0.001, 0.0);
  CHECK(cs.points_touching[foot] == 4);
  CHECK(cs.points_touching[toe] == 4);
  CHECK(cs.total_points_touching == 8);
  CHECK_FALSE(cs.toe_top_touching[toe]);
  CHECK_FALSE(cs.any_toe_top_touching);
  // Foot lifted 1 cm, toe bent down 0.5 rad (positive about +y turns +x down): only the toe's
  // front corners touch.
  eval(0.0, fh.z() + 0.01, 0.5);
  CHECK(cs.points_touching[foot] == 0);
  CHECK(cs.points_touching[toe] == 2);
  // Toe curled under (rotated by ~pi about the hinge): its top touches the ground first: stubbed.
  eval(0.0, fh.z() + 0.005, 3.0);
  CHECK(cs.points_touching[foot] == 0);
  CHECK(cs.toe_top_touching[toe]);
  CHECK(cs.any_toe_top_touching);
  CHECK_FALSE(cs.toe_top_touching[foot]);
  for (int k = 0; k < cs.num_points(); ++k)
    if (m.contact_points[k].role == contact_point::kind::toe_top) CHECK(cs.active[k] == 1);
}

TEST_CASE("implicit damping keeps light bodies stable at 2400 Hz", "[contact][penalty]") {
  // A 1 kg foot with a free 0.15 kg toe dropped flat from 1 cm. With the plain explicit damper
  // (kd = 2000 N s/m per point) kd dt / m_eff >> 2 at the toe corners and the simulation diverges
  // within a few milliseconds; the implicit-Euler damping settles to the static penetration.
  const auto m = foot_with_toe();
  const double h = 0.03 + 0.01;
  contact_parameters p;
  const auto run = [&](bool implicit, double& max_speed) {
    p.implicit_damping = implicit;
    sim_state s{floating_q({0, 0, h}, mat3::Identity(), 1), Eigen::VectorXd::Zero(7), 0.0};
    max_speed = 0.0;
    simulate(
        m, flat_terrain(), p, s, kDt, 2400, {}, [&](const sim_state& st, const contact_state&) {
          max_speed = std::max(max_speed, st.v.allFinite() ? st.v.cwiseAbs().maxCoeff() : INFINITY);
        });
    return s;
  };
  double max_explicit = 0.0, max_implicit = 0.0;
  run(false, max_explicit);
  const sim_state s = run(true, max_implicit);
  CHECK(max_explicit > 100.0);  // diverged (or NaN)
  CHECK(max_implicit < 20.0);   // falling 1 cm: 0.44 m/s; the free toe flaps on impact
  CHECK(s.v.norm() < 1e-4);
  // Resting: 8 points carry 1.15 kg (the toe props up the foot's front through the hinge).
  CHECK(s.q[2] < 0.03 - 1.15 * kG / (8 * p.kp) + 1e-9);
  CHECK(s.q[2] > 0.03 - 1.15 * kG / (4 * p.kp) - 1e-9);
  CHECK(std::abs(s.q[7]) < 0.01);
}

TEST_CASE("a block pushed into a riser is stopped, not lifted", "[contact][penalty][steps]") {
  // Planar block sliding at 1 m/s on the ground toward a 0.2 m step: it must bounce off the riser
  // (x velocity reversed or zero) and stay on the lower level.
  const auto m = box_model<planar_root>(kMass, kHalf, {0, 0, -kG});
  const steps_terrain step({{1.0, 0.2}});
  contact_parameters p;
  p.mu = 0.0;  // frictionless: only the riser can stop it
  const double z0 = kHalf.z() - kMass * kG / (4 * p.kp);
  sim_state s{Eigen::Vector3d(0.5, z0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0), 0.0};
  double max_z = 0.0, max_x = 0.0;
  simulate(m, step, p, s, kDt, 2400, {}, [&](const sim_state& st, const contact_state&) {
    max_z = std::max(max_z, st.q[1]);
    max_x = std::max(max_x, st.q[0]);
  });
  CHECK(max_z < kHalf.z() + 0.01);        // never climbed the 0.2 m step
  CHECK(max_x + kHalf.x() < 1.0 + 0.01);  // front corners went at most ~1 cm into the riser
  CHECK(s.v[0] < 0.0);                    // bounced back
}

TEST_CASE("penalty contact: bad input throws, naming the value", "[contact][penalty]") {
  contact_parameters p;
  p.kp = 0.0;
  CHECK_THROWS_WITH(validate(p), Contains("kp") && Contains("0"));
  p = {};
  p.kd = -1.0;
  CHECK_THROWS_WITH(validate(p), Contains("kd") && Contains("-1"));
  p = {};
  p.mu = std::nan("");
  CHECK_THROWS_WITH(validate(p), Contains("mu") && Contains("nan"));
  p = {};
  p.kt = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(validate(p), Contains("kt"));
  p = {};
  p.bt = -2.0;
  CHECK_THROWS_WITH(validate(p), Contains("bt"));
  CHECK_NOTHROW(validate(contact_parameters{}));

  const auto m = box_model<floating_root>(kMass, kHalf);
  const auto other = box_model<planar_root>(kMass, kHalf);
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, floating_q({0, 0, 1}, mat3::Identity()), Eigen::VectorXd::Zero(6));
  auto cs = make_contact_state(m);
  contact_state empty;
  CHECK_THROWS_WITH(apply_contact_forces(m, ws, flat_terrain(), contact_parameters{}, empty, kDt),
                    Contains("make_contact_state") && Contains("0 points"));
  CHECK_THROWS_WITH(apply_contact_forces(m, ws, flat_terrain(), contact_parameters{}, cs, 0.0),
                    Contains("dt") && Contains("0"));
  CHECK_THROWS_WITH(apply_contact_forces(m, ws, flat_terrain(), contact_parameters{}, cs, -1e-3),
                    Contains("dt"));
  (void)other;
}
