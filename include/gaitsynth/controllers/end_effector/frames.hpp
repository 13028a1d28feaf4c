#pragma once
/// \file controllers/end_effector/frames.hpp
/// The frames of Wu & Popovic 2010, Sec. 5 (Fig. 3): where the ideal PD controllers act, and
/// their current state read from the model's kinematics.
///
/// One *reaction* frame, linear-angular (LA), on the upper body; *action* frames on the feet: a
/// linear (L) frame at each ankle and three linear-relative (LR) frames per foot, two at the toe
/// corners and one at the heel (N = 8). Sec. 6 pairs the reaction frame with every action frame
/// (K = 8 pairs). The planner (later) and the standing controller give targets per end-effector
/// *link* (the upper body and each foot: a pose and a twist), and the frames' desired states
/// follow from them, since every frame is fixed to its link.
///
/// Sec. 6.3 treats an action frame as pinned when "the geometry to which it is attached" touches
/// the ground: each action frame lists the contact points of that geometry (the toe box for the
/// toe frames, the heel box for the heel frame, both boxes for the ankle frame, our choice: the
/// ankle sits over the heel box, and the foot link carries both).
#include <Eigen/Core>
#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/error.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// Fig. 3's frame types.
enum class frame_type {
  linear_angular,   ///< LA: position and orientation (eqs. 1 and 2)
  linear,           ///< L: position (eq. 1)
  linear_relative,  ///< LR: position relative to its link's centre (eq. 3)
};

/// One action frame: fixed to end-effector link `link` (an index into the layout's links, >= 1)
/// at `point` (in that link's body frame).
struct action_frame {
  frame_type type = frame_type::linear;
  int link = 1;
  vec3 point = vec3::Zero();
  std::vector<int> contacts;  ///< contact points of the geometry it is attached to (Sec. 6.3)
  std::string name;
};

/// Whether a contact point of the geometry `a` is attached to touches (`touching`: one flag per
/// contact point of the model, sensors::contact_active). Sec. 6.3's first test.
inline bool frame_touches(const action_frame& a, std::span<const unsigned char> touching) {
  for (const int c : a.contacts)
    if (c >= 0 && static_cast<std::size_t>(c) < touching.size() &&
        touching[static_cast<std::size_t>(c)])
      return true;
  return false;
}

/// A leg for appendix B's null-space knee control: the knee DOF, the body whose origin is the hip
/// joint, the ankle frame, and the sign of a bending torque.
struct knee_leg {
  int knee_dof = -1;       ///< joint DOF index (0-based, after the root)
  int hip_body = -1;       ///< the thigh: its origin is the hip joint
  int ankle_frame = -1;    ///< index into end_effector_layout::action
  double bend_sign = 1.0;  ///< +1 if a positive knee torque bends the knee
};

/// Links, frames and legs of one character. links[0] is the upper body (the reaction frame's
/// link); the others are feet.
struct end_effector_layout {
  std::vector<int> link_body;          ///< body index of each end-effector link
  vec3 reaction_point = vec3::Zero();  ///< LA frame origin in the upper body's frame
  std::vector<action_frame> action;    ///< N action frames
  std::vector<knee_leg> legs;

  int num_links() const { return static_cast<int>(link_body.size()); }
  int num_action() const { return static_cast<int>(action.size()); }
  /// K pairs (the one reaction frame with each action frame): the generalized state has 3K entries.
  int num_pairs() const { return num_action(); }
};

/// The frames of Sec. 5 on a biped whose feet carry heel ("sole") and toe contact points, as
/// models/wu2010.hpp's: LA at the upper body's COM; per foot an L frame at the ankle (the foot
/// body's origin), LR frames at the two front toe corners and at the middle of the heel's back
/// edge, all on the sole. Knee control for `knee` DOFs, bending toward the larger side of their
/// range: positive for the range [0, 2.4], negative for inverted knees (Sec. 9, [-2.4, 0]).
/// \throws std::invalid_argument naming a body, DOF or contact the model lacks.
template <root_joint Root>
end_effector_layout biped_end_effector_layout(const model<Root>& m,
                                              const std::string& upper_body = "upper_body",
                                              const std::string& left = "l",
                                              const std::string& right = "r") {
  end_effector_layout L;
  const int ub = m.body_index(upper_body);
  check_argument(ub >= 0, "biped_end_effector_layout: no body named '", upper_body, "'");
  L.link_body.push_back(ub);
  L.reaction_point = m.bodies[ub].com;
  for (const std::string& S : {left, right}) {
    const int foot = m.body_index(S + "foot");
    check_argument(foot >= 0, "biped_end_effector_layout: no body named '", S + "foot", "'");
    const int link = L.num_links();
    L.link_body.push_back(foot);
    std::vector<int> heel, toe;
    double toe_x = -1e300, heel_x = 1e300;
    for (int c = 0; c < static_cast<int>(m.contact_points.size()); ++c) {
      const contact_point& cp = m.contact_points[c];
      if (cp.body != foot) continue;
      if (cp.role == contact_point::kind::sole) {
        heel.push_back(c);
        heel_x = std::min(heel_x, cp.position.x());
      } else if (cp.role == contact_point::kind::toe) {
        toe.push_back(c);
        toe_x = std::max(toe_x, cp.position.x());
      }
    }
    check_argument(!heel.empty() && !toe.empty(), "biped_end_effector_layout: body '", S + "foot",
                   "' needs sole (heel) and toe contact points, has ", heel.size(), " and ",
                   toe.size());
    std::vector<int> both = heel;
    both.insert(both.end(), toe.begin(), toe.end());
    const int ankle = L.num_action();
    L.action.push_back({frame_type::linear, link, vec3::Zero(), both, S + "ankle"});
    // Toe corners: the front-most toe points; heel: the mean of the rear-most heel points.
    vec3 heel_mid = vec3::Zero();
    int n_heel = 0;
    for (int c : toe)
      if (m.contact_points[c].position.x() == toe_x)
        L.action.push_back({frame_type::linear_relative, link, m.contact_points[c].position, toe,
                            m.contact_points[c].name});
    for (int c : heel)
      if (m.contact_points[c].position.x() == heel_x) {
        heel_mid += m.contact_points[c].position;
        ++n_heel;
      }
    L.action.push_back({frame_type::linear_relative, link, heel_mid / n_heel, heel, S + "heel"});
    const int knee = m.dof_index(S + "knee");
    const int thigh = m.body_index(S + "thigh");
    check_argument(knee >= 0 && thigh >= 0, "biped_end_effector_layout: no DOF '", S + "knee",
                   "' or body '", S + "thigh", "'");
    const joint_limit& range = m.dofs[static_cast<std::size_t>(knee)].limit;
    L.legs.push_back({knee, thigh, ankle, range.upper >= -range.lower ? 1.0 : -1.0});
  }
  return L;
}

/// The current state of every frame (the hatted quantities of eqs. 1-3), world frame.
struct frame_states {
  vec3 reaction_position = vec3::Zero(), reaction_velocity = vec3::Zero();
  mat3 reaction_rotation = mat3::Identity();  ///< the upper body's axes e_0..e_2 as columns
  vec3 reaction_angular_velocity = vec3::Zero();
  std::vector<vec3> position, velocity;           ///< per action frame
  std::vector<vec3> relative, relative_velocity;  ///< LR: r = p - p0 (link centre p0) and its rate
};

inline frame_states make_frame_states(const end_effector_layout& L) {
  frame_states s;
  const std::size_t n = L.action.size();
  s.position.assign(n, vec3::Zero());
  s.velocity.assign(n, vec3::Zero());
  s.relative.assign(n, vec3::Zero());
  s.relative_velocity.assign(n, vec3::Zero());
  return s;
}

/// Reads the frames from a workspace whose poses and velocities are current (forward_kinematics
/// with v). The LR centre p0 is the link's COM.
template <root_joint Root>
void read_frame_states(const model<Root>& m, const workspace<Root>& ws,
                       const end_effector_layout& L, frame_states& s) {
  const int ub = L.link_body[0];
  s.reaction_rotation = ws.body_rotation[ub];
  s.reaction_angular_velocity = ws.body_angular_velocity[ub];
  s.reaction_position = point_position(m, ws, ub, L.reaction_point);
  s.reaction_velocity = point_velocity(m, ws, ub, L.reaction_point);
  for (int i = 0; i < L.num_action(); ++i) {
    const action_frame& a = L.action[i];
    const int b = L.link_body[a.link];
    s.position[i] = point_position(m, ws, b, a.point);
    s.velocity[i] = point_velocity(m, ws, b, a.point);
    const vec3 r = ws.body_rotation[b] * (a.point - m.bodies[b].com);
    s.relative[i] = r;
    s.relative_velocity[i] = ws.body_angular_velocity[b].cross(r);
  }
}

/// A desired pose and twist of an end-effector link (the planner's p(t), R(t) and their rates):
/// the body origin's world position and velocity, the body's rotation and angular velocity.
struct link_target {
  vec3 position = vec3::Zero();
  mat3 rotation = mat3::Identity();
  vec3 velocity = vec3::Zero();
  vec3 angular_velocity = vec3::Zero();
};

/// The desired state of every frame, from the links' targets (frames are fixed to their links).
template <root_joint Root>
void desired_frame_states(const model<Root>& m, const end_effector_layout& L,
                          const std::vector<link_target>& targets, frame_states& d) {
  check_size(static_cast<std::ptrdiff_t>(targets.size()), L.num_links(),
             "desired_frame_states: link targets");
  const link_target& u = targets[0];
  const vec3 ru = u.rotation * L.reaction_point;
  d.reaction_rotation = u.rotation;
  d.reaction_angular_velocity = u.angular_velocity;
  d.reaction_position = u.position + ru;
  d.reaction_velocity = u.velocity + u.angular_velocity.cross(ru);
  for (int i = 0; i < L.num_action(); ++i) {
    const action_frame& a = L.action[i];
    const link_target& t = targets[a.link];
    const vec3 rp = t.rotation * a.point;
    d.position[i] = t.position + rp;
    d.velocity[i] = t.velocity + t.angular_velocity.cross(rp);
    const vec3 r = t.rotation * (a.point - m.bodies[L.link_body[a.link]].com);
    d.relative[i] = r;
    d.relative_velocity[i] = t.angular_velocity.cross(r);
  }
}

}  // namespace gaitsynth
