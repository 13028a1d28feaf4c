// The Wang et al. 2009 humanoids (every Fig. 8 body shape) standing for 1.5 s on their 16 foot and
// toe contact points with the default contact parameters at 2400 Hz: the simulation stays finite
// and bounded, the character stays up, and both feet keep >= 3 points on the ground (the paper's
// "firmly planted"). With the plain explicit damper the same set-up diverges (the toes are light).
// A limp humanoid falls and lies on the ground on its 43 body points (role other) instead of
// sinking through it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/center_of_mass.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/joint_limits.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"

using namespace gaitsynth;

namespace {
struct stand_result {
  bool finite = true;
  double com_drop = 0.0;  // initial minus lowest COM height, m
  int min_left = 1000,
      min_right = 1000;  // fewest points touching on each foot + toes (after 0.1 s)
  double final_speed = 0.0;
};

/// Holds the neutral pose with joint PD gains from the joint-space inertia (a 10 Hz servo on each
/// joint's effective inertia 1 / (M^-1)_jj; at least 1500 N m/rad so the ankles carry the body,
/// at most what explicit Euler keeps stable), on flat ground, for `seconds`.
stand_result stand(const floating_model& m, const contact_parameters& p, double seconds) {
  const double dt = 1.0 / 2400.0, w = 2 * std::numbers::pi * 10.0;
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  Eigen::VectorXd q = standing_configuration(m, 0.0), v = Eigen::VectorXd::Zero(m.nv());
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  const int nj = m.num_joint_dofs();
  const Eigen::MatrixXd Minv = crba(m, ws, q).inverse();
  Eigen::VectorXd kp(nj), kd(nj);
  for (int j = 0; j < nj; ++j) {
    const double inv_i = Minv(6 + j, 6 + j);
    kp[j] = std::min(std::max(w * w / inv_i, 1500.0), 0.25 / (inv_i * dt * dt));
    kd[j] = 2 * w / inv_i;
  }
  const int lfoot = m.body_index("lfoot"), ltoes = m.body_index("ltoes");
  const int rfoot = m.body_index("rfoot"), rtoes = m.body_index("rtoes");
  forward_kinematics(m, ws, q, v);
  const double z0 = center_of_mass(m, ws).z();
  stand_result r;
  const int steps = static_cast<int>(seconds / dt);
  for (int k = 0; k < steps; ++k) {
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, flat_terrain(), p, cs, dt);
    tau.tail(nj) = -kp.cwiseProduct(q.tail(nj)) - kd.cwiseProduct(v.tail(nj));
    v += dt * aba(m, ws, q, v, tau);
    integrate_configuration(m, q, v, dt, q);
    if (!q.allFinite() || !v.allFinite() || v.cwiseAbs().maxCoeff() > 1e3) {
      r.finite = false;
      return r;
    }
    r.com_drop = std::max(r.com_drop, z0 - center_of_mass(m, ws).z());
    if (k * dt > 0.1) {
      r.min_left = std::min(r.min_left, cs.points_touching[lfoot] + cs.points_touching[ltoes]);
      r.min_right = std::min(r.min_right, cs.points_touching[rfoot] + cs.points_touching[rtoes]);
    }
  }
  r.final_speed = v.head<3>().norm();
  return r;
}
}  // namespace

TEST_CASE("Wang 2009 humanoids stand on 16 contact points at 2400 Hz", "[contact][humanoid]") {
  for (const wang2009_shape shape : wang2009_shapes) {
    const auto m = wang2009_humanoid(shape);
    REQUIRE(m.contact_points.size() >= 16);
    INFO(m.name);
    const stand_result r = stand(m, contact_parameters{}, 1.5);
    CHECK(r.finite);
    CHECK(r.com_drop < 0.01);
    CHECK(r.min_left >= 3);
    CHECK(r.min_right >= 3);
    CHECK(r.final_speed < 0.1);
  }
}

TEST_CASE("without implicit damping the humanoid's toes diverge", "[contact][humanoid]") {
  // The reason contact_parameters::implicit_damping defaults to true (penalty_contact.hpp).
  contact_parameters p;
  p.implicit_damping = false;
  const stand_result r = stand(wang2009_humanoid(), p, 0.1);
  CHECK_FALSE(r.finite);
}

namespace {
/// Lowest point of a sphere, box or capsule shape of a body at (p, R), world z.
double lowest_z(const shape& s, const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
  switch (s.type) {
    case shape::kind::sphere:
      return (p + R * s.center).z() - s.radius;
    case shape::kind::capsule:
      return std::min((p + R * s.p0).z(), (p + R * s.p1).z()) - s.radius;
    case shape::kind::box: {
      // The lowest corner: centre minus the half extents along the body axes, each taken downward.
      const Eigen::Vector3d down_in_body = R.transpose() * Eigen::Vector3d(0, 0, -1);
      return (p + R * (s.center + s.half_extents.cwiseProduct(down_in_body.cwiseSign()))).z();
    }
  }
  return 0.0;
}

struct fall_result {
  bool finite = true;
  double com_z = 0.0;          // final COM height, m
  double com_drift = 0.0;      // COM displacement over the last 0.5 s, m
  double head_low = 0.0;       // final lowest point of the head sphere, m
  double head_low_min = 0.0;   // its minimum over the fall, m
  double trunk_low = 0.0;      // final lowest corner of the pelvis and torso boxes, m
  double trunk_low_min = 0.0;  // its minimum over the fall, m
};

/// The humanoid standing at q = 0, limp (zero actuator torques, only the passive joint-limit
/// torques), pitched by an initial root angular velocity `pitch_rate` (rad/s, + forward), on
/// flat ground for `seconds` at 2400 Hz (semi-implicit Euler).
fall_result fall_limp(const floating_model& m, double pitch_rate, double seconds) {
  const double dt = 1.0 / 2400.0;
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  Eigen::VectorXd q = standing_configuration(m, 0.0), v = Eigen::VectorXd::Zero(m.nv());
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(m.nv());
  v[4] = pitch_rate;  // root_wy: about the (upright) pelvis's y axis, + tips the head forward
  const int head = m.body_index("head"), pelvis = m.body_index("pelvis");
  const int torso = m.body_index("torso");
  const int steps = static_cast<int>(seconds / dt), settle = steps - static_cast<int>(0.5 / dt);
  // Lowest point of the body's first shape (the head sphere, the trunk boxes) now.
  const auto low = [&](int b) {
    return lowest_z(m.bodies[b].shapes[0], ws.body_position[b], ws.body_rotation[b]);
  };
  fall_result r;
  r.head_low_min = r.trunk_low_min = 1e9;
  Eigen::Vector3d com_settle = Eigen::Vector3d::Zero();
  for (int k = 0; k < steps; ++k) {
    forward_kinematics(m, ws, q, v);
    if (k == settle) com_settle = center_of_mass(m, ws);
    r.head_low_min = std::min(r.head_low_min, low(head));
    r.trunk_low_min = std::min({r.trunk_low_min, low(pelvis), low(torso)});
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, flat_terrain(), contact_parameters{}, cs, dt);
    tau.setZero();
    joint_limit_torques(m, q, v, tau);
    v += dt * aba(m, ws, q, v, tau);
    integrate_configuration(m, q, v, dt, q);
    if (!q.allFinite() || !v.allFinite() || v.cwiseAbs().maxCoeff() > 1e3) {
      r.finite = false;
      return r;
    }
  }
  forward_kinematics(m, ws, q, v);
  const Eigen::Vector3d com = center_of_mass(m, ws);
  r.com_z = com.z();
  r.com_drift = (com - com_settle).norm();
  r.head_low = low(head);
  r.trunk_low = std::min(low(pelvis), low(torso));
  return r;
}
}  // namespace

TEST_CASE("a limp humanoid falls and lies on the ground", "[contact][humanoid]") {
  // Without the body points the head ended 1.0-1.6 m below the ground and the COM 0.75-0.95 m.
  // Forward (prone) and backward (supine) falls of three body shapes, 3 s each: the character
  // comes to rest with its COM above the ground, its head on the ground (the lowest point of the
  // head sphere within 2 cm of it, at rest and during the fall), and its trunk boxes' corners
  // (contact points) 1 cm at most into it at rest (about 3 cm on impact: kp = 75000 N/m per point
  // is soft for a 20 kg torso landing at 3 m/s). The arms may sink further (up to about 2 limb
  // radii): their capsules carry points on a few sides only.
  struct fall_case {
    wang2009_shape shape;
    double pitch_rate;  // rad/s, + forward
  };
  for (const fall_case c :
       {fall_case{wang2009_shape::stocky, 0.1}, fall_case{wang2009_shape::thin, -0.1},
        fall_case{wang2009_shape::tall, 0.1}}) {
    const floating_model m = wang2009_humanoid(c.shape);
    INFO(m.name << ", pitch rate " << c.pitch_rate);
    const fall_result r = fall_limp(m, c.pitch_rate, 3.0);
    REQUIRE(r.finite);
    CHECK(r.com_z > 0.05);      // lying: the COM about 0.1-0.15 m up
    CHECK(r.com_z < 0.3);       // and it did fall
    CHECK(r.com_drift < 0.01);  // at rest
    CHECK(r.head_low > -0.02);  // on the ground,
    CHECK(r.head_low < 0.02);   // not held above it
    CHECK(r.head_low_min > -0.02);
    CHECK(r.trunk_low > -0.01);
    CHECK(r.trunk_low_min > -0.05);
  }
}
