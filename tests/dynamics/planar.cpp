// The planar fast path (workspace.hpp, planar_scratch) against the general 6D algorithms on random
// planar trees (planar root, every joint axis +-y, 3D joint offsets, COMs and full inertia
// tensors): poses, velocities, COM, momentum, energy and ABA with arbitrary 6D external wrenches
// must agree to rounding, whichever order the algorithms share one workspace in.
#include <catch2/catch.hpp>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;
using gaitsynth::testing::random_inertia;
using gaitsynth::testing::random_vec3;
using gaitsynth::testing::random_vector;

namespace {
/// A random tree of `nb` bodies, one hinge about +y or -y each (two parallel hinges in one body
/// would make M(q) singular).
model<planar_root> random_planar_model(std::mt19937& rng, int nb) {
  model_builder<planar_root> b("random_planar");
  std::uniform_real_distribution<double> mass(0.5, 5.0);
  std::bernoulli_distribution flip(0.5);
  b.add_body({.name = "b0",
              .mass = mass(rng),
              .com = random_vec3(rng, 0.1),
              .inertia = random_inertia(rng)});
  for (int i = 1; i < nb; ++i) {
    const int parent = std::uniform_int_distribution<int>(0, i - 1)(rng);
    const Eigen::Vector3d axis(0.0, flip(rng) ? 1.0 : -1.0, 0.0);
    b.add_body({.name = detail::concat("b", i),
                .parent = detail::concat("b", parent),
                .joint_offset = random_vec3(rng, 0.3),
                .mass = mass(rng),
                .com = random_vec3(rng, 0.15),
                .inertia = random_inertia(rng),
                .dofs = {{.name = detail::concat("j", i), .axis = axis}}});
  }
  return b.build();
}

void check_kinematics_agree(const model<planar_root>& m, const workspace<planar_root>& a,
                            const workspace<planar_root>& b) {
  for (int i = 0; i < m.num_bodies(); ++i) {
    CAPTURE(i);
    REQUIRE_THAT(Eigen::MatrixXd(a.body_rotation[i]), is_approx(b.body_rotation[i], 1e-14, 1e-14));
    REQUIRE_THAT(Eigen::MatrixXd(a.body_position[i]), is_approx(b.body_position[i], 1e-13, 1e-13));
    REQUIRE_THAT(Eigen::MatrixXd(a.body_angular_velocity[i]),
                 is_approx(b.body_angular_velocity[i], 1e-13, 1e-13));
    REQUIRE_THAT(Eigen::MatrixXd(a.body_linear_velocity[i]),
                 is_approx(b.body_linear_velocity[i], 1e-13, 1e-13));
  }
}
}  // namespace

TEST_CASE("the planar fast path is used exactly for planar roots with +-y joint axes",
          "[dynamics][planar]") {
  std::mt19937 rng(1);
  REQUIRE(make_workspace(random_planar_model(rng, 5)).scratch.planar.enabled);
  REQUIRE(make_workspace(sharon2005_human7()).scratch.planar.enabled);
  REQUIRE(make_workspace(sharon2005_human16()).scratch.planar.enabled);
  // Axes off the coordinate axes need the 6D algorithms.
  const auto m3 = gaitsynth::testing::random_model<planar_root>(
      rng, {.num_bodies = 4, .max_dofs_per_body = 1, .random_axes = true});
  REQUIRE_FALSE(make_workspace(m3).scratch.planar.enabled);
}

TEST_CASE("planar fast path: kinematics, COM, momentum, energy and ABA equal the 6D algorithms",
          "[dynamics][planar]") {
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 40; ++trial) {
    CAPTURE(trial);
    const auto m = random_planar_model(rng, 2 + trial % 9);
    auto fast = make_workspace(m);
    auto ref = make_workspace(m);
    disable_planar_path(ref);
    REQUIRE(fast.scratch.planar.enabled);
    REQUIRE_FALSE(ref.scratch.planar.enabled);
    Eigen::VectorXd q = random_vector(rng, m.nq(), 3.0);
    q.head<2>() += random_vector(rng, 2, 100.0);  // far from the origin
    const Eigen::VectorXd v = random_vector(rng, m.nv(), 4.0);
    const Eigen::VectorXd tau = random_vector(rng, m.nv(), 20.0);

    forward_kinematics(m, fast, q, v);
    forward_kinematics(m, ref, q, v);
    check_kinematics_agree(m, fast, ref);
    REQUIRE_THAT(Eigen::MatrixXd(center_of_mass(m, fast)),
                 is_approx(center_of_mass(m, ref), 1e-13, 1e-13));
    REQUIRE_THAT(Eigen::MatrixXd(com_velocity(m, fast)),
                 is_approx(com_velocity(m, ref), 1e-13, 1e-13));
    const momentum hf = centroidal_momentum(m, fast), hr = centroidal_momentum(m, ref);
    REQUIRE_THAT(Eigen::MatrixXd(hf.linear), is_approx(hr.linear, 1e-12, 1e-12));
    REQUIRE_THAT(Eigen::MatrixXd(hf.angular), is_approx(hr.angular, 1e-12, 1e-12));
    REQUIRE(kinetic_energy(m, fast) == Approx(kinetic_energy(m, ref)).epsilon(1e-12).margin(1e-12));
    REQUIRE(potential_energy(m, fast) ==
            Approx(potential_energy(m, ref)).epsilon(1e-12).margin(1e-12));

    // ABA with arbitrary 6D wrenches, out-of-plane parts included (constraint reactions only).
    for (int b = 0; b < m.num_bodies(); ++b) {
      const vec6 f = random_vector(rng, 6, 30.0);
      fast.f_ext[b] = f;
      ref.f_ext[b] = f;
    }
    const Eigen::VectorXd a_ref = aba(m, ref, q, v, tau);
    const Eigen::VectorXd a_fast = aba(m, fast, q, v, tau);
    REQUIRE_THAT(a_fast, is_approx(a_ref, 1e-12, 1e-12));
    // The 6D inverse dynamics on the same workspace (it switches to the 6D scratch) closes the
    // loop: rnea_with_external(q, v, aba(q, v, tau)) == tau.
    REQUIRE_THAT(rnea_with_external(m, fast, q, v, a_fast), is_approx(tau, 1e-11, 1e-11));
    // ... and back to the planar path for the same (q, v) and for a new v.
    REQUIRE_THAT(aba(m, fast, q, v, tau), is_approx(a_ref, 1e-12, 1e-12));
    const Eigen::VectorXd v2 = random_vector(rng, m.nv(), 4.0);
    REQUIRE_THAT(aba(m, fast, q, v2, tau), is_approx(aba(m, ref, q, v2, tau), 1e-12, 1e-12));
    check_kinematics_agree(m, fast, ref);
    REQUIRE(kinetic_energy(m, fast) == Approx(kinetic_energy(m, ref)).epsilon(1e-12).margin(1e-12));
    // CRBA and the Jacobian on a workspace whose last kinematics were planar.
    const Eigen::VectorXd q2 = random_vector(rng, m.nq(), 3.0);
    forward_kinematics(m, fast, q2, v);
    REQUIRE_THAT(crba(m, fast, q2), is_approx(crba(m, ref, q2), 1e-12, 1e-12));
    Eigen::MatrixXd Jf(3, m.nv()), Jr(3, m.nv());
    forward_kinematics(m, fast, q, v);
    point_jacobian(m, fast, q, m.num_bodies() - 1, vec3(0.1, 0.2, 0.3), Jf);
    point_jacobian(m, ref, q, m.num_bodies() - 1, vec3(0.1, 0.2, 0.3), Jr);
    REQUIRE_THAT(Jf, is_approx(Jr, 1e-13, 1e-13));
    // FK after the 6D algorithms left their scratch current: still the right velocities.
    forward_kinematics(m, fast, q, v2);
    forward_kinematics(m, ref, q, v2);
    check_kinematics_agree(m, fast, ref);
    REQUIRE_THAT(Eigen::MatrixXd(com_velocity(m, fast)),
                 is_approx(com_velocity(m, ref), 1e-13, 1e-13));
  }
}

TEST_CASE("planar fast path on the Sharon 2005 human: ABA with contact-like forces",
          "[dynamics][planar]") {
  const auto m = sharon2005_human7();
  std::mt19937 rng(7);
  auto fast = make_workspace(m);
  auto ref = make_workspace(m);
  disable_planar_path(ref);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXd q = random_vector(rng, m.nq(), 1.0);
    const Eigen::VectorXd v = random_vector(rng, m.nv(), 3.0);
    const Eigen::VectorXd tau = random_vector(rng, m.nv(), 100.0);
    forward_kinematics(m, fast, q, v);
    forward_kinematics(m, ref, q, v);
    clear_external_wrenches(fast);
    clear_external_wrenches(ref);
    for (int b = 0; b < m.num_bodies(); ++b) {
      const vec3 p = fast.body_position[b] + random_vec3(rng, 0.1);
      const vec3 f = random_vec3(rng, 500.0);
      add_point_force(m, fast, b, p, f);
      add_point_force(m, ref, b, p, f);
    }
    REQUIRE_THAT(aba(m, fast, q, v, tau), is_approx(aba(m, ref, q, v, tau), 1e-12, 1e-12));
  }
}
