#pragma once
/// \file controllers/reflex/start_state_parameters.hpp
/// The 33 start-state parameters of Wang et al. 2012 Sec. 5 ("33 free parameters describing the
/// initial state of the simulation"). Which 33 the paper frees is in its supplement, which we do
/// not have; ours: the root's height, pitch, roll, its forward, sideways and vertical velocity and
/// pitch rate (7), then the angles and rates of the 13 DOFs that shape a step: hip_y, knee,
/// ankle_y and toe of each leg, back_y, hip_x and ankle_x of each leg (26). Every other
/// coordinate starts at 0.
///
/// Initial values: Geyer & Herr 2010's initial conditions (Sec. II-C of their paper: 1.3 m/s
/// forward; stance leg ankle 85, knee 175, hip 175 degrees; swing leg ankle 90, knee 175, hip
/// 140 degrees, their angles: 180 straight, growing with extension), the right leg standing and the
/// left swinging, every rate 0, and the height that puts the lowest sole or toe point on z = 0.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <string_view>

#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth::reflex {

struct start_state_layout {
  static constexpr int num_root = 7;  ///< z, pitch, roll, vx, vy, vz, wy
  static constexpr int root_vx = 3;   ///< the start's forward velocity, m/s
  static constexpr std::array<std::string_view, num_root> root_names{
      "root_z", "root_pitch", "root_roll", "root_vx", "root_vy", "root_vz", "root_wy"};
  static constexpr std::array<std::string_view, 13> dofs{
      "lhip_y", "lknee",  "lankle_y", "ltoe",   "rhip_y",   "rknee",   "rankle_y",
      "rtoe",   "back_y", "lhip_x",   "rhip_x", "lankle_x", "rankle_x"};
  static constexpr int num_dofs = static_cast<int>(dofs.size());
  static constexpr int size = num_root + 2 * num_dofs;
  static constexpr int angle(int k) { return num_root + k; }
  static constexpr int rate(int k) { return num_root + num_dofs + k; }
};
static_assert(start_state_layout::size == 33);

using start_state_vector = std::array<double, start_state_layout::size>;

/// "start.root_z", ..., "start.q.lhip_y", ..., "start.v.rankle_x".
inline std::string start_state_parameter_name(int i) {
  using L = start_state_layout;
  if (i < L::num_root) return "start." + std::string(L::root_names[static_cast<std::size_t>(i)]);
  const bool rate = i >= L::num_root + L::num_dofs;
  const int k = i - L::num_root - (rate ? L::num_dofs : 0);
  return std::string(rate ? "start.v." : "start.q.") +
         std::string(L::dofs[static_cast<std::size_t>(k)]);
}

/// The model's DOF index of each start DOF (throws naming a DOF the model lacks).
template <root_joint Root>
std::array<int, start_state_layout::num_dofs> start_state_dofs(const model<Root>& m) {
  std::array<int, start_state_layout::num_dofs> out{};
  for (int k = 0; k < start_state_layout::num_dofs; ++k)
    out[static_cast<std::size_t>(k)] =
        m.dof_index(std::string(start_state_layout::dofs[static_cast<std::size_t>(k)]));
  return out;
}

/// Writes the start state of p into s (sizes of m; no allocation when s already has them).
inline void write_start_state(const floating_model& m, const start_state_vector& p,
                              const std::array<int, start_state_layout::num_dofs>& dofs,
                              sim_state& s) {
  using L = start_state_layout;
  s.q.resize(m.nq());
  s.v.resize(m.nv());
  s.q.setZero();
  s.v.setZero();
  s.t = 0.0;
  const double pitch = p[1], roll = p[2];
  const Eigen::Quaterniond r = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
  s.q[2] = p[0];
  s.q[3] = r.w(), s.q[4] = r.x(), s.q[5] = r.y(), s.q[6] = r.z();
  s.v[0] = p[3], s.v[1] = p[4], s.v[2] = p[5];  // world frame
  s.v[4] = p[6];                                // root frame (its y is the pitch axis)
  for (int k = 0; k < L::num_dofs; ++k) {
    const auto j = static_cast<std::size_t>(k);
    s.q[floating_root::nq + dofs[j]] = p[static_cast<std::size_t>(L::angle(k))];
    s.v[floating_root::nv + dofs[j]] = p[static_cast<std::size_t>(L::rate(k))];
  }
}

/// Geyer & Herr's initial conditions on m (file comment).
inline start_state_vector start_state_initial_parameters(const floating_model& m) {
  using L = start_state_layout;
  constexpr double deg = 3.14159265358979323846 / 180.0;
  start_state_vector p{};
  auto set = [&](std::string_view dof, double q) {
    for (int k = 0; k < L::num_dofs; ++k)
      if (L::dofs[static_cast<std::size_t>(k)] == dof) p[static_cast<std::size_t>(L::angle(k))] = q;
  };
  // Their angles to ours: hip_y = phi - 180 deg, knee = 180 deg - phi, ankle_y = phi - 90 deg.
  set("rhip_y", (175.0 - 180.0) * deg);
  set("rknee", (180.0 - 175.0) * deg);
  set("rankle_y", (85.0 - 90.0) * deg);
  set("lhip_y", (140.0 - 180.0) * deg);
  set("lknee", (180.0 - 175.0) * deg);
  set("lankle_y", (90.0 - 90.0) * deg);
  p[L::root_vx] = 1.3;
  sim_state s;
  write_start_state(m, p, start_state_dofs(m), s);
  p[0] = -lowest_foot_point(m, s.q);
  return p;
}

/// Copies a bound start state, refusing a wrong size or a value that is not finite.
inline start_state_vector start_state_parameters_from(std::span<const double> p) {
  check_argument(p.size() == start_state_layout::size, "start-state parameters: expected ",
                 start_state_layout::size, " values, got ", p.size());
  start_state_vector out{};
  for (std::size_t i = 0; i < out.size(); ++i) {
    check_argument(std::isfinite(p[i]), "start-state parameter ",
                   start_state_parameter_name(static_cast<int>(i)), " is not finite (", p[i], ")");
    out[i] = p[i];
  }
  return out;
}

}  // namespace gaitsynth::reflex
