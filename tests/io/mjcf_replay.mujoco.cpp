// The replay file in MuJoCo itself: the model with its keyframes loads, and resetting to key k
// puts every body where the recorded frame k has it (MuJoCo's own kinematics as the oracle, so the
// qpos permutation and quaternion convention are checked end to end).
#include <mujoco/mujoco.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "gaitsynth/io/mjcf_replay.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;

namespace {
template <root_joint Root>
void check_replay_in_mujoco(const model<Root>& m, const trajectory& traj) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("gaitsynth_replay_" + std::to_string(::getpid()) + "_" + m.name + ".xml");
  save_mjcf_replay(m, traj, path.string());
  char error[2048] = "";
  mjModel* mm = mj_loadXML(path.string().c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(path);
  INFO("MuJoCo: " << error);
  REQUIRE(mm != nullptr);
  mjData* d = mj_makeData(mm);
  REQUIRE(mm->nkey == static_cast<int>(traj.frames.size()));
  double worst = 0, worst_rot = 0;
  for (int k = 0; k < mm->nkey; ++k) {
    mj_resetDataKeyframe(mm, d, k);
    mj_kinematics(mm, d);
    CHECK(d->time == traj.frames[k].t);
    for (int b = 0; b < m.num_bodies(); ++b) {
      const int id = mj_name2id(mm, mjOBJ_BODY, m.bodies[b].name.c_str());
      REQUIRE(id > 0);
      const Eigen::Vector3d p(d->xpos[3 * id], d->xpos[3 * id + 1], d->xpos[3 * id + 2]);
      worst = std::max(worst, (p - traj.frames[k].body_position[b]).norm());
      const Eigen::Quaterniond q(d->xquat[4 * id], d->xquat[4 * id + 1], d->xquat[4 * id + 2],
                                 d->xquat[4 * id + 3]);
      worst_rot = std::max(worst_rot, q.angularDistance(traj.frames[k].body_orientation[b]));
    }
  }
  CHECK(worst < 1e-9);
  CHECK(worst_rot < 1e-9);
  mj_deleteData(d);
  mj_deleteModel(mm);
}
}  // namespace

TEST_CASE("MJCF replay: MuJoCo's key k reproduces frame k", "[io][mjcf_replay][mujoco]") {
  const auto planar = viz_test::make_biped<planar_root>();
  check_replay_in_mujoco(planar, viz_test::make_walk(planar, 0.6, 0.02));
  const auto floating = viz_test::make_biped<floating_root>();
  check_replay_in_mujoco(floating, viz_test::make_walk(floating, 0.6, 0.02));
  // A floating root with a joint_offset (io/mjcf.hpp writes slides + a ball joint for it).
  auto offset = floating;
  offset.name = "offset_root";
  offset.bodies[0].joint_offset = {0.1, -0.05, 0.2};
  check_replay_in_mujoco(offset, viz_test::make_walk(offset, 0.6, 0.02));
  auto planar_offset = planar;
  planar_offset.name = "offset_planar";
  planar_offset.bodies[0].joint_offset = {0.1, 0.0, 0.2};
  check_replay_in_mujoco(planar_offset, viz_test::make_walk(planar_offset, 0.6, 0.02));
}
