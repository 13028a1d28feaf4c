// Every built-in character stands still on flat ground in gaitsynth's own simulation (penalty
// contact, semi-implicit Euler at 2400 Hz) when a PD pose hold keeps its joints at q = 0: the
// models' masses, geometry, feet and soft limits make a physically usable character.
#include <catch2/catch.hpp>
#include <vector>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/pose_hold.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/models.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

using namespace gaitsynth;

namespace {

template <class Root>
void check_stands(const model<Root>& m) {
  INFO(m.name);
  rollout_options opt;  // starts at the neutral pose on the ground, 2400 Hz, kp 75000 contact
  opt.duration = 2.0;
  trajectory tr;
  opt.record = &tr;
  opt.record_every = 2400;
  // Stiff enough that the chain of joint springs beats gravity's toppling (sum of m g h over the
  // joints); capped per DOF for the explicit integrator (pd_actuator::capped).
  const int nj = m.num_joint_dofs();
  const auto act = pd_actuator::capped(m, Eigen::VectorXd::Constant(nj, 3000.0),
                                       Eigen::VectorXd::Constant(nj, 100.0), opt.dt);
  std::vector<double> target(nj, 0.0);
  auto scratch = make_rollout_scratch(m);
  const rollout_result r = rollout(m, act, pose_hold(m), distance_objective(), flat_terrain(),
                                   semi_implicit_euler(), target, opt, scratch);
  CHECK(r.reason == stop_reason::horizon);
  CHECK(r.time == Approx(2.0));
  CHECK((r.com_final - r.com_initial).norm() < 0.03);
  REQUIRE(!tr.frames.empty());
  // At the end the feet carry the weight.
  const trajectory_frame& f = tr.frames.back();
  double fz = 0.0;
  for (const Eigen::Vector3d& c : f.contact_force) fz += c.z();
  CHECK(fz == Approx(m.total_mass() * 9.81).epsilon(0.05));
}

}  // namespace

TEST_CASE("every character stands under a PD pose hold", "[models][standing]") {
  check_stands(sharon2005_human7());
  check_stands(sharon2005_human16());
  for (wang2009_shape s : wang2009_shapes) check_stands(wang2009_humanoid(s));
  check_stands(wu2010_biped());
  check_stands(wang2012_humanoid());
}
