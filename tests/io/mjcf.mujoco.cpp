// MuJoCo as an independent oracle for gaitsynth's dynamics, through the MJCF exporter (built only
// when MuJoCo is found). Each model is exported, loaded with mj_loadXML, and for random states
// (random unit quaternion, joint angles in [-pi, pi], random velocities and torques) compared with
// gaitsynth:
//   * joint-space inertia:  mj_fullM(qM) after mj_forward  vs  crba
//   * bias forces:          qfrc_bias (C v + g)             vs  nonlinear_effects
//   * forward dynamics:     qacc with ctrl = tau            vs  aba(q, v, tau)
//   * the same with random external wrenches (xfrc_applied at each body's COM) vs aba with f_ext
//   * body poses and velocities (xpos, xmat, mj_objectVelocity of the XBODY) and contact sites vs
//     forward_kinematics / point_position.
// MuJoCo runs pure rigid-body dynamics: no armature, damping or friction loss in the file, and
// constraints, limits, contacts, passive forces and control clamping disabled (pure_rigid_body).
//
// Metric: for a vector or matrix x with MuJoCo's value x_mj (permuted to gaitsynth's coordinate
// order), err = max_i |x_i - x_mj,i| / max_i |x_mj,i|, the largest element error relative to the
// largest element (an infinity-norm relative error). Both codes are exact up to rounding, so the
// error measures accumulated floating-point error; the bound is 1e-8 for M and bias. ddq = M^-1
// (...) inherits M's condition number (light toes and hands make it large), so for ddq the bound
// applies to the backward error max|M (ddq - ddq_mj)| / (max|M| max|ddq_mj|), what a stable solve
// of either code guarantees (rounding-level, ~1e-16 n), and the plain relative error of ddq only
// has to stay below a conditioning allowance of 1e-6 (observed: up to ~1e-8 for the Wu biped).
// Positions and rotations are compared absolutely (m, unitless) to 1e-12 scaled by their size.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/crba.hpp"
#include "gaitsynth/dynamics/kinematics.hpp"
#include "gaitsynth/dynamics/rnea.hpp"
#include "gaitsynth/dynamics/workspace.hpp"
#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/models.hpp"
#include "io/mjcf_mujoco_support.hpp"
#include "io/mjcf_test_models.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using mjcf_test::load_in_mujoco;

namespace {

using rowmat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

template <class A, class B>
double relerr(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& ref) {
  const double scale = ref.cwiseAbs().maxCoeff();
  return (a - ref).cwiseAbs().maxCoeff() / (scale > 0 ? scale : 1.0);
}

struct oracle_errors {
  double M = 0, bias = 0, ddq = 0, ddq_ext = 0, ddq_force = 0, pos = 0, rot = 0, vel = 0, site = 0;
  void max_with(const oracle_errors& o) {
    M = std::max(M, o.M);
    bias = std::max(bias, o.bias);
    ddq = std::max(ddq, o.ddq);
    ddq_ext = std::max(ddq_ext, o.ddq_ext);
    ddq_force = std::max(ddq_force, o.ddq_force);
    pos = std::max(pos, o.pos);
    rot = std::max(rot, o.rot);
    vel = std::max(vel, o.vel);
    site = std::max(site, o.site);
  }
};

constexpr double tol_dyn = 1e-8;        // relative, M / bias
constexpr double tol_backward = 1e-12;  // backward error of ddq (observed <= ~1e-15)
constexpr double tol_ddq = 1e-6;        // relative, ddq itself (allowance for M's conditioning)
constexpr double tol_kin = 1e-12;       // absolute (scaled by 1 + magnitude), poses and velocities

/// A random state that covers the whole configuration space, not only the joint ranges.
template <root_joint Root>
sim_state random_state(const model<Root>& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> g;
  sim_state s = make_state(m);
  if constexpr (Root::nq == 7) {
    for (int i = 0; i < 3; ++i) s.q[i] = 3.0 * u(rng);
    Eigen::Vector4d qv(g(rng), g(rng), g(rng), g(rng));
    s.q.segment<4>(3) = qv.normalized();
  } else if constexpr (Root::nq == 3) {
    s.q[0] = 3.0 * u(rng);
    s.q[1] = 3.0 * u(rng);
    s.q[2] = std::numbers::pi * u(rng);
  }
  for (int j = 0; j < m.num_joint_dofs(); ++j) s.q[Root::nq + j] = std::numbers::pi * u(rng);
  for (int i = 0; i < m.nv(); ++i) s.v[i] = 3.0 * u(rng);
  return s;
}

/// Compares one model with MuJoCo at `n` random states; CHECKs every bound and returns the
/// largest errors seen.
template <root_joint Root>
oracle_errors compare_with_mujoco(const model<Root>& gm, int n, unsigned seed) {
  INFO("model " << gm.name);
  mjcf_options opt;
  opt.contact_geoms = true;  // geoms must not change the dynamics (they carry no mass)
  const auto mj = load_in_mujoco(gm, opt);
  CHECK(mj->warnings.empty());
  mjModel* m = mj->m;
  mjData* d = mj->d;
  mjcf_test::pure_rigid_body(m);
  REQUIRE(m->nq == gm.nq());
  REQUIRE(m->nv == gm.nv());
  REQUIRE(m->nbody == gm.num_bodies() + 1);
  REQUIRE(m->nu == gm.num_joint_dofs());

  // MuJoCo's own numbering of the joints agrees with the exporter's permutation maps.
  const auto qi = mjcf_qpos_index(gm), vi = mjcf_qvel_index(gm);
  for (int j = 0; j < gm.num_joint_dofs(); ++j) {
    const int id = mj_name2id(m, mjOBJ_JOINT, gm.dofs[j].name.c_str());
    REQUIRE(id >= 0);
    CHECK(qi[m->jnt_qposadr[id]] == Root::nq + j);
    CHECK(vi[m->jnt_dofadr[id]] == Root::nv + j);
    CHECK(m->actuator_trnid[2 * j] == id);  // actuators in gaitsynth DOF order
  }
  // Mass properties as MuJoCo compiled them (principal axes + quaternion) reproduce the model's.
  std::vector<int> body_id(gm.bodies.size());
  for (int b = 0; b < gm.num_bodies(); ++b) {
    body_id[b] = mj_name2id(m, mjOBJ_BODY, gm.bodies[b].name.c_str());
    REQUIRE(body_id[b] >= 1);
    const int id = body_id[b];
    CHECK(m->body_mass[id] == gm.bodies[b].mass);
    CHECK((Eigen::Map<const Eigen::Vector3d>(m->body_ipos + 3 * id) - gm.bodies[b].com).norm() <=
          1e-15 * (1 + gm.bodies[b].com.norm()));
    const Eigen::Quaterniond iq(m->body_iquat[4 * id], m->body_iquat[4 * id + 1],
                                m->body_iquat[4 * id + 2], m->body_iquat[4 * id + 3]);
    const Eigen::Matrix3d R = iq.normalized().toRotationMatrix();
    const Eigen::Matrix3d I =
        R * Eigen::Map<const Eigen::Vector3d>(m->body_inertia + 3 * id).asDiagonal() *
        R.transpose();
    CHECK(relerr(I, gm.bodies[b].inertia) <= 1e-14);
  }

  workspace<Root> ws = make_workspace(gm);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  oracle_errors worst;
  rowmat Mmj(gm.nv(), gm.nv());
  for (int trial = 0; trial < n; ++trial) {
    INFO("state " << trial);
    const sim_state s = random_state(gm, rng);
    Eigen::VectorXd tau(gm.nv());
    tau.setZero();
    for (int j = 0; j < gm.num_joint_dofs(); ++j) tau[Root::nv + j] = 50.0 * u(rng);

    mj_resetData(m, d);
    Eigen::Map<Eigen::VectorXd>(d->qpos, m->nq) = to_mjcf_qpos(gm, s.q);
    Eigen::Map<Eigen::VectorXd>(d->qvel, m->nv) = to_mjcf_qvel(gm, s.v);
    for (int j = 0; j < gm.num_joint_dofs(); ++j) d->ctrl[j] = tau[Root::nv + j];
    mj_forward(m, d);

    oracle_errors e;
    // Joint-space inertia, permuted: M_mj(k, l) = M(vi[k], vi[l]).
    mj_fullM(m, Mmj.data(), d->qM);
    const Eigen::MatrixXd& M = crba(gm, ws, s.q);
    Eigen::MatrixXd Mperm(gm.nv(), gm.nv());
    for (int k = 0; k < gm.nv(); ++k)
      for (int l = 0; l < gm.nv(); ++l) Mperm(k, l) = M(vi[k], vi[l]);
    e.M = relerr(Mperm, Mmj);
    const Eigen::VectorXd bias_mj =
        from_mjcf_qvel(gm, Eigen::Map<const Eigen::VectorXd>(d->qfrc_bias, m->nv));
    e.bias = relerr(nonlinear_effects(gm, ws, s.q, s.v), bias_mj);
    const Eigen::VectorXd qacc_mj =
        from_mjcf_qvel(gm, Eigen::Map<const Eigen::VectorXd>(d->qacc, m->nv));
    clear_external_wrenches(ws);
    const Eigen::VectorXd ddq = aba(gm, ws, s.q, s.v, tau);
    e.ddq = relerr(ddq, qacc_mj);
    const Eigen::MatrixXd Mg = crba(gm, ws, s.q);
    const double scale = Mg.cwiseAbs().maxCoeff();
    e.ddq_force = relerr(Mg * ddq, Mg * qacc_mj) * (Mg * qacc_mj).cwiseAbs().maxCoeff() /
                  (scale * qacc_mj.cwiseAbs().maxCoeff());

    // Kinematics: body origins, orientations, origin velocities; contact sites.
    forward_kinematics(gm, ws, s.q, s.v);
    for (int b = 0; b < gm.num_bodies(); ++b) {
      const int id = body_id[b];
      const Eigen::Vector3d xpos = Eigen::Map<const Eigen::Vector3d>(d->xpos + 3 * id);
      const Eigen::Matrix3d xmat = Eigen::Map<const rowmat>(d->xmat + 9 * id, 3, 3);
      e.pos = std::max(e.pos, (ws.body_position[b] - xpos).norm() / (1 + xpos.norm()));
      e.rot = std::max(e.rot, (ws.body_rotation[b] - xmat).cwiseAbs().maxCoeff());
      mjtNum vel[6];
      // mjOBJ_XBODY: at the body frame's origin (mjOBJ_BODY would give the COM's velocity).
      mj_objectVelocity(m, d, mjOBJ_XBODY, id, vel, 0);  // [angular; linear], world axes
      const Eigen::Map<const Eigen::Vector3d> w(vel), lin(vel + 3);
      e.vel = std::max(e.vel, (ws.body_angular_velocity[b] - w).norm() / (1 + w.norm()));
      e.vel = std::max(e.vel, (ws.body_linear_velocity[b] - lin).norm() / (1 + lin.norm()));
    }
    for (const contact_point& c : gm.contact_points) {
      const int id = mj_name2id(m, mjOBJ_SITE, c.name.c_str());
      REQUIRE(id >= 0);
      const Eigen::Vector3d sp = Eigen::Map<const Eigen::Vector3d>(d->site_xpos + 3 * id);
      e.site = std::max(e.site,
                        (point_position(gm, ws, c.body, c.position) - sp).norm() / (1 + sp.norm()));
    }

    // External wrenches: MuJoCo applies xfrc_applied = [force; torque] at the body's COM (xipos);
    // gaitsynth's f_ext is [torque about the body origin; force], both in world axes.
    clear_external_wrenches(ws);
    for (int b = 0; b < gm.num_bodies(); ++b) {
      const int id = body_id[b];
      const Eigen::Vector3d f(100 * u(rng), 100 * u(rng), 100 * u(rng));
      const Eigen::Vector3d t(10 * u(rng), 10 * u(rng), 10 * u(rng));
      Eigen::Map<Eigen::Vector3d>(d->xfrc_applied + 6 * id) = f;
      Eigen::Map<Eigen::Vector3d>(d->xfrc_applied + 6 * id + 3) = t;
      const Eigen::Vector3d com = Eigen::Map<const Eigen::Vector3d>(d->xipos + 3 * id);
      ws.f_ext[b].template head<3>() = t + (com - ws.body_position[b]).cross(f);
      ws.f_ext[b].template tail<3>() = f;
    }
    mj_forward(m, d);
    const Eigen::VectorXd qacc_ext =
        from_mjcf_qvel(gm, Eigen::Map<const Eigen::VectorXd>(d->qacc, m->nv));
    const Eigen::VectorXd ddq_ext = aba(gm, ws, s.q, s.v, tau);
    e.ddq_ext = relerr(ddq_ext, qacc_ext);
    e.ddq_force = std::max(e.ddq_force, relerr(Mg * ddq_ext, Mg * qacc_ext) *
                                            (Mg * qacc_ext).cwiseAbs().maxCoeff() /
                                            (scale * qacc_ext.cwiseAbs().maxCoeff()));
    clear_external_wrenches(ws);

    CHECK(e.M <= tol_dyn);
    CHECK(e.bias <= tol_dyn);
    CHECK(e.ddq_force <= tol_backward);
    CHECK(e.ddq <= tol_ddq);
    CHECK(e.ddq_ext <= tol_ddq);
    CHECK(e.pos <= tol_kin);
    CHECK(e.rot <= tol_kin);
    CHECK(e.vel <= tol_kin);
    CHECK(e.site <= tol_kin);
    worst.max_with(e);
  }
  // Set GAITSYNTH_ORACLE_REPORT=1 to print the largest errors (docs/mjcf.md quotes them).
  if (std::getenv("GAITSYNTH_ORACLE_REPORT"))
    std::cout << "oracle " << gm.name << " (nv " << gm.nv() << ", " << n << " states): M "
              << worst.M << "  bias " << worst.bias << "  ddq " << worst.ddq << "  ddq+f_ext "
              << worst.ddq_ext << "  ddq backward " << worst.ddq_force << "  pos " << worst.pos
              << "  rot " << worst.rot << "  vel " << worst.vel << "  sites " << worst.site << "\n";
  return worst;
}

constexpr int states_per_model = 20;

}  // namespace

TEST_CASE("MuJoCo agrees with gaitsynth on the test characters", "[io][mjcf][mujoco]") {
  compare_with_mujoco(mjcf_test::planar_biped7(), states_per_model, 1);
  compare_with_mujoco(mjcf_test::humanoid3d(), states_per_model, 2);
  compare_with_mujoco(mjcf_test::fixed_arm(), states_per_model, 3);
}

TEST_CASE("MuJoCo agrees with gaitsynth on the built-in characters", "[io][mjcf][mujoco]") {
  compare_with_mujoco(sharon2005_human7(), states_per_model, 11);
  compare_with_mujoco(sharon2005_human16(), states_per_model, 12);
  unsigned seed = 13;
  for (wang2009_shape s : wang2009_shapes)
    compare_with_mujoco(wang2009_humanoid(s), states_per_model, seed++);
  compare_with_mujoco(wang2012_humanoid(), states_per_model, 20);
  compare_with_mujoco(wu2010_biped(), states_per_model, 21);
}

TEST_CASE("MuJoCo agrees with gaitsynth on random trees", "[io][mjcf][mujoco]") {
  std::mt19937 rng(2024);
  for (int k = 0; k < 4; ++k) {
    testing::random_model_options o;
    o.num_bodies = 4 + 4 * k;
    o.branching = k != 1;
    compare_with_mujoco(testing::random_model<floating_root>(rng, o), 5, 100 + k);
    compare_with_mujoco(testing::random_model<planar_root>(rng, o), 5, 200 + k);
    compare_with_mujoco(testing::random_model<fixed_root>(rng, o), 5, 300 + k);
  }
  // Breadth-first-listed trees (MuJoCo's order is a real permutation) and offset roots (a floating
  // root with an offset is exported as slides + ball; planar and fixed roots sit at the offset).
  auto tree = mjcf_test::random_tree<floating_root>(rng, 14);
  compare_with_mujoco(tree, 5, 400);
  tree.bodies[0].joint_offset = Eigen::Vector3d(0.3, -0.2, 1.1);
  compare_with_mujoco(tree, 5, 401);
  auto ptree = mjcf_test::random_tree<planar_root>(rng, 10);
  ptree.bodies[0].joint_offset = Eigen::Vector3d(0.2, 0.1, 0.9);
  compare_with_mujoco(ptree, 5, 402);
  auto ftree = mjcf_test::random_tree<fixed_root>(rng, 10);
  ftree.bodies[0].joint_offset = Eigen::Vector3d(-0.4, 0.1, 0.5);
  compare_with_mujoco(ftree, 5, 403);
}

TEST_CASE("the exported file loads in MuJoCo without warnings under every option set",
          "[io][mjcf][mujoco]") {
  const auto h = mjcf_test::humanoid3d();
  mjcf_options viewer;  // defaults: floor, shapes, sites, limits, motors
  viewer.keyframe_q = neutral_configuration(h);
  viewer.keyframe_q[2] = 1.0;
  viewer.keyframe_q[7 + h.dof_index("lknee")] = 0.3;
  viewer.keyframe_v = Eigen::VectorXd::Zero(h.nv());
  viewer.keyframe_v[0] = 0.5;
  const auto a = load_in_mujoco(h, viewer);
  CHECK(a->warnings.empty());
  CHECK(a->m->ngeom == 1 + 15);  // floor + one shape per body
  CHECK(a->m->nsite == 16);
  CHECK(a->m->nkey == 1);
  // The keyframe puts the state where gaitsynth's q and v say.
  mj_resetDataKeyframe(a->m, a->d, 0);
  CHECK(from_mjcf_qpos(h, Eigen::Map<const Eigen::VectorXd>(a->d->qpos, a->m->nq)) ==
        viewer.keyframe_q);
  CHECK(from_mjcf_qvel(h, Eigen::Map<const Eigen::VectorXd>(a->d->qvel, a->m->nv)) ==
        viewer.keyframe_v);
  // Joint limits and torque limits arrive as ranges in radians and N m.
  const int knee = mj_name2id(a->m, mjOBJ_JOINT, "lknee");
  CHECK(a->m->jnt_limited[knee] == 1);
  CHECK(a->m->jnt_range[2 * knee] == 0.0);
  CHECK(a->m->jnt_range[2 * knee + 1] == 2.6);
  const int act = mj_name2id(a->m, mjOBJ_ACTUATOR, "lknee");
  CHECK(a->m->actuator_ctrllimited[act] == 1);
  CHECK(a->m->actuator_ctrlrange[2 * act + 1] == 300.0);
  CHECK(a->m->opt.timestep == 1.0 / 2400.0);
  CHECK(a->m->opt.integrator == mjINT_EULER);

  mjcf_options peer;
  peer.contact_geoms = true;
  const auto b = load_in_mujoco(h, peer);
  CHECK(b->warnings.empty());
  CHECK(b->m->ngeom == 1 + 15 + 16);
  // Only the 16 contact spheres can touch the floor: the shapes do not collide.
  int colliding = 0;
  for (int g = 0; g < b->m->ngeom; ++g)
    colliding += b->m->geom_contype[g] != 0 || b->m->geom_conaffinity[g] != 0;
  CHECK(colliding == 1 + 16);

  mjcf_options bare;
  bare.include_floor = false;
  bare.visual_geoms = false;
  bare.contact_sites = false;
  bare.actuators = false;
  bare.joint_limits = false;
  bare.integrator = mjcf_integrator::rk4;
  const auto c = load_in_mujoco(h, bare);
  CHECK(c->warnings.empty());
  CHECK(c->m->ngeom == 0);
  CHECK(c->m->nu == 0);
  CHECK(c->m->opt.integrator == mjINT_RK4);
  for (int j = 0; j < c->m->njnt; ++j) CHECK(c->m->jnt_limited[j] == 0);
}

TEST_CASE("a body resting on its contact spheres stays where the spheres say",
          "[io][mjcf][mujoco]") {
  // The contact geoms are real colliders: a single box with 4 corner contact points, released just
  // above the floor, settles with its corners one sphere radius (less MuJoCo's small
  // soft-constraint penetration) above the floor and stays level.
  model_builder<floating_root> b("box");
  b.add_body({.name = "box", .mass = 2.0, .inertia = mjcf_test::box_inertia(2, {.1, .1, .05})});
  for (double x : {-0.1, 0.1})
    for (double y : {-0.1, 0.1})
      b.add_contact_point({.name = "c" + std::to_string(static_cast<int>(10 * x + 1)) +
                                   std::to_string(static_cast<int>(10 * y + 1)),
                           .body = "box",
                           .position = {x, y, -0.05}});
  const auto gm = b.build();
  mjcf_options o;
  o.contact_geoms = true;
  o.contact_geom_radius = 0.01;
  const auto mj = load_in_mujoco(gm, o);
  mj->d->qpos[2] = 0.05 + 0.01 + 0.002;
  for (int i = 0; i < 2400; ++i) mj_step(mj->m, mj->d);
  CHECK(mj->d->ncon == 4);
  CHECK(mj->d->qpos[2] == Approx(0.06).margin(1e-3));
  CHECK(std::abs(mj->d->qpos[3]) == Approx(1.0).margin(1e-6));
}
