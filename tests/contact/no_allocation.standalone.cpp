// apply_contact_forces and apply_pushes allocate nothing after set-up, on every terrain type, nor
// does apply_self_contact_forces with touching pairs. This
// binary replaces every form of the global operator new / delete with counting versions, and
// builds Eigen with EIGEN_RUNTIME_NO_MALLOC and an eigen_assert that counts instead of aborting
// (Eigen allocates dynamic matrices through malloc, not operator new).
#include "support/counting_allocations.hpp"

#include <catch2/catch.hpp>
#include <vector>
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/penalty_contact.hpp"
#include "gaitsynth/contact/push.hpp"
#include "gaitsynth/contact/self_contact.hpp"
#include "gaitsynth/contact/slope_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/models/wu2010.hpp"

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
  CHECK(counters_see_allocations());
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

TEST_CASE("self-collision forces do not allocate", "[contact][allocation]") {
  const floating_model m = wu2010_biped();
  const self_contact_parameters p = wu2010_leg_collisions(m);
  auto ws = make_workspace(m);
  Eigen::VectorXd q = make_state(m).q, v = Eigen::VectorXd::Random(m.nv()) * 0.1;
  q[floating_root::nq + m.dof_index("lhip_x")] = -0.14;  // the left leg overlaps the right
  forward_kinematics(m, ws, q, v);
  Eigen::internal::set_is_malloc_allowed(false);
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  int touching = 0;
  for (int k = 0; k < 100; ++k) {
    clear_external_wrenches(ws);
    touching += apply_self_contact_forces(m, ws, p);
  }
  const long new_count = g_news.load() - news, eigen_count = g_eigen_asserts.load() - eigen;
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(touching > 0);
  CHECK(new_count == 0);
  CHECK(eigen_count == 0);
}
