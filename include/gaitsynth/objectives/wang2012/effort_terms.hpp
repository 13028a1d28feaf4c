#pragma once
/// \file objectives/wang2012/effort_terms.hpp
/// The other effort terms of Wang et al. 2012 (Sec. 5.1 and 6.2), each an objective of its own:
///
///   J_R       = 1/T sum_t sum_{j in Q_r} tau_{j,t}^2   actuator torques of the DOFs the muscles
///                                                      do not drive ((N m)^2)
///   J_L       = 1/T sum_t sum_{j in Q_s} tau^L_{j,t}^2 soft joint-limit torques of the muscle
///                                                      DOFs (the model's passive torques there)
///   min_torque: J_M = 1/T sum_t sum_{j in Q_s} tau_{j,t}^2   (the ablation of Sec. 6.2, w_M = 5)
///   min_act:    J_M = 1/T sum_t sum_m a_{m,t}^2               (the ablation of Sec. 6.2, w_M =
///   60000)
///
/// Q_s: the sagittal hip, knee and ankle DOFs (those the MTUs span: muscle_dofs); Q_r: every
/// other joint DOF. effort() composes w_e (w_M J_M + w_R J_R + w_L J_L) with the paper's weights.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gaitsynth/actuators/musculotendon/unit.hpp"
#include "gaitsynth/actuators/musculotendon_actuator.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wang2012/metabolic_energy.hpp"
#include "gaitsynth/objectives/weighted_sum.hpp"

namespace gaitsynth::wang2012 {

/// The joint DOFs the MTUs span (Q_s), sorted, each once.
inline std::vector<int> muscle_dofs(const std::vector<musculotendon::unit>& units) {
  std::vector<int> out;
  for (const auto& u : units)
    for (int c = 0; c < u.num_crossings; ++c) out.push_back(u.crossings[c].dof);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// 1/T sum_t sum_{j in dofs} tau_j^2 over actuator or passive (joint-limit) torques.
class mean_squared_joint_torque {
 public:
  enum class source { actuator, passive };
  struct accumulator_type {
    std::int64_t steps = 0;
    double sum = 0.0, last = 0.0;
  };

  /// dofs: joint DOF indices; complement: use every joint DOF not in dofs instead (checked
  /// against the model at make_accumulator); name: the recorded term's name.
  mean_squared_joint_torque(std::vector<int> dofs, bool complement, source from, std::string name)
      : dofs_(std::move(dofs)), complement_(complement), from_(from), name_(std::move(name)) {
    std::sort(dofs_.begin(), dofs_.end());
    for (int j : dofs_)
      check_argument(j >= 0, "wang2012::", name_, ": joint DOF index must be >= 0, got ", j);
  }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    for (int j : dofs_)
      check_argument(j < m.num_joint_dofs(), "wang2012::", name_, ": joint DOF ", j,
                     " is not in the model (", m.num_joint_dofs(), " joint DOFs)");
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    const Eigen::VectorXd& tau = from_ == source::actuator ? v.tau() : v.tau_passive();
    constexpr int nv0 = std::remove_cvref_t<decltype(v.model())>::root_type::nv;
    double s = 0.0;
    if (complement_) {  // every joint DOF not listed (a binary search in a handful of DOFs)
      const int nj = static_cast<int>(tau.size()) - nv0;
      for (int j = 0; j < nj; ++j)
        if (!std::binary_search(dofs_.begin(), dofs_.end(), j)) s += tau[nv0 + j] * tau[nv0 + j];
    } else {
      for (int j : dofs_) s += tau[nv0 + j] * tau[nv0 + j];
    }
    a.last = s;
    a.sum += s;
    ++a.steps;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    return a.steps > 0 ? a.sum / static_cast<double>(a.steps) : 0.0;
  }
  std::array<std::string_view, 1> term_names() const { return {name_}; }
  void terms(const accumulator_type& a, std::span<double> out) const { out[0] = finish(a, {}); }

 private:
  std::vector<int> dofs_;
  bool complement_;
  source from_;
  std::string name_;
};

/// J_R: squared actuator torques of the DOFs the muscles do not span.
inline mean_squared_joint_torque other_joint_torque(const std::vector<musculotendon::unit>& u) {
  return {muscle_dofs(u), true, mean_squared_joint_torque::source::actuator, "J_R"};
}
/// J_L: squared joint-limit torques of the DOFs the muscles span.
inline mean_squared_joint_torque joint_limit_torque(const std::vector<musculotendon::unit>& u) {
  return {muscle_dofs(u), false, mean_squared_joint_torque::source::passive, "J_L"};
}
/// min_torque's J_M: squared actuator torques of the DOFs the muscles span.
inline mean_squared_joint_torque sagittal_joint_torque(const std::vector<musculotendon::unit>& u) {
  return {muscle_dofs(u), false, mean_squared_joint_torque::source::actuator, "J_M_torque"};
}

/// min_act's J_M: 1/T sum_t sum_m a_{m,t}^2 (needs a musculotendon_state).
class mean_squared_activation {
 public:
  struct accumulator_type {
    std::int64_t steps = 0;
    double sum = 0.0;
  };
  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>&) const {
    return {};
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    const musculotendon_state& st = v.actuator_state();
    a.sum += st.activation.squaredNorm();
    ++a.steps;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const {
    return a.steps > 0 ? a.sum / static_cast<double>(a.steps) : 0.0;
  }
  static std::array<std::string_view, 1> term_names() { return {"J_M_activation"}; }
  void terms(const accumulator_type& a, std::span<double> out) const { out[0] = finish(a, {}); }
};

/// The weights of Sec. 5: w_e = 0.004 / body mass, w_M = 100, w_R = 1, w_L = 0.5.
struct effort_weights {
  double effort_per_kg = 0.004;  ///< w_e x body mass
  double metabolic = 100.0;      ///< w_M
  double other_torque = 1.0;     ///< w_R
  double limit_torque = 0.5;     ///< w_L
};

/// w_e J_effort = w_e (w_M J_M + w_R J_R + w_L J_L) for a body of mass body_mass (kg), with any
/// J_M (metabolic_energy, or an ablation: sagittal_joint_torque with w_M = 5,
/// mean_squared_activation with w_M = 60000).
template <class MetabolicTerm>
auto effort(double body_mass, const std::vector<musculotendon::unit>& units, MetabolicTerm j_m,
            const effort_weights& w = {}) {
  check_positive(body_mass, "wang2012::effort: body_mass (kg)");
  const double we = w.effort_per_kg / body_mass;
  return weighted_sum<MetabolicTerm, mean_squared_joint_torque, mean_squared_joint_torque>(
      {we * w.metabolic, we * w.other_torque, we * w.limit_torque}, std::move(j_m),
      other_joint_torque(units), joint_limit_torque(units));
}

}  // namespace gaitsynth::wang2012
