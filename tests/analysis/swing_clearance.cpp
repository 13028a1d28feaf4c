// analysis/swing_clearance.hpp on hand-made walks whose swings and lifts are known.
#include "gaitsynth/analysis/swing_clearance.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gaitsynth/contact/steps_terrain.hpp"
#include "gaitsynth/models/wu2010.hpp"

using namespace gaitsynth;

namespace {

/// 100 Hz frames over [0, 3) s on `ground`. The left foot's sole and toe points move forward at
/// 0.5 m/s; in [0, 0.4) s of each 1 s cycle they touch, in [0.4, 1) s every point is lifted
/// amplitude[cycle] * sin(pi * phase) over the ground under it. The right foot always touches.
/// `scuff_at` >= 0: that frame of the swing touches.
trajectory synthetic_walk(const floating_model& m, const steps_terrain& ground,
                          const double (&amplitude)[3], int scuff_at = -1) {
  trajectory tr;
  const int lfoot = m.body_index("lfoot"), rfoot = m.body_index("rfoot");
  for (int k = 0; k < 300; ++k) {
    trajectory_frame f;
    f.t = 0.01 * k;
    const int cycle = k / 100, in_cycle = k % 100;
    const bool swing = in_cycle >= 40 && in_cycle != scuff_at;
    const double lift = in_cycle >= 40
                            ? amplitude[cycle] * std::sin(std::numbers::pi * (in_cycle - 40) / 60.0)
                            : 0.0;
    for (const contact_point& cp : m.contact_points) {
      const double x = cp.position.x() + 0.5 * f.t, y = cp.position.y();
      f.contact_position.emplace_back(x, y, ground.height(x, y) + (cp.body == lfoot ? lift : 0.0));
      f.contact_active.push_back(cp.body == rfoot || (cp.body == lfoot && !swing) ? 1 : 0);
    }
    tr.frames.push_back(f);
  }
  return tr;
}

}  // namespace

TEST_CASE("swing_clearance finds each complete swing and its peak over the terrain", "[analysis]") {
  const floating_model m = wu2010_biped();
  // A 0.15 m rise at x = 0.8 m: the second swing (x from 0.7 to 1.0 m) crosses it, so a clearance
  // over z = 0 instead of the ground under each point would differ there.
  const steps_terrain ground({{0.8, 0.15}});
  const double amplitude[3] = {0.1, 0.2, 0.3};
  const swing_clearance_report r =
      swing_clearance(m, synthetic_walk(m, ground, amplitude), ground, "lfoot");
  // The third swing runs to the end of the recording: not complete.
  REQUIRE(r.swings.size() == 2u);
  CHECK(r.swings[0].t_begin == Approx(0.4));
  CHECK(r.swings[0].t_end == Approx(0.99));
  CHECK(r.swings[1].t_begin == Approx(1.4));
  // Every point is lifted by the same amount, so the peak is the lift's at the frame nearest mid-
  // swing (phase 30/60: exactly 1).
  CHECK(r.swings[0].peak_clearance == Approx(0.1));
  CHECK(r.swings[1].peak_clearance == Approx(0.2));
  CHECK(r.median_peak_clearance == Approx(0.15));
  CHECK(r.max_peak_clearance == Approx(0.2));
  // The right foot never swings.
  CHECK(swing_clearance(m, synthetic_walk(m, ground, amplitude), ground, "rfoot").swings.empty());
  CHECK(std::isnan(swing_clearance(m, synthetic_walk(m, ground, amplitude), ground, "rfoot")
                       .median_peak_clearance));

  // Read over flat ground instead, the second swing's points past the rise seem 0.15 m higher.
  const steps_terrain flat({{0.8, 0.0}});
  CHECK(swing_clearance(m, synthetic_walk(m, ground, amplitude), flat, "lfoot")
            .swings[1]
            .peak_clearance > 0.3);

  // A scuff mid-swing (frame 70 of each cycle touches) splits every swing in two.
  const swing_clearance_report s =
      swing_clearance(m, synthetic_walk(m, ground, amplitude, 70), ground, "lfoot");
  REQUIRE(s.swings.size() == 5u);  // the last cycle's second half runs to the end
  CHECK(s.swings[0].t_end == Approx(0.69));
  CHECK(s.swings[1].t_begin == Approx(0.71));
}

TEST_CASE("swing_clearance refuses what it cannot read, naming it", "[analysis]") {
  const floating_model m = wu2010_biped();
  const steps_terrain ground({{0.8, 0.15}});
  const double amplitude[3] = {0.1, 0.2, 0.3};
  trajectory tr = synthetic_walk(m, ground, amplitude);
  CHECK_THROWS_WITH(swing_clearance(m, tr, ground, "lhand"), Catch::Contains("'lhand'"));
  CHECK_THROWS_WITH(swing_clearance(m, tr, ground, "upper_body"),
                    Catch::Contains("'upper_body'") && Catch::Contains("no sole or toe"));
  tr.frames[17].contact_position.pop_back();
  CHECK_THROWS_WITH(swing_clearance(m, tr, ground, "lfoot"),
                    Catch::Contains("frame 17") && Catch::Contains("wu2010_biped"));
}
