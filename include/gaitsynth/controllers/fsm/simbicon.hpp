#pragma once
/// \file controllers/fsm/simbicon.hpp
/// SIMBICON, Yin, Loken & van de Panne 2007, on the 30-DOF humanoid: the baseline of Wang et al.
/// 2009 (Table 1, Figs. 1 and 6). Four states with left/right mirrored parameters (numbered as in
/// Wang et al. Fig. 2: 0 and 1 the left leg swinging, 2 and 3 the right):
///   0 -> 1  after `duration` seconds (time-based, unlike Wang's COM-based transition);
///   1 -> 2  when the swing foot touches the ground (after it left it in this swing);
///   0 -> 2  on an early touch-down after `duration` / 2.
/// Per state: torso (pelvis) pitch, swing hip, swing knee, swing ankle, stance knee and stance
/// ankle targets, and the balance feedback theta_d = theta_d0 + c_d d + c_v v of the swing hip,
/// sagittal and coronal (d: the COM relative to the stance ankle, v: the COM velocity). The torso
/// and the swing thigh are servoed in the world; the stance hip applies -(torso) - (swing hip)
/// (Yin et al. Sec. 3.2); knees, ankles (local, as in SIMBICON: the feet stay flat) and the upper
/// body are local PD. As in wang2009_controller, world-frame servos act through their stiffness
/// and damp the joints' own rates, and gains are capped for stability at the timestep.
///
/// Signs are ours (docs/models.md): hip flexion and ankle dorsiflexion negative, knee flexion
/// positive; Yin et al.'s Table 1 walk (swing hip 0.5, knee -1.1, ankle 0.6, ...) is therefore
/// negated for hips, knees and ankles in simbicon_walk_parameters().
///
/// Parameters (22, named): per state s in {0, 1}: duration (s; state 0 only, state 1 ends at
/// contact, its entry is unused and kept for a regular layout), cd_sagittal, cv_sagittal,
/// cd_coronal, cv_coronal, torso (pelvis pitch, rad), swing_hip, swing_knee, swing_ankle,
/// stance_knee, stance_ankle.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

class simbicon_controller {
 public:
  static constexpr int per_state = 11;
  static constexpr std::array<const char*, per_state> field_names{
      "duration",  "cd_sagittal", "cv_sagittal", "cd_coronal",  "cv_coronal",  "torso",
      "swing_hip", "swing_knee",  "swing_ankle", "stance_knee", "stance_ankle"};
  enum field { duration, cd_sag, cv_sag, cd_cor, cv_cor, torso, swh, swk, swa, stk, sta };

  struct state_type {
    int phase = 0;
    double phase_start = 0.0;   ///< s
    bool swing_lifted = false;  ///< the swing foot left the ground in this swing
  };

  /// Gains (N m/rad, N m s/rad), set per DOF by simbicon_walk_gains(); capped at construction.
  Eigen::VectorXd kp, kd;

  /// \param dt the physics timestep the gains' caps are computed for (s).
  simbicon_controller(const floating_model& m, Eigen::VectorXd kp_, Eigen::VectorXd kd_,
                      double dt = 1.0 / 2400.0)
      : kp(std::move(kp_)), kd(std::move(kd_)), layout_(biped_layout::of(m)) {
    const int nj = m.num_joint_dofs();
    check_size(kp.size(), nj, "simbicon_controller kp (one gain per joint DOF)");
    check_size(kd.size(), nj, "simbicon_controller kd (one gain per joint DOF)");
    const pd_actuator capped = pd_actuator::capped(m, kp, kd, dt);
    kp = capped.kp;
    kd = capped.kd;
    mirror_dof_ = m.mirror_dof;
  }

  std::size_t num_parameters() const { return 2 * per_state; }
  std::vector<std::string> parameter_names() const {
    std::vector<std::string> n;
    for (const char* prefix : {"s0.", "s1."})
      for (const char* f : field_names) n.push_back(std::string(prefix) + f);
    return n;
  }
  std::vector<double> parameters() const { return {p_.begin(), p_.end()}; }
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "simbicon_controller parameters");
    std::copy(p.begin(), p.end(), p_.begin());
    check_argument(p_[duration] > 0.0, "simbicon_controller: s0.duration must be > 0 s, got ",
                   p_[duration]);
  }
  double period() const { return 0.0; }
  static constexpr command_kind output_kind() { return command_kind::mixed; }
  state_type make_state(const floating_model&) const { return {}; }
  void reset_state(const floating_model&, state_type& st) const { st = {}; }
  int discrete_state(const state_type& st) const { return st.phase; }

  template <class S>
  void command(const S& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    update_phase(s, st);
    mixed_command out(cmd);
    const int b = st.phase & 1, swing = st.phase >= 2 ? 1 : 0, stance = 1 - swing;
    const double* P = p_.data() + b * per_state;
    const int nj = static_cast<int>(kp.size());
    for (int j = 0; j < nj; ++j) out.set_target(j, 0.0, kp[j], kd[j]);  // upper body holds 0
    const biped_leg& sw = layout_.leg[swing];
    const biped_leg& stl = layout_.leg[stance];
    out.set_target(sw.knee, P[swk], kp[sw.knee], kd[sw.knee]);
    out.set_target(sw.ankle_y, P[swa], kp[sw.ankle_y], kd[sw.ankle_y]);
    out.set_target(stl.knee, P[stk], kp[stl.knee], kd[stl.knee]);
    out.set_target(stl.ankle_y, P[sta], kp[stl.ankle_y], kd[stl.ankle_y]);
    // Swing hip in the world, with balance feedback (Yin et al. eq. 1).
    const vec3 d = s.com - s.body_position[stl.foot];
    const vec3& v = s.com_velocity;
    world_servo_gains g_sw;
    g_sw.kp = {kp[sw.hip_x], kp[sw.hip_y], kp[sw.hip_z]};
    g_sw.target = {P[cd_cor] * d.y() + P[cv_cor] * v.y(),
                   P[swh] - (P[cd_sag] * d.x() + P[cv_sag] * v.x()), 0.0};
    const vec3 tau_swing = world_servo_torque(s, sw.thigh, g_sw);
    // Torso: the pelvis in the world, through the stance hip.
    world_servo_gains g_torso;
    g_torso.kp = {kp[stl.hip_x], kp[stl.hip_y], kp[stl.hip_z]};
    g_torso.target = {0.0, P[torso], 0.0};
    const vec3 tau_stance = -world_servo_torque(s, layout_.pelvis, g_torso) - tau_swing;
    for (const int j : {sw.hip_x, sw.hip_y, sw.hip_z})
      out.set_target(j, 0.0, 0.0, kd[j], dof_world_axis(s, j).dot(tau_swing));
    for (const int j : {stl.hip_x, stl.hip_y, stl.hip_z})
      out.set_target(j, 0.0, 0.0, kd[j], dof_world_axis(s, j).dot(tau_stance));
  }

 private:
  template <class S>
  void update_phase(const S& s, state_type& st) const {
    const int swing = st.phase >= 2 ? 1 : 0;
    const biped_leg& sw = layout_.leg[swing];
    const bool contact = s.contact_count[sw.foot] + s.contact_count[sw.toes] > 0;
    if (!contact) st.swing_lifted = true;
    const double in_state = s.t - st.phase_start;
    int next = st.phase;
    if ((st.phase & 1) == 0) {
      if (in_state >= p_[duration])
        next = st.phase + 1;
      else if (st.swing_lifted && contact && in_state >= 0.5 * p_[duration])
        next = (st.phase + 2) % 4;
    } else if (st.swing_lifted && contact) {
      next = (st.phase + 1) % 4;
    }
    if (next == st.phase) return;
    if ((next >= 2) != (st.phase >= 2)) st.swing_lifted = false;
    st.phase = next;
    st.phase_start = s.t;
  }

  biped_layout layout_;
  std::vector<int> mirror_dof_;
  std::array<double, 2 * per_state> p_{};
};

/// Yin et al. 2007's walk (Table 1) in our signs, with coronal feedback (cv 0.2) for 3D.
inline std::vector<double> simbicon_yin2007_walk_parameters() {
  //                             dt   cd   cv  cdc  cvc torso  swh  swk   swa  stk   sta
  const std::array<double, 11> s0{0.3, 0.0, 0.2, 0.0, 0.2, 0.0, -0.5, 1.1, -0.6, 0.05, 0.0};
  const std::array<double, 11> s1{0.3, 2.2, 0.0, 0.0, 0.2, 0.0, 0.1, 0.05, -0.15, 0.1, -0.2};
  std::vector<double> p(s0.begin(), s0.end());
  p.insert(p.end(), s1.begin(), s1.end());
  return p;
}

/// The walk the tests and Table 1 use: Yin et al.'s, adjusted for push recovery on this body by
/// examples/wang2009_simbicon_tune.cpp (a seeded random search on the Table 1 push forces; its
/// output is copied here).
inline std::vector<double> simbicon_walk_parameters() {
  // Search iteration 58 (scored 1250 in that run's build). Table 1 with these values, 25 N steps,
  // Release build (wang2009_push_test --resolution 25): 75, 100, 150, 75, 150, 125, 200, 100 N.
  return {0.2413,  0.0000, 0.1663,  0.0552,  0.2847, 0.0310, -0.4268, 1.1461,
          -0.6238, 0.1019, -0.0431, 0.3000,  1.6133, 0.0059, 0.1517,  0.2072,
          -0.0134, 0.2907, -0.0545, -0.3108, 0.0996, -0.1131};
}

/// Gains of the SIMBICON humanoid (kd = 0.1 kp), scaled by m's mass / 70 kg: hips and torso 1000,
/// knees and ankles 300, back 300, neck 100, arms 30, toes 20 (as Wang et al. Table 2).
inline std::pair<Eigen::VectorXd, Eigen::VectorXd> simbicon_walk_gains(const floating_model& m) {
  Eigen::VectorXd kp(m.num_joint_dofs());
  for (int j = 0; j < m.num_joint_dofs(); ++j) {
    const std::string& n = m.dofs[j].name;
    auto has = [&](const char* x) { return n.find(x) != std::string::npos; };
    kp[j] = has("hip")                                   ? 1000.0
            : has("knee") || has("ankle") || has("back") ? 300.0
            : has("neck")                                ? 100.0
            : has("toe")                                 ? 20.0
                                                         : 30.0;
  }
  kp *= m.total_mass() / 70.0;
  return {kp, 0.1 * kp};
}

/// The start of the SIMBICON walks: the neutral pose, its lowest sole or toe point on z = 0,
/// moving forward at `speed` (m/s).
inline sim_state simbicon_start_state(const floating_model& m, double speed = 0.5) {
  sim_state s = make_state(m);
  s.q = neutral_configuration(m);
  s.q[2] -= lowest_foot_point(m, s.q);
  s.v[0] = speed;
  return s;
}

}  // namespace gaitsynth
