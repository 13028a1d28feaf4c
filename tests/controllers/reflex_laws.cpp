// The reflex building blocks of Wang et al. 2012 Sec. 4.1 at hand-computed points: force and
// length feedback, the one-sided muscle PD law and the VAS's knee suppression.
#include <catch2/catch.hpp>

#include "gaitsynth/controllers/reflex/reflex_laws.hpp"

using namespace gaitsynth::reflex;

TEST_CASE("force feedback is the gain times the delayed normalized force",
          "[controllers][reflex]") {
  STATIC_REQUIRE(force_feedback(1.2, 0.5) == 0.6);
  CHECK(force_feedback(0.0, 0.9) == 0.0);
}

TEST_CASE("length feedback fires only beyond the offset", "[controllers][reflex]") {
  STATIC_REQUIRE(length_feedback(2.0, 0.5, 0.71) == 0.0);  // shorter than H: nothing
  CHECK(length_feedback(2.0, 0.71, 0.71) == 0.0);
  CHECK(length_feedback(2.0, 0.81, 0.71) == Approx(0.2).epsilon(1e-12));
}

TEST_CASE("muscle PD pulls one way: an extensor on a flexion angle acts when too flexed",
          "[controllers][reflex]") {
  // K (th - th_m) + D thd = 2 (0.3 - 0.1) + 0.5 * 0.2 = 0.5
  CHECK(muscle_pd(2.0, 0.5, 0.3, 0.2, 0.1, true) == Approx(0.5).epsilon(1e-12));
  CHECK(muscle_pd(2.0, 0.5, 0.3, 0.2, 0.1, false) == 0.0);  // the flexor rests
  // Too extended (th < th_m) and extending: the flexor acts, |2 (-0.2) + 0.5 (-0.4)| = 0.6.
  CHECK(muscle_pd(2.0, 0.5, -0.1, -0.4, 0.1, false) == Approx(0.6).epsilon(1e-12));
  CHECK(muscle_pd(2.0, 0.5, -0.1, -0.4, 0.1, true) == 0.0);
  // The damping term alone can switch the side.
  CHECK(muscle_pd(2.0, 0.5, 0.1, -0.4, 0.1, false) == Approx(0.2).epsilon(1e-12));
}

TEST_CASE("the VAS suppression acts only while the knee extends below its offset",
          "[controllers][reflex]") {
  CHECK(knee_extension_suppression(2.0, 0.05, -1.0, 0.1) == Approx(-0.1).epsilon(1e-12));
  CHECK(knee_extension_suppression(2.0, 0.05, +1.0, 0.1) == 0.0);  // flexing: none
  CHECK(knee_extension_suppression(2.0, 0.30, -1.0, 0.1) == 0.0);  // above the offset: none
  STATIC_REQUIRE(reflex_delays::hip == 0.005 && reflex_delays::ankle == 0.020);
}
