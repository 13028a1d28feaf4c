#pragma once
/// \file trajectory.hpp
/// A recorded rollout: per-frame generalized state, joint torques, body poses, contacts, pushes and
/// objective terms, plus the names needed to read it back. Written by the rollout's recorder
/// (rollout/recorder.hpp), read by the viewers and exporters (viz/, io/). Plain data, no algorithms.
///
/// Units: s, m, rad, N, N m. Frames are world frame (z up); quaternions are (w, x, y, z).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
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

}  // namespace gaitsynth
