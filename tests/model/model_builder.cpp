// Validation of model_builder: every invalid model named in the foundation issue throws
// std::invalid_argument whose message names the problem, and the mirror map pairs l/r DOFs with
// the sign a reflection across the sagittal plane gives.
#include <catch2/catch.hpp>

#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/model/state.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;

namespace {
Eigen::Matrix3d diag(double a, double b, double c) { return Eigen::Vector3d(a, b, c).asDiagonal(); }

model_builder<floating_root> two_legs() {
  model_builder<floating_root> b("two_legs");
  b.add_body({.name = "pelvis", .mass = 10, .inertia = diag(0.1, 0.1, 0.1)});
  for (const char* side : {"l", "r"}) {
    const double y = side[0] == 'l' ? 0.1 : -0.1;
    b.add_body({.name = std::string(side) + "thigh",
                .parent = "pelvis",
                .joint_offset = {0, y, -0.1},
                .mass = 7,
                .com = {0, 0, -0.2},
                .inertia = diag(0.1, 0.1, 0.02),
                .dofs = {{.name = std::string(side) + "hip_x", .axis = {1, 0, 0}},
                         {.name = std::string(side) + "hip_y", .axis = {0, 1, 0}},
                         {.name = std::string(side) + "hip_z", .axis = {0, 0, 1}}}});
  }
  b.add_body({.name = "back", .parent = "pelvis", .mass = 20, .inertia = diag(0.5, 0.5, 0.3),
              .dofs = {{.name = "back_y", .axis = {0, 1, 0}}, {.name = "back_z", .axis = {0, 0, 1}}}});
  return b;
}
}  // namespace

TEST_CASE("a valid model builds with the expected dimensions", "[model]") {
  const auto m = two_legs().build();
  CHECK(m.num_bodies() == 4);
  CHECK(m.num_joint_dofs() == 8);
  CHECK(m.nq() == 15);
  CHECK(m.nv() == 14);
  CHECK(m.total_mass() == Approx(44.0));
  CHECK(m.bodies[1].first_dof == 0);
  CHECK(m.bodies[2].first_dof == 3);
  CHECK(m.dof_index("rhip_y") == 4);
  CHECK_THROWS_WITH(m.dof_index("nohip"), Contains("nohip"));
  const auto s = make_state(m);
  CHECK(s.q[3] == 1.0);  // identity quaternion, w first
  CHECK(s.q.norm() == 1.0);
}

TEST_CASE("the mirror map pairs left and right with reflection signs", "[model]") {
  const auto m = two_legs().build();
  const int lx = m.dof_index("lhip_x"), ly = m.dof_index("lhip_y"), lz = m.dof_index("lhip_z");
  const int rx = m.dof_index("rhip_x"), ry = m.dof_index("rhip_y"), rz = m.dof_index("rhip_z");
  CHECK(m.mirror_dof[lx] == rx);
  CHECK(m.mirror_dof[ry] == ly);
  CHECK(m.mirror_dof[lz] == rz);
  // Abduction (x) and axial rotation (z) change sign under reflection; flexion (y) does not.
  CHECK(m.mirror_sign[lx] == -1.0);
  CHECK(m.mirror_sign[ly] == 1.0);
  CHECK(m.mirror_sign[lz] == -1.0);
  const int by = m.dof_index("back_y"), bz = m.dof_index("back_z");
  CHECK(m.mirror_dof[by] == by);
  CHECK(m.mirror_sign[by] == 1.0);
  CHECK(m.mirror_sign[bz] == -1.0);
  CHECK(m.mirror_body[m.body_index("lthigh")] == m.body_index("rthigh"));
  CHECK(m.mirror_body[0] == 0);
}

TEST_CASE("invalid models throw std::invalid_argument naming the problem", "[model][errors]") {
  SECTION("non-positive mass") {
    auto b = two_legs();
    b.bodies()[1].mass = 0.0;
    CHECK_THROWS_AS(b.build(), std::invalid_argument);
    CHECK_THROWS_WITH(b.build(), Contains("lthigh") && Contains("mass"));
  }
  SECTION("NaN mass") {
    auto b = two_legs();
    b.bodies()[2].mass = std::nan("");
    CHECK_THROWS_WITH(b.build(), Contains("rthigh") && Contains("mass"));
  }
  SECTION("inertia not positive definite") {
    auto b = two_legs();
    b.bodies()[0].inertia = diag(0.1, -0.1, 0.1);
    CHECK_THROWS_WITH(b.build(), Contains("pelvis") && Contains("positive definite"));
  }
  SECTION("inertia not symmetric") {
    auto b = two_legs();
    b.bodies()[0].inertia(0, 1) = 0.01;
    CHECK_THROWS_WITH(b.build(), Contains("symmetric"));
  }
  SECTION("principal moments violating the triangle inequality") {
    auto b = two_legs();
    b.bodies()[3].inertia = diag(0.1, 0.1, 0.5);
    CHECK_THROWS_WITH(b.build(), Contains("back") && Contains("triangle"));
  }
  SECTION("unknown parent") {
    auto b = two_legs();
    b.bodies()[1].parent = "torso";
    CHECK_THROWS_WITH(b.build(), Contains("unknown parent 'torso'"));
  }
  SECTION("limit lower > upper") {
    auto b = two_legs();
    b.bodies()[1].dofs[1].limit.lower = 1.0;
    b.bodies()[1].dofs[1].limit.upper = -1.0;
    CHECK_THROWS_WITH(b.build(), Contains("lhip_y") && Contains("lower 1") && Contains("upper -1"));
  }
  SECTION("duplicate body name") {
    auto b = two_legs();
    b.bodies()[2].name = "lthigh";
    CHECK_THROWS_WITH(b.build(), Contains("duplicate body name 'lthigh'"));
  }
  SECTION("duplicate DOF name") {
    auto b = two_legs();
    b.bodies()[2].dofs[0].name = "lhip_x";
    CHECK_THROWS_WITH(b.build(), Contains("duplicate DOF name 'lhip_x'"));
  }
  SECTION("zero axis") {
    auto b = two_legs();
    b.bodies()[3].dofs[0].axis.setZero();
    CHECK_THROWS_WITH(b.build(), Contains("back_y") && Contains("axis"));
  }
  SECTION("non-positive torque limit") {
    auto b = two_legs();
    b.bodies()[3].dofs[1].torque_limit = 0.0;
    CHECK_THROWS_WITH(b.build(), Contains("back_z") && Contains("torque_limit"));
  }
  SECTION("two roots") {
    auto b = two_legs();
    b.bodies()[2].parent = "";
    CHECK_THROWS_WITH(b.build(), Contains("root"));
  }
  SECTION("root with listed DOFs") {
    auto b = two_legs();
    b.bodies()[0].dofs.push_back({.name = "x"});
    CHECK_THROWS_WITH(b.build(), Contains("pelvis") && Contains("root"));
  }
  SECTION("reserved root DOF name") {
    auto b = two_legs();
    b.bodies()[3].dofs[0].name = "root_x";
    CHECK_THROWS_WITH(b.build(), Contains("reserved"));
  }
  SECTION("contact point on an unknown body") {
    auto b = two_legs();
    b.add_contact_point({.name = "heel", .body = "lfoot"});
    CHECK_THROWS_WITH(b.build(), Contains("heel") && Contains("unknown body 'lfoot'"));
  }
  SECTION("empty model") {
    model_builder<planar_root> e("empty");
    CHECK_THROWS_WITH(e.build(), Contains("no bodies"));
  }
}
