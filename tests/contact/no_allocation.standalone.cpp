// apply_contact_forces and apply_pushes allocate nothing after set-up, on every terrain type. This
// binary replaces every form of the global operator new / delete with counting versions, and
// builds Eigen with EIGEN_RUNTIME_NO_MALLOC and an eigen_assert that counts instead of aborting
// (Eigen allocates dynamic matrices through malloc, not operator new).
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_news{0};
std::atomic<long> g_eigen_asserts{0};
}  // namespace
inline void gaitsynth_e1_count_eigen_assert() {
  ++g_eigen_asserts;
}
#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(x)                                           \
  do {                                                            \
    if (!static_cast<bool>(x)) gaitsynth_e1_count_eigen_assert(); \
  } while (false)

#include <catch2/catch.hpp>

#include <vector>

#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace {
// malloc and free out of line, so that GCC does not see a malloc'd pointer reach operator delete
// (a false -Wmismatched-new-delete). Every form goes through these two, so that sanitizers see
// matching malloc / free pairs.
[[gnu::noinline]] void* acquire(std::size_t n) noexcept {
  ++g_news;
  return std::malloc(n ? n : 1);
}
[[gnu::noinline]] void* acquire_aligned(std::size_t n, std::align_val_t a) noexcept {
  ++g_news;
  const std::size_t al = static_cast<std::size_t>(a);
  return std::aligned_alloc(al, (n + al - 1) / al * al);
}
[[gnu::noinline]] void release(void* p) noexcept {
  std::free(p);
}
void* checked(void* p) {
  if (!p) throw std::bad_alloc();
  return p;
}
}  // namespace

void* operator new(std::size_t n) {
  return checked(acquire(n));
}
void* operator new[](std::size_t n) {
  return checked(acquire(n));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return acquire(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return acquire(n);
}
void* operator new(std::size_t n, std::align_val_t a) {
  return checked(acquire_aligned(n, a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return checked(acquire_aligned(n, a));
}
void operator delete(void* p) noexcept {
  release(p);
}
void operator delete[](void* p) noexcept {
  release(p);
}
void operator delete(void* p, std::size_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  release(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  release(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  release(p);
}

using namespace gaitsynth;

namespace {
struct counts {
  long news = 0, eigen = 0;
};

template <terrain T>
counts allocations_in_steps(const floating_model& m, const T& ground, double ground_z) {
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  const std::vector<push> pushes{{.body = 0, .force = {100, 0, 0}, .start = 0.0, .duration = 1.0}};
  Eigen::VectorXd q = standing_configuration(m, ground_z - 0.002);  // feet 2 mm in the ground
  Eigen::VectorXd v = Eigen::VectorXd::Random(m.nv()) * 0.1;
  forward_kinematics(m, ws, q, v);
  Eigen::internal::set_is_malloc_allowed(false);
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  for (int k = 0; k < 100; ++k) {
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, ground, contact_parameters{}, cs, 1.0 / 2400.0);
    apply_pushes(m, ws, pushes, 0.5);
  }
  const counts c{g_news.load() - news, g_eigen_asserts.load() - eigen};
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(cs.total_points_touching > 0);
  return c;
}
}  // namespace

TEST_CASE("contact forces and pushes do not allocate", "[contact][allocation]") {
  {  // the counters see allocations
    const long news = g_news.load(), eigen = g_eigen_asserts.load();
    std::vector<int>* probe = new std::vector<int>(10);
    CHECK(g_news.load() >= news + 2);
    delete probe;
    Eigen::internal::set_is_malloc_allowed(false);
    Eigen::VectorXd x(7);
    Eigen::internal::set_is_malloc_allowed(true);
    CHECK(g_eigen_asserts.load() > eigen);
    x.setZero();
  }
  const auto m = wang2009_humanoid();
  const auto check = [](counts c) {
    CHECK(c.news == 0);
    CHECK(c.eigen == 0);
  };
  check(allocations_in_steps(m, flat_terrain(0.1), 0.1));
  check(allocations_in_steps(m, slope_terrain(0.0, 0.05), 0.05));
  check(allocations_in_steps(m, random_height_field({}, 1), 0.0));
  check(allocations_in_steps(m, steps_terrain::stairs(-0.5, 0.3, 0.15, 5), 0.15));
  check(allocations_in_steps(m, random_boxes({}, 2), 0.0));
}
