// The push protocol of Wang et al. 2009 Table 1 (rollout/push_test.hpp): pushes land where and
// when the protocol says, a walker survives a small push and not a huge one, and max_push_force
// reports the last force of its grid that passed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "gaitsynth/controllers/fsm/simbicon.hpp"
#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/rollout/push_test.hpp"
#include "gaitsynth/rollout/start_perturbations.hpp"

using namespace gaitsynth;

namespace {
/// SIMBICON walking as Table 1 pushes it (Sec. 4.2's friction, E_fail's height, its own start),
/// with the protocol's entry points. Not copied or moved: the controller is built from `m`.
struct simbicon_walk {
  floating_model m = wang2009_humanoid();
  std::pair<Eigen::VectorXd, Eigen::VectorXd> gains = simbicon_walk_gains(m);
  simbicon_controller c{m, gains.first, gains.second};
  std::vector<double> p = simbicon_walk_parameters();
  int torso = m.body_index("torso");

  rollout_options options(const Eigen::VectorXd& velocity_offset = {}) const {
    rollout_options o;
    o.contact.mu = 10.0;
    o.fall_height = 0.7;
    o.initial_state = simbicon_start_state(m);
    o.initial_velocity_offset = velocity_offset;
    return o;
  }
  push_trial trial(const vec3& force, const push_protocol& proto) const {
    return push_trial_run(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                          std::span<const double>(p), options(), torso, force, proto);
  }
  double scan(const vec3& d, const push_protocol& proto,
              const Eigen::VectorXd& velocity_offset = {}) const {
    return max_push_force(m, mixed_pd_actuator{}, c, flat_terrain{}, semi_implicit_euler{},
                          std::span<const double>(p), options(velocity_offset), torso, d, proto);
  }
  push_scan scan_from(const vec3& d, std::span<const Eigen::VectorXd> starts, int required,
                      const push_protocol& proto) const {
    return max_push_force_from_starts(m, mixed_pd_actuator{}, c, flat_terrain{},
                                      semi_implicit_euler{}, std::span<const double>(p), options(),
                                      torso, d, starts, required, proto);
  }
};
}  // namespace

TEST_CASE("push protocol: SIMBICON survives 20 N and not 1500 N; the scan agrees",
          "[rollout][push]") {
  const simbicon_walk w;
  push_protocol proto;
  proto.duration = 12.0;  // pushes at 4 and 8 s, 4 s to recover (the paper's is 40 s)
  const auto trial = [&](double f) { return w.trial(vec3(f, 0, 0), proto); };
  const push_trial small = trial(20.0), huge = trial(1500.0);
  CHECK(small.passed);
  CHECK(small.final_speed > 0.3);
  CHECK_FALSE(huge.passed);
  // Thrown by 600 N s: it falls, or its COM outruns the divergence bound (which of the two
  // depends on the rounding: -O2 gives the second).
  CHECK((huge.result.reason == stop_reason::fell || huge.result.reason == stop_reason::non_finite));
  CHECK(huge.result.time > 4.0);  // it fell after the first push, not before
  proto.resolution = 700.0;
  proto.max_force = 1400.0;
  // 700 N passes or not; 1400 N must not, so the scan reports 0 or 700.
  const double f = w.scan(vec3(1, 0, 0), proto);
  CHECK((f == 0.0 || f == 700.0));
  CHECK(f == (trial(700.0).passed ? 700.0 : 0.0));
  CHECK(table1_directions()[1] == vec3(1, 1, 0));
  proto.period = 0.0;
  CHECK_THROWS_WITH(trial(1.0), Catch::Contains("period"));
}

TEST_CASE("push protocol from several starts: the required-th largest of the starts' own scans",
          "[rollout][push]") {
  const simbicon_walk w;
  push_protocol proto;
  proto.duration = 8.0;  // one push, at 4 s
  proto.resolution = 40.0;
  proto.max_force = 280.0;
  // The own start, one perturbed by 0.3 rad/s and one by 3 rad/s (it falls before any push: the
  // scans differ for any rounding).
  const std::vector<Eigen::VectorXd> starts{Eigen::VectorXd(),
                                            joint_velocity_perturbations(w.m, 1, 0.3, 5)[0],
                                            joint_velocity_perturbations(w.m, 1, 3.0, 5)[0]};
  const vec3 d(-1, 0, 0);
  // Each start's own scan, run independently.
  std::vector<double> own;
  for (const Eigen::VectorXd& dv : starts) own.push_back(w.scan(d, proto, dv));
  std::vector<double> sorted = own;
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  INFO("own scans " << own[0] << ", " << own[1] << ", " << own[2] << " N");
  for (int required = 1; required <= 3; ++required) {
    const push_scan s = w.scan_from(d, starts, required, proto);
    INFO("required " << required);
    CHECK(s.force == sorted[static_cast<std::size_t>(required - 1)]);
    for (std::size_t k = 0; k < 3; ++k) {
      if (s.censored[k]) {  // still passing when the scan stopped: a lower bound
        CHECK(s.per_start[k] >= s.force);
        CHECK(s.per_start[k] <= own[k]);
      } else {
        CHECK(s.per_start[k] == own[k]);
      }
    }
  }
  // The scans differ, so each `required` picks out a different start.
  CHECK(sorted.front() > 0.0);
  CHECK(sorted.back() == 0.0);
  const auto scan = [&](std::span<const Eigen::VectorXd> st, int required) {
    return w.scan_from(d, st, required, proto);
  };
  CHECK_THROWS_WITH(scan(starts, 0), Catch::Contains("required must be in [1, 3]"));
  CHECK_THROWS_WITH(scan(starts, 4), Catch::Contains("got 4"));
  CHECK_THROWS_WITH(scan({}, 1), Catch::Contains("no starts"));
  const std::vector<Eigen::VectorXd> bad{Eigen::VectorXd::Zero(5)};
  CHECK_THROWS_WITH(scan(bad, 1), Catch::Contains("velocity_offsets[0] has 5 entries"));
}
