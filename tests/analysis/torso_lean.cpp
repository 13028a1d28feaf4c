// analysis/torso_lean.hpp on a hand-made trajectory whose torso pitch and roll are known.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "gaitsynth/analysis/torso_lean.hpp"
#include "gaitsynth/gaitsynth.hpp"

using namespace gaitsynth;

namespace {

/// 100 Hz frames over [0, 2) s: the torso pitched forward by 0.1 + 0.05 sin(2 pi t) rad, and from
/// 1 s on also rolled by `roll` rad about x; every other body upright.
trajectory leaning(const floating_model& m, double roll) {
  trajectory tr;
  for (int k = 0; k < 200; ++k) {
    trajectory_frame f;
    f.t = 0.01 * k;
    f.body_orientation.assign(static_cast<std::size_t>(m.num_bodies()),
                              Eigen::Quaterniond::Identity());
    const double pitch = 0.1 + 0.05 * std::sin(2 * std::numbers::pi * f.t);
    Eigen::Quaterniond q(Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()));
    if (f.t >= 1.0) q = Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()) * q;
    f.body_orientation[static_cast<std::size_t>(m.body_index("torso"))] = q;
    tr.frames.push_back(f);
  }
  return tr;
}

}  // namespace

TEST_CASE("torso_lean: mean pitch and largest tilt of a known lean", "[analysis][torso_lean]") {
  const floating_model m = wang2009_humanoid(wang2009_preset("stocky"));
  // Whole sine periods: the mean pitch is the offset; the largest tilt the peak, 0.15 rad.
  const torso_lean_report r = torso_lean(m, leaning(m, 0.0));
  CHECK(r.frames == 200);
  CHECK(r.mean_pitch == Approx(0.1).epsilon(1e-12));
  CHECK(r.max_tilt == Approx(0.15).epsilon(1e-6));
  // A roll of 0.2 rad from 1 s on: the tilt of the up vector combines both, cos t = cos p cos r.
  const torso_lean_report rolled = torso_lean(m, leaning(m, 0.2), 1.0);
  CHECK(rolled.frames == 100);
  CHECK(rolled.max_tilt == Approx(std::acos(std::cos(0.15) * std::cos(0.2))).epsilon(1e-6));
  CHECK(std::abs(rolled.mean_pitch - 0.1) < 0.01);
  // Bad input is named.
  CHECK_THROWS_WITH(torso_lean(m, leaning(m, 0.0), 0.0, "trunk"), Catch::Contains("trunk"));
  CHECK_THROWS_WITH(torso_lean(m, leaning(m, 0.0), 2.5), Catch::Contains("t = 2.5"));
  trajectory bare = leaning(m, 0.0);
  bare.frames[50].body_orientation.clear();
  CHECK_THROWS_WITH(torso_lean(m, bare), Catch::Contains("t = 0.5"));
}
