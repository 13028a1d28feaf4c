#pragma once
/// \file objectives/wu2010/energy.hpp
/// The energetic cost of Wu & Popovic 2010, Sec. 8.1 (eq. 6's third term):
///     E_tau = sum_j ||tau_theta||^2_{W_tau},   W_tau = 8e-2 W_pref,
/// W_pref = diag(1 / tau_max,i^2) from the model's joint torque limits (Sec. 8.3: "to encourage
/// use of stronger muscles"); a DOF without a finite limit is not charged. tau_theta is the
/// actuator's joint torques (step_view::joint_torques(); not the passive limit springs). A sum over
/// eq. 6's timesteps: each physics step counts dt / timestep (common.hpp; 1/64 s, the paper's), 1
/// with timestep = 0. Reads no controller report: any controller.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include "gaitsynth/error.hpp"
#include "gaitsynth/objectives/concept.hpp"
#include "gaitsynth/objectives/wu2010/common.hpp"

namespace gaitsynth::wu2010 {

struct energy_options {
  double scale = 8e-2;               ///< W_tau = scale W_pref (>= 0)
  double timestep = paper_timestep;  ///< s, eq. 6's j (common.hpp); 0: per physics step
};

class energy {
 public:
  using options = energy_options;
  struct accumulator_type {
    Eigen::VectorXd weight;  ///< nj: W_tau's diagonal, 1/(N m)^2
    double sum = 0.0;        ///< E_tau so far
    double last = 0.0;       ///< this step's ||tau_theta||^2_{W_tau} (unweighted)
  };

  explicit energy(options o = {}) : opt_(o) {
    check_argument(std::isfinite(opt_.scale) && opt_.scale >= 0.0,
                   "wu2010::energy: scale must be finite and >= 0, got ", opt_.scale);
    check_timestep(opt_.timestep, "wu2010::energy");
  }
  const options& opts() const { return opt_; }

  template <root_joint Root>
  accumulator_type make_accumulator(const model<Root>& m) const {
    accumulator_type a;
    a.weight.setZero(m.num_joint_dofs());
    for (int j = 0; j < m.num_joint_dofs(); ++j) {
      const double t = m.dofs[j].torque_limit;
      a.weight[j] = std::isfinite(t) && t > 0.0 ? opt_.scale / (t * t) : 0.0;
    }
    return a;
  }
  template <root_joint Root>
  void reset_accumulator(const model<Root>& m, accumulator_type& a) const {
    if (a.weight.size() != m.num_joint_dofs()) a = make_accumulator(m);
    a.sum = a.last = 0.0;
  }
  template <class View>
  void accumulate(accumulator_type& a, const View& v) const {
    a.last = (a.weight.array() * v.joint_torques().array().square()).sum();
    a.sum += timestep_weight(v.dt, opt_.timestep) * a.last;
  }
  double finish(const accumulator_type& a, const rollout_outcome&) const { return a.sum; }

  static std::array<std::string_view, 2> term_names() { return {"E_tau", "tau_weighted"}; }
  void terms(const accumulator_type& a, std::span<double> out) const {
    out[0] = a.sum;
    out[1] = a.last;
  }

 private:
  options opt_;
};

}  // namespace gaitsynth::wu2010
