// The push protocol of Wang et al. 2009 Table 1 (rollout/push_test.hpp): pushes land where and
// when the protocol says, a walker survives a small push and not a huge one, and max_push_force
// reports the last force of its grid that passed.
#include <catch2/catch.hpp>

#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"

using namespace gaitsynth;

TEST_CASE("push protocol: SIMBICON survives 20 N and not 1500 N; the scan agrees",
          "[rollout][push]") {
  const auto m = wang2009_humanoid();
  const auto [kp, kd] = simbicon_walk_gains(m);
  const simbicon_controller c(m, kp, kd);
  const std::vector<double> p = simbicon_walk_parameters();
  rollout_options o;
  o.contact.mu = 10.0;
  o.fall_height = 0.7;
  o.initial_state = simbicon_start_state(m);
  const int torso = m.body_index("torso");
  push_protocol proto;
  proto.duration = 12.0;  // pushes at 4 and 8 s, 4 s to recover (the paper's is 40 s)
  const auto trial = [&](double f) {
    return push_trial_run(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                          std::span<const double>(p), o, torso, vec3(f, 0, 0), proto);
  };
  const push_trial small = trial(20.0), huge = trial(1500.0);
  CHECK(small.passed);
  CHECK(small.final_speed > 0.3);
  CHECK_FALSE(huge.passed);
  CHECK(huge.result.reason == stop_reason::fell);
  CHECK(huge.result.time > 4.0);  // it fell after the first push, not before
  proto.resolution = 700.0;
  proto.max_force = 1400.0;
  // 700 N passes or not; 1400 N must not, so the scan reports 0 or 700.
  const double f = max_push_force(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                                  std::span<const double>(p), o, torso, vec3(1, 0, 0), proto);
  CHECK((f == 0.0 || f == 700.0));
  CHECK(f == (trial(700.0).passed ? 700.0 : 0.0));
  CHECK(table1_directions()[1] == vec3(1, 1, 0));
  proto.period = 0.0;
  CHECK_THROWS_WITH(trial(1.0), Catch::Contains("period"));
}
