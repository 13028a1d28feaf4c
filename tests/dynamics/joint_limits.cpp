// Soft joint-limit torques: zero inside the range, the documented spring laws outside.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;

TEST_CASE("spring_damper and exponential limit torques", "[dynamics][joint_limits]") {
  model_builder<planar_root> b("limits");
  b.add_body({.name = "torso", .mass = 1, .inertia = 0.1 * mat3::Identity()});
  b.add_body({.name = "a", .parent = "torso", .mass = 1, .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "ja", .limit = {.lower = -0.5, .upper = 1.0, .stiffness = 100,
                                                .damping = 5, .model = limit_model::spring_damper}}}});
  b.add_body({.name = "b", .parent = "torso", .mass = 1, .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "jb", .limit = {.lower = -0.2, .upper = 0.3, .stiffness = 2,
                                                .damping = 1, .sharpness = 10,
                                                .model = limit_model::exponential}}}});
  b.add_body({.name = "c", .parent = "torso", .mass = 1, .inertia = 0.1 * mat3::Identity(),
              .dofs = {{.name = "jc", .limit = {.lower = 0, .upper = 0.1}}}});
  const auto m = b.build();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd tau = Eigen::VectorXd::Constant(6, 1.0);

  SECTION("inside the range nothing is added") {
    q.tail<3>() << 0.5, 0.1, 0.05;
    v.tail<3>() << 3, 3, 3;
    joint_limit_torques(m, q, v, tau);
    REQUIRE(tau == Eigen::VectorXd::Constant(6, 1.0));
  }
  SECTION("past the bounds") {
    q.tail<3>() << 1.2, 0.4, 5.0;
    v.tail<3>() << 0.5, -1.0, 3.0;
    joint_limit_torques(m, q, v, tau);
    REQUIRE(tau[3] == Approx(1.0 - 100 * 0.2 - 5 * 0.5));
    REQUIRE(tau[4] == Approx(1.0 - 2 * (std::exp(10 * 0.1) - 1) + 1.0));
    REQUIRE(tau[5] == 1.0);  // limit_model::none
    REQUIRE(tau.head<3>() == Eigen::Vector3d::Constant(1.0));
    q.tail<3>() << -0.7, -0.25, -1.0;
    v.tail<3>() << -0.5, 2.0, 0.0;
    tau.setZero();
    joint_limit_torques(m, q, v, tau);
    REQUIRE(tau[3] == Approx(100 * 0.2 + 5 * 0.5));
    REQUIRE(tau[4] == Approx(2 * (std::exp(10 * 0.05) - 1) - 2.0));
  }
  SECTION("wrong sizes are named") {
    Eigen::VectorXd small(2);
    REQUIRE_THROWS_WITH(joint_limit_torques(m, q, v, small),
                        Catch::Contains("tau_out") && Catch::Contains("expected 6, got 2"));
  }
}
