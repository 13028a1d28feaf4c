// analysis/ankle_push_off.hpp on hand-made trajectories whose stances and ankle power are known.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gaitsynth/analysis/ankle_push_off.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

namespace {

/// 100 Hz frames over [0, 3) s; the left foot is down in [0.2, 0.8), [1.2, 1.8), [2.2, 2.8) s,
/// and the ankle power is sin(pi * phase)^2 * peak shaped to peak at `peak_at` of each stance.
trajectory synthetic_walk(const floating_model& m, double peak_at) {
  trajectory tr;
  const int lfoot = m.body_index("lfoot");
  const int ankle = floating_root::nv + m.dof_index("lankle_y");
  for (int k = 0; k < 300; ++k) {
    trajectory_frame f;
    f.t = 0.01 * k;
    f.v = Eigen::VectorXd::Zero(m.nv());
    f.tau = Eigen::VectorXd::Zero(m.nv());
    f.contact_active.assign(m.contact_points.size(), 0);
    const double cycle = std::fmod(f.t, 1.0);
    if (cycle >= 0.2 - 1e-9 && cycle < 0.8 - 1e-9) {
      for (std::size_t i = 0; i < m.contact_points.size(); ++i)
        if (m.contact_points[i].body == lfoot &&
            m.contact_points[i].role == contact_point::kind::sole)
          f.contact_active[i] = 1;
      const double phase = (cycle - 0.2) / (0.59);  // 0 at the first frame, 1 at the last
      // A bump centred at peak_at (300 W), with a small absorption (negative power) elsewhere.
      const double d = (phase - peak_at) / 0.1;
      f.tau[ankle] = 100.0;
      f.v[ankle] = 3.0 * std::exp(-d * d) - 0.1;
    }
    tr.frames.push_back(f);
  }
  return tr;
}

}  // namespace

TEST_CASE("ankle_push_off finds each stance and where its power peaks", "[analysis]") {
  const auto m = wang2009_humanoid();
  const ankle_push_off_report late =
      ankle_push_off(m, synthetic_walk(m, 0.8), "lankle_y", "lfoot", "ltoes");
  REQUIRE(late.stances.size() == 3u);
  for (const ankle_stance& s : late.stances) {
    CHECK(s.t_end - s.t_begin == Approx(0.59));
    // 100 N m * (3 - 0.1) rad/s at the top; the nearest frame is 0.0034 of stance off it
    CHECK(s.peak_power == Approx(290.0).epsilon(2e-3));
    CHECK(s.peak_fraction == Approx(0.8).margin(0.01));
    // The bump's integral: 300 W * sqrt(pi) * 0.1 * 0.59 s, less the small negative part.
    CHECK(s.positive_work == Approx(300.0 * std::sqrt(std::numbers::pi) * 0.1 * 0.59).epsilon(0.1));
  }
  CHECK(late.late_peak_fraction == 1.0);
  CHECK(late.mean_peak_fraction == Approx(0.8).margin(0.01));
  CHECK(late.mean_curve_peak_fraction == Approx(0.75));  // the bump straddles 0.7-0.8 and 0.8-0.9
  // Tenths far from the bump hold the absorption alone: 100 N m * -0.1 rad/s.
  CHECK(late.mean_power_by_tenth[0] == Approx(-10.0).margin(0.5));

  const ankle_push_off_report early =
      ankle_push_off(m, synthetic_walk(m, 0.3), "lankle_y", "lfoot");
  REQUIRE(early.stances.size() == 3u);
  CHECK(early.late_peak_fraction == 0.0);
  CHECK(early.mean_peak_fraction == Approx(0.3).margin(0.01));
  CHECK(early.mean_curve_peak_fraction < 0.4);

  // A stance cut by the end of the recording is not counted.
  trajectory cut = synthetic_walk(m, 0.8);
  cut.frames.resize(250);
  CHECK(ankle_push_off(m, cut, "lankle_y", "lfoot").stances.size() == 2u);

  // The swing's snap of the ankle in the last frame of contact (dorsiflexion: tau < 0 and v < 0,
  // 20 kW of tau * v) is not push-off: the plantarflexors' power counts only tau > 0.
  const int lankle = floating_root::nv + m.dof_index("lankle_y");
  trajectory snap = synthetic_walk(m, 0.3);
  for (trajectory_frame& f : snap.frames) {
    f.contact_force.assign(m.contact_points.size(), Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < m.contact_points.size(); ++i)
      if (f.contact_active[i]) f.contact_force[i] = {0.0, 0.0, 200.0};
  }
  for (const double t_last : {0.79, 1.79, 2.79}) {
    trajectory_frame& f = snap.frames[static_cast<std::size_t>(std::lround(t_last * 100))];
    f.tau[lankle] = -200.0;
    f.v[lankle] = -100.0;
  }
  const ankle_push_off_report snapped = ankle_push_off(m, snap, "lankle_y", "lfoot");
  REQUIRE(snapped.stances.size() == 3u);
  CHECK(snapped.stances[0].t_end == Approx(0.79));
  CHECK(snapped.mean_power_by_tenth[9] == Approx(-10.0).margin(5.0));  // the snap counts 0
  CHECK(snapped.mean_curve_peak_fraction < 0.4);
  // Recorded forces: a last frame whose points still touch but carry nothing is not stance.
  for (const double t_last : {0.79, 1.79, 2.79})
    for (auto& force :
         snap.frames[static_cast<std::size_t>(std::lround(t_last * 100))].contact_force)
      force.setZero();
  const ankle_push_off_report unloaded = ankle_push_off(m, snap, "lankle_y", "lfoot");
  REQUIRE(unloaded.stances.size() == 3u);
  CHECK(unloaded.stances[0].t_end == Approx(0.78));
  // Without forces in the frames, contact_active alone decides.
  for (trajectory_frame& f : snap.frames) f.contact_force.clear();
  CHECK(ankle_push_off(m, snap, "lankle_y", "lfoot").stances[0].t_end == Approx(0.79));

  CHECK_THROWS_WITH(ankle_push_off(m, cut, "lankle_q", "lfoot"), Catch::Contains("lankle_q"));
  CHECK_THROWS_WITH(ankle_push_off(m, cut, "lankle_y", "lfoot", "", 1.5),
                    Catch::Contains("late_stance must be in [0, 1], got 1.5"));
  cut.frames[3].tau.resize(2);
  CHECK_THROWS_WITH(ankle_push_off(m, cut, "lankle_y", "lfoot"),
                    Catch::Contains("frame 3 does not fit"));
}
