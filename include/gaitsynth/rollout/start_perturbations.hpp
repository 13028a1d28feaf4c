#pragma once
/// \file start_perturbations.hpp
/// Seeded perturbations of a start state's joint velocities, for rollout_options::
/// initial_velocity_offset: the claim tests' "joint velocities perturbed by N(0, 0.05 rad/s)" and
/// the perturbed starts of a robust optimization (each candidate judged from the same starts, so
/// the cost stays a deterministic function of the parameters, whatever the thread count).
///
/// Offset k is drawn from its own engine, seeded (seed, k), so offset k does not depend on how
/// many offsets are drawn. The root's velocities are left alone.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gaitsynth/detail/standard_normal.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"

namespace gaitsynth {

/// `count` velocity offsets of size nv: zero on the root, N(0, sigma^2) (rad/s or m/s) on every
/// joint DOF.
template <root_joint Root>
std::vector<Eigen::VectorXd> joint_velocity_perturbations(const model<Root>& m, int count,
                                                          double sigma, std::uint64_t seed) {
  check_argument(count >= 0, "joint_velocity_perturbations: count must be >= 0, got ", count);
  check_argument(std::isfinite(sigma) && sigma >= 0.0,
                 "joint_velocity_perturbations: sigma must be finite and >= 0, got ", sigma);
  std::vector<Eigen::VectorXd> out;
  out.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(k)};
    std::mt19937_64 rng(seq);
    Eigen::VectorXd v = Eigen::VectorXd::Zero(m.nv());
    detail::fill_standard_normal(rng, v.tail(m.num_joint_dofs()));
    v.tail(m.num_joint_dofs()) *= sigma;
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace gaitsynth
