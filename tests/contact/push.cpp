// External pushes: active only inside [start, start + duration), applied at the body's COM, and
// the impulse they deliver equals F * duration (momentum balance in free flight, no gravity).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/push.hpp"
#include "support/contact_e1.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_e1;
using Catch::Matchers::Contains;

namespace {
/// A two-body chain (floating root + hinged arm) with COMs away from the body origins, no gravity.
model<floating_root> chain() {
  model_builder<floating_root> b("chain");
  b.add_body({.name = "torso",
              .mass = 30.0,
              .com = {0.05, -0.02, 0.2},
              .inertia = box_inertia(30.0, {0.15, 0.1, 0.3})});
  b.add_body({.name = "arm",
              .parent = "torso",
              .joint_offset = {0.0, 0.2, 0.4},
              .mass = 3.0,
              .com = {0.0, 0.0, -0.25},
              .inertia = box_inertia(3.0, {0.04, 0.04, 0.25}),
              .dofs = {{.name = "shoulder_x", .axis = {1, 0, 0}}, {.name = "shoulder_y"}}});
  b.set_gravity(vec3::Zero());
  return b.build();
}

/// Total linear momentum sum m_b v_com_b (from the workspace after forward_kinematics with v).
template <root_joint Root>
vec3 linear_momentum(const model<Root>& m, const workspace<Root>& ws) {
  vec3 p = vec3::Zero();
  for (int b = 0; b < m.num_bodies(); ++b) {
    const vec3 r = ws.body_rotation[b] * m.bodies[b].com;
    p += m.bodies[b].mass * (ws.body_linear_velocity[b] + ws.body_angular_velocity[b].cross(r));
  }
  return p;
}
}  // namespace

TEST_CASE("a push acts only inside its window", "[contact][push]") {
  const push p{.body = 1, .force = {10, -20, 5}, .start = 0.5, .duration = 0.25};
  CHECK_FALSE(p.active(0.4999));
  CHECK(p.active(0.5));
  CHECK(p.active(0.7499));
  CHECK_FALSE(p.active(0.75));
  CHECK_FALSE(push{.duration = 0.0}.active(0.0));

  const auto m = chain();
  auto ws = make_workspace(m);
  Eigen::VectorXd q = floating_q(
      {1, 2, 3}, Eigen::AngleAxisd(0.4, vec3(1, 1, 0).normalized()).toRotationMatrix(), 2);
  q[7] = 0.3;
  q[8] = -0.6;
  forward_kinematics(m, ws, q);
  const std::vector<push> pushes{p};
  for (double t : {0.0, 0.4999, 0.75, 2.0}) {
    clear_external_wrenches(ws);
    apply_pushes(m, ws, pushes, t);
    for (const auto& f : ws.f_ext) CHECK(f.isZero());
  }
  clear_external_wrenches(ws);
  apply_pushes(m, ws, pushes, 0.6);
  CHECK(ws.f_ext[0].isZero());
  CHECK(ws.f_ext[1].tail<3>() == p.force);
  // Applied at the arm's COM: the moment about the body origin is r_com x F.
  const vec3 r = ws.body_rotation[1] * m.bodies[1].com;
  CHECK(ws.f_ext[1].head<3>().isApprox(r.cross(p.force)));
}

TEST_CASE("a push delivers the impulse F * duration in free flight", "[contact][push]") {
  // dt and the window are binary fractions, so the window holds exactly duration / dt steps.
  const double start = 0.25, duration = 0.125;
  const vec3 force(40.0, -25.0, 60.0);
  SECTION("tumbling rigid body, COM at its origin: exact") {
    model_builder<floating_root> b("brick");
    b.add_body({.name = "brick", .mass = 7.0, .inertia = box_inertia(7.0, {0.3, 0.1, 0.05})});
    b.set_gravity(vec3::Zero());
    const auto m = b.build();
    const double dt = 1.0 / 1024.0;
    const std::vector<push> pushes{
        {.body = 0, .force = force, .start = start, .duration = duration}};
    sim_state s = make_state(m);
    s.v << 0.1, 0.2, -0.3, 2.0, -1.0, 3.0;
    vec3 v_start = vec3::Zero();
    simulate(m, flat_terrain(-100.0), contact_parameters{}, s, dt, 512, pushes,
             [&](const sim_state& st, const contact_state&) {
               if (st.t == start) v_start = st.v.head<3>();
             });
    CHECK(s.t == 0.5);
    CHECK((v_start - vec3(0.1, 0.2, -0.3)).norm() < 1e-14);  // nothing before the window
    CHECK((m.bodies[0].mass * (s.v.head<3>() - v_start) - force * duration).norm() < 1e-12);
  }
  SECTION("articulated chain pushed on either body: first order in dt") {
    // Semi-implicit Euler conserves the momentum of a changing configuration only to O(dt), so
    // use a small step; the impulse is 9.5 N s.
    const auto m = chain();
    const int body = GENERATE(0, 1);
    const double dt = 1.0 / 16384.0;
    const std::vector<push> pushes{
        {.body = body, .force = force, .start = start, .duration = duration}};
    sim_state s = make_state(m);
    s.v << 0.1, 0.2, -0.3, 0.5, -0.2, 0.1, 1.0, -0.5;  // tumbling
    auto ws = make_workspace(m);
    forward_kinematics(m, ws, s.q, s.v);
    const vec3 p0 = linear_momentum(m, ws);
    vec3 p_before = vec3::Zero();
    simulate(m, flat_terrain(-100.0), contact_parameters{}, s, dt, 8192, pushes,
             [&](const sim_state& st, const contact_state&) {
               if (st.t == start) {
                 forward_kinematics(m, ws, st.q, st.v);
                 p_before = linear_momentum(m, ws);
               }
             });
    CHECK(s.t == 0.5);
    forward_kinematics(m, ws, s.q, s.v);
    const vec3 p1 = linear_momentum(m, ws);
    INFO("body " << body);
    CHECK((p_before - p0).norm() < 1e-4);
    CHECK((p1 - p0 - force * duration).norm() < 2e-3 * (force * duration).norm());
  }
}

TEST_CASE("periodic pushes and bad pushes", "[contact][push]") {
  const auto ps = periodic_pushes(0, {0, 150, 0}, 2.0, 4.0, 0.4, 10);  // Wang et al. 2009
  REQUIRE(ps.size() == 10);
  CHECK(ps[3].start == 14.0);
  CHECK(ps[3].duration == 0.4);
  CHECK_THROWS_WITH(periodic_pushes(0, vec3::Zero(), 0.0, 0.0, 0.1, 2), Contains("period"));
  CHECK_THROWS_WITH(periodic_pushes(0, vec3::Zero(), 0.0, 1.0, 0.1, -1), Contains("count"));

  const auto m = chain();
  auto ws = make_workspace(m);
  forward_kinematics(m, ws, make_state(m).q);
  const auto bad = [&](auto change) {
    std::vector<push> v(2);
    change(v[1]);
    apply_pushes(m, ws, v, 0.0);
  };
  CHECK_THROWS_WITH(bad([](push& p) { p.body = 2; }), Contains("push 1") && Contains("body 2"));
  CHECK_THROWS_WITH(bad([](push& p) { p.body = -1; }), Contains("body -1"));
  CHECK_THROWS_WITH(bad([](push& p) { p.force.y() = std::nan(""); }), Contains("force"));
  CHECK_THROWS_WITH(bad([](push& p) { p.start = INFINITY; }), Contains("start"));
  CHECK_THROWS_WITH(bad([](push& p) { p.duration = -0.1; }),
                    Contains("duration") && Contains("-0.1"));
  CHECK_NOTHROW(validate_pushes(m, ps));
}
