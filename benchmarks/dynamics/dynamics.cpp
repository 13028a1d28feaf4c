// Dynamics algorithms on the built-in characters: the 7-link planar human of Sharon & van de Panne
// 2005 and the 30-DOF 3D humanoid of Wang et al. 2009 (floating root, nv = 36).
// Each iteration forces the kinematics to be recomputed (invalidate_kinematics) unless the name
// says "cached", so the figures are for a fresh (q, v). Every case runs 5 repetitions and also
// reports their minimum ("_min"): on a shared machine the minimum is the figure least disturbed by
// others.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"

namespace {
using namespace gaitsynth;

template <root_joint Root>
struct fixture {
  model<Root> m;
  workspace<Root> ws;
  Eigen::VectorXd q, v, tau, a;
  explicit fixture(model<Root> model_) : m(std::move(model_)), ws(make_workspace(m)) {
    std::mt19937 rng(42);
    std::mt19937_64 configuration_rng(42);  // random_configuration takes the portable engine
    q = random_configuration(m, configuration_rng);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    v.resize(m.nv());
    tau.resize(m.nv());
    a.resize(m.nv());
    for (int i = 0; i < m.nv(); ++i) {
      v[i] = u(rng);
      tau[i] = 10 * u(rng);
      a[i] = u(rng);
    }
  }
};

fixture<planar_root>& human7() {
  static fixture<planar_root> f(sharon2005_human7());
  return f;
}
fixture<floating_root>& humanoid3d() {
  static fixture<floating_root> f(wang2009_humanoid());
  return f;
}
// The same with ABA by joints (aba_by_joint.hpp, opt-in), the peer of the default single-DOF
// node passes (aba.hpp).
fixture<floating_root>& humanoid3d_by_joint() {
  static fixture<floating_root> f(wang2009_humanoid());
  enable_aba_by_joint(f.ws);
  return f;
}

template <class F>
void label(benchmark::State& st, const F& f) {
  st.SetLabel(f.m.name + " nv=" + std::to_string(f.m.nv()));
}

template <class Get>
void BM_forward_kinematics(benchmark::State& st, Get get) {
  auto& f = get();
  for (auto _ : st) {
    invalidate_kinematics(f.ws);
    forward_kinematics(f.m, f.ws, f.q, f.v);
    benchmark::DoNotOptimize(f.ws.body_position.data());
  }
  label(st, f);
}

template <class Get>
void BM_aba(benchmark::State& st, Get get) {
  auto& f = get();
  for (auto _ : st) {
    invalidate_kinematics(f.ws);
    benchmark::DoNotOptimize(aba(f.m, f.ws, f.q, f.v, f.tau).data());
  }
  label(st, f);
}

// ABA after forward_kinematics(q, v) ran for the same state (the rollout's situation: contacts need
// the kinematics first).
template <class Get>
void BM_aba_cached(benchmark::State& st, Get get) {
  auto& f = get();
  forward_kinematics(f.m, f.ws, f.q, f.v);
  for (auto _ : st) benchmark::DoNotOptimize(aba(f.m, f.ws, f.q, f.v, f.tau).data());
  label(st, f);
}

template <class Get>
void BM_rnea(benchmark::State& st, Get get) {
  auto& f = get();
  for (auto _ : st) {
    invalidate_kinematics(f.ws);
    benchmark::DoNotOptimize(rnea(f.m, f.ws, f.q, f.v, f.a).data());
  }
  label(st, f);
}

template <class Get>
void BM_crba(benchmark::State& st, Get get) {
  auto& f = get();
  for (auto _ : st) {
    invalidate_kinematics(f.ws);
    benchmark::DoNotOptimize(crba(f.m, f.ws, f.q).data());
  }
  label(st, f);
}

// One semi-implicit Euler step with ABA (no contacts) at 2400 Hz.
template <class Get>
void BM_step_semi_implicit_euler(benchmark::State& st, Get get) {
  auto& f = get();
  sim_state s{f.q, f.v, 0.0};
  semi_implicit_euler integ(f.m);
  auto sys = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, double, Eigen::VectorXd& ddq) {
    ddq = aba(f.m, f.ws, q, v, f.tau);
  };
  for (auto _ : st) {
    integ.step(f.m, s, 1.0 / 2400.0, sys);
    if (st.iterations() % 2400 == 0) s = sim_state{f.q, f.v, 0.0};  // stay near the start state
    benchmark::DoNotOptimize(s.q.data());
  }
  label(st, f);
}
void settings(benchmark::internal::Benchmark* b) {
  b->Repetitions(5)->ComputeStatistics(
      "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
}
}  // namespace

BENCHMARK_CAPTURE(BM_forward_kinematics, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_forward_kinematics, humanoid3d, humanoid3d)->Apply(settings);
BENCHMARK_CAPTURE(BM_aba, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_aba, humanoid3d, humanoid3d)->Apply(settings);
BENCHMARK_CAPTURE(BM_aba_cached, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_aba_cached, humanoid3d, humanoid3d)->Apply(settings);
BENCHMARK_CAPTURE(BM_aba_cached, humanoid3d_by_joint, humanoid3d_by_joint)->Apply(settings);
BENCHMARK_CAPTURE(BM_rnea, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_rnea, humanoid3d, humanoid3d)->Apply(settings);
BENCHMARK_CAPTURE(BM_crba, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_crba, humanoid3d, humanoid3d)->Apply(settings);
BENCHMARK_CAPTURE(BM_step_semi_implicit_euler, human7, human7)->Apply(settings);
BENCHMARK_CAPTURE(BM_step_semi_implicit_euler, humanoid3d, humanoid3d)->Apply(settings);
