// The examples of docs/architecture.md ("Defining a new controller", "an actuator with state",
// "an objective"), compiled and run, so the documentation cannot drift from the concepts.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

namespace {

// ---- docs/architecture.md: Defining a new controller ------------------------------------------
struct leaning_hold {
  struct state_type {};  // nothing evolves
  Eigen::VectorXd pose;  // bound parameters: targets, then the gain
  double gain = 0;
  int hip_l, hip_r;  // DOFs to lean with

  explicit leaning_hold(const floating_model& m)
      : pose(Eigen::VectorXd::Zero(m.num_joint_dofs())),
        hip_l(m.dof_index("lhip_y")),
        hip_r(m.dof_index("rhip_y")) {}

  std::size_t num_parameters() const { return pose.size() + 1; }
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "leaning_hold parameters");
    for (Eigen::Index j = 0; j < pose.size(); ++j) pose[j] = p[j];
    gain = p.back();
  }
  double period() const { return 0.01; }
  static constexpr command_kind output_kind() { return command_kind::joint_target; }
  state_type make_state(const floating_model&) const { return {}; }
  void command(const sensors<floating_root>& s, state_type&,
               Eigen::Ref<Eigen::VectorXd> target) const {
    target = pose;
    target[hip_l] += gain * s.com_velocity.x();
    target[hip_r] += gain * s.com_velocity.x();
  }
};
static_assert(controller<leaning_hold, floating_root>);

// ---- docs/architecture.md: Defining an actuator with state ------------------------------------
/// Torque generators behind first-order activation dynamics: excitation u in [0, 1] per DOF,
/// da/dt = (u - a) / tau_act, torque = a * peak. Its state is a vector with a derivative, so the
/// rollout integrates it with (q, v).
struct activated_torque {
  using state_type = Eigen::VectorXd;  // activation per joint DOF
  double tau_act = 0.01;               // s (10 ms)
  double peak = 50.0;                  // N m at full activation

  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return Eigen::VectorXd::Zero(m.num_joint_dofs());
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return m.num_joint_dofs();
  }
  static constexpr command_kind input_kind() { return command_kind::excitation; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
               const state_type& a, Eigen::Ref<Eigen::VectorXd> tau) const {
    tau = peak * a;
  }
  template <root_joint Root>
  void derivative(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd> u,
                  const state_type& a, state_type& da) const {
    da = (u.cwiseMax(0.0).cwiseMin(1.0) - a) / tau_act;
  }
  template <root_joint Root>
  void reset_state(const model<Root>&, state_type& a) const {
    a.setZero();  // no allocation for a worker's next rollout
  }
};
static_assert(actuator_with_continuous_state<activated_torque, floating_root>);

/// Constant excitation of one DOF (the controller side of the example).
struct constant_excitation {
  struct state_type {};
  int dof = 0;
  double u = 0.0;
  std::size_t num_parameters() const { return 1; }
  void bind(std::span<const double> p) {
    check_parameters(p, 1, "constant_excitation");
    u = p[0];
  }
  double period() const { return 0.0; }
  static constexpr command_kind output_kind() { return command_kind::excitation; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void command(const sensors<Root>&, state_type&, Eigen::Ref<Eigen::VectorXd> u_out) const {
    u_out.setZero();
    u_out[dof] = u;
  }
};

// ---- docs/architecture.md: Defining an objective -----------------------------------------------
/// Mean squared whole-body angular momentum about the COM (the E_ang idea of Wang et al. 2009),
/// read from the rollout's own kinematics.
struct angular_momentum_cost {
  struct accumulator_type {
    double integral = 0.0, time = 0.0, last = 0.0;
  };
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.last = centroidal_momentum(v.model(), v.workspace()).angular.squaredNorm();
    a.integral += a.last * v.dt;  // rectangle rule over [t, t + dt)
    a.time += v.dt;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    return a.time > 0.0 ? a.integral / a.time : 0.0;
  }
  static std::array<std::string_view, 1> term_names() { return {"L_squared"}; }
  void terms(const accumulator_type& a, std::span<double> out) const { out[0] = a.last; }
};
static_assert(objective<angular_momentum_cost, floating_root>);

}  // namespace

TEST_CASE("docs/architecture.md: the examples compile and run", "[rollout][docs]") {
  const auto m = wang2009_humanoid();
  rollout_options opt;
  opt.duration = 0.2;
  auto scratch = make_rollout_scratch(m);
  SECTION("a new controller") {
    std::vector<double> params(static_cast<std::size_t>(m.num_joint_dofs()) + 1, 0.0);
    const rollout_result r =
        rollout(m, standing_pd(m, opt.dt), leaning_hold(m), distance_objective(), flat_terrain(),
                semi_implicit_euler(), std::span<const double>(params), opt, scratch);
    CHECK(r.reason == stop_reason::horizon);
  }
  SECTION("an actuator with state, integrated with the body") {
    const int knee = m.dof_index("lknee");
    const std::vector<double> u = {1.0};
    rollout_policy_states<activated_torque, constant_excitation, angular_momentum_cost> states;
    constant_excitation c{.dof = knee};
    semi_implicit_euler integ;
    opt.detect_falls = false;  // a passive body with one kicking knee collapses; keep simulating
    const rollout_result r =
        rollout(m, activated_torque{}, c, angular_momentum_cost{}, flat_terrain(), integ,
                std::span<const double>(u), opt, scratch, states);
    CHECK(r.steps == 480);
    // Activation reached 1 - exp(-0.2 / 0.01) of full excitation; the other DOFs stayed at 0.
    const Eigen::VectorXd& a = *states.actuator;
    CHECK(a[knee] == Approx(1.0 - std::exp(-20.0)).epsilon(1e-6));
    CHECK(a.lpNorm<Eigen::Infinity>() == a[knee]);
    CHECK(r.cost > 0.0);  // the kicking knee gave the body angular momentum
  }
}
