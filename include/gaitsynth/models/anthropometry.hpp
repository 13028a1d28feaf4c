#pragma once
/// \file anthropometry.hpp
/// Published body-segment parameters used by the built-in characters (docs/models.md), and the
/// inertia formulas of the simple solids the characters are made of.
///
/// Source of every number in `de_leva1996`:
///   P. de Leva, "Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters",
///   Journal of Biomechanics 29(9):1223-1230, 1996, Table 4 (male column; reference subject
///   stature 1741 mm, body mass 73.0 kg). Lengths are the distances between the two endpoint
///   landmarks (mm), masses are percent of body mass, the centre of mass is percent of the length
///   measured from the FIRST landmark listed, and the radii of gyration are percent of the length,
///   about the segment's sagittal, transverse and longitudinal axes through its centre of mass.
///   Where Table 4 gives an alternative landmark pair we use the one whose end points are the joint
///   centres of our kinematic chains (head VERT-CERV, upper trunk CERV-XYPH, shank KJC-AJC).
///
/// Axis convention (docs/models.md, "de Leva's axes"): a body frame has x forward
/// (anteroposterior), y to the left (mediolateral), z up. For upright segments r_sagittal is about
/// the anteroposterior axis (x), r_transverse about the mediolateral axis (y), r_longitudinal about
/// the long axis (z); this reading makes the trunk's moment about x (lateral bending, mass spread
/// over the wider mediolateral extent) the larger one, as the data say. The foot lies along x, so
/// its longitudinal radius is about x and its sagittal radius about the vertical axis z.
#include <Eigen/Core>
#include <string_view>

namespace gaitsynth::de_leva1996 {

/// One row of de Leva (1996) Table 4 (male).
struct segment {
  std::string_view name;
  std::string_view from, to;  ///< landmarks; com_percent is measured from `from`
  double length_mm;           ///< mean length of the reference subject, mm
  double mass_percent;        ///< percent of body mass
  double com_percent;         ///< centre of mass, percent of length from `from`
  double r_sagittal;          ///< radius of gyration, percent of length
  double r_transverse;        ///< radius of gyration, percent of length
  double r_longitudinal;      ///< radius of gyration, percent of length
};

inline constexpr double reference_stature = 1.741;  ///< m (Table 4, male)
inline constexpr double reference_mass = 73.0;      ///< kg (Table 4, male)

// clang-format off
// Landmarks: VERT vertex, CERV cervicale (C7), XYPH xiphion, OMPH omphalion, MIDH mid-point of the
// hip joint centres, SJC/EJC/WJC/HJC/KJC/AJC shoulder/elbow/wrist/hip/knee/ankle joint centres,
// MET3 third metacarpale, HEEL heel, TTIP tip of the longest toe.
inline constexpr segment head{"head", "VERT", "CERV", 242.9, 6.94, 50.02, 30.3, 31.5, 26.1};
inline constexpr segment upper_trunk{"upper_trunk", "CERV", "XYPH", 242.1, 15.96, 50.66, 50.5, 32.0, 46.5};
inline constexpr segment middle_trunk{"middle_trunk", "XYPH", "OMPH", 215.5, 16.33, 45.02, 48.2, 38.3, 46.8};
inline constexpr segment lower_trunk{"lower_trunk", "OMPH", "MIDH", 145.7, 11.17, 61.15, 61.5, 55.1, 58.7};
inline constexpr segment upper_arm{"upper_arm", "SJC", "EJC", 281.7, 2.71, 57.72, 28.5, 26.9, 15.8};
inline constexpr segment forearm{"forearm", "EJC", "WJC", 268.9, 1.62, 45.74, 27.6, 26.5, 12.1};
inline constexpr segment hand{"hand", "WJC", "MET3", 86.2, 0.61, 79.00, 62.8, 51.3, 40.1};
inline constexpr segment thigh{"thigh", "HJC", "KJC", 422.2, 14.16, 40.95, 32.9, 32.9, 14.9};
inline constexpr segment shank{"shank", "KJC", "AJC", 440.3, 4.33, 43.95, 25.1, 24.6, 10.2};
inline constexpr segment foot{"foot", "HEEL", "TTIP", 258.1, 1.37, 44.15, 25.7, 24.5, 12.4};
// clang-format on

/// Sum of the mass percentages of the 16 segments (paired ones twice): 100.00.
inline constexpr double mass_percent_sum =
    head.mass_percent + upper_trunk.mass_percent + middle_trunk.mass_percent +
    lower_trunk.mass_percent +
    2.0 * (upper_arm.mass_percent + forearm.mass_percent + hand.mass_percent + thigh.mass_percent +
           shank.mass_percent + foot.mass_percent);

/// Sum of the vertical chain vertex -> CERV -> XYPH -> OMPH -> MIDH -> KJC -> AJC, mm (1708.7).
inline constexpr double vertical_chain_mm = head.length_mm + upper_trunk.length_mm +
                                            middle_trunk.length_mm + lower_trunk.length_mm +
                                            thigh.length_mm + shank.length_mm;

/// Principal inertia about the COM (kg m^2) of an upright segment of mass `mass` (kg) and length
/// `length` (m) from the table's radii: diag(I_x, I_y, I_z) = m (r L)^2 with (sagittal, transverse,
/// longitudinal) on (x, y, z).
inline Eigen::Matrix3d upright_inertia(const segment& s, double mass, double length) {
  const auto sq = [&](double r_percent) {
    const double r = r_percent * 0.01 * length;
    return mass * r * r;
  };
  return Eigen::Vector3d(sq(s.r_sagittal), sq(s.r_transverse), sq(s.r_longitudinal)).asDiagonal();
}

/// The same for the foot, which lies along x: longitudinal about x, transverse about y, sagittal
/// about z.
inline Eigen::Matrix3d foot_inertia(double mass, double length) {
  const auto sq = [&](double r_percent) {
    const double r = r_percent * 0.01 * length;
    return mass * r * r;
  };
  return Eigen::Vector3d(sq(foot.r_longitudinal), sq(foot.r_transverse), sq(foot.r_sagittal))
      .asDiagonal();
}

}  // namespace gaitsynth::de_leva1996

namespace gaitsynth::solid {

/// Solid box of full side lengths (a, b, c) along (x, y, z), about its centre.
inline Eigen::Matrix3d box_inertia(double mass, const Eigen::Vector3d& size) {
  const Eigen::Vector3d s2 = size.cwiseProduct(size);
  return (mass / 12.0 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()))
      .asDiagonal();
}

/// Solid sphere of radius r about its centre.
inline Eigen::Matrix3d sphere_inertia(double mass, double r) {
  return Eigen::Matrix3d::Identity() * (0.4 * mass * r * r);
}

/// Inertia about point `p` (same axes) of a body with COM inertia `Ic` whose COM is at `c`
/// (parallel-axis theorem): Ic + m (|d|^2 I - d d^T), d = c - p.
inline Eigen::Matrix3d shift_inertia(const Eigen::Matrix3d& Ic, double mass,
                                     const Eigen::Vector3d& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = c - p;
  return Ic + mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

/// Mass, COM and COM inertia of two rigid parts welded together (all in one frame).
struct lumped {
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};
inline lumped combine(const lumped& a, const lumped& b) {
  lumped r;
  r.mass = a.mass + b.mass;
  r.com = (a.mass * a.com + b.mass * b.com) / r.mass;
  r.inertia = shift_inertia(a.inertia, a.mass, a.com, r.com) +
              shift_inertia(b.inertia, b.mass, b.com, r.com);
  return r;
}

}  // namespace gaitsynth::solid
