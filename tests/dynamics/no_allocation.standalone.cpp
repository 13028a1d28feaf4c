// No heap allocation after make_workspace: every per-step algorithm and both integrators run with a
// counting global operator new (own test binary, so the replacement affects nothing else).
#include <atomic>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <new>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/odeint.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "support/dynamics_support.hpp"

namespace {
std::atomic<long> allocations{0};
}

// GCC 12 flags free() of memory from a (replaced) operator new once both are inlined into one
// caller; here the pairing is by construction (every replaced new is malloc/aligned_alloc).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  return operator new(n);
}
void* operator new(std::size_t n, std::align_val_t a) {
  ++allocations;
  const std::size_t al = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(al, (n + al - 1) / al * al)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return operator new(n, a);
}
// The nothrow forms too (Catch uses them): under ASan every form must be ours, or a pointer from
// ASan's operator new would reach the free() below (alloc-dealloc-mismatch).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  ++allocations;
  return std::malloc(n ? n : 1);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  ++allocations;
  const std::size_t al = static_cast<std::size_t>(a);
  return std::aligned_alloc(al, (n + al - 1) / al * al);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t& t) noexcept {
  return operator new(n, a, t);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
#pragma GCC diagnostic pop

using namespace gaitsynth;

namespace {
template <root_joint Root>
void check_no_allocation(const model<Root>& m, std::mt19937& rng) {
  auto ws = make_workspace(m);
  const Eigen::VectorXd q = random_configuration(m, rng);
  const Eigen::VectorXd v = gaitsynth::testing::random_vector(rng, m.nv());
  const Eigen::VectorXd tau = gaitsynth::testing::random_vector(rng, m.nv());
  Eigen::VectorXd q2(m.nq()), tau_lim = Eigen::VectorXd::Zero(m.nv());
  Eigen::MatrixXd J(3, m.nv());
  sim_state s{q, v, 0.0};
  semi_implicit_euler se(m);
  odeint_rk4 rk(m);
  auto sys = [&](const Eigen::VectorXd& qq, const Eigen::VectorXd& vv, double,
                 Eigen::VectorXd& ddq) { ddq = aba(m, ws, qq, vv, tau); };

  const long before = allocations.load();
  for (int k = 0; k < 3; ++k) {
    forward_kinematics(m, ws, q);
    forward_kinematics(m, ws, q, v);
    clear_external_wrenches(ws);
    add_point_force(m, ws, m.num_bodies() - 1, ws.body_position.back(), vec3(1, 2, 3));
    aba(m, ws, q, v, tau);
    rnea(m, ws, q, v, tau);
    rnea_with_external(m, ws, q, v, tau);
    nonlinear_effects(m, ws, q, v);
    gravity_forces(m, ws, q);
    crba(m, ws, q);
    point_jacobian(m, ws, q, m.num_bodies() - 1, vec3(0.1, 0, 0), J);
    body_orientation_jacobian(m, ws, q, 0, J);
    (void)center_of_mass(m, ws);
    (void)com_velocity(m, ws);
    (void)centroidal_momentum(m, ws);
    (void)total_energy(m, ws);
    integrate_configuration(m, q, v, 1e-3, q2);
    joint_limit_torques(m, q, v, tau_lim);
    se.step(m, s, 1e-3, sys);
    rk.step(m, s, 1e-3, sys);
  }
  REQUIRE(allocations.load() == before);
}
}  // namespace

TEMPLATE_TEST_CASE("dynamics algorithms and integrator steps do not allocate",
                   "[dynamics][allocation]", planar_root, floating_root, fixed_root) {
  std::mt19937 rng(5);
  check_no_allocation(gaitsynth::testing::random_model<TestType>(rng, {.num_bodies = 7}), rng);
}

TEST_CASE("the planar fast path does not allocate either", "[dynamics][allocation]") {
  std::mt19937 rng(6);
  const auto m = sharon2005_human7();
  REQUIRE(make_workspace(m).scratch.planar.enabled);
  check_no_allocation(m, rng);
}
