// Wu & Popovic 2010's end-effector path planner allocates nothing: neither planning a half-cycle
// (fixed-size arrays for the 64 terrain samples and their hull) nor the per-tick query
// (controllers/end_effector/half_cycle_plan.hpp).
#include "support/counting_allocations.hpp"

#include <catch2/catch.hpp>

#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/controllers/end_effector/half_cycle_plan.hpp"

using namespace gaitsynth;

TEST_CASE("planning a half-cycle and querying it allocate nothing", "[end_effector][allocation]") {
  CHECK(counters_see_allocations());
  const steps_terrain step({{0.3, 0.1}}, 0.0);  // built before counting
  planner_setup setup;
  setup.edge_avoidance = true;
  const planner_parameters p;
  planner_input in;
  in.stance_foot.position = vec3(0.0, 0.1, 0.06);
  in.swing_foot.position = vec3(-0.3, -0.1, 0.06);
  in.upper_body.position = vec3(-0.15, 0.0, 1.45);
  const task_goal goal{0.1, 0.0, 0.65};
  std::array<link_target, 3> links;

  Eigen::internal::set_is_malloc_allowed(false);
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  const half_cycle_plan first = plan_half_cycle(goal, p, setup, in, step);
  const half_cycle_plan second = plan_half_cycle(goal, p, setup, in, step, &first);
  double sum = 0.0;
  for (int k = 0; k < 64; ++k) {
    second.link_targets(k / 64.0, links);
    sum += links[0].position.z() + links[1].velocity.x() + links[2].angular_velocity.z();
  }
  const long news_in_planner = g_news.load() - news,
             eigen_in_planner = g_eigen_asserts.load() - eigen;
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(std::isfinite(sum));
  CHECK(news_in_planner == 0);
  CHECK(eigen_in_planner == 0);
}
