#pragma once
/// \file controllers/fsm/wang2009_shape_transfer.hpp
/// A wang2009_controller parameter vector carried from one body shape to another, by the rule
/// Wang et al. 2009 use to carry Table 2 from "stocky" to the other shapes (Sec. 4.3): kp and kd
/// scaled by the ratio of the bodies' weights. The start state's root height is set so that the
/// lowest sole or toe point keeps its height above the ground (a longer leg starts higher); every
/// other parameter (targets, balance gains, c_trans, angles, rates) is kept. Carrying Table 2 for
/// stocky gives Table 2 for the other shape (tests/controllers/wang2009_shape_transfer.cpp).
#include <span>
#include <vector>

#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/wang2009_controller.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

namespace detail {
/// Height of the lowest sole or toe point in the start state of parameters p.
inline double wang2009_start_clearance(const floating_model& m, const wang2009_controller& c,
                                       std::span<const double> p) {
  wang2009_controller bound = c;
  bound.bind(p);
  sim_state s = make_state(m);
  bound.initial_state(m, s);
  return lowest_foot_point(m, s.q);
}
}  // namespace detail

/// Parameters p of controller `from_c` on body `from`, carried to controller `to_c` on body `to`.
/// Throws std::invalid_argument if p does not fit from_c (bind's checks, naming the parameter).
inline std::vector<double> wang2009_transfer_parameters(const floating_model& from,
                                                        const wang2009_controller& from_c,
                                                        std::span<const double> p,
                                                        const floating_model& to,
                                                        const wang2009_controller& to_c) {
  const double clearance = detail::wang2009_start_clearance(from, from_c, p);
  const wang2009_parameter_layout& L = to_c.layout();
  check_size(static_cast<std::ptrdiff_t>(p.size()), L.size(), "wang2009 parameter vector");
  std::vector<double> out(p.begin(), p.end());
  const double w = to.total_mass() / from.total_mass();
  for (int s = 0; s < 2; ++s)
    for (int role = 0; role < to.num_joint_dofs(); ++role) {
      out[static_cast<std::size_t>(L.kp(s, role))] *= w;
      out[static_cast<std::size_t>(L.kd(s, role))] *= w;
    }
  // Shift the start height by the change of clearance: on the same body the shift is exactly 0,
  // so a walker carried to its own shape keeps every bit (a replay retraces the optimized walk).
  const auto z = static_cast<std::size_t>(L.root_start(0));
  out[z] += clearance - detail::wang2009_start_clearance(to, to_c, out);
  return out;
}

}  // namespace gaitsynth
