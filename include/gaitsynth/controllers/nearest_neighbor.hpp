#pragma once
/// \file nearest_neighbor.hpp
/// The nearest-neighbor controller of Sharon & van de Panne 2005 (section III).
///
/// The controller is a set of nodes w_1..w_n. Node i has a location zeta_i in the input space (a
/// pose: global torso orientation and joint angles) and an output mu_i (a target pose). Each
/// control step the active node is the nearest neighbour of the current simulated pose zeta_t
/// (eq. 1)
///
///     a = argmin_i || w^T (zeta_t - zeta_i) ||_2       (w: per-coordinate weights, elementwise),
///
/// and its target pose drives PD servos at the joints (|tau| <= 370 N m in the paper). A torso
/// servo on the hip of the current stance leg drives the torso to the target's global orientation:
/// the stance hip's torque is the reaction of the torque a PD servo would apply to the torso,
///     tau_hip = -(k_t (theta_d - theta_torso) - d_t omega_torso) / (hip axis . y),
/// minus the swing hip's torque (which reacts on the torso too) when compensate_swing_hip is set.
/// The stance leg is the foot that touches the ground when exactly one does (stance_from_contacts),
/// else the active node's label (from the keyframes' "stance").
///
/// Symmetry (section VI.A): with `symmetric`, node i + n/2 is the left/right mirror image of node
/// i, so only the first n/2 nodes are free. Their free coordinates (the `free_dofs` of the location
/// and of the output; 6 + 6 = 12 per node for the 7-link human) form the parameter vector, node by
/// node: [node0 location..., node0 output..., node1 location..., ...].
///
/// Activation order (section VI.B): with max_advance = k >= 0, when node a is active only nodes
/// a, a+1, ..., a+k (cyclically) may become active next, which removes the ambiguity of styles that
/// pass through similar poses twice per cycle (the back-swing walk). The first control step
/// searches all nodes.
///
/// Initialization (section V.A, Figure 3a): nodes at evenly spaced times t_i = t_0 + i P / n along
/// the cyclic target motion (period P), zeta_i = pose(t_i) and mu_i = zeta_{i+1} = pose(t_{i+1}):
/// each node drives the character towards the next node's location.
///
/// Output modes: joint_torque (with torque_actuator) computes the servo torques here (pd_torque,
/// actuators/pd_law.hpp), clamped to `torque_limit`; joint_target (with pd_actuator, whose gains
/// must then equal this controller's kp/kd: nothing checks it) outputs the target angles, the
/// stance hip's being the angle whose PD torque equals the torso servo's torque:
/// pd_target_for_torque = q_hip + (tau_hip + kd qdot_hip) / kp. Works with any model and root.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/actuators/concept.hpp"
#include "gaitsynth/actuators/pd_law.hpp"
#include "gaitsynth/controllers/concept.hpp"
#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/motion/keyframes.hpp"

namespace gaitsynth {

struct nearest_neighbor_options {
  /// Total number of nodes n (even when symmetric; the paper uses 12, or 24 for the styles).
  int num_nodes = 12;
  /// Node i + n/2 mirrors node i; only the first n/2 nodes are parameters.
  bool symmetric = true;
  /// Coordinates of the input space zeta, by name: "root_pitch" (planar root: the global
  /// orientation) and joint DOF names. Empty: root_pitch (planar root only) and every joint DOF.
  std::vector<std::string> input;
  /// Weights w of eq. 1, one per input coordinate. Empty: all 1.
  std::vector<double> input_weights;
  /// Joint DOFs whose location and output entries are free parameters. Empty: every joint DOF.
  std::vector<std::string> free_dofs;
  /// Activation order: < 0 unrestricted; k >= 0 lets only nodes a..a+k follow active node a.
  int max_advance = -1;
  /// Time of the target motion at which node 0 sits (initialization from keyframes).
  double first_node_time = 0.0;
  /// joint_torque (torque_actuator) or joint_target (pd_actuator).
  command_kind output = command_kind::joint_torque;
  /// PD servo gains per joint DOF (size num_joint_dofs); empty: default_kp / default_kd.
  std::vector<double> kp, kd;
  double default_kp = 600.0;    ///< N m / rad
  double default_kd = 60.0;     ///< N m s / rad
  double torque_limit = 370.0;  ///< N m, clamp of every servo torque (joint_torque mode)
  /// Torso servo on the stance hip. Needs a stance side per node (from the keyframes' "stance").
  bool torso_servo = true;
  std::string torso_body;                             ///< empty: the root body
  std::string left_hip = "lhip", right_hip = "rhip";  ///< the hip DOFs the servo drives
  double torso_kp = 1000.0;                           ///< N m / rad
  double torso_kd = 100.0;                            ///< N m s / rad
  /// Stance leg from the feet's contacts when exactly one foot touches the ground (the node's
  /// stance label otherwise): the torso servo then acts on the leg that really supports the body
  /// even when the walk runs early or late against the nodes. Off by default: the paper's stance
  /// leg is the node's (our optimizations walked worse with it on: see
  /// docs/reproductions/sharon2005.md).
  std::string left_foot = "lfoot", right_foot = "rfoot";
  bool stance_from_contacts = false;
  /// Subtract the swing hip's torque from the stance hip's, so that the torso feels exactly the
  /// servo's torque (the two hip torques both react on the torso; SIMBICON does the same). Off by
  /// default, as the paper describes the servo on the stance hip alone.
  bool compensate_swing_hip = false;
  /// Seconds between commands (0: every physics step).
  double period = 0.0;
};

/// One node: location zeta (input coordinates), output target joint angles (every joint DOF), the
/// torso's target world pitch, and the stance leg (for the torso servo).
struct nn_node {
  Eigen::VectorXd location;  ///< size = number of input coordinates
  Eigen::VectorXd output;    ///< size = num_joint_dofs, rad
  double torso_pitch = 0.0;  ///< rad, world pitch about +y
  stance_side stance = stance_side::none;
};

template <root_joint Root>
class nearest_neighbor_controller {
 public:
  using options = nearest_neighbor_options;
  struct state_type {
    int active = -1;            ///< active node, -1 before the first command
    std::int64_t switches = 0;  ///< number of changes of the active node
    std::int64_t commands = 0;
  };

  /// From explicit free nodes (the first n/2 when symmetric, else all n); the mirrored ones are
  /// derived. Throws std::invalid_argument naming the bad value.
  nearest_neighbor_controller(const model<Root>& m, options o, std::vector<nn_node> free_nodes)
      : opt_(std::move(o)) {
    setup(m);
    const int nf = num_free_nodes();
    check_argument(static_cast<int>(free_nodes.size()) == nf, "nearest_neighbor: expected ", nf,
                   " free nodes (", opt_.num_nodes, " nodes", opt_.symmetric ? ", symmetric" : "",
                   "), got ", free_nodes.size());
    for (int i = 0; i < nf; ++i) {
      const nn_node& nd = free_nodes[i];
      check_size(nd.location.size(), num_inputs(), "nearest_neighbor: node location");
      check_size(nd.output.size(), nj_, "nearest_neighbor: node output (one angle per joint DOF)");
      check_finite(nd.location, "nearest_neighbor: node location");
      check_finite(nd.output, "nearest_neighbor: node output");
      check_argument(std::isfinite(nd.torso_pitch), "nearest_neighbor: node ", i,
                     " torso_pitch is not finite (", nd.torso_pitch, ")");
      loc_.col(i) = nd.location;
      out_.col(i) = nd.output;
      torso_pitch_[i] = nd.torso_pitch;
      stance_[i] = nd.stance;
    }
    update_mirrors();
  }

  /// Section V.A: nodes along the target motion, each output the next node's pose.
  nearest_neighbor_controller(const model<Root>& m, const keyframe_motion<Root>& target, options o)
      : opt_(std::move(o)) {
    setup(m);
    check_argument(target.nq() == m.nq(), "nearest_neighbor: target motion has nq = ", target.nq(),
                   ", model '", m.name, "' has ", m.nq());
    check_argument(std::isfinite(opt_.first_node_time),
                   "nearest_neighbor: first_node_time is not finite");
    check_argument(!opt_.symmetric || target.symmetric(),
                   "nearest_neighbor: symmetric nodes need a symmetric (mirrored) target motion");
    const int n = opt_.num_nodes;
    const double P = target.period();
    auto ws = make_workspace(m);
    Eigen::VectorXd q(m.nq()), qn(m.nq());
    for (int i = 0; i < num_free_nodes(); ++i) {
      const double ti = opt_.first_node_time + P * i / n;
      const double tn = opt_.first_node_time + P * (i + 1) / n;
      target.pose(ti, q);
      target.pose(tn, qn);
      for (int k = 0; k < num_inputs(); ++k) loc_(k, i) = q[input_q_[k]];
      out_.col(i) = qn.tail(nj_);
      forward_kinematics(m, ws, qn);
      const mat3& R = ws.body_rotation[torso_];
      torso_pitch_[i] = std::atan2(R(0, 2), R(2, 2));
      // The stance leg of the stretch of motion the node governs (from t_i to t_{i+1}).
      stance_[i] = target.stance_at(0.5 * (ti + tn));
    }
    update_mirrors();
  }

  const options& opts() const { return opt_; }
  int num_nodes() const { return opt_.num_nodes; }
  int num_free_nodes() const { return opt_.symmetric ? opt_.num_nodes / 2 : opt_.num_nodes; }
  int num_inputs() const { return static_cast<int>(input_q_.size()); }
  int num_joint_dofs() const { return nj_; }
  /// q indices of the input coordinates.
  const std::vector<int>& input_indices() const { return input_q_; }
  const std::vector<std::string>& input_names() const { return input_names_; }
  const Eigen::VectorXd& input_weights() const { return w_; }
  /// Node i (any i in [0, n)), mirrored ones included.
  nn_node node(int i) const {
    return nn_node{loc_.col(i), out_.col(i), torso_pitch_[i], stance_[i]};
  }
  const Eigen::VectorXd& kp() const { return kp_; }
  const Eigen::VectorXd& kd() const { return kd_; }

  /// 12 per free node for the 7-link human: free location entries then free output entries.
  std::size_t num_parameters() const {
    return static_cast<std::size_t>(num_free_nodes()) * (free_in_.size() + free_out_.size());
  }
  /// Names of the parameters, e.g. "node0.location.lhip", "node0.output.rknee".
  std::vector<std::string> parameter_names() const {
    std::vector<std::string> n;
    for (int i = 0; i < num_free_nodes(); ++i) {
      for (int k : free_in_)
        n.push_back("node" + std::to_string(i) + ".location." + input_names_[k]);
      for (int j : free_out_) n.push_back("node" + std::to_string(i) + ".output." + dof_names_[j]);
    }
    return n;
  }
  /// The current parameter vector (the initialization, or the last bind).
  std::vector<double> parameters() const {
    std::vector<double> p;
    p.reserve(num_parameters());
    for (int i = 0; i < num_free_nodes(); ++i) {
      for (int k : free_in_) p.push_back(loc_(k, i));
      for (int j : free_out_) p.push_back(out_(j, i));
    }
    return p;
  }
  /// Sets the free node coordinates (and their mirrors). Validates size and finiteness.
  void bind(std::span<const double> p) {
    check_parameters(p, num_parameters(), "nearest_neighbor parameters");
    std::size_t c = 0;
    for (int i = 0; i < num_free_nodes(); ++i) {
      for (int k : free_in_) loc_(k, i) = p[c++];
      for (int j : free_out_) out_(j, i) = p[c++];
    }
    update_mirrors();
  }

  double period() const { return opt_.period; }
  command_kind output_kind() const { return opt_.output; }
  int discrete_state(const state_type& st) const { return st.active; }

  state_type make_state(const model<Root>& m) const {
    check_argument(m.num_joint_dofs() == nj_ && m.num_bodies() == nb_,
                   "nearest_neighbor: controller was made for a model with ", nj_,
                   " joint DOFs and ", nb_, " bodies, model '", m.name, "' has ",
                   m.num_joint_dofs(), " and ", m.num_bodies());
    return {};
  }

  /// Nearest node to pose q (eq. 1) among all nodes, or (restricted) among from..from+max_advance.
  template <class Q>
  int nearest(const Q& q, int from = -1) const {
    const int n = opt_.num_nodes;
    const bool restricted = opt_.max_advance >= 0 && from >= 0;
    const int count = restricted ? std::min(opt_.max_advance + 1, n) : n;
    const int start = restricted ? from : 0;
    int best = start;
    double best_d = std::numeric_limits<double>::infinity();
    for (int c = 0; c < count; ++c) {
      const int i = (start + c) % n;
      double d = 0.0;
      for (int k = 0; k < num_inputs(); ++k) {
        const double e = w_[k] * (q[input_q_[k]] - loc_(k, i));
        d += e * e;
      }
      if (d < best_d) {  // strict: ties keep the earlier node (the active one when restricted)
        best_d = d;
        best = i;
      }
    }
    return best;
  }

  template <class S>
  requires std::derived_from<S, sensors<Root>>
  void command(const S& s, state_type& st, Eigen::Ref<Eigen::VectorXd> cmd) const {
    ++st.commands;
    const Eigen::VectorXd& q = s.q();
    const Eigen::VectorXd& v = s.v();
    const int a = nearest(q, st.active);
    if (a != st.active) {
      if (st.active >= 0) ++st.switches;
      st.active = a;
    }
    // Torso servo torque on the stance hip (reaction on the torso = PD on its world pitch).
    int servo_dof = -1, swing_dof = -1;
    double servo_tau = 0.0;
    stance_side stance = stance_[a];
    if (opt_.stance_from_contacts && lfoot_ >= 0) {
      const bool l = s.contact_count[lfoot_] > 0, r = s.contact_count[rfoot_] > 0;
      if (l != r) stance = l ? stance_side::left : stance_side::right;
    }
    if (opt_.torso_servo && stance != stance_side::none) {
      servo_dof = stance == stance_side::left ? lhip_ : rhip_;
      swing_dof = stance == stance_side::left ? rhip_ : lhip_;
      const mat3& R = s.body_rotation[torso_];
      const double pitch = std::atan2(R(0, 2), R(2, 2));
      const double omega = s.body_angular_velocity[torso_].y();
      double err = torso_pitch_[a] - pitch;
      err = std::remainder(err, 2.0 * std::numbers::pi);
      const double t_torso = opt_.torso_kp * err - opt_.torso_kd * omega;
      servo_tau = -t_torso / hip_axis_y_[servo_dof == lhip_ ? 0 : 1];
      if (opt_.compensate_swing_hip) {
        // The swing hip's PD torque (as applied, after the limit) also reacts on the torso.
        const double ts = std::clamp(pd_torque(kp_[swing_dof], kd_[swing_dof], out_(swing_dof, a),
                                               q[Root::nq + swing_dof], v[Root::nv + swing_dof]),
                                     -opt_.torque_limit, opt_.torque_limit);
        servo_tau -=
            ts * hip_axis_y_[swing_dof == lhip_ ? 0 : 1] / hip_axis_y_[servo_dof == lhip_ ? 0 : 1];
      }
    }
    if (opt_.output == command_kind::joint_torque) {
      for (int j = 0; j < nj_; ++j) {
        const double t = (j == servo_dof) ? servo_tau
                                          : pd_torque(kp_[j], kd_[j], out_(j, a), q[Root::nq + j],
                                                      v[Root::nv + j]);
        cmd[j] = std::clamp(t, -opt_.torque_limit, opt_.torque_limit);
      }
    } else {
      for (int j = 0; j < nj_; ++j) cmd[j] = out_(j, a);
      if (servo_dof >= 0) {
        // The target whose PD torque kp (target - q) - kd qdot equals the servo torque.
        const double t = std::clamp(servo_tau, -opt_.torque_limit, opt_.torque_limit);
        cmd[servo_dof] = pd_target_for_torque(kp_[servo_dof], kd_[servo_dof], t,
                                              q[Root::nq + servo_dof], v[Root::nv + servo_dof]);
      }
      if (cmd.size() > nj_) cmd.tail(cmd.size() - nj_).setZero();  // no feed-forward torque
    }
  }

 private:
  void setup(const model<Root>& m) {
    nj_ = m.num_joint_dofs();
    nb_ = m.num_bodies();
    const int n = opt_.num_nodes;
    check_argument(n >= 1, "nearest_neighbor: num_nodes must be >= 1, got ", n);
    check_argument(!opt_.symmetric || n % 2 == 0,
                   "nearest_neighbor: a symmetric controller needs an even num_nodes, got ", n);
    check_argument(std::isfinite(opt_.period) && opt_.period >= 0,
                   "nearest_neighbor: period must be finite and >= 0, got ", opt_.period);
    check_argument(
        opt_.output == command_kind::joint_torque || opt_.output == command_kind::joint_target,
        "nearest_neighbor: output must be joint_torque or joint_target");
    for (const auto& d : m.dofs) dof_names_.push_back(d.name);
    // Input coordinates.
    std::vector<std::string> in = opt_.input;
    if (in.empty()) {
      if constexpr (Root::nq == 3) in.push_back("root_pitch");
      for (const auto& d : m.dofs) in.push_back(d.name);
    }
    for (const auto& name : in) {
      int qi = -1;
      if (name == "root_pitch") {
        check_argument(Root::nq == 3, "nearest_neighbor: input 'root_pitch' needs a planar root");
        qi = 2;
      } else {
        const int j = m.find_dof(name);
        check_argument(j >= 0, "nearest_neighbor: unknown input coordinate '", name, "' (model '",
                       m.name, "')");
        qi = Root::nq + j;
      }
      for (int k : input_q_)
        check_argument(k != qi, "nearest_neighbor: input coordinate '", name, "' listed twice");
      input_q_.push_back(qi);
      input_names_.push_back(name);
    }
    check_argument(!input_q_.empty(), "nearest_neighbor: the input space is empty");
    const int ni = num_inputs();
    w_ = Eigen::VectorXd::Ones(ni);
    if (!opt_.input_weights.empty()) {
      check_size(static_cast<std::ptrdiff_t>(opt_.input_weights.size()), ni,
                 "nearest_neighbor: input_weights (one per input coordinate)");
      for (int k = 0; k < ni; ++k) {
        check_argument(std::isfinite(opt_.input_weights[k]) && opt_.input_weights[k] >= 0,
                       "nearest_neighbor: input weight of '", input_names_[k],
                       "' must be finite and >= 0, got ", opt_.input_weights[k]);
        w_[k] = opt_.input_weights[k];
      }
    }
    // Mirror map of the input coordinates.
    in_mirror_.assign(ni, -1);
    in_sign_.assign(ni, 1.0);
    for (int k = 0; k < ni; ++k) {
      const int qi = input_q_[k];
      int mq = qi;
      double sg = 1.0;
      if (qi >= Root::nq) {
        mq = Root::nq + m.mirror_dof[qi - Root::nq];
        sg = m.mirror_sign[qi - Root::nq];
      }
      for (int l = 0; l < ni; ++l)
        if (input_q_[l] == mq) in_mirror_[k] = l;
      in_sign_[k] = sg;
      check_argument(!opt_.symmetric || in_mirror_[k] >= 0, "nearest_neighbor: input coordinate '",
                     input_names_[k], "' has no mirror image among the inputs (symmetric nodes)");
    }
    // Free coordinates.
    std::vector<std::string> fr = opt_.free_dofs;
    if (fr.empty())
      for (const auto& d : m.dofs) fr.push_back(d.name);
    for (const auto& name : fr) {
      const int j = m.find_dof(name);
      check_argument(j >= 0, "nearest_neighbor: unknown free DOF '", name, "' (model '", m.name,
                     "')");
      for (int f : free_out_)
        check_argument(f != j, "nearest_neighbor: free DOF '", name, "' listed twice");
      free_out_.push_back(j);
      for (int k = 0; k < ni; ++k)
        if (input_q_[k] == Root::nq + j) free_in_.push_back(k);
    }
    std::sort(free_in_.begin(), free_in_.end());
    std::sort(free_out_.begin(), free_out_.end());
    // Gains.
    auto gains = [&](const std::vector<double>& g, double def, const char* what) {
      Eigen::VectorXd x = Eigen::VectorXd::Constant(nj_, def);
      if (!g.empty()) {
        check_size(static_cast<std::ptrdiff_t>(g.size()), nj_, what);
        for (int j = 0; j < nj_; ++j) x[j] = g[j];
      }
      for (int j = 0; j < nj_; ++j)
        check_argument(std::isfinite(x[j]) && x[j] >= 0, "nearest_neighbor: ", what, " of DOF '",
                       dof_names_[j], "' must be finite and >= 0, got ", x[j]);
      return x;
    };
    kp_ = gains(opt_.kp, opt_.default_kp, "kp");
    kd_ = gains(opt_.kd, opt_.default_kd, "kd");
    check_argument(opt_.torque_limit > 0, "nearest_neighbor: torque_limit must be > 0, got ",
                   opt_.torque_limit);
    check_argument(std::isfinite(opt_.torso_kp) && opt_.torso_kp >= 0 &&
                       std::isfinite(opt_.torso_kd) && opt_.torso_kd >= 0,
                   "nearest_neighbor: torso gains must be finite and >= 0, got ", opt_.torso_kp,
                   ", ", opt_.torso_kd);
    check_argument(opt_.max_advance < n, "nearest_neighbor: max_advance must be < num_nodes (", n,
                   "), got ", opt_.max_advance);
    torso_ = opt_.torso_body.empty() ? 0 : m.body_index(opt_.torso_body);
    if (opt_.stance_from_contacts && !opt_.left_foot.empty() && !opt_.right_foot.empty()) {
      lfoot_ = m.body_index(opt_.left_foot);
      rfoot_ = m.body_index(opt_.right_foot);
    }
    if (opt_.torso_servo) {
      lhip_ = m.dof_index(opt_.left_hip);
      rhip_ = m.dof_index(opt_.right_hip);
      hip_axis_y_[0] = m.dofs[lhip_].axis.y();
      hip_axis_y_[1] = m.dofs[rhip_].axis.y();
      for (int s = 0; s < 2; ++s)
        check_argument(std::abs(hip_axis_y_[s]) > 0.5, "nearest_neighbor: torso servo hip DOF '",
                       s == 0 ? opt_.left_hip : opt_.right_hip,
                       "' must rotate about (nearly) the pitch axis y, its axis y component is ",
                       hip_axis_y_[s]);
      if (opt_.output == command_kind::joint_target)
        for (int j : {lhip_, rhip_})
          check_argument(kp_[j] > 0,
                         "nearest_neighbor: joint_target mode needs kp > 0 at the hip '",
                         dof_names_[j], "' (the torso servo's equivalent target divides by it)");
    }
    loc_ = Eigen::MatrixXd::Zero(ni, n);
    out_ = Eigen::MatrixXd::Zero(nj_, n);
    torso_pitch_.assign(n, 0.0);
    stance_.assign(n, stance_side::none);
    mirror_dof_ = m.mirror_dof;
    mirror_sign_ = m.mirror_sign;
  }

  void update_mirrors() {
    if (!opt_.symmetric) return;
    const int h = opt_.num_nodes / 2;
    for (int i = 0; i < h; ++i) {
      for (int k = 0; k < num_inputs(); ++k) loc_(in_mirror_[k], h + i) = in_sign_[k] * loc_(k, i);
      for (int j = 0; j < nj_; ++j) out_(j, h + i) = mirror_sign_[j] * out_(mirror_dof_[j], i);
      torso_pitch_[h + i] = torso_pitch_[i];
      stance_[h + i] = opposite(stance_[i]);
    }
  }

  options opt_;
  int nj_ = 0, nb_ = 0;
  std::vector<std::string> dof_names_;
  std::vector<int> input_q_;
  std::vector<std::string> input_names_;
  Eigen::VectorXd w_;
  std::vector<int> in_mirror_;
  std::vector<double> in_sign_;
  std::vector<int> free_in_, free_out_;
  Eigen::VectorXd kp_, kd_;
  int torso_ = 0, lhip_ = -1, rhip_ = -1, lfoot_ = -1, rfoot_ = -1;
  double hip_axis_y_[2] = {1.0, 1.0};
  Eigen::MatrixXd loc_, out_;  ///< input coordinates x nodes; joint DOFs x nodes
  std::vector<double> torso_pitch_;
  std::vector<stance_side> stance_;
  std::vector<int> mirror_dof_;
  std::vector<double> mirror_sign_;
};

}  // namespace gaitsynth
