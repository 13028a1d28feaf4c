// Command kinds (actuators/command_kind.hpp): names, static kinds detected, the compile-time
// predicate check_command_kinds static_asserts on, and the run-time check's message.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/models/sharon2005.hpp"

using namespace gaitsynth;

namespace {

/// A controller whose type fixes its output kind K (static constexpr output_kind()).
template <command_kind K>
struct static_kind_controller {
  struct state_type {};
  std::size_t num_parameters() const { return 0; }
  void bind(std::span<const double> p) { check_parameters(p, 0, "static_kind_controller"); }
  double period() const { return 0; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  static constexpr command_kind output_kind() { return K; }
  template <root_joint Root>
  void command(const sensors<Root>&, state_type&, Eigen::Ref<Eigen::VectorXd> cmd) const {
    cmd.setZero();
  }
};
using torque_controller = static_kind_controller<command_kind::joint_torque>;
using target_controller = static_kind_controller<command_kind::joint_target>;
using mixed_controller = static_kind_controller<command_kind::mixed>;

/// An actuator whose kind is decided per object (input_kind() is not static).
struct dynamic_kind_actuator {
  using state_type = no_actuator_state;
  command_kind kind = command_kind::joint_torque;
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  command_kind input_kind() const { return kind; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type&, Eigen::Ref<Eigen::VectorXd> tau) const {
    tau = cmd;
  }
};

/// A controller without output_kind(): nothing to check.
struct unkinded_controller {
  struct state_type {};
};

/// An actuator whose torques change its state: not an actuator (torques must be pure).
struct mutating_actuator {
  using state_type = int;
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return 0;
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::joint_torque; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
               state_type& calls, Eigen::Ref<Eigen::VectorXd>) const {
    ++calls;
  }
};

}  // namespace

static_assert(controller<torque_controller, planar_root>);
static_assert(actuator<dynamic_kind_actuator, planar_root>);
static_assert(!actuator<mutating_actuator, planar_root>);  // torques takes the state by const&

TEST_CASE("command kinds are named", "[actuators][command_kind]") {
  STATIC_REQUIRE(to_string(command_kind::joint_torque) == "joint_torque");
  STATIC_REQUIRE(to_string(command_kind::joint_target) == "joint_target");
  STATIC_REQUIRE(to_string(command_kind::excitation) == "excitation");
  STATIC_REQUIRE(to_string(command_kind::mixed) == "mixed");
  CHECK(to_string(static_cast<command_kind>(42)) == "unknown");
}

TEST_CASE("static kinds are detected: constexpr static members only", "[actuators][command_kind]") {
  STATIC_REQUIRE(actuator_with_static_input_kind<torque_actuator>);
  STATIC_REQUIRE(actuator_with_static_input_kind<pd_actuator>);
  STATIC_REQUIRE(actuator_with_static_input_kind<mixed_pd_actuator>);
  STATIC_REQUIRE(!actuator_with_static_input_kind<dynamic_kind_actuator>);
  STATIC_REQUIRE(controller_with_static_output_kind<torque_controller>);
  STATIC_REQUIRE(controller_with_output_kind<torque_controller>);
  // pose_hold's kind is an option: known at run time only.
  STATIC_REQUIRE(controller_with_output_kind<pose_hold>);
  STATIC_REQUIRE(!controller_with_static_output_kind<pose_hold>);
  STATIC_REQUIRE(!controller_with_output_kind<unkinded_controller>);
}

TEST_CASE("command_kinds_compatible is false exactly for two different static kinds",
          "[actuators][command_kind]") {
  STATIC_REQUIRE(command_kinds_static<torque_controller, torque_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<torque_controller, torque_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<target_controller, pd_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<mixed_controller, mixed_pd_actuator>);
  STATIC_REQUIRE(!command_kinds_compatible<torque_controller, pd_actuator>);
  STATIC_REQUIRE(!command_kinds_compatible<target_controller, torque_actuator>);
  STATIC_REQUIRE(!command_kinds_compatible<target_controller, mixed_pd_actuator>);
  STATIC_REQUIRE(!command_kinds_compatible<mixed_controller, pd_actuator>);
  // A kind known only at run time defers the decision to check_command_kinds' run-time path.
  STATIC_REQUIRE(!command_kinds_static<pose_hold, torque_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<pose_hold, torque_actuator>);
  STATIC_REQUIRE(!command_kinds_static<torque_controller, dynamic_kind_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<torque_controller, dynamic_kind_actuator>);
  STATIC_REQUIRE(command_kinds_compatible<unkinded_controller, pd_actuator>);
}

TEST_CASE("check_command_kinds: static pairs that match compile and pass",
          "[actuators][command_kind]") {
  CHECK_NOTHROW(check_command_kinds(torque_controller{}, torque_actuator{}));
  CHECK_NOTHROW(check_command_kinds(mixed_controller{}, mixed_pd_actuator{}));
  CHECK_NOTHROW(check_command_kinds(unkinded_controller{}, torque_actuator{}));
  // check_command_kinds(torque_controller{}, pd_actuator{}) does not compile (static_assert).
}

TEST_CASE("check_command_kinds: run-time kinds are compared and both are named",
          "[actuators][command_kind]") {
  const planar_model m = sharon2005_human7();
  CHECK_NOTHROW(check_command_kinds(pose_hold(m), pd_actuator{}));
  CHECK_NOTHROW(
      check_command_kinds(pose_hold(m, {.output = command_kind::joint_torque}), torque_actuator{}));
  CHECK_NOTHROW(
      check_command_kinds(pose_hold(m, {.output = command_kind::mixed}), mixed_pd_actuator{}));
  CHECK_THROWS_AS(check_command_kinds(pose_hold(m), torque_actuator{}), std::invalid_argument);
  CHECK_THROWS_WITH(
      check_command_kinds(pose_hold(m), torque_actuator{}),
      Catch::Contains("controller outputs joint_target, actuator expects joint_torque"));
  CHECK_THROWS_WITH(
      check_command_kinds(pose_hold(m, {.output = command_kind::mixed}), pd_actuator{}),
      Catch::Contains("controller outputs mixed, actuator expects joint_target"));
  // A static controller kind against a run-time actuator kind.
  dynamic_kind_actuator a;
  a.kind = command_kind::excitation;
  CHECK_THROWS_WITH(
      check_command_kinds(torque_controller{}, a),
      Catch::Contains("controller outputs joint_torque, actuator expects excitation"));
  a.kind = command_kind::joint_torque;
  CHECK_NOTHROW(check_command_kinds(torque_controller{}, a));
}
