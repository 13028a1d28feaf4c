#pragma once
/// \file root.hpp
/// Root (base) joint policies of a kinematic tree. The root is a compile-time policy so that the
/// dynamics algorithms specialize for planar and floating bases without runtime branching.
///
/// Conventions (docs/dynamics.md): world z is up, gravity is -z, the planar biped walks along +x in
/// the x-z plane and pitches about +y.
///
/// * planar_root:   q_root = [x, z, pitch],  v_root = [xdot, zdot, pitchdot]      (nq = nv = 3).
///   Same as MuJoCo's slide-x, slide-z, hinge-y chain.
/// * floating_root: q_root = [px, py, pz, qw, qx, qy, qz] (unit quaternion, Hamilton, w first),
///   v_root = [vx, vy, vz (world frame, of the root frame origin), wx, wy, wz (root body frame)]
///   (nq = 7, nv = 6). This is MuJoCo's free-joint convention, so the oracle tests compare
///   joint-space quantities without a change of variables.
/// * fixed_root:    no DOF (nq = nv = 0); the root body is welded to the world (used in tests).
#include <array>
#include <string_view>

namespace gaitsynth {

struct planar_root {
  static constexpr int nq = 3;
  static constexpr int nv = 3;
  static constexpr std::array<std::string_view, 3> dof_names{"root_x", "root_z", "root_pitch"};
  static constexpr std::string_view name = "planar";
};

struct floating_root {
  static constexpr int nq = 7;
  static constexpr int nv = 6;
  static constexpr std::array<std::string_view, 6> dof_names{"root_x",  "root_y",  "root_z",
                                                             "root_wx", "root_wy", "root_wz"};
  static constexpr std::string_view name = "floating";
};

struct fixed_root {
  static constexpr int nq = 0;
  static constexpr int nv = 0;
  static constexpr std::array<std::string_view, 0> dof_names{};
  static constexpr std::string_view name = "fixed";
};

template <class R>
concept root_joint = requires {
  { R::nq } -> std::convertible_to<int>;
  { R::nv } -> std::convertible_to<int>;
  R::dof_names;
};

}  // namespace gaitsynth
