// apply_contact_forces and apply_pushes allocate nothing after set-up, on every terrain type
// (global operator new is replaced in this binary to count allocations).
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <new>
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
std::atomic<long> g_allocations{0};
// malloc and free out of line, so that GCC does not see a malloc'd pointer reach operator delete
// (a false -Wmismatched-new-delete).
[[gnu::noinline]] void* acquire(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void release(void* p) noexcept {
  std::free(p);
}
}  // namespace

void* operator new(std::size_t n) {
  return acquire(n);
}
void* operator new[](std::size_t n) {
  return acquire(n);
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

using namespace gaitsynth;

namespace {
template <terrain T>
long allocations_per_call(const floating_model& m, const T& ground, double ground_z) {
  auto ws = make_workspace(m);
  auto cs = make_contact_state(m);
  const std::vector<push> pushes{{.body = 0, .force = {100, 0, 0}, .start = 0.0, .duration = 1.0}};
  Eigen::VectorXd q = standing_configuration(m, ground_z - 0.002);  // feet 2 mm in the ground
  Eigen::VectorXd v = Eigen::VectorXd::Random(m.nv()) * 0.1;
  forward_kinematics(m, ws, q, v);
  const long before = g_allocations.load();
  for (int k = 0; k < 100; ++k) {
    clear_external_wrenches(ws);
    apply_contact_forces(m, ws, ground, contact_parameters{}, cs, 1.0 / 2400.0);
    apply_pushes(m, ws, pushes, 0.5);
  }
  const long n = g_allocations.load() - before;
  CHECK(cs.total_points_touching > 0);
  return n;
}
}  // namespace

TEST_CASE("contact forces and pushes do not allocate", "[contact][allocation]") {
  {  // the counter sees allocations
    const long before = g_allocations.load();
    std::vector<int> probe(10);
    CHECK(g_allocations.load() == before + 1);
  }
  const auto m = wang2009_humanoid();
  CHECK(allocations_per_call(m, flat_terrain(0.1), 0.1) == 0);
  CHECK(allocations_per_call(m, slope_terrain(0.0, 0.05), 0.05) == 0);
  CHECK(allocations_per_call(m, random_height_field({}, 1), 0.0) == 0);
  CHECK(allocations_per_call(m, steps_terrain::stairs(-0.5, 0.3, 0.15, 5), 0.15) == 0);
  CHECK(allocations_per_call(m, random_boxes({}, 2), 0.0) == 0);
}
