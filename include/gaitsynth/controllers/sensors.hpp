#pragma once
/// \file sensors.hpp
/// What a controller may read: a non-owning, allocation-free view of the sensed state, filled by
/// the rollout loop once per controller tick (rollout/rollout.hpp).
///
/// All quantities are in the world frame (z up) unless named otherwise, SI units:
///   - generalized q (nq), v (nv), time t (s), physics step dt (s);
///   - per body: rotation R_world_body, origin position (m), angular velocity (rad/s, world axes),
///     origin linear velocity (m/s);
///   - per body: number of its contact points touching the terrain; per contact point: touching
///     flag (from this physics step's contact evaluation, which runs before the controller: what
///     a foot sensor reports now);
///   - whole-body COM and COM velocity, and the COM relative to any body point (the stance ankle of
///     SIMBICON-style balance feedback, Wang et al. 2009 Sec. 3; d in Wang et al. 2012 Sec. 4.3);
///   - time-delayed q, v, contact counts, COM and COM velocity, body rotations and the
///     actuator's sensed values (neural delays of 5-20 ms, Wang et al. 2012 Sec. 4:
///     "time-delayed features of the body"), read from a ring buffer the rollout fills every
///     physics step (controllers/sensor_history.hpp). A controller that needs them declares
///     `double max_sensor_delay() const` (s); the rollout then sizes the buffer at set-up. Before
///     enough history exists, the oldest sample (the initial state) is returned, as if the
///     character had been still before t0, touching the ground where it touches at t0;
///   - read-only views of what the rollout already computed this step: the dynamics workspace
///     (every body's pose and velocity, the spatial scratch) and the contact state (per-point
///     positions, depths, normals and forces), so a controller never recomputes them.
///
/// Actuators with their own state (muscles) are visible through sensors_with<Root, ActuatorState>,
/// which derives from sensors<Root>: a controller taking `const sensors<Root>&` accepts both.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <span>

#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/controllers/sensor_history.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/model/model.hpp"
#include "gaitsynth/spatial/types.hpp"

namespace gaitsynth {

/// The sensed state handed to controller::command. Public members are filled by the rollout (or by
/// a test); the member functions are conveniences over them. Never owns memory.
template <root_joint Root>
struct sensors {
  const gaitsynth::model<Root>* model_ptr = nullptr;
  double t = 0.0;                                 ///< s
  double dt = 0.0;                                ///< physics timestep, s
  int step = 0;                                   ///< physics step index k (t = t0 + k dt)
  const Eigen::VectorXd* q_ptr = nullptr;         ///< nq
  const Eigen::VectorXd* v_ptr = nullptr;         ///< nv
  std::span<const mat3> body_rotation;            ///< R_world_body per body
  std::span<const vec3> body_position;            ///< body origin, world, m
  std::span<const vec3> body_angular_velocity;    ///< world axes, rad/s
  std::span<const vec3> body_linear_velocity;     ///< body origin, world, m/s
  std::span<const int> contact_count;             ///< per body: contact points touching
  std::span<const unsigned char> contact_active;  ///< per contact point: 1 if touching
  vec3 com = vec3::Zero();                        ///< whole-body centre of mass, world, m
  vec3 com_velocity = vec3::Zero();               ///< m/s
  const sensor_history* history = nullptr;  ///< delayed samples (may be null: no delay available)
  const gaitsynth::workspace<Root>* workspace_ptr =
      nullptr;                                  ///< this step's kinematics (read only)
  const contact_state* contacts_ptr = nullptr;  ///< this step's contact evaluation (read only)
  std::span<const double> sensed;  ///< the actuator's sensed values now (actuators/concept.hpp)

  const gaitsynth::model<Root>& model() const { return *model_ptr; }
  /// The rollout's workspace after this step's forward kinematics of (q, v).
  const gaitsynth::workspace<Root>& workspace() const { return *workspace_ptr; }
  const contact_state& contacts() const { return *contacts_ptr; }
  const Eigen::VectorXd& q() const { return *q_ptr; }
  const Eigen::VectorXd& v() const { return *v_ptr; }
  int num_joint_dofs() const { return model_ptr->num_joint_dofs(); }
  /// Joint DOF j's angle (rad) and rate (rad/s).
  double joint_angle(int j) const { return (*q_ptr)[Root::nq + j]; }
  double joint_velocity(int j) const { return (*v_ptr)[Root::nv + j]; }
  auto joint_angles() const { return q_ptr->tail(model_ptr->num_joint_dofs()); }
  auto joint_velocities() const { return v_ptr->tail(model_ptr->num_joint_dofs()); }

  /// Body `b`'s axes in the world: up = R e_z, forward = R e_x (the up and forward vectors of
  /// Wang et al. 2009 Sec. 3, whose projections define world-frame angles).
  vec3 body_up(int b) const { return body_rotation[b].col(2); }
  vec3 body_forward(int b) const { return body_rotation[b].col(0); }
  /// World pitch of body b about +y (planar characters; rad, positive tips +z toward +x).
  double body_pitch(int b) const {
    const mat3& R = body_rotation[b];
    return std::atan2(R(0, 2), R(2, 2));
  }
  /// World position of a point given in body b's frame, m.
  vec3 point_position(int b, const vec3& p_body) const {
    return body_position[b] + body_rotation[b] * p_body;
  }
  /// COM relative to body b's origin (the ankle when b is a foot: joints sit at body origins),
  /// world axes, m. SIMBICON's balance feedback uses its horizontal part d and the COM velocity.
  vec3 com_relative_to(int b) const { return com - body_position[b]; }
  vec3 com_relative_to(int b, const vec3& p_body) const { return com - point_position(b, p_body); }
  bool touching(int b) const { return contact_count[b] > 0; }

  /// Physics steps corresponding to a delay (s), rounded to nearest.
  int delay_steps(double delay) const {
    return dt > 0.0 ? static_cast<int>(std::lround(delay / dt)) : 0;
  }
  /// q, v and contact count `delay` seconds ago (rounded to the physics step). Without a history,
  /// the current values.
  Eigen::Ref<const Eigen::VectorXd> delayed_q(double delay) const {
    if (history == nullptr || history->size() == 0) return *q_ptr;
    return history->q(delay_steps(delay));
  }
  Eigen::Ref<const Eigen::VectorXd> delayed_v(double delay) const {
    if (history == nullptr || history->size() == 0) return *v_ptr;
    return history->v(delay_steps(delay));
  }
  double delayed_joint_angle(int j, double delay) const { return delayed_q(delay)[Root::nq + j]; }
  int delayed_contact_count(int b, double delay) const {
    if (history == nullptr || history->size() == 0) return contact_count[b];
    return history->contact_count(delay_steps(delay), b);
  }
  vec3 delayed_com(double delay) const {
    if (history == nullptr || history->size() == 0) return com;
    return history->com(delay_steps(delay));
  }
  vec3 delayed_com_velocity(double delay) const {
    if (history == nullptr || history->size() == 0) return com_velocity;
    return history->com_velocity(delay_steps(delay));
  }
  mat3 delayed_body_rotation(int b, double delay) const {
    if (history == nullptr || history->size() == 0) return body_rotation[b];
    return history->body_rotation(delay_steps(delay), b);
  }
  /// The actuator's sensed values `delay` seconds ago (e.g. normalized muscle force, fiber length).
  Eigen::Ref<const Eigen::VectorXd> delayed_sensed(double delay) const {
    if (history == nullptr || history->size() == 0)
      return Eigen::Map<const Eigen::VectorXd>(sensed.data(),
                                               static_cast<Eigen::Index>(sensed.size()));
    return history->sensed(delay_steps(delay));
  }
};

/// Sensors plus read access to the actuator's own state (muscle activation, fiber length).
template <root_joint Root, class ActuatorState>
struct sensors_with : sensors<Root> {
  const ActuatorState* actuator_state_ptr = nullptr;
  const ActuatorState& actuator_state() const { return *actuator_state_ptr; }
};

}  // namespace gaitsynth
