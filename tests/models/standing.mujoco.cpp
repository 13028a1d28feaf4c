// Independent check of the characters' mass properties and geometry: exported as MJCF (contact
// spheres at the contact points), every character stands still in MuJoCo under the same PD pose
// hold as in tests/models/standing.cpp.
#include <mujoco/mujoco.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <string>

#include "gaitsynth/actuators/pd.hpp"
#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/models/models.hpp"

using namespace gaitsynth;

namespace {

template <class Root>
void check_stands_in_mujoco(const model<Root>& gm) {
  INFO(gm.name);
  mjcf_options o;
  o.contact_geoms = true;  // spheres centred at the contact points
  o.joint_limits = false;  // gaitsynth's limits are soft springs; q = 0 is inside them anyway
  o.visual_geoms = false;
  o.keyframe_q = standing_configuration(gm, o.contact_geom_radius);
  // Load the exported text through MuJoCo's virtual file system (no temporary file).
  const std::string xml = to_mjcf_string(gm, o);
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  REQUIRE(mj_makeEmptyFileVFS(&vfs, "character.xml", static_cast<int>(xml.size())) == 0);
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "character.xml")], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML("character.xml", &vfs, error, sizeof(error));
  mj_deleteVFS(&vfs);
  INFO(error);
  REQUIRE(m != nullptr);
  mjData* d = mj_makeData(m);
  mj_resetDataKeyframe(m, d, 0);
  const int nj = gm.num_joint_dofs();
  const auto pd = pd_actuator::capped(gm, Eigen::VectorXd::Constant(nj, 3000.0),
                                      Eigen::VectorXd::Constant(nj, 100.0), o.timestep);
  const auto qi = mjcf_qpos_index(gm);
  const auto vi = mjcf_qvel_index(gm);
  mj_forward(m, d);
  const Eigen::Vector3d com0(d->subtree_com[3], d->subtree_com[4], d->subtree_com[5]);
  const int steps = static_cast<int>(2.0 / o.timestep);
  for (int k = 0; k < steps; ++k) {
    for (int j = 0; j < nj; ++j)
      d->ctrl[j] = -pd.kp[j] * d->qpos[qi[Root::nq + j]] - pd.kd[j] * d->qvel[vi[Root::nv + j]];
    mj_step(m, d);
  }
  mj_forward(m, d);
  const Eigen::Vector3d com1(d->subtree_com[3], d->subtree_com[4], d->subtree_com[5]);
  CHECK((com1 - com0).norm() < 0.03);
  CHECK(d->ncon >= 4);
  mj_deleteData(d);
  mj_deleteModel(m);
}

}  // namespace

TEST_CASE("every character stands in MuJoCo under a PD pose hold", "[models][standing][mujoco]") {
  check_stands_in_mujoco(sharon2005_human7());
  check_stands_in_mujoco(sharon2005_human16());
  for (wang2009_shape s : wang2009_shapes) check_stands_in_mujoco(wang2009_humanoid(s));
  check_stands_in_mujoco(wu2010_biped());
  check_stands_in_mujoco(wang2012_humanoid());
}
