#pragma once
/// \file synthesis/wang2009_search_space.hpp
/// The search space of Wang, Fleet & Hertzmann 2009 (Sec. 4.3): the 184 parameters of
/// wang2009_controller with bounds, so that CMA-ES works on parameters "scaled to lie roughly
/// between 0 and 1" (parameter_space maps each bound pair onto [0, 1]) with sigma = 0.0025.
///
/// The paper gives no bounds; ours (docs/reproductions/wang2009.md) are wide enough to hold every
/// Table 2 value with room to move, so that sigma = 0.0025 is a step of about 0.1-0.4 % of each
/// range: gains [0, 2000 w] (kp) and [0, 200 w] (kd), w the weight relative to 70 kg (Table 2's
/// largest kp is 1000); targets and start angles [-2.5, 2.5] rad; balance gains [-1, 1];
/// alpha_arm [-3, 3]; c_trans [-0.3, 0.3] m; start root height +-0.15 m about Table 2's, pitch
/// [-0.5, 0.5] rad, forward speed [0, 3] m/s, vertical speed [-1, 1] m/s, pitch rate [-5, 5]
/// rad/s; joint rates [-20, 20] rad/s (Table 2 starts the swing ankle at -15 rad/s).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/optimizers/parameter_space.hpp"

namespace gaitsynth {

/// The parameter space of controller c on model m, with `initial` (e.g. Table 2's parameters or a
/// saved controller) as the initial values. \throws std::invalid_argument naming a parameter
/// whose initial value lies outside its bounds.
inline parameter_space wang2009_search_space(const floating_model& m, const wang2009_controller& c,
                                             const std::vector<double>& initial) {
  const wang2009_parameter_layout& L = c.layout();
  check_size(static_cast<std::ptrdiff_t>(initial.size()), L.size(),
             "wang2009_search_space: initial parameters");
  const std::vector<std::string> names = c.parameter_names();
  const double w = m.total_mass() / 70.0;
  std::vector<double> lo(names.size(), -2.5), hi(names.size(), 2.5);
  auto range = [&](int i, double a, double b) {
    lo[static_cast<std::size_t>(i)] = a;
    hi[static_cast<std::size_t>(i)] = b;
  };
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < L.nj; ++r) {
      range(L.kp(s, r), 0.0, 2000.0 * w);
      range(L.kd(s, r), 0.0, 200.0 * w);
    }
  for (int k = 0; k < L.num_balance; ++k) range(L.balance(k), -1.0, 1.0);
  range(L.alpha_arm(), -3.0, 3.0);
  range(L.c_trans(), -0.3, 0.3);
  const double z0 = initial[static_cast<std::size_t>(L.root_start(0))];
  range(L.root_start(0), z0 - 0.15, z0 + 0.15);
  range(L.root_start(1), -0.5, 0.5);
  range(L.root_start(2), 0.0, 3.0);
  range(L.root_start(3), -1.0, 1.0);
  range(L.root_start(4), -5.0, 5.0);
  for (int k = 0; k < static_cast<int>(L.start_dofs.size()); ++k) range(L.start_rate(k), -20, 20);
  parameter_space space;
  for (std::size_t i = 0; i < names.size(); ++i)
    space.add({.name = names[i], .lower = lo[i], .upper = hi[i], .initial = initial[i]});
  return space;
}

}  // namespace gaitsynth
