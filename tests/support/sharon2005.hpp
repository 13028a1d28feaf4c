#pragma once
// Shared helpers of the Sharon 2005 tests (helper G): a small planar biped built with the builder
// (independent of the library's characters), and a sensors view filled from a workspace.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "gaitsynth/controllers/sensors.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/model/model_builder.hpp"
#include "gaitsynth/motion/keyframes.hpp"

namespace sharon_test {

// Torso root with two legs of thigh + shin; q = [x, z, pitch, lhip, lknee, rhip, rknee].
// Segment ends are set so the mass-distance points are at the joints and the shin ends.
inline gaitsynth::planar_model small_biped() {
  using namespace gaitsynth;
  model_builder<planar_root> b("small_biped");
  const Eigen::Matrix3d I = Eigen::Vector3d(0.1, 0.1, 0.1).asDiagonal();
  b.add_body({.name = "torso",
              .mass = 10,
              .com = {0, 0, 0.25},
              .inertia = I,
              .length = 0.5,
              .segment_end = {0, 0, 0.5}});
  for (std::string s : {"l", "r"}) {
    b.add_body({.name = s + "thigh",
                .parent = "torso",
                .mass = 2,
                .com = {0, 0, -0.2},
                .inertia = I,
                .dofs = {{.name = s + "hip"}},
                .length = 0.4,
                .segment_end = {0, 0, -0.4}});
    b.add_body({.name = s + "shin",
                .parent = s + "thigh",
                .joint_offset = {0, 0, -0.4},
                .mass = 1,
                .com = {0, 0, -0.2},
                .inertia = I,
                .dofs = {{.name = s + "knee"}},
                .length = 0.4,
                .segment_end = {0, 0, -0.4}});
  }
  return b.build();
}

inline Eigen::VectorXd vec(std::initializer_list<double> x) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(x.size()));
  Eigen::Index i = 0;
  for (double e : x) v[i++] = e;
  return v;
}

// A symmetric walk of small_biped: right stance in the listed step (3 keyframes, 0.6 s).
inline gaitsynth::keyframe_motion<gaitsynth::planar_root> small_walk(
    const gaitsynth::planar_model& m) {
  using namespace gaitsynth;
  std::vector<keyframe> k = {{0.0, vec({0.0, 0.78, 0.05, 0.4, -0.1, -0.3, -0.05})},
                             {0.2, vec({0.15, 0.8, 0.0, 0.3, -0.9, -0.1, 0.0})},
                             {0.4, vec({0.3, 0.79, -0.05, 0.0, -0.4, 0.1, -0.1})}};
  return keyframe_motion<planar_root>(m, k, 0.6, true, vec({0.5, 0.0, 0.0}), stance_side::right);
}

// Sensors filled from a workspace after forward_kinematics(m, ws, q, v).
template <gaitsynth::root_joint Root>
struct sensor_fixture {
  const gaitsynth::model<Root>& m;
  gaitsynth::workspace<Root> ws;
  Eigen::VectorXd q, v;
  std::vector<int> counts;
  std::vector<unsigned char> active;
  gaitsynth::sensors<Root> s;

  explicit sensor_fixture(const gaitsynth::model<Root>& model)
      : m(model),
        ws(gaitsynth::make_workspace(model)),
        q(model.nq()),
        v(model.nv()),
        counts(model.num_bodies(), 0),
        active(model.contact_points.size(), 0) {
    q = gaitsynth::neutral_configuration(model);
    v.setZero();
  }
  const gaitsynth::sensors<Root>& update(double t = 0.0) {
    gaitsynth::forward_kinematics(m, ws, q, v);
    s.model_ptr = &m;
    s.t = t;
    s.dt = 1.0 / 2400;
    s.q_ptr = &q;
    s.v_ptr = &v;
    s.body_rotation = ws.body_rotation;
    s.body_position = ws.body_position;
    s.body_angular_velocity = ws.body_angular_velocity;
    s.body_linear_velocity = ws.body_linear_velocity;
    s.contact_count = counts;
    s.contact_active = active;
    return s;
  }
};

}  // namespace sharon_test
