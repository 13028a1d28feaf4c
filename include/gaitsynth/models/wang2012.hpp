#pragma once
/// \file wang2012.hpp
/// The humanoid of Wang, Hamner, Delp & Koltun, "Optimizing Locomotion Controllers Using
/// Biologically-Based Actuators and Objectives", ACM TOG 31(4), 2012 (Section 3): "30 joint DOFs
/// and mass distributions approximating a 180 cm, 70 kg male", cylinders approximating the heel and
/// the ball of the foot, and the soft joint limits of Geyer & Herr 2010 on the sagittal hip, knee
/// and ankle DOFs.
///
/// The paper takes its model from Wang et al. 2010 (the same 30-DOF SIMBICON-with-toes character as
/// Wang et al. 2009) and adjusts its lower-body joint locations and mass distribution to Hamner et
/// al. 2010 without printing numbers; we build it like wang2009_humanoid (de Leva 1996, see
/// docs/models.md) at 1.80 m and 70 kg, with the same DOF names and order (wang2009.hpp), and
/// replace the foot's 4 box corners with heel and ball cylinders sampled by contact points (and
/// the same 43 body points of role other, so that a fall lies on the ground).
///
/// Geyer & Herr soft limits (0.3 N m/deg = 17.19 N m/rad past the bound): ankle between 20 deg of
/// dorsiflexion and 40 deg of plantarflexion (their 70..130 deg shank-foot angle), knee
/// hyperextension beyond 5 deg of flexion (175 deg), hip extension beyond 50 deg (230 deg). Their
/// velocity factor (1 - dphi/omega_max) is not a linear damper; we use 1 N m s/rad
/// (docs/models.md).
#include "gaitsynth/models/detail/humanoid30.hpp"

namespace gaitsynth {

/// Passive settings of the paper's controller that belong with the character (Section 4.3-4.4):
/// the toe joint is a spring (30 N m/rad, target 0, no damping) and every arm joint a
/// spring-damper (30 N m/rad, 3 N m s/rad, target 0).
struct wang2012_passive {
  static constexpr double toe_stiffness = 30.0;  ///< N m / rad
  static constexpr double arm_stiffness = 30.0;  ///< N m / rad
  static constexpr double arm_damping = 3.0;     ///< N m s / rad
};

/// The Wang 2012 humanoid: 180 cm, 70 kg, 30 joint DOFs in wang2009_humanoid's order. Each foot has
/// 12 sole points (heel and ball cylinders, 3 points of the lower arc at each end), the toes 4
/// bottom corners (role toe) and 2 top points (role toe_top).
inline floating_model wang2012_humanoid() {
  detail::characters::humanoid30_spec sp;
  sp.name = "wang2012_humanoid";
  sp.height = 1.80;
  sp.mass = 70.0;
  sp.feet = detail::characters::foot_contact_style::cylinders;
  sp.geyer_herr_sagittal_limits = true;
  return detail::characters::build_humanoid30(sp);
}

}  // namespace gaitsynth
