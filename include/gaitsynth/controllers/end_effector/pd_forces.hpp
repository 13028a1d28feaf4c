#pragma once
/// \file controllers/end_effector/pd_forces.hpp
/// The ideal PD controllers of Wu & Popovic 2010, Sec. 5, eqs. 1-3: the forces and torque each
/// frame would like to receive. "Ideal": they are never applied; the QP of Sec. 6.2
/// (force_qp.hpp) reproduces them as well as joint torques can. Their coefficients (Table 1's
/// names) are the lower-level parameters Pi with the QP's weight and appendix B's rho.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <span>

#include "gaitsynth/controllers/end_effector/frames.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Eq. 1 (LA and L frames): f = kp (p - p^) + bp (p' - p^') + cp z, cp the bias along world z
/// that spares the feedback terms from carrying gravity.
inline vec3 linear_pd_force(double kp, double bp, double cp, const vec3& p, const vec3& pdot,
                            const vec3& p_hat, const vec3& pdot_hat) {
  return kp * (p - p_hat) + bp * (pdot - pdot_hat) + vec3(0.0, 0.0, cp);
}

/// Eq. 2 (LA frames): tau = sum_j e^_j x [ko (e_j - e^_j) + bo (e_j' - e^_j')], e_j the columns of
/// the desired rotation R, e^_j the current R^, e' = omega x e. For a small rotation error phi
/// about a this is 2 ko phi a (and 2 bo times a rate error): the gains are per axis pair.
inline vec3 angular_pd_torque(double ko, double bo, const mat3& R, const vec3& omega,
                              const mat3& R_hat, const vec3& omega_hat) {
  vec3 tau = vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const vec3 e = R.col(j), e_hat = R_hat.col(j);
    tau += e_hat.cross(ko * (e - e_hat) + bo * (omega.cross(e) - omega_hat.cross(e_hat)));
  }
  return tau;
}

/// Eq. 3 (LR frames): f = kr (r - r^) + br (r' - r^'), r = p - p0 relative to the link's centre.
inline vec3 relative_pd_force(double kr, double br, const vec3& r, const vec3& rdot,
                              const vec3& r_hat, const vec3& rdot_hat) {
  return kr * (r - r_hat) + br * (rdot - rdot_hat);
}

/// The lower-level parameters Pi (Sec. 5, 6.2 and appendix B) with Table 1's names. Units: N/m,
/// N s/m, N; ko in N m (per unit axis error), bo in N m s; rho in N (N m of knee torque per m).
/// The defaults are ours (the paper optimizes them, Table 1 gives their bounds); they hold the
/// Table 3 biped standing (tests/controllers/end_effector_standing.cpp).
struct end_effector_gains {
  double ub_kp = 1500.0;           ///< upper body, eq. 1     Table 1: [0, 4000]
  double ub_bp = 300.0;            ///<                       [0, 800]
  double ub_cp = 730.0;            ///< ~ 74.6 kg x g: the weight above the feet [0, 140 x 9.8]
  double ub_ko = 1000.0;           ///< upper body, eq. 2     [0, 4000] (Table 1's k_a)
  double ub_bo = 60.0;             ///<                       [0, 80] (b_a)
  double ankle_kp = 1000.0;        ///< ankles, eq. 1      [0, 4000]
  double ankle_bp = 100.0;         ///<                    [0, 400]
  double ankle_cp = 9.8;           ///< the foot's weight  [0, 10 x 9.8]
  double toe_heel_kr = 1000.0;     ///< toes and heels, eq. 3  [0, 8000]
  double toe_heel_br = 20.0;       ///<                        [0, 100]
  double upper_body_weight = 1.0;  ///< W's entries on the upper body's rows (the feet's are 1)
  double rho = 300.0;              ///< appendix B, eq. 12's knee coefficient

  static constexpr std::size_t size = 12;
  std::array<double, size> to_array() const {
    return {ub_kp,
            ub_bp,
            ub_cp,
            ub_ko,
            ub_bo,
            ankle_kp,
            ankle_bp,
            ankle_cp,
            toe_heel_kr,
            toe_heel_br,
            upper_body_weight,
            rho};
  }
  static constexpr std::array<const char*, size> names{"ub_kp",
                                                       "ub_bp",
                                                       "ub_cp",
                                                       "ub_ko",
                                                       "ub_bo",
                                                       "ankle_kp",
                                                       "ankle_bp",
                                                       "ankle_cp",
                                                       "toe_heel_kr",
                                                       "toe_heel_br",
                                                       "upper_body_weight",
                                                       "rho"};
  /// From a parameter vector in to_array()'s order. Throws std::invalid_argument naming the
  /// parameter and its value when one is not finite or is negative (every coefficient is a gain,
  /// a bias or a weight that is >= 0; Table 1's bounds all start at 0).
  static end_effector_gains from(std::span<const double> p) {
    check_size(static_cast<std::ptrdiff_t>(p.size()), static_cast<std::ptrdiff_t>(size),
               "end_effector_gains (parameters)");
    for (std::size_t i = 0; i < size; ++i)
      check_argument(std::isfinite(p[i]) && p[i] >= 0.0, "end_effector_gains: ", names[i],
                     " (parameter ", i, ") must be finite and >= 0, got ", p[i]);
    return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9], p[10], p[11]};
  }
  void validate() const {
    const auto a = to_array();
    from(a);
  }
};

/// The ideal wrenches of every frame: b's blocks of eq. 4.
struct ideal_wrenches {
  vec3 reaction_force = vec3::Zero(), reaction_torque = vec3::Zero();
  std::vector<vec3> action_force;  ///< per action frame
};

/// Eqs. 1-3 for every frame: current state `s`, desired state `d`.
inline void compute_ideal_wrenches(const end_effector_layout& L, const end_effector_gains& g,
                                   const frame_states& s, const frame_states& d,
                                   ideal_wrenches& out) {
  out.reaction_force =
      linear_pd_force(g.ub_kp, g.ub_bp, g.ub_cp, d.reaction_position, d.reaction_velocity,
                      s.reaction_position, s.reaction_velocity);
  out.reaction_torque =
      angular_pd_torque(g.ub_ko, g.ub_bo, d.reaction_rotation, d.reaction_angular_velocity,
                        s.reaction_rotation, s.reaction_angular_velocity);
  out.action_force.resize(L.action.size());  // no-op after the first call
  for (int i = 0; i < L.num_action(); ++i) {
    if (L.action[i].type == frame_type::linear_relative)
      out.action_force[i] =
          relative_pd_force(g.toe_heel_kr, g.toe_heel_br, d.relative[i], d.relative_velocity[i],
                            s.relative[i], s.relative_velocity[i]);
    else
      out.action_force[i] = linear_pd_force(g.ankle_kp, g.ankle_bp, g.ankle_cp, d.position[i],
                                            d.velocity[i], s.position[i], s.velocity[i]);
  }
}

}  // namespace gaitsynth
