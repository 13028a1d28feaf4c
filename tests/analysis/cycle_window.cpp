// cycle_window (analysis/cycle_window.hpp): mean, minimum and maximum of a gait curve over a
// window of the cycle, on hand-computed cases, and bad input refused by name.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "gaitsynth/analysis/cycle_window.hpp"

using namespace gaitsynth;

TEST_CASE("cycle_window: statistics of the samples inside the window, ends included",
          "[analysis]") {
  std::vector<double> p, y;
  for (int i = 0; i <= 100; ++i) {
    p.push_back(i);
    y.push_back(i % 2 == 0 ? i : -i);  // even percents positive, odd ones negative
  }
  const cycle_window_stats s = cycle_window(p, y, {10.0, 14.0});  // 10, -11, 12, -13, 14
  CHECK(s.samples == 5);
  CHECK(s.mean == Approx((10.0 - 11.0 + 12.0 - 13.0 + 14.0) / 5.0));
  CHECK(s.min == -13.0);
  CHECK(s.max == 14.0);
  const cycle_window_stats m = cycle_window(p, y, gait_windows::mid_stance);
  CHECK(m.samples == 36);  // 15..50
  CHECK(m.min == -49.0);
  CHECK(m.max == 50.0);
  CHECK(cycle_window(p, y, gait_windows::terminal_swing).samples == 11);
  CHECK(cycle_window(p, y, {37.5, 38.5}).mean == 38.0);
}

TEST_CASE("cycle_window: bad input is refused naming it", "[analysis]") {
  const std::vector<double> p{0.0, 50.0, 100.0}, y{1.0, 2.0, 3.0}, short_y{1.0, 2.0};
  CHECK_THROWS_WITH(cycle_window(p, short_y, {}), Catch::Contains("3 and 2"));
  CHECK_THROWS_WITH(cycle_window(p, y, {60.0, 40.0}), Catch::Contains("[60, 40]"));
  CHECK_THROWS_WITH(cycle_window(p, y, {10.0, 20.0}), Catch::Contains("no sample in [10, 20]"));
  const std::vector<double> bad{1.0, std::nan(""), 3.0};
  CHECK_THROWS_WITH(cycle_window(p, bad, {}), Catch::Contains("50 %") && Catch::Contains("nan"));
}
