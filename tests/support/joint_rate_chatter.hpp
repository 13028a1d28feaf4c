#pragma once
/// \file joint_rate_chatter.hpp
/// A numerical oscillation of the joint rates, step by step: a light link (a foot rolling back and
/// forth every physics step, docs/reproductions/wu2010.md) shows it; smooth motion and impacts do
/// not. Two measures, fed one state per physics step:
///   - the largest second difference |v_k - 2 v_k-1 + v_k-2| of a joint rate (rad/s): small when
///     the motion is smooth, large at an impact as well as in a chatter;
///   - the longest run of consecutive steps in which a joint rate's change v_k - v_k-1 reverses
///     its sign and exceeds `threshold` (1 rad/s): an impact makes a run of a step or two, an
///     explicit step on an over-damped light mode a run as long as the mode lives.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace gaitsynth::testing {

struct joint_rate_chatter {
  double threshold = 1.0;  ///< rad/s
  double largest_second_difference = 0.0;
  int longest_alternation = 0;  ///< steps
  int longest_dof = -1;         ///< joint DOF index of the longest run
  double longest_time = 0.0;    ///< s, when it ended
  Eigen::VectorXd v1, v2, change, run;
  std::int64_t steps = 0;

  /// The joint rates at time t (one call per physics step).
  void add(double t, const Eigen::Ref<const Eigen::VectorXd>& v) {
    if (steps == 0) {
      change = Eigen::VectorXd::Zero(v.size());
      run = Eigen::VectorXd::Zero(v.size());
    }
    if (steps >= 2)
      largest_second_difference =
          std::max(largest_second_difference, (v - 2.0 * v1 + v2).cwiseAbs().maxCoeff());
    if (steps >= 1)
      for (Eigen::Index j = 0; j < v.size(); ++j) {
        const double d = v[j] - v1[j];
        run[j] = std::abs(d) > threshold && d * change[j] < 0.0 ? run[j] + 1.0 : 0.0;
        change[j] = d;
        if (run[j] > longest_alternation) {
          longest_alternation = static_cast<int>(run[j]);
          longest_dof = static_cast<int>(j);
          longest_time = t;
        }
      }
    v2 = v1;
    v1 = v;
    ++steps;
  }
};

}  // namespace gaitsynth::testing
