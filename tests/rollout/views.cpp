// What policies see of the rollout: the sensors' and the step view's read-only workspace and
// contact state are this step's (nothing to recompute), and the delayed sensor history carries
// the COM, its velocity, body rotations and the actuator's sensed values.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/momentum.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

constexpr double dt = 1.0 / 2400.0;
constexpr double delay = 0.01;  // 24 steps: the VAS / ground-contact delay of Wang et al. 2012

/// What the probes saw, per physics step (preallocated by the test).
struct views_log {
  std::vector<vec3> com, delayed_com, com_velocity, delayed_com_velocity;
  std::vector<mat3> torso_rotation, delayed_torso_rotation;
  std::vector<double> sensed, delayed_sensed;
  double max_momentum_error = 0.0, max_contact_force_error = 0.0;
  int same_workspace = 0, calls = 0;
  explicit views_log(int n) {
    com.resize(n), delayed_com.resize(n), com_velocity.resize(n), delayed_com_velocity.resize(n);
    torso_rotation.resize(n), delayed_torso_rotation.resize(n);
    sensed.resize(n), delayed_sensed.resize(n);
  }
};

/// PD servos that also sense one value: the step index the PD law last saw (its "fiber length").
struct sensing_pd {
  pd_actuator pd;
  using state_type = no_actuator_state;
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return pd.make_state(m);
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return pd.command_size(m);
  }
  command_kind input_kind() const { return pd.input_kind(); }
  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type& st, Eigen::Ref<Eigen::VectorXd> tau) const {
    pd.torques(m, s, cmd, st, tau);
  }
  template <root_joint Root>
  int sensed_size(const model<Root>&) const {
    return 2;
  }
  // The sensed value is the time the last torques were computed at, so a delayed read can be
  // checked exactly: sense() runs before the controller, so it reports the previous step's.
  mutable double last_t = 0.0;
  template <root_joint Root>
  void sense(const model<Root>&, const state_type&, std::span<double> out) const {
    out[0] = last_t;
    out[1] = -1.0;
  }
};

/// sensing_pd whose sensed value is the time of the last torques it computed.
struct timed_pd : sensing_pd {
  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
               const state_type& st, Eigen::Ref<Eigen::VectorXd> tau) const {
    sensing_pd::torques(m, s, cmd, st, tau);
    last_t = s.t;
  }
};

/// PD servos that check the workspace they are handed against a fresh forward kinematics.
struct kinematics_reading_pd {
  pd_actuator pd;
  double* max_error;
  int* calls;
  using state_type = no_actuator_state;
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return pd.make_state(m);
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return pd.command_size(m);
  }
  static constexpr command_kind input_kind() { return command_kind::joint_target; }
  template <root_joint Root>
  void torques(const model<Root>& m, const sim_state& s, const workspace<Root>& ws,
               Eigen::Ref<const Eigen::VectorXd> cmd, const state_type& st,
               Eigen::Ref<Eigen::VectorXd> tau) const {
    auto fresh = make_workspace(m);  // (allocates: a test actuator)
    forward_kinematics(m, fresh, s.q, s.v);
    for (int b = 0; b < m.num_bodies(); ++b)
      *max_error = std::max({*max_error, (ws.body_position[b] - fresh.body_position[b]).norm(),
                             (ws.body_linear_velocity[b] - fresh.body_linear_velocity[b]).norm()});
    ++*calls;
    pd.torques(m, s, cmd, st, tau);
  }
};

struct views_probe {
  struct state_type {};
  pose_hold inner;
  views_log* log;
  int torso;
  std::size_t num_parameters() const { return inner.num_parameters(); }
  void bind(std::span<const double> p) { inner.bind(p); }
  double period() const { return 0.0; }
  double max_sensor_delay() const { return delay; }
  command_kind output_kind() const { return command_kind::joint_target; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <class S>
  void command(const S& s, state_type&, Eigen::Ref<Eigen::VectorXd> cmd) const {
    const auto k = static_cast<std::size_t>(s.step);
    log->com[k] = s.com;
    log->delayed_com[k] = s.delayed_com(delay);
    log->com_velocity[k] = s.com_velocity;
    log->delayed_com_velocity[k] = s.delayed_com_velocity(delay);
    log->torso_rotation[k] = s.body_rotation[static_cast<std::size_t>(torso)];
    log->delayed_torso_rotation[k] = s.delayed_body_rotation(torso, delay);
    if (!s.sensed.empty()) {
      log->sensed[k] = s.sensed[0];
      log->delayed_sensed[k] = s.delayed_sensed(delay)[0];
    }
    log->same_workspace += s.workspace().body_position.data() == s.body_position.data() &&
                           s.contacts().points_touching.data() == s.contact_count.data();
    ++log->calls;
    pose_hold::state_type unused;
    inner.command(s, unused, cmd);
  }
};

/// Checks the step view's workspace and contacts against a recomputation from (q, v).
struct views_objective {
  views_log* log;
  struct accumulator_type {};
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type&, const View& v) const {
    auto ws = make_workspace(v.model());  // (allocates: a test objective)
    forward_kinematics(v.model(), ws, v.q(), v.v());
    const momentum h_view = centroidal_momentum(v.model(), v.workspace());
    const momentum h_fresh = centroidal_momentum(v.model(), ws);
    log->max_momentum_error =
        std::max({log->max_momentum_error, (h_view.angular - h_fresh.angular).norm(),
                  (h_view.linear - h_fresh.linear).norm()});
    for (std::size_t c = 0; c < v.contact_force.size(); ++c)
      log->max_contact_force_error = std::max(log->max_contact_force_error,
                                              (v.contacts().force[c] - v.contact_force[c]).norm());
  }
  double finish(const accumulator_type&, const rollout_outcome&) const { return 0.0; }
};

}  // namespace

TEST_CASE("policies read this step's workspace and contacts through const views",
          "[rollout][views]") {
  const auto m = wang2009_humanoid();
  rollout_options opt;
  opt.duration = 0.1;
  opt.pushes = {push{0, vec3(150, 60, 0), 0.02, 0.08}};  // momentum changes: a real comparison
  views_log log(240);
  auto scr = make_rollout_scratch(m);
  const auto r =
      rollout(m, standing_pd(m, dt), views_probe{pose_hold(m), &log, m.body_index("torso")},
              views_objective{&log}, flat_terrain(), semi_implicit_euler(),
              Eigen::VectorXd::Zero(m.num_joint_dofs()), opt, scr);
  REQUIRE(r.steps == 240);
  CHECK(log.same_workspace == 240);
  CHECK(log.max_momentum_error == 0.0);  // the same sums over the same momenta
  CHECK(log.max_contact_force_error == 0.0);
}

TEST_CASE("the sensor history delays the COM, body rotations and the actuator's sensed values",
          "[rollout][views][sensors]") {
  const auto m = wang2009_humanoid();
  rollout_options opt;
  opt.duration = 0.1;
  opt.pushes = {push{0, vec3(150, 60, 0), 0.02, 0.08}};
  views_log log(240);
  auto scr = make_rollout_scratch(m);
  static_assert(actuator_with_sensing<timed_pd, floating_root>);
  const auto r = rollout(m, timed_pd{standing_pd(m, dt)},
                         views_probe{pose_hold(m), &log, m.body_index("torso")},
                         distance_objective(), flat_terrain(), semi_implicit_euler(),
                         Eigen::VectorXd::Zero(m.num_joint_dofs()), opt, scr);
  REQUIRE(r.steps == 240);
  REQUIRE(log.calls == 240);
  const int lag = 24;
  for (int k = 0; k < 240; ++k) {
    const auto i = static_cast<std::size_t>(k), j = static_cast<std::size_t>(std::max(k - lag, 0));
    INFO("step " << k);
    REQUIRE(log.delayed_com[i] == log.com[k >= lag ? j : 0]);
    REQUIRE(log.delayed_com_velocity[i] == log.com_velocity[k >= lag ? j : 0]);
    REQUIRE(log.delayed_torso_rotation[i] == log.torso_rotation[k >= lag ? j : 0]);
    REQUIRE(log.delayed_sensed[i] == log.sensed[k >= lag ? j : 0]);
    // sense() runs before the controller: it reports the time of the previous step's torques.
    REQUIRE(log.sensed[i] == (k == 0 ? 0.0 : (k - 1) * dt));
  }
  CHECK((log.com[200] - log.com[100]).norm() > 1e-4);  // the push moved it: not vacuous
  CHECK((log.torso_rotation[200] - log.torso_rotation[100]).norm() > 1e-6);
}

TEST_CASE("an actuator may read the rollout's kinematics", "[rollout][views][actuators]") {
  const auto m = wang2009_humanoid();
  static_assert(actuator<kinematics_reading_pd, floating_root>);
  static_assert(actuator_with_kinematics<kinematics_reading_pd, floating_root>);
  static_assert(!actuator_with_state_only_torques<kinematics_reading_pd, floating_root>);
  rollout_options opt;
  opt.duration = 0.05;
  opt.pushes = {push{0, vec3(150, 60, 0), 0.0, 0.05}};
  double err = 0.0;
  int calls = 0;
  auto scr = make_rollout_scratch(m);
  const auto r = rollout(m, kinematics_reading_pd{standing_pd(m, dt), &err, &calls}, pose_hold(m),
                         distance_objective(), flat_terrain(), semi_implicit_euler(),
                         Eigen::VectorXd::Zero(m.num_joint_dofs()), opt, scr);
  REQUIRE(r.steps == 120);
  CHECK(calls == 120);
  CHECK(err == 0.0);
}
