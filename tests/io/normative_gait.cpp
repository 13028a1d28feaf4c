// io/normative_gait.hpp: the human reference curves of data/normative_gait/ read back as the file's
// README describes them, and every kind of bad table rejected with the file, line and value.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>

#include "gaitsynth/io/normative_gait.hpp"

using namespace gaitsynth;

namespace {
const std::string header = "speed_mps,percent_gait_cycle,variable,mean,sd,unit\n";

normative_gait parse(const std::string& text) {
  std::istringstream in(text);
  return read_normative_gait(in, "bad.csv");
}
}  // namespace

TEST_CASE("normative gait: the repository's adult walking data", "[io][normative_gait]") {
  const normative_gait g = load_normative_gait(
      std::string(GAITSYNTH_SOURCE_DIR) + "/data/normative_gait/falisse2019_subject1_walking.csv");
  CHECK(g.curves.size() == 9);  // 3 angles, 3 moments, 3 moments per kg (README)
  for (const normative_curve& c : g.curves) {
    INFO(c.variable);
    CHECK(c.percent.size() == 100);
    CHECK(c.percent.front() == 0.0);
    CHECK(c.percent.back() == Approx(100.0));
    CHECK(c.speed == Approx(1.3175));
  }
  // Human knee flexion (README: flexion positive, deg): about 12 degrees at heel strike, a
  // loading-response bend at 10-20 %, and the swing peak of about 60-70 degrees at 70-80 %.
  const normative_curve& knee = g.curve("knee_flexion_angle");
  CHECK(knee.unit == "deg");
  CHECK(knee.mean.front() > 5.0);
  CHECK(knee.mean.front() < 20.0);
  CHECK(knee.mean[15] > knee.mean.front() + 10.0);  // 15 % of the cycle
  const auto peak = std::max_element(knee.mean.begin(), knee.mean.end());
  CHECK(*peak > 55.0);
  CHECK(*peak < 75.0);
  const double peak_pct = knee.percent[static_cast<std::size_t>(peak - knee.mean.begin())];
  CHECK(peak_pct > 65.0);
  CHECK(peak_pct < 80.0);
  CHECK_THROWS_WITH(g.curve("elbow"), Catch::Contains("no variable 'elbow'") &&
                                          Catch::Contains("knee_flexion_angle"));
}

TEST_CASE("normative gait: columns in any order, CRLF line ends", "[io][normative_gait]") {
  const normative_gait g = parse(
      "unit,variable,sd,mean,percent_gait_cycle,speed_mps\r\n"
      "deg,knee,1,5,0,1.3\r\ndeg,knee,2,60,50,1.3\r\ndeg,knee,1,6,100,1.3\r\n");
  REQUIRE(g.curves.size() == 1);
  CHECK(g.curves[0].mean == std::vector<double>{5, 60, 6});
  CHECK(g.curves[0].sd == std::vector<double>{1, 2, 1});
  CHECK(g.curves[0].percent == std::vector<double>{0, 50, 100});
  CHECK(g.curves[0].unit == "deg");
}

TEST_CASE("normative gait: bad tables name the file, the line and the value",
          "[io][normative_gait]") {
  const std::string ok = "1.3,0,knee,5,1,deg\n";
  CHECK_THROWS_AS(parse(""), normative_gait_error);
  CHECK_THROWS_WITH(parse(""), Catch::Contains("bad.csv:1") && Catch::Contains("empty"));
  CHECK_THROWS_WITH(parse("speed_mps,percent_gait_cycle,variable,mean,unit\n" + ok),
                    Catch::Contains("bad.csv:1") && Catch::Contains("'sd'"));
  CHECK_THROWS_WITH(parse(header), Catch::Contains("no data rows"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,60,1\n"),
                    Catch::Contains("bad.csv:3") && Catch::Contains("5 fields"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,nan,1,deg\n"),
                    Catch::Contains("bad.csv:3") && Catch::Contains("mean 'nan'"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,1e999,1,deg\n"),
                    Catch::Contains("mean '1e999'"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,6x,1,deg\n"), Catch::Contains("mean '6x'"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,150,knee,6,1,deg\n"),
                    Catch::Contains("bad.csv:3") && Catch::Contains("150 is outside [0, 100]"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,0,knee,6,1,deg\n"),
                    Catch::Contains("bad.csv:3") && Catch::Contains("does not follow"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,6,-1,deg\n"),
                    Catch::Contains("sd -1 is negative"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,knee,6,1,rad\n"),
                    Catch::Contains("unit 'rad'") && Catch::Contains("'deg'"));
  CHECK_THROWS_WITH(parse(header + ok + "1.3,50,,6,1,deg\n"), Catch::Contains("empty variable"));
  CHECK_THROWS_WITH(parse(header + ok), Catch::Contains("knee: 1 sample(s)"));
  CHECK_THROWS_WITH(parse(std::string("\x01\x02\xff garbage\n") + ok), Catch::Contains("header"));
  CHECK_THROWS_WITH(load_normative_gait("/nonexistent/gait.csv"),
                    Catch::Contains("cannot open") && Catch::Contains("/nonexistent/gait.csv"));
}
