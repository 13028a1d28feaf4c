#pragma once
// MuJoCo peer of the rollout benchmarks: MuJoCo's mj_step on the exported MJCF (io/mjcf.hpp) of the
// same characters at the same timestep, so gaitsynth / MuJoCo ratios can come from one run.
// Registered only when MuJoCo is found (GAITSYNTH_HAVE_MUJOCO); otherwise this header is empty.
//
// Include it from exactly one translation unit of a benchmark binary: bench_mujoco_peer does
// (mujoco_peer.cpp), and bench_rollout may too, to put the peer next to gaitsynth's rollout.
//
// Set-up, the same for every case (docs/mjcf.md, "Benchmark peer"):
//  * the character is exported with a sphere geom (radius 1 cm, condim 3, mu = 1) at every contact
//    point: the Wang 2009 humanoid has 20 (4 heel/ball per foot, 4 per toe segment = the 16 that
//    carry the standing weight, and 2 toe-top points per toe that stay in the air), the 7-link
//    planar human 4 (heel and toe per foot); a floor plane; no joint limits (gaitsynth's are soft
//    springs, MuJoCo's hard constraints would add solver rows at the knees' zero limit);
//    Euler integrator at 1/2400 s; MuJoCo 2.2.2 defaults otherwise (pyramidal cones, Newton
//    solver, 100 iterations max, warm start);
//  * it starts standing (standing_configuration, soles one sphere radius above the floor) and holds
//    the neutral pose with PD servos computed every step into ctrl:
//    tau_j = kp_j (0 - q_j) - kd_j qdot_j, clamped to the DOF's torque limit (the motor's
//    ctrlrange), gains kp = 1000 N m/rad, kd = 100 N m s/rad capped per DOF for an explicit
//    integrator with the rule of pd_actuator::capped (kd <= I/dt, kp <= I/dt^2, I the DOF's
//    effective inertia).
// Cases:
//  BM_MuJoCo_Step_<character>:       one mj_step (+ the PD law) in steady standing contact;
//  BM_MuJoCo_Rollout10s_<character>: reset, then 24000 steps (10 s at 2400 Hz) with the PD law;
//  BM_MuJoCo_RigidBodyForward_<character>: mj_forward with every constraint disabled (the
//      rigid-body part MuJoCo does per step, compare with aba).
// Counters: realtime_factor (simulated s per wall s), time_per_step (s), contacts (mean active
// contacts), pelvis_z (root height at the end of the last iteration, m: it stayed standing).
#ifdef GAITSYNTH_HAVE_MUJOCO

#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/io/mjcf.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/standing.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace gaitsynth::mujoco_peer {

inline constexpr double timestep = 1.0 / 2400.0;
inline constexpr double sphere_radius = 0.01;
/// PD gains, capped per DOF at pd_margin times the explicit-integrator bounds (see peer()). With
/// margin 1 the Wang humanoid's toes (effective inertia 1.3e-4 kg m^2) chatter against MuJoCo's
/// soft contacts and it falls within 1 s; at 0.5 it stands for the whole 10 s on 16 contacts.
inline constexpr double pd_kp = 1000.0, pd_kd = 100.0, pd_margin = 0.5;

/// A loaded MuJoCo model of an exported gaitsynth character, standing, with a PD pose hold.
class peer {
 public:
  template <root_joint Root>
  explicit peer(const model<Root>& gm) : name_(gm.name), nj_(gm.num_joint_dofs()) {
    mjcf_options o;
    o.timestep = timestep;
    o.contact_geoms = true;
    o.contact_geom_radius = sphere_radius;
    o.contact_sites = false;
    o.joint_limits = false;
    o.keyframe_q = standing_configuration(gm, sphere_radius);
    load(to_mjcf_string(gm, o));
    for (int j = 0; j < nj_; ++j) {
      const int id = mj_name2id(m_, mjOBJ_JOINT, gm.dofs[j].name.c_str());
      if (id < 0) throw std::runtime_error("mujoco_peer: joint " + gm.dofs[j].name + " missing");
      qadr_.push_back(m_->jnt_qposadr[id]);
      dadr_.push_back(m_->jnt_dofadr[id]);
    }
    root_z_adr_ = Root::nq == 7 ? 2 : (Root::nq == 3 ? 1 : -1);
    reset();
    // PD gains capped as pd_actuator::capped does (kd <= m I_j / dt, kp <= m I_j / dt^2 with I_j =
    // 1 / (M^-1)_jj, the effective inertia at the neutral pose), with M from MuJoCo itself: the
    // same numbers to rounding (tests/io/mjcf.mujoco.cpp), without Eigen's gemm, which GCC 12
    // warns about under -march=native.
    mj_forward(m_, d_);
    std::vector<mjtNum> x(m_->nv);
    for (int j = 0; j < nj_; ++j) {
      std::fill(x.begin(), x.end(), 0.0);
      x[dadr_[j]] = 1.0;
      mj_solveM(m_, d_, x.data(), x.data(), 1);
      const double inertia = 1.0 / x[dadr_[j]];
      kp_.push_back(std::min(pd_kp, pd_margin * inertia / (timestep * timestep)));
      kd_.push_back(std::min(pd_kd, pd_margin * inertia / timestep));
    }
  }
  ~peer() {
    if (d_) mj_deleteData(d_);
    if (m_) mj_deleteModel(m_);
  }
  peer(const peer&) = delete;
  peer& operator=(const peer&) = delete;

  void reset() { mj_resetDataKeyframe(m_, d_, 0); }
  /// PD law into ctrl (ctrl[j] drives gaitsynth DOF j; MuJoCo clamps it to the torque limit).
  void control() {
    for (int j = 0; j < nj_; ++j)
      d_->ctrl[j] = -kp_[j] * d_->qpos[qadr_[j]] - kd_[j] * d_->qvel[dadr_[j]];
  }
  void step() {
    control();
    mj_step(m_, d_);
  }
  double root_z() const { return root_z_adr_ >= 0 ? d_->qpos[root_z_adr_] : 0.0; }
  int contacts() const { return d_->ncon; }
  mjModel* m() { return m_; }
  mjData* d() { return d_; }
  const std::string& name() const { return name_; }

 private:
  void load(const std::string& xml) {
    // Load from memory through MuJoCo's virtual file system (no temporary file).
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    if (mj_makeEmptyFileVFS(vfs.get(), "peer.xml", static_cast<int>(xml.size())) != 0)
      throw std::runtime_error("mujoco_peer: cannot create the VFS file");
    const int idx = mj_findFileVFS(vfs.get(), "peer.xml");
    std::memcpy(vfs->filedata[idx], xml.data(), xml.size());
    char err[1024] = "";
    m_ = mj_loadXML("peer.xml", vfs.get(), err, sizeof(err));
    mj_deleteVFS(vfs.get());
    if (!m_) throw std::runtime_error("mujoco_peer: MuJoCo rejected " + name_ + ": " + err);
    d_ = mj_makeData(m_);
  }

  std::string name_;
  int nj_ = 0;
  mjModel* m_ = nullptr;
  mjData* d_ = nullptr;
  std::vector<double> kp_, kd_;
  std::vector<int> qadr_, dadr_;
  int root_z_adr_ = -1;
};

inline peer& humanoid3d() {
  static peer p(wang2009_humanoid());
  return p;
}
inline peer& human7() {
  static peer p(sharon2005_human7());
  return p;
}

inline void label(benchmark::State& st, peer& p) {
  st.SetLabel(p.name() + " nv=" + std::to_string(p.m()->nv) +
              " geoms=" + std::to_string(p.m()->ngeom) + " MuJoCo " + mj_versionString());
}

/// One mj_step in steady standing contact (after 0.5 s of settling).
template <class Get>
void BM_MuJoCo_Step(benchmark::State& st, Get get) {
  peer& p = get();
  p.reset();
  for (int i = 0; i < 1200; ++i) p.step();
  double contacts = 0;
  for (auto _ : st) {
    p.step();
    contacts += p.contacts();
  }
  st.counters["realtime_factor"] =
      benchmark::Counter(timestep, benchmark::Counter::kIsIterationInvariantRate);
  st.counters["time_per_step"] = benchmark::Counter(
      1.0, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.counters["contacts"] = benchmark::Counter(contacts, benchmark::Counter::kAvgIterations);
  st.counters["pelvis_z"] = p.root_z();
  label(st, p);
}

/// A 10 s standing rollout: 24000 steps at 2400 Hz from the standing keyframe.
template <class Get>
void BM_MuJoCo_Rollout10s(benchmark::State& st, Get get) {
  peer& p = get();
  constexpr int steps = 24000;
  double contacts = 0;
  for (auto _ : st) {
    p.reset();
    for (int i = 0; i < steps; ++i) {
      p.step();
      contacts += p.contacts();
    }
    benchmark::DoNotOptimize(p.d()->qpos);
  }
  st.counters["realtime_factor"] =
      benchmark::Counter(steps * timestep, benchmark::Counter::kIsIterationInvariantRate);
  st.counters["time_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.counters["contacts"] =
      benchmark::Counter(contacts / steps, benchmark::Counter::kAvgIterations);
  st.counters["pelvis_z"] = p.root_z();
  label(st, p);
}

/// mj_forward with every constraint disabled: MuJoCo's rigid-body work per step.
template <class Get>
void BM_MuJoCo_RigidBodyForward(benchmark::State& st, Get get) {
  peer& p = get();
  p.reset();
  const int saved = p.m()->opt.disableflags;
  p.m()->opt.disableflags |= mjDSBL_CONSTRAINT | mjDSBL_CONTACT | mjDSBL_LIMIT;
  for (int i = 0; i < p.m()->nv; ++i) p.d()->qvel[i] = 0.1 * (i % 7 - 3);
  for (auto _ : st) {
    mj_forward(p.m(), p.d());
    benchmark::DoNotOptimize(p.d()->qacc);
  }
  p.m()->opt.disableflags = saved;
  label(st, p);
}

// Explicit names (BM_MuJoCo_<case>_<character>) to sit next to gaitsynth's BM_..._<character>.
inline bool register_all() {
  using namespace benchmark;
  RegisterBenchmark("BM_MuJoCo_Step_Humanoid3D", BM_MuJoCo_Step<peer& (*)()>, &humanoid3d);
  RegisterBenchmark("BM_MuJoCo_Rollout10s_Humanoid3D", BM_MuJoCo_Rollout10s<peer& (*)()>,
                    &humanoid3d)
      ->Unit(kMillisecond)
      ->MinTime(2.0);
  RegisterBenchmark("BM_MuJoCo_RigidBodyForward_Humanoid3D",
                    BM_MuJoCo_RigidBodyForward<peer& (*)()>, &humanoid3d);
  RegisterBenchmark("BM_MuJoCo_Step_Human7", BM_MuJoCo_Step<peer& (*)()>, &human7);
  RegisterBenchmark("BM_MuJoCo_Rollout10s_Human7", BM_MuJoCo_Rollout10s<peer& (*)()>, &human7)
      ->Unit(kMillisecond)
      ->MinTime(1.0);
  RegisterBenchmark("BM_MuJoCo_RigidBodyForward_Human7", BM_MuJoCo_RigidBodyForward<peer& (*)()>,
                    &human7);
  return true;
}
static const bool registered = register_all();

}  // namespace gaitsynth::mujoco_peer

#endif  // GAITSYNTH_HAVE_MUJOCO
