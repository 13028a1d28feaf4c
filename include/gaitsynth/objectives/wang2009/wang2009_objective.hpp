#pragma once
/// \file objectives/wang2009/wang2009_objective.hpp
/// The complete objective of Wang, Fleet & Hertzmann 2009, eq. 16,
///     E = sum_s w_s E_s,  s in {user, vel, land, fail, sym, ang, head, power, ratio},
/// as a weighted_sum of the nine terms (eqs. 4-15, one file each in this folder) with the paper's
/// weights, and a report of each term's raw and weighted value.
///
///   auto obj = wang2009_objective(m, {.target_speed = 1.0});   // any controller
///   rollout_policy_states<A, C, decltype(obj)> states;          // to keep the accumulator
///   const rollout_result r = rollout(m, act, ctrl, obj, ground, integ, params, opt, scr, states);
///   print_wang2009_report(std::cout, wang2009_report(obj, *states.objective, r, opt));
///
/// A weight of 0 ablates a term (Fig. 3: without E_ratio); it is still measured (and reported and
/// recorded), only not added. With no target speed the paper replaces E_power by the cost of
/// transport E_power / v_x (Sec. 4.1); options::cost_of_transport overrides that choice.
///
/// A tenth term, E_posture (torso_posture.hpp, ours), keeps the torso upright, and an eleventh,
/// E_pelvis (the same measure on the pelvis, ours), the pelvis; their weights are 0 unless set,
/// so that eq. 16 is the paper's.
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <ios>
#include <optional>
#include <ostream>
#include <string_view>
#include <tuple>
#include <utility>

#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2009/angular_momentum.hpp"
#include "gaitsynth/objectives/wang2009/common.hpp"
#include "gaitsynth/objectives/wang2009/failure.hpp"
#include "gaitsynth/objectives/wang2009/head.hpp"
#include "gaitsynth/objectives/wang2009/landing.hpp"
#include "gaitsynth/objectives/wang2009/power.hpp"
#include "gaitsynth/objectives/wang2009/power_ratio.hpp"
#include "gaitsynth/objectives/wang2009/symmetry.hpp"
#include "gaitsynth/objectives/wang2009/torso_posture.hpp"
#include "gaitsynth/objectives/wang2009/user_gait.hpp"
#include "gaitsynth/objectives/wang2009/velocity.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"

namespace gaitsynth {

/// The weights of eq. 16 (Sec. 4.1, "for all experiments").
struct wang2009_weights {
  double user = 100.0;
  double vel = 100.0;
  double land = 1.2;
  double fail = 120000.0;
  double sym = 100.0;
  double ang = 10.0;
  double head = 100.0;
  std::optional<double> power;  ///< unset: the paper's 1e-5 (70 kg / model mass)
  double ratio = 1.0;
  double posture = 0.0;  ///< E_posture, ours (torso_posture.hpp); 0: eq. 16 as published
  double pelvis = 0.0;   ///< E_pelvis, ours (torso_posture.hpp on the pelvis); 0: as published
};

struct wang2009_objective_options {
  std::optional<double> target_speed;        ///< m/s (E_user; E_vel's footnote 2; E_ang's V)
  std::optional<double> target_step_length;  ///< m (E_user)
  double fail_height = 0.7;    ///< m, COM height of E_fail (0.4 for the "long arm" character)
  double ground_height = 0.0;  ///< m, the ground's z for E_fail
  std::optional<bool> cost_of_transport;  ///< E_power / v_x; unset: when no target speed
  bool read_controller_phase = true;      ///< false: E_land ignores the phase (not Wang's FSM)
  std::optional<double> height;           ///< m, E_ang's H; unset: the standing COM height
  wang2009_weights weights;
};

using wang2009_objective_type =
    weighted_sum<wang2009::user_gait, wang2009::velocity, wang2009::landing, wang2009::failure,
                 wang2009::symmetry, wang2009::angular_momentum, wang2009::head, wang2009::power,
                 wang2009::power_ratio, wang2009::torso_posture, wang2009::torso_posture>;

/// Part indices of wang2009_objective_type (obj.part<wang2009_term::ratio>()).
struct wang2009_term {
  static constexpr std::size_t user = 0, vel = 1, land = 2, fail = 3, sym = 4, ang = 5, head = 6,
                               power = 7, ratio = 8, posture = 9, pelvis = 10, count = 11;
};
inline constexpr std::array<std::string_view, wang2009_term::count> wang2009_term_names{
    "E_user", "E_vel",   "E_land",  "E_fail",    "E_sym",   "E_ang",
    "E_head", "E_power", "E_ratio", "E_posture", "E_pelvis"};

/// eq. 16 for model m (the Wang 2009 humanoid or any model with its foot bodies, head and leg
/// DOF names). \throws std::invalid_argument naming a bad option, weight or missing name.
template <root_joint Root>
wang2009_objective_type wang2009_objective(const model<Root>& m,
                                           const wang2009_objective_options& o = {}) {
  const wang2009_weights& w = o.weights;
  const double mass = m.total_mass();
  check_positive(mass, "wang2009_objective: model total mass (kg)");
  const std::array<double, wang2009_term::count> weights{
      w.user,  w.vel,     w.land,  w.fail,
      w.sym,   w.ang,     w.head,  w.power.value_or(1e-5 * 70.0 / mass),
      w.ratio, w.posture, w.pelvis};
  for (std::size_t i = 0; i < weights.size(); ++i)
    check_argument(std::isfinite(weights[i]) && weights[i] >= 0.0, "wang2009_objective: weight w_",
                   wang2009_term_names[i].substr(2), " must be finite and >= 0, got ", weights[i]);
  return wang2009_objective_type(
      weights,
      wang2009::user_gait(
          m, {.target_speed = o.target_speed, .target_step_length = o.target_step_length}),
      wang2009::velocity({.target_speed = o.target_speed}),
      wang2009::landing(m, {.read_phase = o.read_controller_phase}),
      wang2009::failure({.fail_height = o.fail_height, .ground_height = o.ground_height}),
      wang2009::symmetry{},
      wang2009::angular_momentum(m, {.speed = o.target_speed, .height = o.height}),
      wang2009::head(m),
      wang2009::power({.cost_of_transport = o.cost_of_transport.value_or(!o.target_speed)}),
      wang2009::power_ratio(m), wang2009::torso_posture(m),
      wang2009::torso_posture(m, {.body = "pelvis", .term = "E_pelvis"}));
}

/// One row of the report: a term's value, its weight and their product.
struct wang2009_report_row {
  std::string_view name;
  double raw = 0.0;
  double weight = 0.0;
  double weighted = 0.0;
};

/// What wang2009_report returns.
struct wang2009_breakdown {
  std::array<wang2009_report_row, wang2009_term::count> terms{};
  double total = 0.0;                   ///< E of eq. 16 (the rollout's cost)
  std::array<double, 3> power_ratio{};  ///< r of eq. 13: hip, knee, ankle
  double average_speed = 0.0;           ///< v_x, m/s
  double step_length = 0.0;             ///< mean step length, m (0: none completed)
  int steps = 0;                        ///< completed steps
  double e_power = 0.0;                 ///< E_power of eq. 12, (N m)^2 (before cost of transport)
  bool cost_of_transport = false;       ///< the E_power row is E_power / v_x
  stop_reason reason = stop_reason::horizon;
  double time = 0.0;      ///< simulated, s
  double duration = 0.0;  ///< horizon, s
};

/// The report of a finished rollout from its accumulator (rollout_policy_states::objective) and
/// outcome. total equals the objective's finish().
inline wang2009_breakdown wang2009_report(const wang2009_objective_type& obj,
                                          const wang2009_objective_type::accumulator_type& acc,
                                          const rollout_outcome& out) {
  wang2009_breakdown b;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((b.terms[I] = {wang2009_term_names[I], obj.part<I>().finish(std::get<I>(acc), out),
                    obj.weights()[I], 0.0}),
     ...);
  }
  (std::make_index_sequence<wang2009_term::count>{});
  for (auto& row : b.terms) row.weighted = row.weight != 0.0 ? row.weight * row.raw : 0.0;
  b.total = obj.finish(acc, out);
  b.power_ratio = wang2009::power_ratio::ratio(std::get<wang2009_term::ratio>(acc));
  b.average_speed = wang2009::average_com_velocity(out).x();
  b.step_length = wang2009::user_gait::step_length(std::get<wang2009_term::user>(acc));
  b.steps = wang2009::user_gait::step_count(std::get<wang2009_term::user>(acc));
  b.e_power = wang2009::power::mean_squared_torque(std::get<wang2009_term::power>(acc));
  b.cost_of_transport = obj.part<wang2009_term::power>().opts().cost_of_transport;
  b.reason = out.reason;
  b.time = out.time;
  b.duration = out.duration;
  return b;
}

/// The outcome rollout() gave finish(), rebuilt from its rollout_result and rollout_options (the
/// horizon is ceil(duration / dt) steps, as the rollout counts it). Templates, so that objectives/
/// includes no more of rollout/ than concept.hpp does.
template <class Result, class Options>
rollout_outcome wang2009_outcome(const Result& r, const Options& opt) {
  check_positive(opt.dt, "wang2009_outcome: rollout_options::dt (s)");
  rollout_outcome out;
  out.reason = r.reason;
  out.time = r.time;
  out.duration = std::ceil(opt.duration / opt.dt - 1e-9) * opt.dt;
  out.steps = r.steps;
  out.com_initial = r.com_initial;
  out.com_final = r.com_final;
  return out;
}

/// The report of a rollout: its rollout_result r, run with rollout_options opt.
template <class Result, class Options>
wang2009_breakdown wang2009_report(const wang2009_objective_type& obj,
                                   const wang2009_objective_type::accumulator_type& acc,
                                   const Result& r, const Options& opt) {
  return wang2009_report(obj, acc, wang2009_outcome(r, opt));
}

/// Prints the report as a table: one row per term (raw value, weight, weighted value), the total,
/// then the gait measures.
inline void print_wang2009_report(std::ostream& os, const wang2009_breakdown& b) {
  const std::ios_base::fmtflags flags = os.flags();
  const std::streamsize precision = os.precision();
  os << std::left << std::setw(10) << "term" << std::right << std::setw(16) << "raw"
     << std::setw(14) << "weight" << std::setw(16) << "weighted" << '\n';
  os << std::scientific << std::setprecision(5);
  for (const wang2009_report_row& row : b.terms) {
    std::string_view name = row.name;
    if (name == "E_power" && b.cost_of_transport) name = "E_pow/v_x";
    os << std::left << std::setw(10) << name << std::right << std::setw(16) << row.raw
       << std::setw(14) << std::setprecision(4) << row.weight << std::setw(16)
       << std::setprecision(5) << row.weighted << '\n';
  }
  os << std::left << std::setw(10) << "E (16)" << std::right << std::setw(46) << b.total << '\n';
  os << std::defaultfloat << std::setprecision(4);
  os << "stopped: " << to_string(b.reason) << " after " << b.time << " s of " << b.duration
     << " s\n";
  os << "v_x " << b.average_speed << " m/s, step length " << b.step_length << " m (" << b.steps
     << " steps), E_power " << b.e_power << " (N m)^2, power ratio [" << b.power_ratio[0] << ", "
     << b.power_ratio[1] << ", " << b.power_ratio[2] << "] (hip, knee, ankle)\n";
  os.flags(flags);
  os.precision(precision);
}

}  // namespace gaitsynth
