// Zero heap allocation in the rollout's step loop (after set-up). This binary replaces the global
// operator new / delete with counting versions, and builds Eigen with EIGEN_RUNTIME_NO_MALLOC and
// an eigen_assert that counts instead of aborting, because Eigen allocates through malloc, not
// operator new. The counted region runs from the objective's first accumulate (step 0) to its last
// (step N-1): every per-step code path (kinematics, contact, pushes, sensing and the delay line,
// controller, actuator, objective, recorder, integrator) runs inside it many times.
#include "support/counting_allocations.hpp"  // first: it configures Eigen

#include <catch2/catch.hpp>

#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/controllers/fsm/wang2009_table2.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/controllers/reflex/wang2012_reflex_controller.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/objectives/mass_distance.hpp"
#include "gaitsynth/objectives/wang2009/wang2009_objective.hpp"
#include "gaitsynth/objectives/wang2012/effort_terms.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/rollout/rollout.hpp"
#include "gaitsynth/synthesis/nearest_neighbor_synthesis.hpp"
#include "support/counting_objective.hpp"
#include "support/rollout_e2.hpp"

using namespace gaitsynth;
using namespace gaitsynth::test_alloc;
using namespace gaitsynth::test_e2;

namespace {

constexpr double dt = 1.0 / 2400.0;

/// A controller that reads delayed sensors at 64 Hz (exercises the delay line and the period).
struct delayed_reader {
  struct state_type {
    double sum = 0;
  };
  pose_hold inner;
  explicit delayed_reader(const auto& m) : inner(m) {}
  std::size_t num_parameters() const { return inner.num_parameters(); }
  void bind(std::span<const double> p) { inner.bind(p); }
  double period() const { return 1.0 / 64.0; }
  double max_sensor_delay() const { return 0.02; }
  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  template <root_joint Root>
  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    st.sum += s.delayed_q(0.02).sum() + s.delayed_v(0.005).sum() +
              s.delayed_contact_count(0, 0.01) + s.com_relative_to(1).norm() + s.body_up(0).z();
    pose_hold::state_type unused;
    inner.command(s, unused, cmd);
  }
};

/// The step loop of one rollout (controller parameters: the standing pose) allocates nothing.
/// `inner`: the objective (distance by default).
template <class Model, class Actuator, class Controller, class Terrain, class Integrator,
          class Inner = decltype(distance_objective())>
void require_no_allocation(const Model& m, const Actuator& act, Controller&& ctrl,
                           const Terrain& ground, Integrator&& integ, rollout_options opt,
                           Inner inner = distance_objective()) {
  auto scratch = make_rollout_scratch(m);
  region r;
  const counting_objective<Inner> obj{std::move(inner), &r};
  const Eigen::VectorXd p = standing_pose(m);
  const auto res = rollout(m, act, ctrl, obj, ground, integ, p, opt, scratch);
  Eigen::internal::set_is_malloc_allowed(true);
  INFO(m.name << ": " << to_string(res.reason) << " after " << res.steps << " steps");
  REQUIRE(res.reason == stop_reason::horizon);
  REQUIRE(r.views == res.steps);
  CHECK(r.news_at_end - r.news_at_start == 0);
  CHECK(r.eigen_at_end - r.eigen_at_start == 0);
}

template <class Model>
rollout_options options_for(const Model& m, const auto& ground) {
  rollout_options o;
  o.dt = dt;
  o.duration = 0.1;
  o.initial_state = make_state(m);
  place_on_terrain(m, ground, o.initial_state.q);
  o.pushes = {push{0, vec3(40, 10, 0), 0.02, 0.05}};
  return o;
}

/// PD servos behind a first-order lag (state: one torque per joint DOF), integrated with the body.
struct lagged_pd {
  pd_actuator pd;
  using state_type = Eigen::VectorXd;
  template <root_joint Root>
  state_type make_state(const model<Root>& m) const {
    return Eigen::VectorXd::Zero(m.num_joint_dofs());
  }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return pd.command_size(m);
  }
  static constexpr command_kind input_kind() { return command_kind::joint_target; }
  template <root_joint Root>
  void torques(const model<Root>&, const sim_state&, Eigen::Ref<const Eigen::VectorXd>,
               const state_type& z, Eigen::Ref<Eigen::VectorXd> tau) const {
    tau = z;
  }
  template <root_joint Root>
  void derivative(const model<Root>& m, const sim_state& s, Eigen::Ref<const Eigen::VectorXd> cmd,
                  const state_type& z, state_type& dz) const {
    for (int j = 0; j < m.num_joint_dofs(); ++j)
      dz[j] = (pd_torque(pd.kp[j], pd.kd[j], cmd[j], s.q[Root::nq + j], s.v[Root::nv + j]) - z[j]) /
              0.005;
  }
};

/// Keeps the compiler from eliding an allocation (new/delete pairs may be elided since C++14).
void benchmark_escape(void* p) {
  asm volatile("" : : "g"(p) : "memory");
}

}  // namespace

TEST_CASE("the counters see allocations (the test is not vacuous)", "[rollout][allocation]") {
  const long n0 = g_news.load();
  std::vector<int> v(100);
  benchmark_escape(v.data());
  CHECK(g_news.load() - n0 >= 1);
  const long e0 = g_eigen_asserts.load();
  Eigen::internal::set_is_malloc_allowed(false);
  Eigen::VectorXd x(1000);
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(g_eigen_asserts.load() - e0 >= 1);
  CHECK(x.size() == 1000);
}

TEST_CASE("no heap allocation in the step loop of a rollout", "[rollout][allocation]") {
  SECTION("3D humanoid, PD, flat ground, semi-implicit Euler, pushes") {
    const auto m = wang2009_humanoid();
    require_no_allocation(m, standing_pd(m, dt), pose_hold(m), flat_terrain(),
                          semi_implicit_euler(), options_for(m, flat_terrain()));
  }
  SECTION("3D humanoid, torque actuator, slope, Odeint RK4") {
    const auto m = wang2009_humanoid();
    const pd_actuator g = standing_pd(m, dt);
    require_no_allocation(
        m, torque_actuator{},
        pose_hold(m, {.output = command_kind::joint_torque, .kp = g.kp, .kd = g.kd}),
        slope_terrain(0.05), odeint_rk4(), options_for(m, slope_terrain(0.05)));
  }
  SECTION("3D humanoid, delayed sensors at 64 Hz") {
    const auto m = wang2009_humanoid();
    require_no_allocation(m, standing_pd(m, dt), delayed_reader(m), flat_terrain(),
                          semi_implicit_euler(), options_for(m, flat_terrain()));
  }
  SECTION("3D humanoid, mixed PD actuator (gains in the command)") {
    const auto m = wang2009_humanoid();
    const pd_actuator g = standing_pd(m, dt);
    require_no_allocation(m, mixed_pd_actuator{},
                          pose_hold(m, {.output = command_kind::mixed, .kp = g.kp, .kd = g.kd}),
                          flat_terrain(), semi_implicit_euler(), options_for(m, flat_terrain()));
  }
  SECTION("3D humanoid, mixed PD actuator, implicit joint damping") {
    const auto m = wang2009_humanoid();
    const pd_actuator g = standing_pd(m, dt);
    auto opt = options_for(m, flat_terrain());
    opt.implicit_joint_damping = true;
    require_no_allocation(m, mixed_pd_actuator{},
                          pose_hold(m, {.output = command_kind::mixed, .kp = g.kp, .kd = g.kd}),
                          flat_terrain(), semi_implicit_euler(), opt);
  }
  SECTION("3D humanoid, lagged PD integrated with the body by RK4 (torques at every stage)") {
    const auto m = wang2009_humanoid();
    static_assert(actuator_with_continuous_state<lagged_pd, floating_root>);
    require_no_allocation(m, lagged_pd{standing_pd(m, dt)}, pose_hold(m), flat_terrain(),
                          odeint_rk4(), options_for(m, flat_terrain()));
  }
  SECTION("3D humanoid, 16 Hill-type MTUs (Wang 2012), metabolic effort objective") {
    const auto m = wang2012_humanoid();
    const auto units = musculotendon::geyer_herr_leg_muscles(m);
    const musculotendon_actuator act(units);
    const pd_actuator g = standing_pd(m, dt);
    require_no_allocation(
        m, act,
        pose_hold(m, {.output = command_kind::excitation,
                      .kp = g.kp,
                      .kd = g.kd,
                      .num_excitations = act.num_units(),
                      .excitation = 0.2}),
        flat_terrain(), semi_implicit_euler(), options_for(m, flat_terrain()),
        wang2012::effort(m.total_mass(), units, wang2012::metabolic_energy(units)));
  }
  SECTION("3D humanoid, 16 MTUs driven by the reflex controller (delayed muscle sensors)") {
    const auto m = wang2012_humanoid();
    const auto units = musculotendon::geyer_herr_leg_muscles(m);
    const musculotendon_actuator act(units);
    const auto p = wang2012_reflex_controller::initial_parameters(m);  // its start, Sec. 4.4
    auto opt = options_for(m, flat_terrain());
    opt.detect_falls = false;
    auto scratch = make_rollout_scratch(m);
    region r;
    const counting_objective<decltype(distance_objective())> obj{distance_objective(), &r};
    const Eigen::VectorXd params = Eigen::Map<const Eigen::VectorXd>(p.data(), p.size());
    const auto res = rollout(m, act, wang2012_reflex_controller(m), obj, flat_terrain(),
                             semi_implicit_euler(), params, opt, scratch);
    Eigen::internal::set_is_malloc_allowed(true);
    REQUIRE(res.reason == stop_reason::horizon);
    CHECK(r.news_at_end - r.news_at_start == 0);
    CHECK(r.eigen_at_end - r.eigen_at_start == 0);
  }
  SECTION("7-link planar human with the recorder on") {
    const auto m = sharon2005_human7();
    auto opt = options_for(m, flat_terrain());
    trajectory tr;
    opt.record = &tr;
    opt.record_every = 4;
    require_no_allocation(m, standing_pd(m, dt), pose_hold(m), flat_terrain(),
                          semi_implicit_euler(), opt);
    CHECK(tr.frames.size() == 61);
  }
}

namespace {
/// Allocations (operator new and Eigen mallocs) of one more prob.cost on a used context.
template <class Problem>
void require_allocation_free_cost(const Problem& prob, const Eigen::VectorXd& x, double horizon) {
  auto ctx = prob.make_context();
  const double first = prob.cost(x, horizon, ctx);  // set-up: sizes every buffer
  const long n0 = g_news.load(), e0 = g_eigen_asserts.load();
  Eigen::internal::set_is_malloc_allowed(false);
  const double second = prob.cost(x, horizon, ctx);
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(second == first);
  CHECK(g_news.load() - n0 == 0);
  CHECK(g_eigen_asserts.load() - e0 == 0);
}
}  // namespace

TEST_CASE("an evaluation on a reused problem context allocates nothing",
          "[rollout][allocation][problem]") {
  SECTION("7-link walker: nearest-neighbor controller, mass-distance cost, 3 start states") {
    const auto m = sharon2005_human7();
    const std::string dir = std::string(GAITSYNTH_SOURCE_DIR) + "/data/sharon2005/";
    const auto target = load_keyframes(m, dir + "normal_walk.keyframes.json");
    const auto ctrl = load_nearest_neighbor(m, dir + "normal_walk.controller.json");
    rollout_options ro;
    ro.initial_state = target.initial_state();
    rollout_problem prob{m,
                         torque_actuator{},
                         ctrl,
                         mass_distance<planar_root>(m, target),
                         flat_terrain{},
                         semi_implicit_euler{},
                         ro};
    prob.starts = perturbed_starts(m, ro.initial_state);
    require_allocation_free_cost(prob, prob.initial_parameters(), 0.5);
  }
  SECTION("3D humanoid: PD pose hold, pushes, RK4") {
    const auto m = wang2009_humanoid();
    const rollout_problem prob{m,
                               standing_pd(m, dt),
                               pose_hold(m),
                               distance_objective(),
                               flat_terrain{},
                               odeint_rk4{},
                               options_for(m, flat_terrain())};
    require_allocation_free_cost(prob, standing_pose(m), 0.1);
  }
  SECTION("3D humanoid: Wang 2009 controller from Table 2, the whole eq. 16 objective") {
    const auto m = wang2009_humanoid();
    wang2009_controller c(m);
    const std::vector<double> p = wang2009_table2_parameters(m, c);
    c.bind(p);
    rollout_options ro;
    ro.contact.mu = 10.0;
    ro.initial_state = make_state(m);  // sized: the controller writes its start state in place
    const rollout_problem prob{
        m, mixed_pd_actuator{}, c, wang2009_objective(m), flat_terrain{}, semi_implicit_euler{},
        ro};
    require_allocation_free_cost(prob, prob.initial_parameters(), 0.3);
  }
  SECTION("3D humanoid: SIMBICON, the Wang 2009 objective with a target speed") {
    const auto m = wang2009_humanoid();
    const auto [kp, kd] = simbicon_walk_gains(m);
    simbicon_controller c(m, kp, kd);
    c.bind(simbicon_walk_parameters());
    rollout_options ro;
    ro.contact.mu = 10.0;
    ro.initial_state = simbicon_start_state(m);
    const rollout_problem prob{m,
                               mixed_pd_actuator{},
                               c,
                               wang2009_objective(m, {.target_speed = 1.0}),
                               flat_terrain{},
                               semi_implicit_euler{},
                               ro};
    require_allocation_free_cost(prob, prob.initial_parameters(), 0.5);
  }
}
