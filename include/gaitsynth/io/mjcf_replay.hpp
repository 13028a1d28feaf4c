#pragma once
/// \file mjcf_replay.hpp
/// A recorded trajectory for MuJoCo: keyframes (<keyframe><key time qpos qvel/>) in the coordinate
/// order of the MJCF file that io/mjcf.hpp writes for the same model (MuJoCo numbers joints
/// depth-first, gaitsynth only parents-first: to_mjcf_qpos / to_mjcf_qvel apply the permutation).
///
/// * write_mjcf_keyframes: just the <keyframe> element, to paste into an exported model.
/// * write_mjcf_replay / save_mjcf_replay: the whole model (write_mjcf) with the keyframes in it.
///   Open it in MuJoCo's `simulate`, pause, and move the "Key" slider (Load key) to step through
///   the motion; mj_resetDataKeyframe(m, d, k) loads key k in code. Key k is the k-th kept frame
///   (the options' own keyframe_q "initial" key is left out so that indices match).
/// * write_mjcf_qpos_csv: "time,<qpos names>" rows in MuJoCo's qpos order, to drive a replay loop
///   in MuJoCo's Python bindings (docs/viewer.md shows one).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/error.hpp"
#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/rollout/trajectory.hpp"
#include "gaitsynth/viz/scene.hpp"

namespace gaitsynth {

struct mjcf_replay_options {
  mjcf_options model;      ///< passed to write_mjcf (its keyframe_q / keyframe_v are ignored)
  double interval = 0.0;   ///< s between keys (nearest recorded frame); 0: every frame
  int max_keys = 2000;     ///< more frames than this are thinned by a constant stride
  bool velocities = true;  ///< write qvel too (needs the frames' v)
};

namespace detail::mjcf_replay {

/// Indices of the frames that become keys.
inline std::vector<int> pick_frames(const trajectory& traj, const mjcf_replay_options& opt) {
  std::vector<int> picks;
  const auto& fr = traj.frames;
  if (fr.empty()) return picks;
  if (opt.interval > 0) {
    for (long k = 0;; ++k) {
      const double t = fr.front().t + k * opt.interval;
      if (t > fr.back().t + 1e-12 || k > 10000000) break;
      const int f = viz_detail::nearest_frame(traj, t);
      if (picks.empty() || picks.back() != f) picks.push_back(f);
    }
  } else {
    for (std::size_t i = 0; i < fr.size(); ++i) picks.push_back(static_cast<int>(i));
  }
  if (static_cast<int>(picks.size()) > opt.max_keys) {
    const std::size_t stride = (picks.size() + opt.max_keys - 1) / opt.max_keys;
    std::vector<int> thin;
    for (std::size_t i = 0; i < picks.size(); i += stride) thin.push_back(picks[i]);
    picks.swap(thin);
  }
  return picks;
}

}  // namespace detail::mjcf_replay

/// Writes "<keyframe> ... </keyframe>" (one <key name="f<frame>" time qpos [qvel]> per kept frame).
/// Throws std::invalid_argument when the trajectory does not fit the model or options are invalid.
template <root_joint Root>
void write_mjcf_keyframes(const model<Root>& m, const trajectory& traj, std::ostream& os,
                          const mjcf_replay_options& opt = {}) {
  using detail::mjcf::num;
  viz_detail::check_trajectory(m, traj, "write_mjcf_keyframes");
  check_argument(std::isfinite(opt.interval) && opt.interval >= 0,
                 "write_mjcf_keyframes: interval must be finite and >= 0, got ", opt.interval);
  check_argument(opt.max_keys >= 1, "write_mjcf_keyframes: max_keys must be >= 1, got ",
                 opt.max_keys);
  const std::vector<int> picks = detail::mjcf_replay::pick_frames(traj, opt);
  std::string x = "  <keyframe>\n";
  for (int f : picks) {
    const trajectory_frame& fr = traj.frames[f];
    Eigen::VectorXd q = fr.q;
    if constexpr (Root::nq == 7) q.segment<4>(3).normalize();  // MuJoCo wants a unit quaternion
    const Eigen::VectorXd qpos = to_mjcf_qpos(m, q);
    x += "    <key name=\"f" + std::to_string(f) + "\" time=\"" + num(fr.t) + "\" qpos=\"";
    for (Eigen::Index i = 0; i < qpos.size(); ++i) {
      if (i) x += ' ';
      x += num(qpos[i]);
    }
    x += "\"";
    if (opt.velocities && fr.v.size() == m.nv() && m.nv() > 0) {
      check_finite(fr.v, "write_mjcf_keyframes: frame v");
      const Eigen::VectorXd qvel = to_mjcf_qvel(m, fr.v);
      x += " qvel=\"";
      for (Eigen::Index i = 0; i < qvel.size(); ++i) {
        if (i) x += ' ';
        x += num(qvel[i]);
      }
      x += "\"";
    }
    x += "/>\n";
  }
  x += "  </keyframe>\n";
  os << x;
}

/// The MJCF model of io/mjcf.hpp with the trajectory's keyframes inserted before </mujoco>.
template <root_joint Root>
void write_mjcf_replay(const model<Root>& m, const trajectory& traj, std::ostream& os,
                       const mjcf_replay_options& opt = {}) {
  mjcf_options mo = opt.model;
  mo.keyframe_q.resize(0);
  mo.keyframe_v.resize(0);
  std::string xml = to_mjcf_string(m, mo);
  std::ostringstream keys;
  write_mjcf_keyframes(m, traj, keys, opt);
  const auto end = xml.rfind("</mujoco>");
  check_argument(end != std::string::npos,
                 "write_mjcf_replay: the exported MJCF has no </mujoco> element");
  xml.insert(end, keys.str());
  os << xml;
}

/// Writes write_mjcf_replay's document to `path` (nothing when the arguments are invalid).
template <root_joint Root>
void save_mjcf_replay(const model<Root>& m, const trajectory& traj, const std::string& path,
                      const mjcf_replay_options& opt = {}) {
  std::ostringstream s;
  write_mjcf_replay(m, traj, s, opt);
  std::ofstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("save_mjcf_replay: cannot open '" + path + "' for writing");
  f << s.str();
  f.close();
  if (!f) throw std::runtime_error("save_mjcf_replay: failed writing '" + path + "'");
}

/// "time,<MuJoCo qpos names>" then one row per frame, qpos in MuJoCo's order (a replay loop in
/// MuJoCo's Python bindings sets d.qpos from each row and calls mj_forward).
template <root_joint Root>
void write_mjcf_qpos_csv(const model<Root>& m, const trajectory& traj, std::ostream& os) {
  using detail::mjcf::num;
  viz_detail::check_trajectory(m, traj, "write_mjcf_qpos_csv");
  const std::vector<std::string> names = q_coordinate_names(m);
  const std::vector<int> idx = mjcf_qpos_index(m);
  std::string x = "time";
  for (int i : idx) {
    x += ',';
    x += names[i];
  }
  x += '\n';
  for (const auto& fr : traj.frames) {
    Eigen::VectorXd q = fr.q;
    if constexpr (Root::nq == 7) q.segment<4>(3).normalize();
    x += num(fr.t);
    for (int i : idx) {
      x += ',';
      x += num(q[i]);
    }
    x += '\n';
  }
  os << x;
}

}  // namespace gaitsynth
