// robust_variants (synthesis/robust_variants.hpp): the perturbed copies of a problem that a robust
// optimization scores each candidate on. Starts carry the seeded offsets of
// joint_velocity_perturbations (so a claim test seeded apart sees other starts), pushes follow the
// documented schedule in Table 1's directions, nothing else of the problem changes, and bad
// options are refused naming the value.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/problem.hpp"
#include "gaitsynth/synthesis/robust_variants.hpp"

using namespace gaitsynth;

namespace {

auto standing_problem(const floating_model& m) {
  rollout_options ro;
  ro.pushes.push_back(push{0, vec3(0, 0, 5), 0.5, 0.1});  // the problem's own push is kept
  return rollout_problem{m,
                         pd_actuator::uniform(m, 300, 30),
                         pose_hold(m),
                         distance_travelled{},
                         flat_terrain{},
                         semi_implicit_euler{},
                         ro};
}

}  // namespace

TEST_CASE("robust_variants: seeded starts, then pushes on the documented schedule") {
  const floating_model m = wang2009_humanoid();
  const auto prob = standing_problem(m);
  const auto v = robust_variants(prob, {.starts = 3,
                                        .start_sigma = 0.05,
                                        .seed = 1001,
                                        .pushes = 2,
                                        .push_force = 80.0,
                                        .horizon = 10.0});
  REQUIRE(v.size() == 5);
  const auto offsets = joint_velocity_perturbations(m, 3, 0.05, 1001);
  for (int k = 0; k < 3; ++k) {
    CHECK(v[k].options.initial_velocity_offset == offsets[k]);
    CHECK(v[k].options.pushes.size() == 1);  // only the problem's own
  }
  CHECK(offsets[0] != offsets[1]);
  const int torso = m.body_index("torso");
  for (int k = 0; k < 2; ++k) {
    const auto& o = v[3 + k].options;
    CHECK(o.initial_velocity_offset.size() == prob.options.initial_velocity_offset.size());
    // The problem's push, then pushes at 2, 5, 8 s (8.4 < 10; 11 s would pass the horizon).
    REQUIRE(o.pushes.size() == 4);
    for (int i = 0; i < 3; ++i) {
      const push& p = o.pushes[1 + i];
      CHECK(p.body == torso);
      CHECK(p.start == Approx(2.0 + 3.0 * i));
      CHECK(p.duration == 0.4);
      CHECK((p.force - 80.0 * table1_directions()[(k + i) % 8]).norm() == 0.0);
    }
  }
  // push_direction_step = pushes: three variants of three pushes cover all eight directions.
  const auto spread = robust_variants(prob, {.pushes = 3, .push_direction_step = 3});
  REQUIRE(spread.size() == 3);
  std::set<int> seen;
  for (int k = 0; k < 3; ++k) {
    REQUIRE(spread[k].options.pushes.size() == 4);
    for (int i = 0; i < 3; ++i) {
      const vec3 f = spread[k].options.pushes[1 + i].force;
      CHECK((f - 100.0 * table1_directions()[(k + 3 * i) % 8]).norm() == 0.0);
      for (int j = 0; j < 8; ++j)
        if ((f - 100.0 * table1_directions()[j]).norm() == 0.0) seen.insert(j);
    }
  }
  CHECK(seen.size() == 8);
  // push_direction_step = 0, K = 8: each variant pushes its own direction every push_period, as
  // Table 1's protocol repeats one direction (14 s, 4 s apart: at 2, 6, 10 s).
  const auto own = robust_variants(
      prob, {.pushes = 8, .push_period = 4.0, .horizon = 14.0, .push_direction_step = 0});
  REQUIRE(own.size() == 8);
  for (int k = 0; k < 8; ++k) {
    REQUIRE(own[k].options.pushes.size() == 4);
    for (int i = 0; i < 3; ++i) {
      const push& p = own[k].options.pushes[1 + i];
      CHECK(p.start == Approx(2.0 + 4.0 * i));
      CHECK((p.force - 100.0 * table1_directions()[k]).norm() == 0.0);
    }
  }
  // push_directions: variant k starts where the list says; a direction listed twice is pushed by
  // two variants (and with step 1 each later push still turns one direction on from there).
  const robust_variant_options lo{.pushes = 3,
                                  .push_period = 4.0,
                                  .horizon = 14.0,
                                  .push_direction_step = 0,
                                  .push_directions = {4, 7, 4}};
  auto listed = robust_variants(prob, lo);
  REQUIRE(listed.size() == 3);
  const int want[] = {4, 7, 4};
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < 3; ++k) {
      REQUIRE(listed[k].options.pushes.size() >= 3);
      for (std::size_t i = 1; i < listed[k].options.pushes.size(); ++i)
        CHECK((listed[k].options.pushes[i].force - 100.0 * table1_directions()[want[k]]).norm() ==
              0.0);
    }
    redraw_push_phases(listed, prob, lo, 5);  // moved pushes keep their listed directions
  }
  const auto turning = robust_variants(prob, {.pushes = 1, .push_directions = {6}});
  REQUIRE(turning[0].options.pushes.size() == 4);
  for (int i = 0; i < 3; ++i)
    CHECK((turning[0].options.pushes[1 + i].force - 100.0 * table1_directions()[(6 + i) % 8])
              .norm() == 0.0);
  // push_force_magnitude: 100 N along the diagonals too, not 100 N per component.
  const auto unit = robust_variants(prob, {.pushes = 2, .push_force_magnitude = true});
  REQUIRE(unit.size() == 2);
  for (const auto& v : unit)
    for (std::size_t i = 1; i < v.options.pushes.size(); ++i)
      CHECK(v.options.pushes[i].force.norm() == Approx(100.0).epsilon(1e-14));
  CHECK(unit[0].options.pushes[2].force.x() == Approx(100.0 / std::sqrt(2.0)).epsilon(1e-14));
  // A horizon shorter than the first push's end leaves push variants unpushed.
  const auto w = robust_variants(prob, {.pushes = 1, .horizon = 2.3});
  REQUIRE(w.size() == 1);
  CHECK(w[0].options.pushes.size() == 1);
  CHECK(robust_variants(prob, {}).empty());
}

TEST_CASE("redraw_push_phases: every pushed variant's pushes move by its own seeded phase") {
  const floating_model m = wang2009_humanoid();
  const auto prob = standing_problem(m);
  const robust_variant_options o{.starts = 2,
                                 .pushes = 8,
                                 .push_period = 4.0,
                                 .horizon = 14.0,
                                 .push_direction_step = 0,
                                 .push_force_magnitude = true};
  auto v = robust_variants(prob, o);
  const auto fixed = v;
  redraw_push_phases(v, prob, o, 77);
  const std::vector<double> phase = push_phases(o, 77);
  REQUIRE(phase.size() == 8);
  std::set<double> distinct;
  for (int k = 0; k < 8; ++k) {
    INFO("variant " << k << ", phase " << phase[k]);
    CHECK(phase[k] >= 0.0);
    CHECK(phase[k] < 4.0);
    distinct.insert(phase[k]);
    const auto& pushes = v[2 + k].options.pushes;
    const auto& before = fixed[2 + k].options.pushes;
    REQUIRE(pushes.size() >= 3);  // the problem's own, then 2 or 3 within 14 s
    CHECK(pushes[0].start == prob.options.pushes[0].start);  // the problem's push kept
    for (std::size_t i = 1; i < pushes.size(); ++i) {
      CHECK(pushes[i].start == 2.0 + phase[k] + 4.0 * static_cast<double>(i - 1));
      CHECK(pushes[i].start + pushes[i].duration < 14.0);
      CHECK(pushes[i].force == before[1].force);  // the direction and force stay
      CHECK(pushes[i].body == before[1].body);
    }
    CHECK(pushes.size() == (2.0 + phase[k] + 8.0 + 0.4 < 14.0 ? 4u : 3u));
  }
  CHECK(distinct.size() == 8);
  for (int k = 0; k < 2; ++k) CHECK(v[k].options.pushes.size() == 1);  // starts untouched
  // Deterministic per seed; another seed, other phases; redrawing replaces, never accumulates.
  auto again = robust_variants(prob, o);
  redraw_push_phases(again, prob, o, 78);
  redraw_push_phases(again, prob, o, 77);
  for (int k = 0; k < 10; ++k)
    for (std::size_t i = 0; i < v[k].options.pushes.size(); ++i)
      CHECK(again[k].options.pushes[i].start == v[k].options.pushes[i].start);
  CHECK(push_phases(o, 78) != phase);
  CHECK_THROWS_WITH(
      redraw_push_phases(again, prob, robust_variant_options{.pushes = 3}, 1),
      Catch::Matchers::Contains("expected 3 variants") && Catch::Matchers::Contains("got 10"));
}

TEST_CASE("robust_variants: bad options are refused naming the value") {
  const floating_model m = wang2009_humanoid();
  const auto prob = standing_problem(m);
  CHECK_THROWS_WITH(robust_variants(prob, {.starts = -1}), Catch::Contains("-1"));
  CHECK_THROWS_WITH(robust_variants(prob, {.starts = 1, .start_sigma = -0.1}),
                    Catch::Contains("sigma") && Catch::Contains("-0.1"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 1, .push_direction_step = -2}),
                    Catch::Contains("push_direction_step") && Catch::Contains("-2"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 1, .push_force = std::nan("")}),
                    Catch::Contains("push_force") && Catch::Contains("nan"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 1, .push_period = 0.0}),
                    Catch::Contains("push_period"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 1, .push_body = "tail"}),
                    Catch::Contains("tail"));
  CHECK_THROWS_WITH(robust_variants(prob, {.horizon = -1.0}), Catch::Contains("horizon"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 2, .push_directions = {1, 8}}),
                    Catch::Contains("push_directions") && Catch::Contains("got 8"));
  CHECK_THROWS_WITH(robust_variants(prob, {.pushes = 2, .push_directions = {-1, 0}}),
                    Catch::Contains("push_directions") && Catch::Contains("got -1"));
  CHECK_THROWS_WITH(
      robust_variants(prob, {.pushes = 3, .push_directions = {1, 2}}),
      Catch::Contains("one direction per pushed variant (3)") && Catch::Contains("got 2"));
  // redraw_push_phases meets the same check (its options need not be those of robust_variants).
  auto v = robust_variants(prob, {.pushes = 2});
  CHECK_THROWS_WITH(redraw_push_phases(v, prob, {.pushes = 2, .push_directions = {0, 9}}, 1),
                    Catch::Contains("got 9"));
}
