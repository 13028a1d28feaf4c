// contact/terrain_ref.hpp: a terrain read through a pointer answers every query as the terrain it
// refers to (the optional ones only when that terrain has them), a rollout on it retraces the
// rollout on the terrain itself bit for bit, and replacing the referenced terrain between rollouts
// changes what every copy sees (Wu & Popovic 2010 Sec. 8.3: a new height field per CMA iteration,
// seen by the rollout's contact and by the planner's own copy alike). contact/terrain_choice.hpp:
// one of two terrains chosen at run time (Sec. 8.3's height fields and boxes) answers as the
// chosen one, riser pushes included, and a rollout on it retraces the rollout on that terrain.
#include <catch2/catch.hpp>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/contact/height_field_terrain.hpp"
#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/contact/terrain_choice.hpp"
#include "gaitsynth/contact/terrain_ref.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

static_assert(terrain<terrain_ref<flat_terrain>>);
static_assert(terrain_with_height_bound<terrain_ref<flat_terrain>>);
static_assert(!terrain_with_penetration<terrain_ref<flat_terrain>>);
static_assert(terrain_with_penetration<terrain_ref<steps_terrain>>);
using field_or_boxes = terrain_choice<height_field_terrain, steps_terrain>;
static_assert(terrain_with_penetration<field_or_boxes>);
static_assert(terrain_with_height_bound<terrain_ref<field_or_boxes>>);

namespace {

random_height_field_options field_options() {
  random_height_field_options o;
  o.origin = Eigen::Vector2d(-2.0, -3.0);
  o.nx = 12;
  o.ny = 7;
  return o;
}

/// 0.7 s of Wu & Popovic's cyclical controller (a plan at 0 and at t_h = 0.55 s, both sampling
/// the terrain the controller was given) on `ground`, started on it; the final configuration.
template <class Terrain>
Eigen::VectorXd walk(const floating_model& m, const Terrain& ground) {
  const planned_walk<Terrain> c(m, ground);
  rollout_options o;
  o.duration = 0.7;
  o.initial_state = make_state(m);
  place_on_terrain(m, ground, o.initial_state.q);
  auto scratch = make_rollout_scratch(m);
  const rollout_result r = rollout(m, torque_actuator{}, c, distance_objective(), ground,
                                   semi_implicit_euler{}, c.default_parameters(), o, scratch);
  REQUIRE(r.reason == stop_reason::horizon);
  return scratch.state.q;
}

}  // namespace

TEST_CASE("terrain_ref: every query equals the referenced terrain's", "[contact][terrain]") {
  const height_field_terrain field = random_height_field(field_options(), 7);
  const terrain_ref ref(field);
  const steps_terrain steps = steps_terrain::stairs(0.0, 0.3, 0.15, 4);
  const terrain_ref step_ref(steps);
  for (double x = -2.5; x < 9.0; x += 0.37)
    for (double y = -3.5; y < 4.0; y += 0.41) {
      CHECK(ref.height(x, y) == field.height(x, y));
      CHECK(ref.normal(x, y) == field.normal(x, y));
      CHECK(ref.max_height(x, y, 0.3) == field.max_height(x, y, 0.3));
      const vec3 p(x, y, 0.1);
      const surface_contact a = terrain_penetration(step_ref, p), b = terrain_penetration(steps, p);
      CHECK(a.depth == b.depth);
      CHECK(a.normal == b.normal);
    }
}

TEST_CASE("terrain_ref: a rollout follows the referenced terrain, also after it is replaced",
          "[contact][terrain]") {
  const floating_model m = wu2010_biped();
  height_field_terrain field = random_height_field(field_options(), 1);
  const terrain_ref ref(field);
  const Eigen::VectorXd direct1 = walk(m, field);
  CHECK(walk(m, ref) == direct1);  // bit for bit: the same queries in the same order
  field = random_height_field(field_options(), 2);  // the next "iteration"
  const Eigen::VectorXd direct2 = walk(m, field);
  CHECK(walk(m, ref) == direct2);
  CHECK(direct2 != direct1);  // the new field matters, so the check above can fail
}

TEST_CASE("terrain_choice answers as the terrain in use, and a rollout on it retraces it",
          "[contact][terrain]") {
  const height_field_terrain field = random_height_field(field_options(), 7);
  random_boxes_options bo;
  bo.origin = Eigen::Vector2d(-2.0, -3.0);
  bo.nx = 12;
  bo.ny = 7;
  const steps_terrain boxes = random_boxes(bo, 7);
  field_or_boxes choice(field, boxes);
  int riser_pushes = 0;
  for (const bool second : {false, true}) {
    choice.use_second = second;
    for (double x = -2.5; x < 9.0; x += 0.37)
      for (double y = -3.5; y < 4.0; y += 0.41) {
        const double h = second ? boxes.height(x, y) : field.height(x, y);
        CHECK(choice.height(x, y) == h);
        CHECK(choice.normal(x, y) == (second ? boxes.normal(x, y) : field.normal(x, y)));
        CHECK(choice.max_height(x, y, 0.3) ==
              (second ? boxes.max_height(x, y, 0.3) : field.max_height(x, y, 0.3)));
        const vec3 p(x, y, 0.1);
        const surface_contact a = terrain_penetration(choice, p);
        const surface_contact b =
            second ? terrain_penetration(boxes, p) : terrain_penetration(field, p);
        CHECK(a.depth == b.depth);
        CHECK(a.normal == b.normal);
        riser_pushes += second && a.depth > 0.0 && a.normal.z() < 0.5;
      }
  }
  CHECK(riser_pushes > 0);  // the boxes' own rule (a riser's horizontal push) is the one used
  const floating_model m = wu2010_biped();
  choice.use_second = true;
  CHECK(walk(m, choice) == walk(m, boxes));
  choice.use_second = false;
  CHECK(walk(m, choice) == walk(m, field));
}
