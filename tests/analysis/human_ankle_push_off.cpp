// analysis/human_ankle_push_off.hpp on hand-made curves whose power is known in closed form, and
// on the adult of data/normative_gait/ (Falisse et al. 2019), whose push-off is the reference.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gaitsynth/analysis/human_ankle_push_off.hpp"

using namespace gaitsynth;

namespace {

/// 101 samples at 0, 1, ..., 100 % of a 1 s cycle. The ankle plantarflexes steadily, 0.2 deg
/// per % (20 deg/s); the dorsiflexor moment is +10 N m (dorsiflexing: no plantarflexor power)
/// before 5 % and -100 sin(pi p / 50) N m (plantarflexing) from 5 % to 50 %, 0 after.
normative_gait synthetic_ankle() {
  normative_curve angle{"ankle_dorsiflexion_angle", "deg", 1.3, {}, {}, {}};
  normative_curve moment{"ankle_dorsiflexion_moment", "N*m", 1.3, {}, {}, {}};
  for (int k = 0; k <= 100; ++k) {
    const double p = k;
    angle.percent.push_back(p);
    moment.percent.push_back(p);
    angle.mean.push_back(-0.2 * p);
    moment.mean.push_back(k < 5     ? 10.0
                          : k <= 50 ? -100.0 * std::sin(std::numbers::pi * p / 50)
                                    : 0);
    angle.sd.push_back(0.0);
    moment.sd.push_back(0.0);
  }
  return {{angle, moment}};
}

}  // namespace

TEST_CASE("human_ankle_push_off: the power of known curves, by tenths of stance",
          "[analysis][human_ankle_push_off]") {
  const normative_gait h = synthetic_ankle();
  const human_ankle_push_off_report r = human_ankle_push_off(h, 1.0);
  // The moment falls below 5 % of its 100 N m peak at 50 % (sin(pi) = 0).
  CHECK(r.toe_off_percent == 50.0);
  // A linear angle: central differences are exact, 20 deg/s of plantarflexion.
  const double qdot = 20.0 * std::numbers::pi / 180.0;
  CHECK(r.peak_power == Approx(100.0 * qdot).epsilon(1e-12));  // at 25 %, half of stance
  CHECK(r.peak_fraction == Approx(0.5));
  // Tenth i holds the samples 5i .. 5i + 4 % (and 50 % in the last); before 5 % the moment
  // dorsiflexes, so the first tenth has no plantarflexor power.
  CHECK(r.power_by_tenth[0] == 0.0);
  for (int i = 1; i < 10; ++i) {
    double sum = 0.0;
    int count = 0;
    for (int k = 5 * i; k < 5 * i + 5 || (i == 9 && k <= 50); ++k, ++count)
      sum += 100.0 * std::sin(std::numbers::pi * k / 50.0) * qdot;
    INFO("tenth " << i);
    CHECK(r.power_by_tenth[static_cast<std::size_t>(i)] == Approx(sum / count).epsilon(1e-12));
  }
  // sin over 25..29 % exceeds sin over 20..24 %: the 6th tenth holds the curve's peak.
  CHECK(r.curve_peak_fraction == Approx(0.55));
  // Power scales with 1 / stride_time; the fractions do not move.
  const human_ankle_push_off_report r2 = human_ankle_push_off(h, 2.0);
  CHECK(r2.peak_power == Approx(0.5 * r.peak_power).epsilon(1e-12));
  CHECK(r2.curve_peak_fraction == r.curve_peak_fraction);
}

TEST_CASE("human_ankle_push_off: the adult's plantarflexors push off just before toe-off",
          "[analysis][human_ankle_push_off]") {
  const normative_gait h = load_normative_gait(
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv");
  // data/normative_gait/README.md: stride 1.377 m at 1.3175 m/s.
  const human_ankle_push_off_report r = human_ankle_push_off(h, 1.377 / 1.3175);
  INFO("toe-off at " << r.toe_off_percent << " %, peak " << r.peak_power << " W at "
                     << r.peak_fraction << " of stance");
  // Toe-off near 60 % of the cycle (Perry's 62 %); the burst in the last fifth of stance, after
  // the plantarflexors absorb while the shank rotates over the foot in mid-stance.
  CHECK(r.toe_off_percent > 58.0);
  CHECK(r.toe_off_percent < 66.0);
  CHECK(r.curve_peak_fraction >= 0.8);
  CHECK(r.peak_fraction >= 0.8);
  CHECK(r.peak_power > 100.0);
  CHECK(r.peak_power < 400.0);
  CHECK(*std::min_element(r.power_by_tenth.begin() + 3, r.power_by_tenth.begin() + 7) < 0.0);
  // The figures docs/reproductions/wang2009.md gives (toe-off at 64 %, W by tenth, rounded).
  CHECK(r.toe_off_percent == Approx(63.64).margin(0.01));
  constexpr std::array<double, 10> page{0, 0, -5, -19, -22, -34, -31, 23, 163, 94};
  for (std::size_t i = 0; i < 10; ++i) CHECK(r.power_by_tenth[i] == Approx(page[i]).margin(0.5));
}

TEST_CASE("human_ankle_push_off: bad input names what is wrong",
          "[analysis][human_ankle_push_off]") {
  const normative_gait h = synthetic_ankle();
  CHECK_THROWS_WITH(human_ankle_push_off(h, 0.0),
                    Catch::Contains("stride_time") && Catch::Contains("got 0"));
  CHECK_THROWS_WITH(human_ankle_push_off(h, std::nan("")), Catch::Contains("stride_time"));
  CHECK_THROWS_AS(human_ankle_push_off(h, 1.0, "knee_flexion_angle"), std::out_of_range);
  normative_gait bad = h;
  bad.curves[1].unit = "N*m/kg";
  CHECK_THROWS_WITH(human_ankle_push_off(bad, 1.0), Catch::Contains("N*m/kg"));
  bad = h;
  bad.curves[1].percent.back() = 99.5;
  CHECK_THROWS_WITH(human_ankle_push_off(bad, 1.0), Catch::Contains("same samples"));
  bad = h;
  for (double& v : bad.curves[1].mean) v = std::abs(v);  // dorsiflexing throughout
  CHECK_THROWS_WITH(human_ankle_push_off(bad, 1.0), Catch::Contains("never plantarflexes"));
}
