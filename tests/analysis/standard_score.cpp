// The standard score of a gait curve against human data (analysis/standard_score.hpp): a hand
// case, the data against itself (0) and one s.d. away (1), and bad input refused by name.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "gaitsynth/analysis/standard_score.hpp"
#include "gaitsynth/io/normative_gait.hpp"

using namespace gaitsynth;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

TEST_CASE("standard score: mean of |sim - mean| / sd over the cycle", "[analysis]") {
  normative_curve h;
  h.variable = "knee_flexion_angle";
  h.percent = {0.0, 50.0, 100.0};
  h.mean = {0.0, 10.0, 0.0};
  h.sd = {1.0, 2.0, 1.0};
  const std::vector<double> p{0.0, 100.0}, zero{0.0, 0.0};
  // n = 3: points 0, 50, 100 % -> (0 / 1 + 10 / 2 + 0 / 1) / 3.
  CHECK_THAT(standard_score(p, zero, h, 3), WithinAbs(5.0 / 3.0, 1e-15));
  // n = 5 adds 25 and 75 %: mean 5, sd 1.5 there -> (0 + 5/1.5 + 5 + 5/1.5 + 0) / 5.
  CHECK_THAT(standard_score(p, zero, h, 5),
             WithinAbs((10.0 / 3.0 + 5.0 + 10.0 / 3.0) / 5.0, 1e-14));

  const normative_gait human = load_normative_gait(
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv");
  for (const char* v : {"hip_flexion_angle", "knee_flexion_angle", "ankle_dorsiflexion_angle"}) {
    const normative_curve& c = human.curve(v);
    INFO(v);
    CHECK_THAT(standard_score(c.percent, c.mean, c), WithinAbs(0.0, 1e-12));
    std::vector<double> above = c.mean, below = c.mean;
    for (std::size_t i = 0; i < above.size(); ++i) {
      above[i] += c.sd[i];
      below[i] -= 2.0 * c.sd[i];
    }
    CHECK_THAT(standard_score(c.percent, above, c), WithinAbs(1.0, 1e-9));
    CHECK_THAT(standard_score(c.percent, below, c), WithinAbs(2.0, 1e-9));
  }
}

TEST_CASE("standard score: bad input is refused by name", "[analysis][bad_input]") {
  normative_curve h;
  h.variable = "hip_flexion_angle";
  h.percent = {0.0, 100.0};
  h.mean = {0.0, 0.0};
  h.sd = {1.0, 0.0};
  const std::vector<double> p{0.0, 100.0}, y{0.0, 0.0};
  CHECK_THROWS_WITH(standard_score(p, y, h),
                    Contains("hip_flexion_angle") && Contains("s.d. 0") && Contains("100 %"));
  h.sd = {1.0, 1.0};
  CHECK_THROWS_WITH(standard_score(std::vector<double>{0.0, 90.0}, y, h), Contains("0-100 %"));
  CHECK_THROWS_WITH(standard_score(p, std::vector<double>{0.0, NAN}, h), Contains("not finite"));
  CHECK_THROWS_WITH(standard_score(p, std::vector<double>{0.0}, h), Contains("sim"));
  CHECK_THROWS_WITH(standard_score(p, y, h, 1), Contains("n must be >= 2"));
}
