#pragma once
/// \file controllers/reflex/wang2012_reflex_controller.hpp
/// The muscle-reflex controller of Wang et al. 2012 Sec. 4.1-4.3 for the 16 leg MTUs of
/// musculotendon::geyer_herr_leg_muscles (in that order: per leg GLU, HFL, VAS, TA, SOL, HAM, RF,
/// GAS; left first), with its parameters in reflex_parameters.hpp. Per leg, per physics step:
///
///   stance   u_SOL = p + G_SOL F_SOL          u_TA  = p + u^L_TA - G_SOL_TA F_SOL
///            u_GAS = p + G_GAS F_GAS          u_VAS = p + G_VAS F_VAS + {k (th_k -
///            th_off)}-,thd_k<0 u_HAM = p + {u^Theta_HAM}lead    u_RF  = p u_GLU = p +
///            {u^Theta_GLU}lead    u_HFL = p + {u^Theta_HFL}lead
///     swing initiation: u_VAS -= s_VAS, u_RF += s_RF, u_GLU -= s_GLU, u_HFL += s_HFL
///   swing    u_TA = q + u^L_TA, u_HAM = q + u^L_HAM, u_GLU = q + u^L_GLU,
///            u_HFL = q + u^L_HFL - u^L_HAM + k_lean (Theta_lto - Theta_d), others q
///     stance preparation: u_VAS = q + u^th_k, u_GLU = q + u^th_h, u_HFL = q + u^th_h with the
///     shared hip target th_h = hip_target + c_d d + c_v v (SIMBICON balance feedback: d, v the
///     COM's horizontal offset from the stance ankle and its velocity along the heading)
///
/// with the neural delays of reflex_delays (ankle MTUs 20 ms, VAS and contact 10 ms, hip MTUs
/// 5 ms). F and l are the actuator's sensed F_MTU / F_max and l_CE / l_opt (musculotendon_actuator
/// ::sense); th_k the knee flexion, th_h the hip flexion (-hip_y); Theta the trunk's lean, the
/// sagittal world angle of the torso (5 ms delay; ours: the paper's upper-body-to-pelvis COM
/// vector is not in the delayed sensor history), its rate by a difference of two delayed samples.
/// "lead": in double stance only the leading leg (ankle further ahead) holds the trunk.
///
/// The DOFs the muscles do not drive follow Sec. 4.4 (upper_body_control.hpp) in two mirrored
/// states, the leg that struck last standing. The parameter vector is the 58 of
/// reflex_parameters.hpp, the 31 of upper_body_parameters.hpp and the 33 of
/// start_state_parameters.hpp: 122 (the paper: 124; the difference is in upper_body_parameters).
/// The rollout starts from the start-state parameters (controller_with_initial_state) unless
/// options::start_from_parameters is false.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/command_kind.hpp"
#include "gaitsynth/actuators/mixed_pd.hpp"
#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/fsm/biped_layout.hpp"
#include "gaitsynth/controllers/reflex/leg_phase.hpp"
#include "gaitsynth/controllers/reflex/reflex_laws.hpp"
#include "gaitsynth/controllers/reflex/reflex_parameters.hpp"
#include "gaitsynth/controllers/reflex/start_state_parameters.hpp"
#include "gaitsynth/controllers/reflex/upper_body_control.hpp"
#include "gaitsynth/controllers/reflex/upper_body_parameters.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/models/wang2012.hpp"
#include "gaitsynth/spatial/world_angles.hpp"

namespace gaitsynth {

struct wang2012_reflex_options {
  double leg_length = 0.0;   ///< m, normalizes d; 0: hip-to-ankle length of the model at q = 0
  double dt = 1.0 / 2400.0;  ///< s, the physics timestep the PD gains are capped for
  bool start_from_parameters = true;  ///< false: keep the rollout's initial state
};

class wang2012_reflex_controller {
 public:
  static constexpr int num_muscles = 16;  ///< 8 per leg, geyer_herr_leg_muscles order
  using options = wang2012_reflex_options;

  /// The parameter vector's parts, in order.
  static constexpr std::size_t num_reflex = reflex::reflex_parameter_count;
  static constexpr std::size_t num_upper_body = reflex::upper_body_parameter_count;
  static constexpr std::size_t num_start = reflex::start_state_layout::size;
  static constexpr std::size_t parameter_count = num_reflex + num_upper_body + num_start;

  struct state_type {
    std::array<reflex::leg_state, 2> legs;
    int support =
        1;  ///< the leg that struck last (Sec. 4.4's state); the start stands on the right
    std::array<double, 2> lean_at_liftoff{};  ///< Theta when each leg last lifted off, rad
    std::int64_t commands = 0;
  };

  explicit wang2012_reflex_controller(const floating_model& m, options o = {})
      : opt_(o), layout_(biped_layout::of(m)), params_(reflex::reflex_initial_parameters()) {
    if (opt_.leg_length <= 0.0) {
      // Hip to ankle at q = 0: the thigh's and shin's joint offsets (models/detail/humanoid30).
      opt_.leg_length =
          m.bodies[static_cast<std::size_t>(layout_.leg[0].shin)].joint_offset.norm() +
          m.bodies[static_cast<std::size_t>(layout_.leg[0].foot)].joint_offset.norm();
    }
    check_positive(opt_.leg_length, "wang2012_reflex_controller: leg_length (m)");
    check_positive(opt_.dt, "wang2012_reflex_controller: dt (s)");
    // Caps: pd_actuator::capped with requests no DOF can take (as wang2009_controller).
    const int nj = m.num_joint_dofs();
    const pd_actuator c = pd_actuator::capped(m, Eigen::VectorXd::Constant(nj, 1e7),
                                              Eigen::VectorXd::Constant(nj, 1e6), opt_.dt);
    caps_ = {c.kp, c.kd};
    start_dofs_ = reflex::start_state_dofs(m);
    const auto p = initial_parameters(m);
    bind(p);
  }

  /// Geyer & Herr's reflex values, our Sec. 4.4 values and Geyer & Herr's start (each part's file).
  static std::vector<double> initial_parameters(const floating_model& m) {
    std::vector<double> out;
    out.reserve(parameter_count);
    for (double x : reflex::reflex_initial_parameters()) out.push_back(x);
    for (double x : reflex::upper_body_initial_parameters()) out.push_back(x);
    for (double x : reflex::start_state_initial_parameters(m)) out.push_back(x);
    return out;
  }
  /// The running start of Sec. 6.3: initial_parameters with the start's forward velocity 3.05 m/s
  /// instead of 1.3, the force-feedback gains of GAS and SOL (G_GAS, G_SOL) doubled and the elbow
  /// bent. The paper's exact elbow angle is in its supplemental material, which we do not have:
  /// ours, 1.5 rad of flexion (a runner's near right angle).
  static std::vector<double> initial_running_parameters(const floating_model& m) {
    std::vector<double> out = initial_parameters(m);
    out[reflex::G_GAS] *= 2.0;
    out[reflex::G_SOL] *= 2.0;
    out[num_reflex + reflex::elbow_target] = -1.5;
    out[num_reflex + num_upper_body + reflex::start_state_layout::root_vx] = 3.05;
    return out;
  }
  /// Every parameter's name, in order.
  static std::vector<std::string> parameter_names() {
    std::vector<std::string> out;
    for (auto n : reflex::reflex_parameter_names) out.emplace_back(n);
    for (auto n : reflex::upper_body_parameter_names) out.emplace_back(n);
    for (int i = 0; i < static_cast<int>(num_start); ++i)
      out.push_back(reflex::start_state_parameter_name(i));
    return out;
  }

  std::size_t num_parameters() const { return parameter_count; }
  void bind(std::span<const double> p) {
    check_argument(p.size() == parameter_count, "wang2012_reflex_controller: expected ",
                   parameter_count, " parameters (", num_reflex, " reflex, ", num_upper_body,
                   " upper-body, ", num_start, " start-state), got ", p.size());
    params_ = reflex::reflex_parameters_from(p.first(num_reflex));
    upper_ = reflex::upper_body_parameters_from(p.subspan(num_reflex, num_upper_body));
    start_ = reflex::start_state_parameters_from(p.subspan(num_reflex + num_upper_body));
  }
  const reflex::reflex_parameter_vector& parameters() const { return params_; }
  const reflex::upper_body_parameter_vector& upper_body_parameters() const { return upper_; }
  const reflex::start_state_vector& start_state_parameters() const { return start_; }

  /// The start state of the parameters (no allocation when s has the model's sizes).
  void initial_state(const floating_model& m, sim_state& s) const {
    if (opt_.start_from_parameters) reflex::write_start_state(m, start_, start_dofs_, s);
  }
  double leg_length() const { return opt_.leg_length; }

  double period() const { return 0.0; }
  double max_sensor_delay() const { return reflex::reflex_delays::ankle + 1.0 / 2400.0; }
  static constexpr command_kind output_kind() { return command_kind::excitation; }
  template <root_joint Root>
  int command_size(const model<Root>& m) const {
    return num_muscles + 4 * m.num_joint_dofs();
  }

  template <root_joint Root>
  state_type make_state(const model<Root>&) const {
    return {};
  }
  /// 4 x left phase + right phase (reflex::leg_phase values), for the recorder.
  int discrete_state(const state_type& st) const {
    return 4 * static_cast<int>(st.legs[0].phase) + static_cast<int>(st.legs[1].phase);
  }

  template <root_joint Root>
  void command(const sensors<Root>& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    using namespace reflex;
    const auto& P = params_;
    const int nj = s.num_joint_dofs();
    ++st.commands;
    // Heading, trunk lean and the legs' d (COM ahead of the ankle, over the leg length).
    const double heading = body_heading(s.body_rotation[layout_.pelvis]);
    const vec3 fwd(std::cos(heading), std::sin(heading), 0.0);
    const double lean = trunk_lean(s, reflex_delays::hip, heading);
    const double lean_rate =
        s.dt > 0.0 ? (lean - trunk_lean(s, reflex_delays::hip + s.dt, heading)) / s.dt : 0.0;
    std::array<double, 2> d{}, ankle_x{};
    std::array<bool, 2> contact{};
    for (int k = 0; k < 2; ++k) {
      const biped_leg& g = layout_.leg[k];
      ankle_x[k] = s.body_position[g.foot].dot(fwd);
      d[k] = (s.com.dot(fwd) - ankle_x[k]) / opt_.leg_length;
      contact[k] = s.delayed_contact_count(g.foot, reflex_delays::contact) +
                       s.delayed_contact_count(g.toes, reflex_delays::contact) >
                   0;
    }
    if (st.commands == 1) {
      // The start's support: the lower foot (a tie: the right, as the start-state parameters
      // stand). Not contact, which a start placed exactly on the ground may not register yet.
      const auto height = [&](int k) { return s.body_position[layout_.leg[k].foot].z(); };
      st.support = height(0) < height(1) ? 0 : 1;
    }
    for (int k = 0; k < 2; ++k) {
      const leg_phase before = st.legs[k].phase;
      st.legs[k].update(contact[k], st.legs[1 - k], d[k], P[d_SI], P[d_SP], s.t);
      if (in_stance(before) && !in_stance(st.legs[k].phase)) st.lean_at_liftoff[k] = lean;
      if (!in_stance(before) && in_stance(st.legs[k].phase)) st.support = k;  // foot strike
    }
    const bool double_stance = in_stance(st.legs[0].phase) && in_stance(st.legs[1].phase);
    const int lead = ankle_x[0] >= ankle_x[1] ? 0 : 1;
    // The stance leg's offset and the COM velocity for the swing hip's balance feedback (m, m/s).
    const int stance_leg = in_stance(st.legs[0].phase) ? 0 : 1;
    const double balance =
        P[c_d] * d[stance_leg] * opt_.leg_length + P[c_v] * s.com_velocity.dot(fwd);

    const auto F_ankle = s.delayed_sensed(reflex_delays::ankle);
    const auto F_knee = s.delayed_sensed(reflex_delays::knee);
    const auto F_hip = s.delayed_sensed(reflex_delays::hip);
    const auto v_knee = s.delayed_v(reflex_delays::knee);
    const auto q_knee = s.delayed_q(reflex_delays::knee);
    const auto v_hip = s.delayed_v(reflex_delays::hip);
    const auto q_hip = s.delayed_q(reflex_delays::hip);
    auto force = [&](const auto& sensed, int i) { return sensed[i]; };
    auto length = [&](const auto& sensed, int i) { return sensed[num_muscles + i]; };

    for (int k = 0; k < 2; ++k) {
      const biped_leg& g = layout_.leg[k];
      const int b = 8 * k;  // this leg's MTUs: GLU, HFL, VAS, TA, SOL, HAM, RF, GAS
      const int GLU = b, HFL = b + 1, VAS = b + 2, TA = b + 3, SOL = b + 4, HAM = b + 5, RF = b + 6,
                GAS = b + 7;
      const double knee = q_knee[Root::nq + g.knee], knee_rate = v_knee[Root::nv + g.knee];
      const double hip_flex = -q_hip[Root::nq + g.hip_y], hip_rate = -v_hip[Root::nv + g.hip_y];
      const leg_phase ph = st.legs[k].phase;
      if (in_stance(ph)) {
        const double sol_f = force(F_ankle, SOL);
        cmd[SOL] = P[p_SOL] + force_feedback(P[G_SOL], sol_f);
        cmd[TA] = P[p_TA] + length_feedback(P[G_TA], length(F_ankle, TA), P[H_TA]) -
                  force_feedback(P[G_SOL_TA], sol_f);
        cmd[GAS] = P[p_GAS] + force_feedback(P[G_GAS], force(F_ankle, GAS));
        cmd[VAS] = P[p_VAS] + force_feedback(P[G_VAS], force(F_knee, VAS)) +
                   knee_extension_suppression(P[k_knee], knee, knee_rate, P[knee_offset]);
        cmd[RF] = P[p_RF];
        const bool holds_trunk = !double_stance || lead == k;
        cmd[HAM] = P[p_HAM] + (holds_trunk ? muscle_pd(P[K_HAM_lean], P[D_HAM_lean], lean,
                                                       lean_rate, P[lean_HAM], true)
                                           : 0.0);
        cmd[GLU] = P[p_GLU] + (holds_trunk ? muscle_pd(P[K_GLU_lean], P[D_GLU_lean], lean,
                                                       lean_rate, P[lean_GLU], true)
                                           : 0.0);
        cmd[HFL] = P[p_HFL] + (holds_trunk ? muscle_pd(P[K_HFL_lean], P[D_HFL_lean], lean,
                                                       lean_rate, P[lean_HFL], false)
                                           : 0.0);
        if (ph == leg_phase::swing_initiation) {
          cmd[VAS] -= P[s_VAS];
          cmd[RF] += P[s_RF];
          cmd[GLU] -= P[s_GLU];
          cmd[HFL] += P[s_HFL];
        }
      } else {
        const double ham_l = length_feedback(P[G_HAM_swing], length(F_hip, HAM), P[H_HAM_swing]);
        cmd[TA] = P[q_TA] + length_feedback(P[G_TA_swing], length(F_ankle, TA), P[H_TA_swing]);
        cmd[HAM] = P[q_HAM] + ham_l;
        cmd[SOL] = P[q_SOL];
        cmd[GAS] = P[q_GAS];
        cmd[RF] = P[q_RF];
        if (ph == leg_phase::stance_preparation) {
          const double target = P[hip_target] + balance;
          cmd[VAS] = P[q_VAS] +
                     muscle_pd(P[K_VAS_knee], P[D_VAS_knee], knee, knee_rate, P[knee_target], true);
          cmd[GLU] =
              P[q_GLU] + muscle_pd(P[K_GLU_hip], P[D_GLU_hip], hip_flex, hip_rate, target, true);
          cmd[HFL] =
              P[q_HFL] + muscle_pd(P[K_HFL_hip], P[D_HFL_hip], hip_flex, hip_rate, target, false);
        } else {
          cmd[VAS] = P[q_VAS];
          cmd[GLU] = P[q_GLU] + length_feedback(P[G_GLU_swing], length(F_hip, GLU), P[H_GLU_swing]);
          cmd[HFL] = P[q_HFL] +
                     length_feedback(P[G_HFL_swing], length(F_hip, HFL), P[H_HFL_swing]) - ham_l +
                     P[k_lean] * (st.lean_at_liftoff[k] - P[lean_HFL]);
        }
      }
    }
    mixed_command out(cmd.segment(num_muscles, 4 * nj));
    const vec3 offset = s.com - s.body_position[layout_.leg[st.support].foot];
    upper_body_control(s, layout_, upper_, caps_, st.support, heading, offset, s.com_velocity, out);
  }

 private:
  /// The torso's sagittal world angle `delay` ago (rad, + leaning forward).
  template <root_joint Root>
  double trunk_lean(const sensors<Root>& s, double delay, double heading) const {
    return body_sagittal_angle(s.delayed_body_rotation(layout_.torso, delay), heading);
  }

  options opt_;
  biped_layout layout_;
  reflex::reflex_parameter_vector params_;
  reflex::upper_body_parameter_vector upper_{};
  reflex::start_state_vector start_{};
  std::array<int, reflex::start_state_layout::num_dofs> start_dofs_{};
  reflex::gain_caps caps_;
};

}  // namespace gaitsynth
