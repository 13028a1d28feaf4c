// The effort terms of Wang et al. 2012 (objectives/wang2012/): the metabolic rates at points
// computed by hand from the published forms, J_M's bookkeeping over a muscle-driven rollout
// against an observer that recomputes every step, J_R / J_L / min_torque / min_act against the
// torques and activations the rollout applied, effort()'s weights, and the Sec. 5 objective.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "gaitsynth/actuators/musculotendon/leg_muscles.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/objectives/wang2012/effort_terms.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/wang2012/wang2012_objective.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("metabolic rates at hand-computed points (Bhargava et al. 2004 forms)",
          "[objectives][wang2012]") {
  // SOL: 4000 N / 0.25 MPa * 1059.7 kg/m^3 * 0.04 m = 0.678208 kg.
  const musculotendon::unit_parameters sol{4000.0, 0.04, 0.26, 6.0};
  CHECK_THAT(wang2012::muscle_mass(sol), WithinRel(0.678208, 1e-12));
  // Full excitation recruits both fiber types: 40 r + 133 (1 - r) = 86.5 W/kg at r = 0.5.
  CHECK_THAT(wang2012::recruited_rate(1.0, 40.0, 133.0, 0.5), WithinRel(86.5, 1e-14));
  // Half: 20 sin(pi/4) + 66.5 (1 - cos(pi/4)) = 14.1421 + 19.4774.
  CHECK_THAT(wang2012::recruited_rate(0.5, 40.0, 133.0, 0.5), WithinRel(33.6195, 1e-5));
  CHECK(wang2012::recruited_rate(0.0, 40.0, 133.0, 0.5) == 0.0);
  CHECK(wang2012::maintenance_length_dependence(0.3) == 0.5);
  CHECK(wang2012::maintenance_length_dependence(0.75) == 0.75);
  CHECK(wang2012::maintenance_length_dependence(1.25) == 0.5);
  CHECK(wang2012::maintenance_length_dependence(1.8) == 0.0);
  // Shortening at 0.1 m/s with F_MTU = 1000 N, F_CE = 900 N: S = 25 W, W = 90 W.
  const double m = 0.5;
  const auto r = wang2012::muscle_metabolic_rates(m, 1.0, 1.0, 1.0, -0.1, 1000.0, 900.0);
  CHECK_THAT(r.activation, WithinRel(0.5 * 86.5, 1e-14));
  CHECK_THAT(r.maintenance, WithinRel(0.5 * (37.0 + 55.5), 1e-14));  // g(1) = 1
  CHECK_THAT(r.shortening, WithinRel(25.0, 1e-14));
  CHECK_THAT(r.work, WithinRel(90.0, 1e-14));
  // Lengthening: no shortening heat, no positive work.
  const auto e = wang2012::muscle_metabolic_rates(m, 1.0, 1.0, 1.0, +0.1, 1000.0, 900.0);
  CHECK(e.shortening == 0.0);
  CHECK(e.work == 0.0);
}

namespace {

constexpr double dt = 1.0 / 2400.0;

/// Recomputes each step's rates and squared torques from what the rollout shows its observers.
struct effort_recorder {
  std::vector<double> masses, l_opt;
  std::vector<int> qs;  // muscle DOFs
  double metabolic = 0.0, other = 0.0, limit = 0.0, sagittal = 0.0, activation = 0.0;
  long steps = 0;
  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = ob.actuator_state();
    const auto& tau = ob.tau();
    const auto& tl = ob.tau_passive();
    for (std::size_t i = 0; i < masses.size(); ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      metabolic += wang2012::muscle_metabolic_rates(
                       masses[i], ob.command()[k], st.activation[k], st.fiber_length[k] / l_opt[i],
                       st.fiber_velocity[k], st.force[k], st.active_force[k])
                       .total();
      activation += st.activation[k] * st.activation[k];
    }
    const int nj = ob.model().num_joint_dofs();
    for (int j = 0; j < nj; ++j) {
      const double t = tau[floating_root::nv + j], p = tl[floating_root::nv + j];
      if (std::find(qs.begin(), qs.end(), j) != qs.end()) {
        sagittal += t * t;
        limit += p * p;
      } else {
        other += t * t;
      }
    }
    ++steps;
  }
};

}  // namespace

TEST_CASE("J_M, J_R, J_L and the ablations average what the rollout applied",
          "[objectives][wang2012][rollout]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const musculotendon_actuator act(units);
  // Weak hold gains: the body sags, so the joint limits, the fibers and the torques all work.
  const pd_actuator g = standing_pd(m, dt, 0.2);
  const pose_hold hold(m, {.output = command_kind::excitation,
                           .kp = g.kp,
                           .kd = g.kd,
                           .num_excitations = act.num_units(),
                           .excitation = 0.3});
  const wang2012::metabolic_energy jm(units);
  auto objective =
      weighted_sum<wang2012::metabolic_energy, wang2012::mean_squared_joint_torque,
                   wang2012::mean_squared_joint_torque, wang2012::mean_squared_joint_torque,
                   wang2012::mean_squared_activation>(
          {1e3, 1.0, 1e-3, 1e-6, 1e-9}, jm, wang2012::other_joint_torque(units),
          wang2012::joint_limit_torque(units), wang2012::sagittal_joint_torque(units),
          wang2012::mean_squared_activation{});
  effort_recorder rec;
  rec.masses = jm.muscle_masses();
  for (const auto& u : units) rec.l_opt.push_back(u.parameters.optimal_fiber_length);
  rec.qs = wang2012::muscle_dofs(units);
  REQUIRE(rec.qs.size() == 6);
  rollout_options opt;
  opt.duration = 0.5;
  auto scratch = make_rollout_scratch(m);
  const std::vector<double> params(static_cast<std::size_t>(m.num_joint_dofs()), 0.0);
  trajectory tr;
  opt.record = &tr;
  const rollout_result r = rollout(m, act, hold, objective, flat_terrain(), semi_implicit_euler(),
                                   std::span<const double>(params), opt, scratch, rec);
  REQUIRE(r.steps == rec.steps);
  const double n = static_cast<double>(rec.steps);
  const double basal = 1.51 * m.total_mass();
  const double j_m = basal + rec.metabolic / n, j_r = rec.other / n, j_l = rec.limit / n;
  const double j_s = rec.sagittal / n, j_a = rec.activation / n;
  INFO("J_M " << j_m << " W, J_R " << j_r << ", J_L " << j_l << ", sagittal " << j_s
              << ", activation " << j_a);
  CHECK(j_m > basal + 10.0);  // the muscles spend something
  CHECK(j_l > 0.0);
  CHECK_THAT(r.cost, WithinRel(1e3 * j_m + j_r + 1e-3 * j_l + 1e-6 * j_s + 1e-9 * j_a, 1e-12));
  // The recorded terms are the parts' own: the last frame shows J_M as finish() computes it.
  REQUIRE(!tr.frames.empty());
  CHECK(tr.objective_term_names[0] == "J_M");
}

TEST_CASE("effort() weighs J_M, J_R and J_L as Sec. 5 does", "[objectives][wang2012]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const auto e = wang2012::effort(70.0, units, wang2012::metabolic_energy(units));
  const double we = 0.004 / 70.0;
  CHECK_THAT(e.weights()[0], WithinRel(we * 100.0, 1e-15));
  CHECK_THAT(e.weights()[1], WithinRel(we * 1.0, 1e-15));
  CHECK_THAT(e.weights()[2], WithinRel(we * 0.5, 1e-15));
  const auto a =
      wang2012::effort(70.0, units, wang2012::mean_squared_activation{}, {.metabolic = 60000.0});
  CHECK_THAT(a.weights()[0], WithinRel(we * 60000.0, 1e-15));
  CHECK_THROWS_WITH(wang2012::effort(-1.0, units, wang2012::mean_squared_activation{}),
                    Contains("body_mass") && Contains("-1"));
  CHECK_THROWS_WITH(wang2012::metabolic_energy(units, {.slow_twitch_ratio = 1.5}),
                    Contains("slow_twitch_ratio") && Contains("1.5"));
}

TEST_CASE("the Sec. 5 objective: the task terms of Wang 2009 and the effort, by name and weight",
          "[objectives][wang2012]") {
  const auto m = wang2012_humanoid();
  const auto units = musculotendon::geyer_herr_leg_muscles(m);
  const auto obj =
      wang2012::objective(m, units, wang2012::metabolic_energy(units), {.target_speed = 1.5});
  const auto& w = obj.weights();
  CHECK(w[0] == 100.0);     // E_user
  CHECK(w[2] == 120000.0);  // E_fail
  CHECK(w[5] == 1.0);       // w_e J_effort (w_e inside the effort)
  CHECK(obj.part<0>().opts().target_speed == 1.5);
  CHECK(obj.part<1>().opts().target_speed == 1.5);
  CHECK_THAT(obj.part<5>().weights()[0], WithinRel(0.004 / m.total_mass() * 100.0, 1e-15));
  // The total of a rollout is the weighted sum of its terms, each measured alone (the others'
  // weights 0) on the same deterministic rollout.
  const musculotendon_actuator act(units);
  const pd_actuator g = standing_pd(m, 1.0 / 2400.0, 0.2);
  const pose_hold hold(m, {.output = command_kind::excitation,
                           .kp = g.kp,
                           .kd = g.kd,
                           .num_excitations = act.num_units(),
                           .excitation = 0.1});
  rollout_options opt;
  opt.duration = 0.5;
  auto cost_with = [&](const wang2012::task_weights& tw) {
    auto scratch = make_rollout_scratch(m);
    const auto o = wang2012::objective(m, units, wang2012::metabolic_energy(units),
                                       {.target_speed = 1.5, .weights = tw});
    const std::vector<double> zeros(static_cast<std::size_t>(m.num_joint_dofs()), 0.0);
    return rollout(m, act, hold, o, flat_terrain(), semi_implicit_euler(),
                   std::span<const double>(zeros), opt, scratch)
        .cost;
  };
  const wang2012::task_weights none{0, 0, 0, 0, 0, 0};
  double sum = 0.0;
  for (std::size_t i = 0; i < 6; ++i) {
    wang2012::task_weights one = none;
    std::array<double*, 6> field{&one.user, &one.vel,     &one.fail,
                                 &one.head, &one.posture, &one.effort};
    *field[i] = 1.0;
    const double term = cost_with(one);
    INFO(wang2012::objective_term_names[i] << " = " << term);
    CHECK(std::isfinite(term));
    CHECK(term >= 0.0);
    sum += w[i] * term;
  }
  CHECK(cost_with(none) == 0.0);
  CHECK_THAT(cost_with({}), WithinRel(sum, 1e-12));
  CHECK_THROWS_WITH(
      wang2012::objective(m, units, wang2012::metabolic_energy(units), {.weights = {.head = -1.0}}),
      Contains("E_head") && Contains("-1"));
  CHECK_THROWS_WITH(
      wang2012::objective(m, units, wang2012::metabolic_energy(units), {.target_speed = NAN}),
      Contains("target_speed"));
}
