#pragma once
/// \file actuators/musculotendon/path.hpp
/// How an MTU spans a joint DOF: its moment arm and its share of the MTU length (Wang et al. 2012
/// Sec. 3.1; Geyer & Herr 2010 Table II). Angles phi are Geyer & Herr's joint angles (rad): hip
/// and knee 180 deg when straight, ankle 90 deg when the foot is square to the shank, each growing
/// with extension (plantarflexion at the ankle). A crossing maps the model's DOF q to phi by
/// phi = angle_offset + angle_scale q, so one table serves any model's sign conventions.
///
///   moment arm  r(phi) = r0 cos(phi - phi_max)   (knee, ankle: variable arm)
///               r(phi) = r0                      (hip: constant arm; phi_max NaN)
///   length      dl = -s rho r0 [sin(phi - phi_max) - sin(phi_ref - phi_max)]   (variable arm)
///               dl = -s rho r0 (phi - phi_ref)                                 (constant arm)
///   torque      tau_q = s angle_scale r(phi) F_MTU
///
/// s = +1 for an MTU that extends the joint, -1 for one that flexes it: an extensor shortens as
/// the joint extends (dl/dphi = -s rho r). rho (< 1) is Geyer & Herr's factor for pennation and
/// the compliance of the attachment: without it (rho = 1) the torque would be exactly the virtual
/// work -F dl/dq. l_MTU = l_opt + l_slack + sum of the crossings' dl, so that at phi = phi_ref
/// on every crossing the MTU's length is l_opt + l_slack.
#include <cmath>

namespace gaitsynth::musculotendon {

struct joint_crossing {
  int dof = -1;                   ///< joint DOF index (model::dofs order)
  double action = 1.0;            ///< s: +1 extends the joint (Geyer's phi grows), -1 flexes it
  double moment_arm = 0.05;       ///< r0, m: the largest arm (variable) or the arm (constant)
  double angle_of_max_arm = NAN;  ///< phi_max, rad; NaN for a constant arm
  double reference_angle = 0.0;   ///< phi_ref, rad
  double length_factor = 0.7;     ///< rho
  double angle_offset = 0.0;      ///< phi = angle_offset + angle_scale q
  double angle_scale = 1.0;       ///< +1 or -1

  bool constant_arm() const { return std::isnan(angle_of_max_arm); }
  double angle(double q) const { return angle_offset + angle_scale * q; }

  /// sin(phi_ref - phi_max), the constant of a variable arm's length (0 for a constant arm): an
  /// actuator computes it once (unit::reference_sines) instead of every step.
  double reference_sine() const {
    return constant_arm() ? 0.0 : std::sin(reference_angle - angle_of_max_arm);
  }

  /// r(phi) at DOF angle q (m).
  double arm(double q) const {
    return constant_arm() ? moment_arm : moment_arm * std::cos(angle(q) - angle_of_max_arm);
  }
  /// This crossing's share of the MTU length at DOF angle q (m; 0 at phi_ref).
  double length_change(double q) const { return length_change(q, reference_sine()); }
  /// The same with reference_sine() given.
  double length_change(double q, double reference_sine) const {
    const double phi = angle(q);
    if (constant_arm()) return -action * length_factor * moment_arm * (phi - reference_angle);
    return -action * length_factor * moment_arm *
           (std::sin(phi - angle_of_max_arm) - reference_sine);
  }
  /// The torque on DOF q of MTU force F (N m, in the model's sign of q).
  double torque(double q, double force) const { return torque_with_arm(arm(q), force); }
  /// The same with the arm r(phi) given.
  double torque_with_arm(double arm, double force) const {
    return action * angle_scale * arm * force;
  }
};

}  // namespace gaitsynth::musculotendon
