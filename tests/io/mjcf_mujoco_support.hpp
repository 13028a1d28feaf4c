#pragma once
// Loading an exported model in MuJoCo for the oracle tests (tests/io/mjcf.mujoco.cpp): the exported
// file goes through save_mjcf to a temporary file and mj_loadXML, exactly as a user would load it.
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "gaitsynth/io/mjcf.hpp"

namespace gaitsynth::mjcf_test {

/// Owns an mjModel and one mjData.
struct mujoco_instance {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  std::string warnings;  ///< whatever mj_loadXML wrote to its error buffer on success
  mujoco_instance() = default;
  mujoco_instance(const mujoco_instance&) = delete;
  mujoco_instance& operator=(const mujoco_instance&) = delete;
  ~mujoco_instance() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
};

/// Exports `gm` with `opt` to a unique temporary file, loads it with mj_loadXML and deletes the
/// file. Throws std::runtime_error with MuJoCo's message if it does not load.
template <root_joint Root>
std::unique_ptr<mujoco_instance> load_in_mujoco(const model<Root>& gm,
                                                const mjcf_options& opt = {}) {
  static std::atomic<int> counter{0};
  const auto path =
      std::filesystem::temp_directory_path() /
      ("gaitsynth_mjcf_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".xml");
  save_mjcf(gm, path.string(), opt);
  auto out = std::make_unique<mujoco_instance>();
  char error[2048] = "";
  out->m = mj_loadXML(path.string().c_str(), nullptr, error, sizeof(error));
  std::error_code ec;
  std::filesystem::remove(path, ec);
  if (!out->m)
    throw std::runtime_error("MuJoCo rejected the exported model '" + gm.name + "': " + error);
  out->warnings = error;
  out->d = mj_makeData(out->m);
  return out;
}

/// Switches off everything that is not rigid-body dynamics: constraints (contacts, joint limits,
/// equality, friction loss), passive forces and control clamping (ctrl then is the joint torque).
/// The exported file already has no armature, damping, stiffness or friction loss.
inline void pure_rigid_body(mjModel* m) {
  m->opt.disableflags |= mjDSBL_CONSTRAINT | mjDSBL_CONTACT | mjDSBL_LIMIT | mjDSBL_EQUALITY |
                         mjDSBL_FRICTIONLOSS | mjDSBL_PASSIVE | mjDSBL_CLAMPCTRL;
}

}  // namespace gaitsynth::mjcf_test
