// The Wang et al. 2009 humanoids (every Fig. 8 body shape) standing for 1.5 s on their 16 foot and
// toe contact points with the default contact parameters at 2400 Hz: the simulation stays finite
// and bounded, the character stays up, and both feet keep >= 3 points on the ground (the paper's
// "firmly planted"). With the plain explicit damper the same set-up diverges (the toes are light).
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
