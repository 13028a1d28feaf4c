// flight_phases (analysis/flight_phases.hpp) on hand-made contact records of the 30-DOF humanoid:
// a run (two 0.15 s flights per cycle), a walk (double support, none), chatter shorter than
// min_flight, a cycle without flight among cycles with, given cycle starts; bad input by name.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gaitsynth/analysis/flight_phases.hpp"
#include "gaitsynth/model/state.hpp"
#include "gaitsynth/models/wang2009.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

/// Frames every 0.01 s for `seconds`; the left foot's (and toes') points touch when left(t), the
/// right's when right(t), nothing else ever.
trajectory contacts(const floating_model& m, double seconds,
                    const std::function<bool(double)>& left,
                    const std::function<bool(double)>& right) {
  trajectory tr;
  for (const contact_point& c : m.contact_points) {
    tr.contact_names.push_back(c.name);
    tr.contact_bodies.push_back(c.body);
  }
  for (const auto& b : m.bodies) {
    tr.body_names.push_back(b.name);
    tr.body_parents.push_back(b.parent);
  }
  const int lfoot = m.body_index("lfoot"), ltoes = m.body_index("ltoes");
  const int rfoot = m.body_index("rfoot"), rtoes = m.body_index("rtoes");
  for (int f = 0; f <= static_cast<int>(std::lround(seconds * 100)); ++f) {
    trajectory_frame fr;
    fr.t = f / 100.0;
    fr.q = neutral_configuration(m);
    for (const contact_point& c : m.contact_points) {
      const bool on = ((c.body == lfoot || c.body == ltoes) && left(fr.t)) ||
                      ((c.body == rfoot || c.body == rtoes) && right(fr.t));
      fr.contact_active.push_back(on ? 1 : 0);
    }
    tr.frames.push_back(std::move(fr));
  }
  return tr;
}

/// Phase within a 1 s cycle, robust to the frame times' rounding.
double phase(double t) {
  return t - std::floor(t + 1e-9);
}

}  // namespace

TEST_CASE("flight_phases: a run has two flights per cycle, a walk none", "[analysis]") {
  const floating_model m = wang2009_humanoid();
  // Run: left stance [0, 0.35), flight, right stance [0.5, 0.85), flight; per 1 s cycle.
  const trajectory run = contacts(
      m, 4.0, [](double t) { return phase(t) < 0.35 - 1e-9; },
      [](double t) { return phase(t) >= 0.5 - 1e-9 && phase(t) < 0.85 - 1e-9; });
  const flight_phase_report r = flight_phases(m, run, {.t_begin = 0.5});
  CHECK(r.cycles == 3);  // left strikes at 1, 2, 3, 4 s (none counted at the first frame)
  CHECK(r.cycles_with_flight == 3);
  CHECK(r.every_cycle());
  CHECK(r.flights == 6);
  CHECK_THAT(r.mean_flight, WithinAbs(0.15, 1e-9));
  CHECK_THAT(r.airborne_fraction, WithinAbs(0.3, 1e-9));

  // Walk: left [0, 0.6), right [0.5, 1.1): always a foot down.
  const trajectory walk = contacts(
      m, 4.0, [](double t) { return phase(t) < 0.6 - 1e-9; },
      [](double t) { return phase(t) >= 0.5 - 1e-9 || phase(t) < 0.1 - 1e-9; });
  const flight_phase_report w = flight_phases(m, walk, {.t_begin = 0.5});
  CHECK(w.cycles == 3);
  CHECK(w.cycles_with_flight == 0);
  CHECK_FALSE(w.every_cycle());
  CHECK(w.flights == 0);
  CHECK(w.mean_flight == 0.0);
  CHECK(w.airborne_fraction == 0.0);
}

TEST_CASE("flight_phases: chatter is not flight; one cycle without flight breaks every_cycle",
          "[analysis]") {
  const floating_model m = wang2009_humanoid();
  // The walk, with the right foot, alone on the ground, off for one frame at 1.8 s and 2.8 s
  // (chatter), and in the third cycle the left foot lifting early (3.56 s) and the right landing
  // late (3.7 s): a 0.14 s flight.
  const trajectory tr = contacts(
      m, 4.0, [](double t) { return phase(t) < 0.6 - 1e-9 && !(t > 3.55 && t < 3.7 - 1e-9); },
      [](double t) {
        const double p = phase(t);
        if (t > 3.0 && t < 4.0) return p >= 0.7 - 1e-9;
        return (p >= 0.5 - 1e-9 || p < 0.1 - 1e-9) &&
               !(std::abs(t - 1.8) < 1e-6 || std::abs(t - 2.8) < 1e-6);
      });
  const flight_phase_report r = flight_phases(m, tr, {.t_begin = 0.5});
  CHECK(r.cycles == 3);
  CHECK(r.cycles_with_flight == 1);
  CHECK_FALSE(r.every_cycle());
  CHECK(r.flights == 1);
  CHECK_THAT(r.mean_flight, WithinAbs(0.14, 1e-9));  // airborne from 3.56 to 3.70
  // min_flight 0: the chatter counts too, in the first two cycles.
  const flight_phase_report all = flight_phases(m, tr, {.t_begin = 0.5, .min_flight = 0.0});
  CHECK(all.flights == 3);
  CHECK(all.every_cycle());
  // Given cycle starts instead of heel strikes: [1, 2) and [2, 3) hold only the chatter.
  const flight_phase_report given = flight_phases(m, tr, {.cycle_starts = {1.0, 2.0, 3.0}});
  CHECK(given.cycles == 2);
  CHECK(given.flights == 0);
}

TEST_CASE("flight_phases: bad input is refused by name", "[analysis][bad_input]") {
  const floating_model m = wang2009_humanoid();
  trajectory tr = contacts(
      m, 2.0, [](double) { return true; }, [](double) { return true; });
  CHECK_THROWS_WITH(flight_phases(m, tr, {.side = "left"}), Contains("\"left\""));
  CHECK_THROWS_WITH(flight_phases(m, tr, {.min_flight = -0.1}), Contains("min_flight"));
  CHECK_THROWS_WITH(flight_phases(m, tr, {.t_begin = NAN}), Contains("t_begin"));
  CHECK_THROWS_WITH(flight_phases(m, tr, {.cycle_starts = {1.0, 0.5}}), Contains("increase"));
  tr.frames[7].contact_active.pop_back();
  CHECK_THROWS_WITH(flight_phases(m, tr), Contains("frame 7"));
  tr.contact_bodies.clear();
  CHECK_THROWS_WITH(flight_phases(m, tr), Contains("no contact points"));
}
