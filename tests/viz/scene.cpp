// Body poses, trajectory completion and terrain interpolation of viz/scene.hpp, checked against
// hand-derived kinematics (not against the dynamics module: the viewer must not depend on it).
#include <catch2/catch.hpp>

#include <cmath>

#include "gaitsynth/model/state.hpp"
#include "gaitsynth/viz/scene.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

TEST_CASE("compute_body_poses: planar chain matches hand-derived positions", "[viz][scene]") {
  const auto m = viz_test::make_biped<planar_root>();
  Eigen::VectorXd q = neutral_configuration(m);
  const double x = 0.3, z = 1.1, pitch = 0.2, hip = -0.5, knee = 0.7;
  q[0] = x;
  q[1] = z;
  q[2] = pitch;
  q[planar_root::nq + m.dof_index("lhip")] = hip;
  q[planar_root::nq + m.dof_index("lknee")] = knee;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Quaterniond> r;
  compute_body_poses(m, q, p, r);
  // A rotation a about +y maps (0, 0, -L) to (-L sin a, 0, -L cos a) and (u, 0, w) to
  // (u cos a + w sin a, 0, -u sin a + w cos a).
  auto ry = [](double a, Eigen::Vector3d v) {
    return Eigen::Vector3d(v.x() * std::cos(a) + v.z() * std::sin(a), v.y(),
                           -v.x() * std::sin(a) + v.z() * std::cos(a));
  };
  const Eigen::Vector3d pelvis(x, 0, z);
  const Eigen::Vector3d hipj = pelvis + ry(pitch, {0, 0.1, -0.07});
  const Eigen::Vector3d kneej = hipj + ry(pitch + hip, {0, 0, -viz_test::thigh_len});
  const Eigen::Vector3d ankle = kneej + ry(pitch + hip + knee, {0, 0, -viz_test::shin_len});
  CHECK((p[0] - pelvis).norm() < 1e-14);
  CHECK((p[m.body_index("lthigh")] - hipj).norm() < 1e-14);
  CHECK((p[m.body_index("lshin")] - kneej).norm() < 1e-14);
  CHECK((p[m.body_index("lfoot")] - ankle).norm() < 1e-14);
  const Eigen::Quaterniond shin = r[m.body_index("lshin")];
  CHECK(shin.angularDistance(Eigen::Quaterniond(
            Eigen::AngleAxisd(pitch + hip + knee, Eigen::Vector3d::UnitY()))) < 1e-12);
}

TEST_CASE("compute_body_poses: floating root and two DOFs in one body", "[viz][scene]") {
  const auto m = viz_test::make_biped<floating_root>();
  Eigen::VectorXd q = neutral_configuration(m);
  const Eigen::Quaterniond root(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  q.head<3>() << 1, 2, 3;
  q.segment<4>(3) << root.w(), root.x(), root.y(), root.z();
  const int hx = m.dof_index("rhip_x"), hy = m.dof_index("rhip");
  q[7 + hx] = 0.3;
  q[7 + hy] = -0.6;
  std::vector<Eigen::Vector3d> p;
  std::vector<Eigen::Quaterniond> r;
  compute_body_poses(m, q, p, r);
  const int thigh = m.body_index("rthigh");
  // Intrinsic composition in DOF order (model.hpp): R = R_root * Rx(0.3) * Ry(-0.6).
  const Eigen::Matrix3d expected =
      root.toRotationMatrix() *
      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix() *
      Eigen::AngleAxisd(-0.6, Eigen::Vector3d::UnitY()).toRotationMatrix();
  CHECK((r[thigh].toRotationMatrix() - expected).norm() < 1e-12);
  CHECK((p[thigh] - (Eigen::Vector3d(1, 2, 3) + root * Eigen::Vector3d(0, -0.1, -0.07))).norm() <
        1e-12);
  // A root joint_offset shifts the root origin (root origin = joint_offset + q[0:3], as in
  // dynamics/kinematics.hpp and io/mjcf.hpp) and with it every body.
  auto shifted = m;
  shifted.bodies[0].joint_offset = {0.1, -0.2, 0.3};
  std::vector<Eigen::Vector3d> p2;
  std::vector<Eigen::Quaterniond> r2;
  compute_body_poses(shifted, q, p2, r2);
  for (int b = 0; b < m.num_bodies(); ++b) {
    CHECK((p2[b] - p[b] - Eigen::Vector3d(0.1, -0.2, 0.3)).norm() < 1e-14);
    CHECK(r2[b].angularDistance(r[b]) < 1e-14);
  }
  Eigen::VectorXd bad = q.head(5);
  CHECK_THROWS_AS(compute_body_poses(m, bad, p, r), std::invalid_argument);
}

TEST_CASE("fill_missing_kinematics completes a hand-made trajectory", "[viz][scene]") {
  const auto m = viz_test::make_biped<planar_root>();
  trajectory traj;
  trajectory_frame fr;
  fr.q = neutral_configuration(m);
  fr.q[1] = 1.0;
  traj.frames.push_back(fr);
  fill_missing_kinematics(m, traj);
  REQUIRE(traj.q_names.size() == static_cast<std::size_t>(m.nq()));
  CHECK(traj.q_names[0] == "root_x");
  CHECK(traj.q_names[3] == m.dofs[0].name);
  CHECK(traj.planar);
  CHECK(traj.body_parents[m.body_index("lshin")] == m.body_index("lthigh"));
  const auto& f = traj.frames[0];
  REQUIRE(f.body_position.size() == static_cast<std::size_t>(m.num_bodies()));
  REQUIRE(f.contact_position.size() == m.contact_points.size());
  // Standing straight at q = 0 (root at z = 1): the heel is at 1 - 0.07 - 0.45 - 0.45 - 0.06.
  CHECK(f.contact_position[m.contact_points.size() == 4 ? 0 : 0].z() ==
        Approx(1 - 0.07 - 0.9 - 0.06).margin(1e-12));
  // COM: mass-weighted mean of the bodies' COMs, x = sum m_i c_x / M (only the feet are offset).
  CHECK(f.com.x() == Approx(2 * 1 * 0.05 / m.total_mass()).margin(1e-12));
  traj.frames[0].q = Eigen::VectorXd::Zero(2);
  traj.frames[0].body_position.clear();
  CHECK_THROWS_WITH(fill_missing_kinematics(m, traj),
                    Catch::Contains("frame 0") && Catch::Contains("nq"));
}

TEST_CASE("terrain_height interpolates the samples bilinearly and is exact on planes",
          "[viz][scene]") {
  terrain_samples ts;
  CHECK(terrain_height(ts, 3, 4) == 0.0);  // flat ground
  ts.x0 = -1;
  ts.y0 = -2;
  ts.dx = 0.5;
  ts.dy = 0.25;
  ts.nx = 9;
  ts.ny = 17;
  auto plane = [](double x, double y) { return 0.1 + 0.2 * x - 0.05 * y; };
  for (int j = 0; j < ts.ny; ++j)
    for (int i = 0; i < ts.nx; ++i)
      ts.height.push_back(plane(ts.x0 + i * ts.dx, ts.y0 + j * ts.dy));
  for (double x : {-1.0, -0.7, 0.0, 1.13, 2.9})
    for (double y : {-2.0, -1.1, 0.37, 1.99})
      CHECK(terrain_height(ts, x, y) == Approx(plane(x, y)).margin(1e-12));
  // Outside the grid: the edge value (clamped).
  CHECK(terrain_height(ts, 10, 0) == Approx(plane(3, 0)).margin(1e-12));
  CHECK(terrain_height(ts, -5, -7) == Approx(plane(-1, -2)).margin(1e-12));
}

TEST_CASE("side_of_body follows the mirror map", "[viz][scene]") {
  const auto m = viz_test::make_biped<planar_root>();
  CHECK(side_of_body(m, m.body_index("lthigh")) == body_side::left);
  CHECK(side_of_body(m, m.body_index("rfoot")) == body_side::right);
  CHECK(side_of_body(m, m.body_index("torso")) == body_side::centre);
}
