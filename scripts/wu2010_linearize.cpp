// Linearizes Wu & Popovic 2010's lower level about states of a saved forward-walk controller
// (docs/reproductions/wu2010.md, "Why it does not walk"): replays the controller without its
// helper force on flat ground (2400 Hz, a command every step) up to each requested time, takes
// the state, the link targets and the contact flags of that command, and differentiates the
// lower level's torque by central differences in v (D = d tau / d v) and in the joint angles
// (K = d tau / d q). Prints, per time, the pinned frames with Sec. 6.3's test for each (touching,
// distance to its target, the target's speed), the eigenvalues of the explicit step
//
//   v+ = v + h M^-1 [0; D] v                          (rates only: a value below -1 is a chatter)
//   (q+, v+) from semi-implicit Euler with K and D    (a value above 1 a divergence)
//
// that leave the unit circle, with the DOFs that dominate each mode, and D's diagonal on the
// ankle_x DOFs split into eq. 5's part (J^T f) and the rest. Compile against any tree's include/
// (the figures before 2026-12-05's null-space fix came from f54a017's: `git worktree add`):
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_linearize.cpp -o /tmp/linearize
//   /tmp/linearize data/wu2010/runs/f1/wu2010_walk.controller.json 0.25 0.4 1.3 1.41
//
// (one command line each).
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gaitsynth/gaitsynth.hpp"
#include "gaitsynth/wu2010.hpp"

using namespace gaitsynth;

namespace {

using walk = planned_walk<flat_terrain>;

/// What the controller saw and planned at the first command at or after `at`.
struct snapshot {
  double at = 0.0, t = -1.0;
  Eigen::VectorXd q, v;
  std::vector<link_target> targets;
  std::vector<unsigned char> touching;
  int parity = 0;
};

/// planned_walk recording one command.
struct recording_walk : walk {
  snapshot* snap = nullptr;
  using walk::walk;
  void command(const sensors<floating_root>& s, state_type& st,
               Eigen::Ref<Eigen::VectorXd> cmd) const {
    walk::command(s, st, cmd);
    if (snap->t < 0.0 && s.t >= snap->at) {
      snap->t = s.t;
      snap->q = s.q();
      snap->v = s.v();
      snap->targets = st.targets;
      snap->touching.assign(s.contact_active.begin(), s.contact_active.end());
      snap->parity = static_cast<int>(st.half_cycle % 2);
    }
  }
};

std::string dof_name(const floating_model& m, Eigen::Index i) {  // i over v (root first)
  return i < 6 ? "root" + std::to_string(i) : m.dofs[static_cast<std::size_t>(i - 6)].name;
}

void print_mode(const floating_model& m, const Eigen::VectorXd& e, Eigen::Index offset) {
  const Eigen::VectorXd u = e / e.norm();
  for (Eigen::Index a = 0; a < u.size(); ++a)
    if (std::abs(u[a]) > 0.1)
      std::printf(" %s%s=%.2f", a < offset ? "q:" : "",
                  dof_name(m, a < offset ? a + 6 : a - offset).c_str(), u[a]);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s CONTROLLER.json TIME...\n", argv[0]);
    return 2;
  }
  const floating_model m = wu2010_biped();
  planned_walk_options po;  // helper force off: the controller as checked
  recording_walk c(m, flat_terrain{}, po);
  nlohmann::json j;
  std::ifstream(argv[1]) >> j;
  std::vector<double> x;
  for (const std::string& n : c.parameter_names())
    for (std::size_t i = 0; i < j.at("parameter_names").size(); ++i)
      if (j["parameter_names"][i] == n) x.push_back(j["parameters"][i].get<double>());
  if (x.size() != c.num_parameters()) throw std::invalid_argument("parameters missing in the file");
  c.bind(x);
  const int nv = m.nv(), nj = m.num_joint_dofs();
  const double h = 1.0 / 2400.0;
  auto scratch = make_rollout_scratch(m);
  for (int a = 2; a < argc; ++a) {
    snapshot snap;
    snap.at = std::stod(argv[a]);
    c.snap = &snap;
    rollout_options opt;
    opt.initial_state = make_state(m);
    place_on_terrain(m, flat_terrain{}, opt.initial_state.q);
    opt.duration = snap.at + 0.002;
    const rollout_result r =
        rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                semi_implicit_euler{}, std::span<const double>(x), opt, scratch);
    if (snap.t < 0.0) {
      std::printf("t = %s: the rollout stopped first (%s at %.4f s)\n", argv[a],
                  std::string(to_string(r.reason)).c_str(), r.time);
      continue;
    }
    auto ws = make_lower_level_workspace(m, c.layout());
    const end_effector_gains& g = c.gains(snap.parity);
    auto tau = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
      return Eigen::VectorXd(
          lower_level_torques(m, c.layout(), g, po.lower, q, v, snap.targets, snap.touching, ws));
    };
    tau(snap.q, snap.v);
    std::printf("t = %.4f s, pinned frames:", snap.t);
    for (const unsigned char p : ws.pinned) std::printf("%d", p);
    std::printf("\n");
    // Sec. 6.3's test per action frame: touching, distance to the target, the target's speed.
    for (int f = 0; f < c.layout().num_action(); ++f) {
      bool touching = false;
      for (const int k : c.layout().action[static_cast<std::size_t>(f)].contacts)
        touching = touching || snap.touching[static_cast<std::size_t>(k)] != 0;
      std::printf("  %-15s touching %d, |target - p| %.3f m, target speed %.3f m/s\n",
                  c.layout().action[static_cast<std::size_t>(f)].name.c_str(), touching ? 1 : 0,
                  (ws.desired.position[static_cast<std::size_t>(f)] -
                   ws.current.position[static_cast<std::size_t>(f)])
                      .norm(),
                  ws.desired.velocity[static_cast<std::size_t>(f)].norm());
    }
    Eigen::MatrixXd D(nj, nv), D5(nj, nv), K(nj, nj);
    for (int i = 0; i < nv; ++i) {
      const double e = 1e-6;
      Eigen::VectorXd vp = snap.v, vm = snap.v;
      vp[i] += e;
      vm[i] -= e;
      const Eigen::VectorXd tp = tau(snap.q, vp), t5p = ws.qp.tau;
      const Eigen::VectorXd tm = tau(snap.q, vm), t5m = ws.qp.tau;
      D.col(i) = (tp - tm) / (2 * e);
      D5.col(i) = (t5p - t5m) / (2 * e);
    }
    for (int i = 0; i < nj; ++i) {
      const double e = 1e-7;
      Eigen::VectorXd qp = snap.q, qm = snap.q;
      qp[7 + i] += e;
      qm[7 + i] -= e;
      K.col(i) = (tau(qp, snap.v) - tau(qm, snap.v)) / (2 * e);
    }
    auto dyn = make_workspace(m);
    forward_kinematics(m, dyn, snap.q, snap.v);
    const Eigen::MatrixXd Minv = crba(m, dyn, snap.q).inverse();
    Eigen::MatrixXd Dfull = Eigen::MatrixXd::Zero(nv, nv), Kfull = Eigen::MatrixXd::Zero(nv, nj);
    Dfull.bottomRows(nj) = D;
    Kfull.bottomRows(nj) = K;
    // Rates only.
    const Eigen::MatrixXd Av = Eigen::MatrixXd::Identity(nv, nv) + h * Minv * Dfull;
    Eigen::EigenSolver<Eigen::MatrixXd> ev(Av);
    for (int i = 0; i < nv; ++i) {
      const std::complex<double> l = ev.eigenvalues()[i];
      if (std::abs(l) <= 1.0 + 1e-9) continue;
      std::printf("  rates: eigenvalue %.3f%+.3fi, mode:", l.real(), l.imag());
      print_mode(m, ev.eigenvectors().col(i).real(), 0);
    }
    // Joint angles and rates (semi-implicit Euler: v+ = Aq dq + Av v, q+ = q + h v+).
    const Eigen::MatrixXd Aq = h * Minv * Kfull;
    Eigen::MatrixXd B(nj + nv, nj + nv);
    B.topLeftCorner(nj, nj) = Eigen::MatrixXd::Identity(nj, nj) + h * Aq.bottomRows(nj);
    B.topRightCorner(nj, nv) = h * Av.bottomRows(nj);
    B.bottomLeftCorner(nv, nj) = Aq;
    B.bottomRightCorner(nv, nv) = Av;
    Eigen::EigenSolver<Eigen::MatrixXd> eb(B);
    for (int i = 0; i < nj + nv; ++i) {
      const std::complex<double> l = eb.eigenvalues()[i];
      if (std::abs(l) <= 1.0 + 1e-9) continue;
      std::printf("  angles and rates: eigenvalue %.4f%+.4fi, mode:", l.real(), l.imag());
      print_mode(m, eb.eigenvectors().col(i).real(), nj);
    }
    for (int i = 0; i < nj; ++i)
      if (m.dofs[static_cast<std::size_t>(i)].name.find("ankle_x") != std::string::npos)
        std::printf(
            "  %s: d tau / d v %.2f N m s/rad (eq. 5's J^T f: %.2f), M^-1 %.0f, h d M^-1 %.2f\n",
            m.dofs[static_cast<std::size_t>(i)].name.c_str(), D(i, 6 + i), D5(i, 6 + i),
            Minv(6 + i, 6 + i), h * D(i, 6 + i) * Minv(6 + i, 6 + i));
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_linearize: %s\n", e.what());
  return 1;
}
