// Mixing the dynamics algorithms on one workspace (docs/dynamics.md, "Internal representation"):
// whatever ran before on the same (q, v), every algorithm and reader returns what it returns on a
// fresh workspace; after a q-only algorithm moved the workspace to another configuration, the
// velocity readers refuse instead of returning stale or zeroed velocities (issue 10, item 2:
// forward_kinematics(q, v) then gravity_forces(q) left kinetic_energy, centroidal_momentum and
// com_velocity at 0 on 3D models).
#include <catch2/catch.hpp>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "gaitsynth/dynamics.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/models/wang2009.hpp"
#include "support/dynamics_support.hpp"

using namespace gaitsynth;
using gaitsynth::testing::is_approx;
using gaitsynth::testing::random_vector;

namespace {

/// The inputs every algorithm of one test sees: a random non-neutral state, accelerations for the
/// inverse dynamics, torques for ABA and external wrenches (set on every workspace).
template <root_joint Root>
struct problem {
  Eigen::VectorXd q, v, a, tau;
  std::vector<vec6> f_ext;
  int body = 0;         ///< the body of the Jacobians and point readers
  vec3 point{0, 0, 0};  ///< a point of it, body frame
  bool planar = true;   ///< false: run the 6D code on a planar model (disable_planar_path)
};

template <root_joint Root>
problem<Root> random_problem(const model<Root>& m, std::mt19937& rng, bool planar = true) {
  problem<Root> p;
  std::mt19937_64 configuration_rng(rng());  // random_configuration takes the portable engine
  p.q = random_configuration(m, configuration_rng);
  p.v = random_vector(rng, m.nv(), 1.5);
  p.a = random_vector(rng, m.nv(), 3.0);
  p.tau = random_vector(rng, m.nv(), 20.0);
  p.f_ext.resize(m.num_bodies());
  for (auto& f : p.f_ext) f = random_vector(rng, 6, 10.0);
  p.body = m.num_bodies() - 1;
  p.point = gaitsynth::testing::random_vec3(rng, 0.1);
  p.planar = planar;
  return p;
}

template <root_joint Root>
workspace<Root> fresh_workspace(const model<Root>& m, const problem<Root>& p) {
  auto ws = make_workspace(m);
  if (!p.planar) disable_planar_path(ws);
  for (int b = 0; b < m.num_bodies(); ++b) add_body_wrench(ws, b, p.f_ext[b]);
  return ws;
}

template <class Vec>
Eigen::VectorXd flatten(const std::vector<Vec>& xs) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(xs.size()) * Vec::SizeAtCompileTime);
  Eigen::Index i = 0;
  for (const auto& x : xs) {
    out.segment(i, x.size()) = Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
    i += x.size();
  }
  return out;
}
template <class Mat>
Eigen::VectorXd flatten_matrix(const Mat& M) {
  return Eigen::Map<const Eigen::VectorXd>(Eigen::MatrixXd(M).data(), M.size());
}
Eigen::VectorXd cat(std::initializer_list<Eigen::VectorXd> parts) {
  Eigen::Index n = 0;
  for (const auto& x : parts) n += x.size();
  Eigen::VectorXd out(n);
  n = 0;
  for (const auto& x : parts) {
    out.segment(n, x.size()) = x;
    n += x.size();
  }
  return out;
}

template <root_joint Root>
Eigen::VectorXd poses(const workspace<Root>& ws) {
  return cat({flatten(ws.body_position), flatten(ws.body_rotation)});
}
template <root_joint Root>
Eigen::VectorXd poses_and_velocities(const workspace<Root>& ws) {
  return cat({poses(ws), flatten(ws.body_angular_velocity), flatten(ws.body_linear_velocity)});
}
Eigen::VectorXd scalar(double x) {
  return Eigen::VectorXd::Constant(1, x);
}

/// What an algorithm takes: q, or q and v (it computes the kinematics it needs itself), or
/// nothing but the workspace (a reader of the poses, or of the poses and velocities, that
/// forward_kinematics left).
enum class takes { q, q_v, poses, velocities };

/// One public algorithm or reader, run on (q, v) of a problem; returns its output flattened.
template <root_joint Root>
struct algorithm {
  std::string name;
  takes input;
  bool needs_v() const { return input == takes::q_v || input == takes::velocities; }
  bool reader() const { return input == takes::poses || input == takes::velocities; }
  std::function<Eigen::VectorXd(const model<Root>&, workspace<Root>&, const problem<Root>&)> run;
};

template <root_joint Root>
std::vector<algorithm<Root>> algorithms() {
  using M = model<Root>;
  using W = workspace<Root>;
  using P = problem<Root>;
  return {
      {"forward_kinematics(q)", takes::q,
       [](const M& m, W& ws, const P& p) {
         forward_kinematics(m, ws, p.q);
         return poses(ws);
       }},
      {"forward_kinematics(q, v)", takes::q_v,
       [](const M& m, W& ws, const P& p) {
         forward_kinematics(m, ws, p.q, p.v);
         return poses_and_velocities(ws);
       }},
      {"gravity_forces", takes::q,
       [](const M& m, W& ws, const P& p) { return Eigen::VectorXd(gravity_forces(m, ws, p.q)); }},
      {"nonlinear_effects", takes::q_v,
       [](const M& m, W& ws, const P& p) {
         return Eigen::VectorXd(nonlinear_effects(m, ws, p.q, p.v));
       }},
      {"rnea", takes::q_v,
       [](const M& m, W& ws, const P& p) { return Eigen::VectorXd(rnea(m, ws, p.q, p.v, p.a)); }},
      {"rnea_with_external", takes::q_v,
       [](const M& m, W& ws, const P& p) {
         return Eigen::VectorXd(rnea_with_external(m, ws, p.q, p.v, p.a));
       }},
      {"crba", takes::q,
       [](const M& m, W& ws, const P& p) { return flatten_matrix(crba(m, ws, p.q)); }},
      {"aba", takes::q_v,
       [](const M& m, W& ws, const P& p) { return Eigen::VectorXd(aba(m, ws, p.q, p.v, p.tau)); }},
      {"point_jacobian", takes::q,
       [](const M& m, W& ws, const P& p) {
         Eigen::MatrixXd J(3, m.nv());
         point_jacobian(m, ws, p.q, p.body, p.point, J);
         return flatten_matrix(J);
       }},
      {"body_orientation_jacobian", takes::q,
       [](const M& m, W& ws, const P& p) {
         Eigen::MatrixXd J(3, m.nv());
         body_orientation_jacobian(m, ws, p.q, p.body, J);
         return flatten_matrix(J);
       }},
      {"point_position", takes::poses,
       [](const M& m, W& ws, const P& p) {
         return Eigen::VectorXd(point_position(m, ws, p.body, p.point));
       }},
      {"point_velocity", takes::velocities,
       [](const M& m, W& ws, const P& p) {
         return Eigen::VectorXd(point_velocity(m, ws, p.body, p.point));
       }},
      {"center_of_mass", takes::poses,
       [](const M& m, W& ws, const P&) { return Eigen::VectorXd(center_of_mass(m, ws)); }},
      {"com_velocity", takes::velocities,
       [](const M& m, W& ws, const P&) { return Eigen::VectorXd(com_velocity(m, ws)); }},
      {"centroidal_momentum", takes::velocities,
       [](const M& m, W& ws, const P&) {
         const momentum h = centroidal_momentum(m, ws);
         return cat({h.linear, h.angular});
       }},
      {"kinetic_energy", takes::velocities,
       [](const M& m, W& ws, const P&) { return scalar(kinetic_energy(m, ws)); }},
      {"potential_energy", takes::poses,
       [](const M& m, W& ws, const P&) { return scalar(potential_energy(m, ws)); }},
      {"total_energy", takes::velocities,
       [](const M& m, W& ws, const P&) { return scalar(total_energy(m, ws)); }},
  };
}

/// B's output on a fresh workspace after the forward_kinematics call it needs.
template <root_joint Root>
Eigen::VectorXd reference(const model<Root>& m, const problem<Root>& p, const algorithm<Root>& b) {
  auto ws = fresh_workspace(m, p);
  if (b.needs_v())
    forward_kinematics(m, ws, p.q, p.v);
  else
    forward_kinematics(m, ws, p.q);
  return b.run(m, ws, p);
}

/// Compares an output with its reference: bit for bit where both come from the same code on the
/// same inputs (every 3D model, and planar models with the planar path disabled); to rounding on
/// the planar path, where a 6D algorithm in between (rnea, nonlinear_effects, crba, Jacobians,
/// gravity_forces) rewrites the shared poses (and velocities) with the 6D code's rounding and
/// leaves the 6D scratch current, which the readers may then read instead of the planar one.
void require_same(const Eigen::VectorXd& got, const Eigen::VectorXd& ref, bool exact) {
  REQUIRE(got.size() == ref.size());
  REQUIRE(got.allFinite());
  if (exact)
    REQUIRE_THAT(got, is_approx(ref, 0.0, 0.0));
  else
    REQUIRE_THAT(got, is_approx(ref, 1e-12, 0.0));
}

template <root_joint Root>
void check_all_pairs(const model<Root>& m, const problem<Root>& p, bool exact) {
  const auto algos = algorithms<Root>();
  std::vector<Eigen::VectorXd> refs;
  for (const auto& b : algos) refs.push_back(reference(m, p, b));
  for (const auto& a : algos)
    for (std::size_t ib = 0; ib < algos.size(); ++ib) {
      const auto& b = algos[ib];
      CAPTURE(m.name, p.planar, a.name, b.name);
      auto ws = fresh_workspace(m, p);
      forward_kinematics(m, ws, p.q, p.v);
      (void)a.run(m, ws, p);
      require_same(b.run(m, ws, p), refs[ib], exact);
    }
}

/// Random sequences of algorithms after forward_kinematics(q, v): each output equals its reference.
template <root_joint Root>
void check_random_sequences(const model<Root>& m, const problem<Root>& p, bool exact,
                            std::mt19937& rng) {
  const auto algos = algorithms<Root>();
  std::vector<Eigen::VectorXd> refs;
  for (const auto& b : algos) refs.push_back(reference(m, p, b));
  std::uniform_int_distribution<std::size_t> pick(0, algos.size() - 1);
  for (int trial = 0; trial < 40; ++trial) {
    auto ws = fresh_workspace(m, p);
    forward_kinematics(m, ws, p.q, p.v);
    std::string seq = "forward_kinematics(q, v)";
    for (int k = 0; k < 6; ++k) {
      const std::size_t i = pick(rng);
      seq += ", " + algos[i].name;
      CAPTURE(m.name, p.planar, seq);
      require_same(algos[i].run(m, ws, p), refs[i], exact);
    }
  }
}

bool names_the_fix(const std::logic_error& e) {
  return std::string(e.what()).find("forward_kinematics(m, ws, q, v)") != std::string::npos;
}

/// After forward_kinematics(q, v), an algorithm that takes only a q different from the cached one
/// leaves the poses of that q and no velocities: the pose readers follow it, the velocity readers
/// throw until forward_kinematics(q2, v2); an algorithm taking (q2, v2) leaves their kinematics.
template <root_joint Root>
void check_new_configuration(const model<Root>& m, const problem<Root>& p, const problem<Root>& p2,
                             bool exact) {
  const auto algos = algorithms<Root>();
  std::vector<Eigen::VectorXd> refs2;
  for (const auto& b : algos) refs2.push_back(reference(m, p2, b));
  for (const auto& a : algos) {
    if (a.reader()) continue;
    for (std::size_t ib = 0; ib < algos.size(); ++ib) {
      const auto& b = algos[ib];
      if (!b.reader()) continue;
      CAPTURE(m.name, p.planar, a.name, b.name);
      auto ws = fresh_workspace(m, p);
      forward_kinematics(m, ws, p.q, p.v);
      (void)a.run(m, ws, p2);
      if (a.input == takes::q && b.input == takes::velocities) {
        REQUIRE_THROWS_MATCHES(b.run(m, ws, p2), std::logic_error,
                               Catch::Predicate<std::logic_error>(names_the_fix));
        forward_kinematics(m, ws, p2.q, p2.v);
      }
      require_same(b.run(m, ws, p2), refs2[ib], exact);
    }
  }
}

/// The readers on a fresh workspace, and the velocity readers after forward_kinematics(q) only.
template <root_joint Root>
void check_unset_workspace(const model<Root>& m, const problem<Root>& p) {
  for (const auto& b : algorithms<Root>()) {
    // point_position reads the public poses, valid (identity) from make_workspace on.
    if (!b.reader() || b.name == "point_position") continue;
    CAPTURE(m.name, p.planar, b.name);
    auto ws = fresh_workspace(m, p);
    REQUIRE_THROWS_AS(b.run(m, ws, p), std::logic_error);
    forward_kinematics(m, ws, p.q);
    if (b.input == takes::velocities)
      REQUIRE_THROWS_MATCHES(b.run(m, ws, p), std::logic_error,
                             Catch::Predicate<std::logic_error>(names_the_fix));
    else
      REQUIRE_NOTHROW(b.run(m, ws, p));
  }
}

}  // namespace

TEST_CASE("every pair of dynamics algorithms can share a workspace (3D humanoid)",
          "[dynamics][mixing]") {
  std::mt19937 rng(101);
  const auto m = wang2009_humanoid();
  const auto p = random_problem(m, rng);
  check_all_pairs(m, p, true);
  check_random_sequences(m, p, true, rng);
}

TEST_CASE("every pair of dynamics algorithms can share a workspace (planar human)",
          "[dynamics][mixing][planar]") {
  std::mt19937 rng(102);
  const auto m = sharon2005_human7();
  const auto p = random_problem(m, rng);
  REQUIRE(make_workspace(m).scratch.planar.enabled);
  check_all_pairs(m, p, false);
  check_random_sequences(m, p, false, rng);
  // The same model through the general 6D code: one representation, so bit for bit.
  const auto p6 = random_problem(m, rng, false);
  check_all_pairs(m, p6, true);
  check_random_sequences(m, p6, true, rng);
}

TEST_CASE("forward_kinematics(q, v) then gravity_forces keeps the velocity readers (issue 10.2)",
          "[dynamics][mixing]") {
  std::mt19937 rng(103);
  const auto m = wang2009_humanoid();
  const auto p = random_problem(m, rng);
  auto ref = fresh_workspace(m, p);
  forward_kinematics(m, ref, p.q, p.v);
  const double ke = kinetic_energy(m, ref);
  const momentum h = centroidal_momentum(m, ref);
  const vec3 vc = com_velocity(m, ref);
  REQUIRE(ke > 1.0);
  REQUIRE(h.linear.norm() > 1.0);
  REQUIRE(h.angular.norm() > 0.1);
  REQUIRE(vc.norm() > 0.01);

  auto ws = fresh_workspace(m, p);
  forward_kinematics(m, ws, p.q, p.v);
  (void)gravity_forces(m, ws, p.q);
  CHECK(kinetic_energy(m, ws) == ke);
  const momentum hw = centroidal_momentum(m, ws);
  CHECK(hw.linear == h.linear);
  CHECK(hw.angular == h.angular);
  CHECK(com_velocity(m, ws) == vc);
  // And the velocity-dependent algorithms after it still see v.
  CHECK(Eigen::VectorXd(nonlinear_effects(m, ws, p.q, p.v)) ==
        Eigen::VectorXd(nonlinear_effects(m, ref, p.q, p.v)));
}

TEST_CASE("a new configuration drops the cached velocities, a new state replaces them",
          "[dynamics][mixing]") {
  std::mt19937 rng(104);
  {
    const auto m = wang2009_humanoid();
    const auto p = random_problem(m, rng), p2 = random_problem(m, rng);
    check_new_configuration(m, p, p2, true);
  }
  {
    const auto m = sharon2005_human7();
    const auto p = random_problem(m, rng), p2 = random_problem(m, rng);
    check_new_configuration(m, p, p2, false);
    const auto p6 = random_problem(m, rng, false), p26 = random_problem(m, rng, false);
    check_new_configuration(m, p6, p26, true);
  }
}

TEST_CASE("the readers refuse a workspace without the kinematics they need", "[dynamics][mixing]") {
  std::mt19937 rng(105);
  const auto m3 = wang2009_humanoid();
  check_unset_workspace(m3, random_problem(m3, rng));
  const auto m2 = sharon2005_human7();
  check_unset_workspace(m2, random_problem(m2, rng));
  check_unset_workspace(m2, random_problem(m2, rng, false));
  // invalidate_kinematics forgets them too.
  const auto p = random_problem(m3, rng);
  auto ws = fresh_workspace(m3, p);
  forward_kinematics(m3, ws, p.q, p.v);
  invalidate_kinematics(ws);
  REQUIRE_THROWS_AS(kinetic_energy(m3, ws), std::logic_error);
  forward_kinematics(m3, ws, p.q, p.v);
  REQUIRE(kinetic_energy(m3, ws) > 0.0);
}
