#pragma once
/// \file trajectory.hpp
/// A recorded rollout: per-frame generalized state, joint torques, body poses, contacts, pushes and
/// objective terms, plus the names needed to read it back. Written by the rollout's recorder
/// (rollout/recorder.hpp), read by the viewers and exporters (viz/, io/). Plain data, no algorithms.
///
/// Units: s, m, rad, N, N m. Frames are world frame (z up); quaternions are (w, x, y, z).
///
/// trajectory_channels (the end of this file) describes every per-frame member of
/// trajectory_frame: its items, components, unit and how to get and set one value. The trajectory
/// CSV (io/trajectory_csv.hpp) derives its header, writer and reader from that list, so a new
/// recorded member needs one entry there and nothing in io/.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gaitsynth {

struct trajectory_frame {
  double t = 0.0;                               ///< s
  Eigen::VectorXd q;                            ///< nq
  Eigen::VectorXd v;                            ///< nv
  Eigen::VectorXd tau;                          ///< nv: generalized force applied by the actuator (root entries 0)
  std::vector<Eigen::Vector3d> body_position;   ///< per body, world, m
  std::vector<Eigen::Quaterniond> body_orientation;  ///< per body, world
  Eigen::Vector3d com = Eigen::Vector3d::Zero();     ///< world, m
  std::vector<Eigen::Vector3d> contact_position;     ///< per contact point, world, m
  std::vector<Eigen::Vector3d> contact_force;        ///< per contact point, world, N (zero if not touching)
  std::vector<unsigned char> contact_active;         ///< per contact point, 1 if touching
  /// Active pushes at this frame: (body index, force in world frame N).
  std::vector<std::pair<int, Eigen::Vector3d>> pushes;
  std::vector<double> objective_terms;               ///< running values, named by trajectory::objective_term_names
  int controller_state = -1;  ///< controller's discrete state (FSM phase, active node), -1 if none
};

/// Heights of the terrain sampled on a regular grid, so a viewer can draw it without the policy.
struct terrain_samples {
  double x0 = -2.0, y0 = -2.0;  ///< grid origin, m
  double dx = 0.5, dy = 0.5;    ///< spacing, m
  int nx = 0, ny = 0;           ///< samples along x and y (0: flat ground at height 0)
  std::vector<double> height;   ///< nx * ny, row-major in x (height[iy * nx + ix]), m
};

struct trajectory {
  std::string model_name;
  bool planar = false;  ///< planar characters are shown in side view
  std::vector<std::string> q_names;   ///< nq names (root first)
  std::vector<std::string> v_names;   ///< nv names
  std::vector<std::string> body_names;
  std::vector<int> body_parents;
  std::vector<std::string> contact_names;
  std::vector<int> contact_bodies;
  std::vector<std::string> objective_term_names;
  terrain_samples terrain;
  std::vector<trajectory_frame> frames;

  double duration() const { return frames.empty() ? 0.0 : frames.back().t - frames.front().t; }
};

/// One per-frame member of trajectory_frame as the exporters see it: one entry per item (per q
/// coordinate, per body, ..., or one per frame), each with the same components in one unit, got
/// and set one double at a time so that a single table drives every column of a format.
struct trajectory_channel {
  /// What there is one entry per. pushed_body: each body pushed in some frame of the trajectory,
  /// the entry being the sum of that frame's pushes on the body (zero: not pushed).
  enum class per { frame, q_name, v_name, body, contact_point, pushed_body, objective_term };
  enum class presence {
    always,         ///< every frame has one entry per item
    optional,       ///< all frames or none (hand-made trajectories may leave it out)
    with_previous,  ///< exactly when the channel before it in the list is recorded
  };
  enum class value { real, flag, integer };  ///< flag: 0 or 1; integer: an int

  /// Name prefix of the columns ("q", "body"); consecutive channels of one name form a group,
  /// whose columns interleave item by item (body:pelvis:x..qz, then body:torso:x..qz).
  std::string_view name;
  std::string_view member;  ///< the trajectory_frame member, for messages
  per items = per::frame;
  std::string_view components;  ///< space-separated ("x y z"); empty: one value per item
  std::string_view unit;        ///< SI unit of every component, unless unit_of is set
  const char* (*unit_of)(std::string_view item) = nullptr;  ///< the unit by coordinate name
  presence when = presence::always;
  value type = value::real;
  std::size_t (*size)(const trajectory_frame&) = nullptr;      ///< items in a frame; null: fixed
  void (*resize)(trajectory_frame&, std::size_t n) = nullptr;  ///< make n zero items; null: fixed
  double (*get)(const trajectory_frame&, std::size_t item, int component) = nullptr;
  void (*set)(trajectory_frame&, std::size_t item, int component, double x) = nullptr;
  void (*finish)(trajectory_frame&) = nullptr;  ///< after a frame's last set(); null: none
};

namespace detail::channels {
using F = trajectory_frame;
using I = std::size_t;
using enum trajectory_channel::per;
using enum trajectory_channel::presence;
using enum trajectory_channel::value;
// Root translations are lengths (m, m/s, N), root_qw..qz quaternion components (1); every other
// coordinate (root pitch and angular velocity, joints) is an angle (rad, rad/s, N m).
inline bool root_translation(std::string_view n) {
  return n == "root_x" || n == "root_y" || n == "root_z";
}
inline const char* q_unit(std::string_view n) {
  if (root_translation(n)) return "m";
  if (n == "root_qw" || n == "root_qx" || n == "root_qy" || n == "root_qz") return "1";
  return "rad";
}
inline const char* v_unit(std::string_view n) {
  return root_translation(n) ? "m/s" : "rad/s";
}
inline const char* tau_unit(std::string_view n) {
  return root_translation(n) ? "N" : "N m";
}
template <auto M>
I count(const F& f) {
  return static_cast<I>((f.*M).size());
}
/// The entry of body b in f.pushes, kept in body order (a new entry is zero).
inline Eigen::Vector3d& push_on(F& f, I b) {
  auto it = std::find_if(f.pushes.begin(), f.pushes.end(),
                         [b](const auto& p) { return static_cast<I>(p.first) >= b; });
  if (it == f.pushes.end() || static_cast<I>(it->first) != b)
    it = f.pushes.insert(it, {static_cast<int>(b), Eigen::Vector3d::Zero()});
  return it->second;
}

// clang-format off
inline constexpr trajectory_channel list[] = {
  {.name = "t", .member = "t", .unit = "s",
   .get = [](const F& f, I, int) { return f.t; },
   .set = [](F& f, I, int, double x) { f.t = x; }},
  {.name = "q", .member = "q", .items = q_name, .unit_of = q_unit,
   .size = count<&F::q>, .resize = [](F& f, I n) { f.q.setZero(static_cast<Eigen::Index>(n)); },
   .get = [](const F& f, I i, int) { return f.q[static_cast<Eigen::Index>(i)]; },
   .set = [](F& f, I i, int, double x) { f.q[static_cast<Eigen::Index>(i)] = x; }},
  {.name = "v", .member = "v", .items = v_name, .unit_of = v_unit, .when = optional,
   .size = count<&F::v>, .resize = [](F& f, I n) { f.v.setZero(static_cast<Eigen::Index>(n)); },
   .get = [](const F& f, I i, int) { return f.v[static_cast<Eigen::Index>(i)]; },
   .set = [](F& f, I i, int, double x) { f.v[static_cast<Eigen::Index>(i)] = x; }},
  {.name = "tau", .member = "tau", .items = v_name, .unit_of = tau_unit, .when = optional,
   .size = count<&F::tau>,
   .resize = [](F& f, I n) { f.tau.setZero(static_cast<Eigen::Index>(n)); },
   .get = [](const F& f, I i, int) { return f.tau[static_cast<Eigen::Index>(i)]; },
   .set = [](F& f, I i, int, double x) { f.tau[static_cast<Eigen::Index>(i)] = x; }},
  {.name = "body", .member = "body_position", .items = body, .components = "x y z", .unit = "m",
   .when = optional, .size = count<&F::body_position>,
   .resize = [](F& f, I n) { f.body_position.assign(n, Eigen::Vector3d::Zero()); },
   .get = [](const F& f, I i, int k) { return f.body_position[i][k]; },
   .set = [](F& f, I i, int k, double x) { f.body_position[i][k] = x; }},
  {.name = "body", .member = "body_orientation", .items = body, .components = "qw qx qy qz",
   .unit = "1", .when = with_previous, .size = count<&F::body_orientation>,
   .resize = [](F& f, I n) { f.body_orientation.assign(n, Eigen::Quaterniond::Identity()); },
   .get = [](const F& f, I i, int k) {
     return k == 0 ? f.body_orientation[i].w() : f.body_orientation[i].vec()[k - 1]; },
   .set = [](F& f, I i, int k, double x) {
     (k == 0 ? f.body_orientation[i].w() : f.body_orientation[i].vec()[k - 1]) = x; }},
  {.name = "com", .member = "com", .components = "x y z", .unit = "m",
   .get = [](const F& f, I, int k) { return f.com[k]; },
   .set = [](F& f, I, int k, double x) { f.com[k] = x; }},
  {.name = "contact", .member = "contact_position", .items = contact_point,
   .components = "x y z", .unit = "m", .when = optional, .size = count<&F::contact_position>,
   .resize = [](F& f, I n) { f.contact_position.assign(n, Eigen::Vector3d::Zero()); },
   .get = [](const F& f, I i, int k) { return f.contact_position[i][k]; },
   .set = [](F& f, I i, int k, double x) { f.contact_position[i][k] = x; }},
  {.name = "contact", .member = "contact_force", .items = contact_point,
   .components = "fx fy fz", .unit = "N", .when = optional, .size = count<&F::contact_force>,
   .resize = [](F& f, I n) { f.contact_force.assign(n, Eigen::Vector3d::Zero()); },
   .get = [](const F& f, I i, int k) { return f.contact_force[i][k]; },
   .set = [](F& f, I i, int k, double x) { f.contact_force[i][k] = x; }},
  {.name = "contact", .member = "contact_active", .items = contact_point,
   .components = "active", .unit = "1", .when = optional, .type = flag,
   .size = count<&F::contact_active>,
   .resize = [](F& f, I n) { f.contact_active.assign(n, 0); },
   .get = [](const F& f, I i, int) { return f.contact_active[i] ? 1.0 : 0.0; },
   .set = [](F& f, I i, int, double x) { f.contact_active[i] = x != 0; }},
  {.name = "push", .member = "pushes", .items = pushed_body, .components = "fx fy fz",
   .unit = "N",
   .get = [](const F& f, I b, int k) {
     double sum = 0;
     for (const auto& p : f.pushes)
       if (static_cast<I>(p.first) == b) sum += p.second[k];
     return sum; },
   .set = [](F& f, I b, int k, double x) { push_on(f, b)[k] = x; },
   .finish = [](F& f) {  // a zero sum is no push
     std::erase_if(f.pushes, [](const auto& p) { return p.second.isZero(0.0); }); }},
  {.name = "obj", .member = "objective_terms", .items = objective_term,
   .unit = "-",  // in the units of each term's definition
   .size = count<&F::objective_terms>,
   .resize = [](F& f, I n) { f.objective_terms.assign(n, 0.0); },
   .get = [](const F& f, I i, int) { return f.objective_terms[i]; },
   .set = [](F& f, I i, int, double x) { f.objective_terms[i] = x; }},
  {.name = "controller_state", .member = "controller_state", .unit = "1", .type = integer,
   .get = [](const F& f, I, int) { return static_cast<double>(f.controller_state); },
   .set = [](F& f, I, int, double x) { f.controller_state = static_cast<int>(x); }},
};
// clang-format on
}  // namespace detail::channels

/// Every per-frame member of trajectory_frame, in the order of the CSV columns. To record a new
/// member, add it to trajectory_frame, fill it in the recorder (rollout/recorder.hpp) and add its
/// entry here.
inline constexpr const auto& trajectory_channels = detail::channels::list;

}  // namespace gaitsynth
