// Contact benchmarks: penalty forces for the Wang 2009 humanoid's 16 foot and toe points on each
// terrain type (kinematics done once outside the loop), the 7-link planar human's 4 points on the
// planar path and on the general path, terrain queries, one full physics step (kinematics +
// contact + ABA + semi-implicit Euler) standing on flat ground, and Wu & Popovic's 9 inter-leg
// capsule pairs (self_contact.hpp) apart (the rollout's per-step cost when the legs do not touch)
// and overlapping.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/dynamics/aba.hpp"
#include "gaitsynth/dynamics/configuration.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/models/wu2010.hpp"

using namespace gaitsynth;

namespace {
constexpr double kDt = 1.0 / 2400.0;

/// The humanoid standing with its feet `sink` m into terrain at height `ground`, small random v.
struct humanoid_fixture {
  floating_model m = wang2009_humanoid();
  workspace<floating_root> ws = make_workspace(m);
  contact_state cs = make_contact_state(m);
  Eigen::VectorXd q, v;
  explicit humanoid_fixture(double ground, double sink = 0.001) {
    q = standing_configuration(m, ground - sink);
    std::mt19937_64 rng(1);
    std::normal_distribution<double> n(0.0, 0.05);
    v = Eigen::VectorXd::Zero(m.nv());
    for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = n(rng);
    forward_kinematics(m, ws, q, v);
  }
};

template <terrain T>
void contact_forces(benchmark::State& state, const T& ground, double ground_z) {
  humanoid_fixture f(ground_z);
  const contact_parameters p;
  for (auto _ : state) {
    clear_external_wrenches(f.ws);
    apply_contact_forces(f.m, f.ws, ground, p, f.cs, kDt);
    benchmark::DoNotOptimize(f.ws.f_ext.data());
    benchmark::ClobberMemory();
  }
  state.counters["points"] = static_cast<double>(f.m.contact_points.size());
  state.counters["touching"] = f.cs.total_points_touching;
}
}  // namespace

/// The 7-link human standing 1 mm into flat ground (all 4 foot points touch), small random v;
/// `planar_path` false runs the general path on the same kinematics.
static void contact_human7(benchmark::State& state, bool planar_path) {
  const planar_model m = sharon2005_human7();
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  const Eigen::VectorXd q = standing_configuration(m, -0.001);
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n(0.0, 0.05);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(m.nv());
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = n(rng);
  forward_kinematics(m, ws, q, v);
  ws.scratch.planar.enabled = planar_path;  // internal switch; kinematics stay as computed
  const contact_parameters p;
  for (auto _ : state) {
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, flat_terrain(), p, cs, kDt);
    benchmark::DoNotOptimize(ws.f_ext.data());
    benchmark::ClobberMemory();
  }
  state.counters["touching"] = cs.total_points_touching;
}
static void BM_contact_human7_planar_path(benchmark::State& s) {
  contact_human7(s, true);
}
BENCHMARK(BM_contact_human7_planar_path);
static void BM_contact_human7_general_path(benchmark::State& s) {
  contact_human7(s, false);
}
BENCHMARK(BM_contact_human7_general_path);

static void BM_contact_flat(benchmark::State& s) {
  contact_forces(s, flat_terrain(0.0), 0.0);
}
BENCHMARK(BM_contact_flat);
static void BM_contact_flat_explicit_damping(benchmark::State& state) {
  humanoid_fixture f(0.0);
  contact_parameters p;
  p.implicit_damping = false;
  for (auto _ : state) {
    clear_external_wrenches(f.ws);
    apply_contact_forces(f.m, f.ws, flat_terrain(), p, f.cs, kDt);
    benchmark::DoNotOptimize(f.ws.f_ext.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_contact_flat_explicit_damping);
static void BM_contact_slope(benchmark::State& s) {
  contact_forces(s, slope_terrain(0.0, 0.0), 0.0);
}
BENCHMARK(BM_contact_slope);
static void BM_contact_height_field(benchmark::State& s) {
  // A field flat at 0.1 m so that all 16 points touch, but every query goes through the grid.
  random_height_field_options o;
  o.min_height = o.max_height = 0.1;
  contact_forces(s, random_height_field(o, 1), 0.1);
}
BENCHMARK(BM_contact_height_field);
static void BM_contact_steps(benchmark::State& s) {
  contact_forces(s, steps_terrain({{-5.0, 0.1}, {5.0, 0.3}}), 0.1);
}
BENCHMARK(BM_contact_steps);

static void BM_contact_with_pushes(benchmark::State& state) {
  humanoid_fixture f(0.0);
  const std::vector<push> pushes = periodic_pushes(0, {0, 200, 0}, 0.0, 4.0, 0.4, 3);
  const contact_parameters p;
  for (auto _ : state) {
    clear_external_wrenches(f.ws);
    apply_contact_forces(f.m, f.ws, flat_terrain(), p, f.cs, kDt);
    apply_pushes(f.m, f.ws, pushes, 0.2);
    benchmark::DoNotOptimize(f.ws.f_ext.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_contact_with_pushes);

/// Wu's biped in the neutral pose (`adduction` 0: no pair touches, the broad phase rejects most)
/// or with its left hip adducted so that the left leg overlaps the right (pairs touching).
static void self_contact_legs(benchmark::State& state, double adduction) {
  const floating_model m = wu2010_biped();
  const self_contact_parameters p = wu2010_leg_collisions(m);
  auto ws = make_workspace(m);
  Eigen::VectorXd q = make_state(m).q, v = Eigen::VectorXd::Zero(m.nv());
  q[floating_root::nq + m.dof_index("lhip_x")] = -adduction;
  forward_kinematics(m, ws, q, v);
  int touching = 0;
  for (auto _ : state) {
    clear_external_wrenches(ws);
    touching = apply_self_contact_forces(m, ws, p);
    benchmark::DoNotOptimize(ws.f_ext.data());
    benchmark::ClobberMemory();
  }
  state.counters["pairs"] = static_cast<double>(p.pairs.size());
  state.counters["touching"] = touching;
}
static void BM_self_contact_legs_apart(benchmark::State& s) {
  self_contact_legs(s, 0.0);
}
BENCHMARK(BM_self_contact_legs_apart);
static void BM_self_contact_legs_overlapping(benchmark::State& s) {
  self_contact_legs(s, 0.14);
}
BENCHMARK(BM_self_contact_legs_overlapping);

/// One physics step: kinematics, contact, ABA, semi-implicit Euler (zero joint torques; the state
/// is reset every 64 steps so it stays a standing contact state).
static void BM_step_with_contact(benchmark::State& state) {
  humanoid_fixture f(0.0);
  const contact_parameters p;
  const Eigen::VectorXd q0 = f.q, v0 = f.v, tau = Eigen::VectorXd::Zero(f.m.nv());
  int k = 0;
  for (auto _ : state) {
    if ((++k & 63) == 0) {
      f.q = q0;
      f.v = v0;
    }
    forward_kinematics(f.m, f.ws, f.q, f.v);
    clear_external_wrenches(f.ws);
    apply_contact_forces(f.m, f.ws, flat_terrain(), p, f.cs, kDt);
    f.v += kDt * aba(f.m, f.ws, f.q, f.v, tau);
    integrate_configuration(f.m, f.q, f.v, kDt, f.q);
    benchmark::DoNotOptimize(f.q.data());
  }
}
BENCHMARK(BM_step_with_contact);

namespace {
std::vector<Eigen::Vector2d> query_points(int n) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> ux(-6.0, 46.0), uy(-6.0, 6.0);
  std::vector<Eigen::Vector2d> p(static_cast<std::size_t>(n));
  for (auto& x : p) x = {ux(rng), uy(rng)};
  return p;
}
}  // namespace

static void BM_height_field_height(benchmark::State& state) {
  const auto t = random_height_field({}, 3);
  const auto pts = query_points(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& p = pts[i++ & 1023];
    benchmark::DoNotOptimize(t.height(p.x(), p.y()));
  }
}
BENCHMARK(BM_height_field_height);

static void BM_height_field_normal(benchmark::State& state) {
  const auto t = random_height_field({}, 3);
  const auto pts = query_points(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& p = pts[i++ & 1023];
    benchmark::DoNotOptimize(t.normal(p.x(), p.y()));
  }
}
BENCHMARK(BM_height_field_normal);

static void BM_random_boxes_penetration(benchmark::State& state) {
  const auto t = random_boxes({}, 4);
  const auto pts = query_points(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& p = pts[i & 1023];
    const double z = 0.2 * static_cast<double>(i++ & 7) / 8.0;
    benchmark::DoNotOptimize(terrain_penetration(t, vec3(p.x(), p.y(), z)));
  }
}
BENCHMARK(BM_random_boxes_penetration);
