#pragma once
/// \file controllers/fsm/wang2009_controller.hpp
/// The walking controller of Wang, Fleet & Hertzmann 2009 (Sec. 3): SIMBICON's finite-state PD
/// control (Yin et al. 2007) with world-frame ankles, arm swing coupled to the hips, and toes,
/// whose 184 parameters (controllers/fsm/wang2009_parameters.hpp) include the start state.
///
/// States (Fig. 2): 0 left swings, right stands; 1 the same with the right heel off; 2, 3 their
/// mirror images. Transitions, checked at every command:
///   0 -> 1  the COM is more than c_trans ahead of the stance ankle (sagittal, signed);
///   1 -> 2  the swing foot (foot or toe) touches with its world sagittal angle below -0.1 rad,
///           i.e. toes up by more than 0.1 rad, heel first (the paper: "the swing ankle global
///           orientation exceeds 0.1 radians"; its sign, not stated, is read so that the condition
///           accepts heel strikes and rejects the toe-down scuffs of early swing, which is what the
///           paper says it is for);
///   0 -> 2  the swing foot touches (early contact).
/// A contact counts only after the swing foot has left the ground in that swing (the new swing
/// foot is still on the ground when a state begins).
///
/// Torques (Eq. 1, tau = kp (theta_d - theta) - kd theta_dot, through mixed_pd_actuator):
///   - local PD at every DOF with the state's gains and target, except:
///   - swing hip: servos the swing thigh's world angles to (coronal cd_cor d_y + cv_cor v_y,
///     sagittal swing_hip_y - (cd_sag d_x + cv_sag v_x), transverse 0), d the COM relative to the
///     stance ankle and v the COM velocity (SIMBICON balance feedback; a COM ahead of the ankle
///     swings the leg further forward, one to the left places the foot further left);
///   - stance hip: -(torso torque) - (swing hip torque), the torso torque servoing the pelvis's
///     world angles to (0, torso_y, 0) with the torso_* gains; its z DOF acts only while the
///     stance foot is planted (more than 3 points on the foot or the toe), else a local PD to 0
///     (footnote 1);
///   - ankles: world-frame servos of the feet's coronal (target 0) and sagittal angles;
///   The hips and the ankles act on world angles with their stiffness and damp their own joint
///   rates (SIMBICON damps the world angular velocity; shared out by the joint axes, such a
///   damper puts the hip_x gain on a flexed thigh's light twist and rings at 2400 Hz, and when
///   the stance foot is off the ground it damps the pelvis by kicking the stance leg);
///   - shoulders about y: target alpha_arm (q_rhip_y - q_lhip_y) on the left, its negative on
///     the right (Eq. 2);
///   - toes: target 0 except the stance toe in states 1 and 3.
/// World torques reach the hip and ankle DOFs through their world axes (controllers/fsm/
/// world_servo.hpp). The heading is +x (Sec. 3: straight walking along x).
///
/// Gains are used up to a per-DOF cap computed once from the model and timestep (the caps of
/// pd_actuator::capped with unbounded requests): Table 2's ankle and toe dampers are unstable as
/// explicit PD at 2400 Hz on this body (see pd_actuator::capped), and a candidate from the
/// optimizer must never make the simulation blow up. Negative gains are used as 0.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/fsm/wang2009_parameters.hpp"
#include "gaitsynth/controllers/fsm/world_servo.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/model/state.hpp"

namespace gaitsynth {

class wang2009_controller {
 public:
  struct state_type {
    int phase = 0;              ///< FSM state 0..3 (Fig. 2)
    double phase_start = 0.0;   ///< s, when the current state began
    bool swing_lifted = false;  ///< the swing foot has left the ground since the swing began
  };

  /// Heel-strike condition of 1 -> 2: the swing foot's world sagittal angle must be below this
  /// (rad; toes up by more than 0.1 rad, see the file comment).
  double landing_foot_angle = -0.1;

  /// \param dt the physics timestep the gains' caps are computed for (s).
  explicit wang2009_controller(const floating_model& m, double dt = 1.0 / 2400.0)
      : layout_(biped_layout::of(m)), params_{m.num_joint_dofs()} {
    const int nj = m.num_joint_dofs();
    check_argument(nj == 30, "wang2009_controller: model '", m.name, "' has ", nj,
                   " joint DOFs, expected the 30 of the Wang 2009 humanoid");
    names_ = wang2009_parameter_names(m);
    // Caps: pd_actuator::capped with requests no DOF can take (every DOF capped at c I_j / dt^2
    // and c I_j / dt, c the largest stable for all of them at once).
    const pd_actuator caps = pd_actuator::capped(m, Eigen::VectorXd::Constant(nj, 1e7),
                                                 Eigen::VectorXd::Constant(nj, 1e6), dt);
    kp_cap_ = caps.kp;
    kd_cap_ = caps.kd;
    mirror_dof_ = m.mirror_dof;
    mirror_sign_ = m.mirror_sign;
    for (int k = 0; k < static_cast<int>(wang2009_parameter_layout::start_dofs.size()); ++k)
      start_dof_[k] = m.dof_index(wang2009_parameter_layout::start_dofs[k]);
    // Which role each free target drives (in state 0's orientation: left swings).
    const biped_leg& sw = layout_.leg[0];
    const biped_leg& st = layout_.leg[1];
    target_role_ = {sw.hip_y,
                    st.hip_y,
                    sw.knee,
                    st.knee,
                    sw.ankle_y,
                    st.ankle_y,
                    layout_.back_y,
                    layout_.back_z,
                    layout_.neck_y,
                    layout_.arm[0].elbow_y,
                    layout_.arm[1].elbow_y,
                    st.toe};
    p_.assign(static_cast<std::size_t>(params_.size()), 0.0);
  }

  std::size_t num_parameters() const { return static_cast<std::size_t>(params_.size()); }
  std::vector<std::string> parameter_names() const { return names_; }
  /// The bound parameters (zeros before the first bind).
  std::vector<double> parameters() const { return p_; }
  const wang2009_parameter_layout& layout() const { return params_; }
  const biped_layout& body_layout() const { return layout_; }

  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "wang2009_controller parameters");
    // A public setting: a NaN would silently keep 1 -> 2 from ever firing.
    check_argument(std::isfinite(landing_foot_angle),
                   "wang2009_controller: landing_foot_angle must be finite, got ",
                   landing_foot_angle);
    std::copy(p.begin(), p.end(), p_.begin());
    for (int s = 0; s < 2; ++s) {
      for (int r = 0; r < params_.nj; ++r) {
        kp_[s][r] = std::clamp(p_[params_.kp(s, r)], 0.0, kp_cap_[r]);
        kd_[s][r] = std::clamp(p_[params_.kd(s, r)], 0.0, kd_cap_[r]);
        target_[s][r] = 0.0;
      }
      const int nt = s == 0 ? params_.num_targets_state0 : params_.num_targets_state1;
      for (int k = 0; k < nt; ++k) target_[s][target_role_[k]] = p_[params_.target(s, k)];
    }
  }

  double period() const { return 0.0; }
  static constexpr command_kind output_kind() { return command_kind::mixed; }
  state_type make_state(const floating_model&) const { return {}; }
  void reset_state(const floating_model&, state_type& st) const { st = {}; }
  int discrete_state(const state_type& st) const { return st.phase; }

  /// The start state of the parameters (Sec. 3): root at (0, 0, z) pitched about y, moving in the
  /// x-z plane, the free joint DOFs at their angles and rates, every other DOF at 0.
  /// Writes in place (no allocation when s already has the model's sizes: give the rollout an
  /// initial state of those sizes, e.g. make_state(m), so it skips placing its default one).
  void initial_state(const floating_model& m, sim_state& s) const {
    s.q.resize(m.nq());
    s.v.resize(m.nv());
    s.q.setZero();
    s.v.setZero();
    const double z = p_[params_.root_start(0)], pitch = p_[params_.root_start(1)];
    s.q[2] = z;
    s.q[3] = std::cos(0.5 * pitch);
    s.q[5] = std::sin(0.5 * pitch);
    s.v[0] = p_[params_.root_start(2)];
    s.v[2] = p_[params_.root_start(3)];
    s.v[4] = p_[params_.root_start(4)];  // pelvis frame; its y axis is the world's under a pitch
    for (std::size_t k = 0; k < start_dof_.size(); ++k) {
      s.q[floating_root::nq + start_dof_[k]] = p_[params_.start_angle(static_cast<int>(k))];
      s.v[floating_root::nv + start_dof_[k]] = p_[params_.start_rate(static_cast<int>(k))];
    }
  }

  template <class S>
  void command(const S& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    update_phase(s, st);
    mixed_command out(cmd);
    const int p = st.phase, b = p & 1;
    const bool mirrored = p >= 2;
    const int swing = mirrored ? 1 : 0, stance = 1 - swing;
    const int nj = params_.nj;
    // Local PD with the state's gains at every DOF (overwritten below where the servo differs).
    for (int r = 0; r < nj; ++r) {
      const int j = mirrored ? mirror_dof_[r] : r;
      const double sign = mirrored ? mirror_sign_[r] : 1.0;
      out.set_target(j, sign * target_[b][r], kp_[b][r], kd_[b][r]);
    }
    const biped_leg& sw = layout_.leg[swing];
    const biped_leg& stl = layout_.leg[stance];
    const biped_leg& role_sw = layout_.leg[0];  // roles are written for the left swinging
    const biped_leg& role_st = layout_.leg[1];
    // Balance feedback: the COM relative to the stance ankle (the foot body's origin).
    const vec3 d = s.com - s.body_position[stl.foot];
    const double p_cd_sag = p_[params_.balance(0)], p_cv_sag = p_[params_.balance(1)];
    const double p_cd_cor = p_[params_.balance(2)], p_cv_cor = p_[params_.balance(3)];
    // Swing hip: the swing thigh in the world.
    world_servo_gains g_sw;
    g_sw.kp = {kp_[b][role_sw.hip_x], kp_[b][role_sw.hip_y], kp_[b][role_sw.hip_z]};
    g_sw.kd = {kd_[b][role_sw.hip_x], kd_[b][role_sw.hip_y], kd_[b][role_sw.hip_z]};
    g_sw.target = {p_cd_cor * d.y() + p_cv_cor * s.com_velocity.y(),
                   target_[b][role_sw.hip_y] - (p_cd_sag * d.x() + p_cv_sag * s.com_velocity.x()),
                   0.0};
    // Stiffness in the world, damping on the hip's own rates (below): world damping, shared out
    // by the axes, would damp the thigh's light twist with the heavy hip_x gain and ring at
    // 2400 Hz.
    const std::array<double, 3> kd_sw = g_sw.kd;
    g_sw.kd = {};
    const vec3 tau_swing = world_servo_torque(s, sw.thigh, g_sw);
    // Torso (the pelvis) through the stance hip.
    world_servo_gains g_torso;
    g_torso.kp = {kp_[b][role_st.hip_x], kp_[b][role_st.hip_y], kp_[b][role_st.hip_z]};
    g_torso.kd = {kd_[b][role_st.hip_x], kd_[b][role_st.hip_y], kd_[b][role_st.hip_z]};
    g_torso.target = {0.0, target_[b][role_st.hip_y], 0.0};
    const std::array<double, 3> kd_torso = g_torso.kd;
    g_torso.kd = {};
    const vec3 tau_torso = world_servo_torque(s, layout_.pelvis, g_torso);
    const vec3 tau_stance = -tau_torso - tau_swing;
    {
      const std::array<int, 3> hip{sw.hip_x, sw.hip_y, sw.hip_z};
      for (int a = 0; a < 3; ++a)
        out.set_target(hip[a], 0.0, 0.0, kd_sw[a], dof_world_axis(s, hip[a]).dot(tau_swing));
    }
    const bool planted = s.contact_count[stl.foot] > 3 || s.contact_count[stl.toes] > 3;
    {
      const std::array<int, 3> hip{stl.hip_x, stl.hip_y, stl.hip_z};
      for (int a = 0; a < 3; ++a) {
        if (a == 2 && !planted)
          out.set_target(hip[a], 0.0, kp_[b][role_st.hip_z], kd_torso[a]);
        else
          out.set_target(hip[a], 0.0, 0.0, kd_torso[a], dof_world_axis(s, hip[a]).dot(tau_stance));
      }
    }
    // Ankles: the feet in the world.
    for (int side = 0; side < 2; ++side) {
      const biped_leg& leg = layout_.leg[side];
      const biped_leg& role = side == swing ? role_sw : role_st;
      world_servo_gains g;
      g.kp = {kp_[b][role.ankle_x], kp_[b][role.ankle_y], 0.0};
      g.target = {0.0, target_[b][role.ankle_y], 0.0};
      const vec3 tau = world_servo_torque(s, leg.foot, g);  // damping on the ankle's own rates
      out.set_target(leg.ankle_x, 0.0, 0.0, kd_[b][role.ankle_x],
                     dof_world_axis(s, leg.ankle_x).dot(tau));
      out.set_target(leg.ankle_y, 0.0, 0.0, kd_[b][role.ankle_y],
                     dof_world_axis(s, leg.ankle_y).dot(tau));
    }
    // Arms swing with the legs (Eq. 2).
    const double arm = p_[params_.alpha_arm()] *
                       (s.joint_angle(layout_.leg[1].hip_y) - s.joint_angle(layout_.leg[0].hip_y));
    for (int side = 0; side < 2; ++side) {
      const int j = layout_.arm[side].shoulder_y;
      const int role = side == swing ? layout_.arm[0].shoulder_y : layout_.arm[1].shoulder_y;
      out.set_target(j, side == 0 ? arm : -arm, kp_[b][role], kd_[b][role]);
    }
  }

 private:
  template <class S>
  void update_phase(const S& s, state_type& st) const {
    const int swing = st.phase >= 2 ? 1 : 0, stance = 1 - swing;
    const biped_leg& sw = layout_.leg[swing];
    const bool swing_contact = s.contact_count[sw.foot] + s.contact_count[sw.toes] > 0;
    if (!swing_contact) st.swing_lifted = true;
    const bool touchdown = st.swing_lifted && swing_contact;
    int next = st.phase;
    if ((st.phase & 1) == 0) {
      const double d = s.com.x() - s.body_position[layout_.leg[stance].foot].x();
      if (d > p_[params_.c_trans()])
        next = st.phase + 1;
      else if (touchdown)
        next = (st.phase + 2) % 4;  // early contact
    } else if (touchdown && body_sagittal_angle(s.body_rotation[sw.foot]) < landing_foot_angle) {
      next = (st.phase + 1) % 4;
    }
    if (next == st.phase) return;
    if ((next >= 2) != (st.phase >= 2)) st.swing_lifted = false;  // the other leg swings now
    st.phase = next;
    st.phase_start = s.t;
  }

  biped_layout layout_;
  wang2009_parameter_layout params_;
  std::vector<std::string> names_;
  Eigen::VectorXd kp_cap_, kd_cap_;
  std::vector<int> mirror_dof_;
  std::vector<double> mirror_sign_;
  std::array<int, wang2009_parameter_layout::start_dofs.size()> start_dof_{};
  std::array<int, 12> target_role_{};
  std::vector<double> p_;
  std::array<std::array<double, 30>, 2> kp_{}, kd_{}, target_{};
};

}  // namespace gaitsynth
