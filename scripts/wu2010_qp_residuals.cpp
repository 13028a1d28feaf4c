// Why eq. 5 of Wu & Popovic 2010 leaves residuals that the helper force fills
// (docs/reproductions/wu2010.md, "Where eq. 5 falls short"): replays a saved forward walk WITH
// its helper on flat ground for SECONDS and, at every command after the first second, splits the
// residual h = b - A f of each row group of eq. 4 (the upper body's force and torque, each action
// frame's force, the frames of the standing and the swinging foot apart) into what each of eq. 5's
// restrictions costs, by solving three weighted least-squares problems over the QP's rows:
//   free   min ||A f - b||_W over every f (what eq. 4's own structure cannot reach),
//   range  the same with f in range(J) (eq. 5d: the joints must be able to exert f),
//   qp     the QP's answer (adds the bounds 5b and 5c and the regularization).
// Pinned frames (Sec. 6.3) leave the QP and are counted apart. Then, per foot, the net force of
// the residual over its unpinned frames (what the joints left out, as opposed to forces between
// the frames of one rigid foot, which cancel) and of the clipped helper; why a standing foot's
// frames were not pinned; by tenth of the half-cycle, how often the standing foot touches nothing
// and the swinging foot touches, and how fast the swinging frames' targets move (when in the
// half-cycle the walk leaves its plan); and how often each joint's torque sits at its bound.
// STANCE_TARGET=first_contact in the environment replays with that stance target instead of the
// saved one; PIN_BY=link with lower_level_options::pin_by = link instead of the saved
// controller's contact test. Compile against the tree's include/:
//
//   g++ -std=c++20 -O2 -DNDEBUG -Iinclude -isystem /usr/include/eigen3
//       scripts/wu2010_qp_residuals.cpp -o /tmp/wu2010_qp_residuals
//   /tmp/wu2010_qp_residuals data/wu2010/runs/f9/wu2010_walk.mean.json 10
//
// (one command line each).
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "gaitsynth/actuators/torque.hpp"
#include "gaitsynth/contact/flat_terrain.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/integrators/semi_implicit_euler.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/objectives/distance.hpp"
#include "gaitsynth/rollout/rollout.hpp"

#include "wu2010_saved_rollout.hpp"

using namespace gaitsynth;

namespace {

/// Per row group: summed |b|, |h| of the three problems, and the commands counted.
struct group_sums {
  double b = 0, free = 0, range = 0, qp = 0;
  long n = 0, pinned = 0;
};

struct residuals {
  const end_effector_layout* L = nullptr;
  Eigen::VectorXd tau_max;
  // groups: 0 upper-body force, 1 upper-body torque, 2 + j frame j standing, 2 + N + j swinging
  std::vector<group_sums> g;
  Eigen::VectorXd at_bound;  ///< per joint DOF: commands with |tau| at tau_max
  double h_max = 0.0;
  /// Per foot [standing, swinging]: summed |sum_j b_j|, |sum_j h_j| of the QP's residual and of
  /// the clipped helper, over the foot's unpinned frames: the net force the residual leaves out.
  std::array<group_sums, 3> net{};  // standing; swinging with the standing foot all pinned; not
  /// Per action frame while its foot stands and it is not pinned: commands whose geometry did not
  /// touch, whose frame was eps_p or more from its target, whose target moved eps_pdot or faster.
  std::vector<std::array<long, 3>> why;
  /// Per tenth of the half-cycle (s_h): standing-foot commands, those whose foot touched nothing,
  /// and those whose swinging foot touched (when in the half-cycle the walker leaves its plan).
  std::array<std::array<long, 3>, 10> by_tenth{};
  double t_h = 0.55;
  std::array<double, 10> swing_speed{};  ///< summed |target velocity| of the swinging frames
  std::array<long, 10> swing_far{}, swing_n{};
  double eps_p = 0.2, eps_pdot = 0.05;
  pin_contact pin_by = pin_contact::frame_geometry;
  long commands = 0;
  std::int64_t last_command = -1;

  template <class Ob>
  void observe(const Ob& ob) {
    const auto& st = *ob.controller_state_ptr;
    if (ob.t < 1.0 || st.commands == last_command || st.half_cycle < 0) return;
    last_command = st.commands;
    const auto& qp = st.lower.qp;
    const int N = L->num_action();
    if (g.empty()) {
      g.assign(static_cast<std::size_t>(2 + 2 * N), {});
      at_bound = Eigen::VectorXd::Zero(qp.nj);
    }
    ++commands;
    // The QP's rows (as solve_force_qp keeps them), weighted.
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < 3; ++i) rows.push_back(i);
    for (int j = 0; j < N; ++j)
      if (!st.lower.pinned[static_cast<std::size_t>(j)])
        for (Eigen::Index i = 0; i < 3; ++i) rows.push_back(action_row(j) + i);
    for (Eigen::Index i = qp.rows_full - 3; i < qp.rows_full; ++i) rows.push_back(i);
    const Eigen::Index r = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd A(r, qp.K3);
    Eigen::VectorXd b(r), s(r);
    for (Eigen::Index i = 0; i < r; ++i) {
      s[i] = std::sqrt(qp.w[rows[i]]);
      A.row(i) = s[i] * qp.A.row(rows[i]);
      b[i] = s[i] * qp.b[rows[i]];
    }
    const Eigen::VectorXd f_free = A.completeOrthogonalDecomposition().solve(b);
    const Eigen::MatrixXd U = qp.U.leftCols(qp.rank);
    const Eigen::VectorXd c = (A * U).completeOrthogonalDecomposition().solve(b);
    const Eigen::VectorXd f_range = U * c;
    // Residuals over all rows of eq. 4 (unweighted), as the helper sees them.
    const Eigen::VectorXd h_free = qp.b - qp.A * f_free, h_range = qp.b - qp.A * f_range,
                          h_qp = qp.b - qp.A * qp.f;
    const int stance_link = st.stance == stance_side::left ? 1 : 2;
    auto add = [&](group_sums& G, Eigen::Index row, bool pinned) {
      if (pinned) {
        ++G.pinned;
        return;
      }
      ++G.n;
      G.b += qp.b.segment(row, 3).norm();
      G.free += h_free.segment(row, 3).norm();
      G.range += h_range.segment(row, 3).norm();
      G.qp += h_qp.segment(row, 3).norm();
    };
    add(g[0], 0, false);
    add(g[1], qp.rows_full - 3, false);
    for (int j = 0; j < N; ++j) {
      const bool standing = L->action[static_cast<std::size_t>(j)].link == stance_link;
      add(g[static_cast<std::size_t>(2 + (standing ? j : N + j))], action_row(j),
          st.lower.pinned[static_cast<std::size_t>(j)] != 0);
    }
    if (why.empty()) why.assign(static_cast<std::size_t>(N), {0, 0, 0});
    for (int j = 0; j < N; ++j) {
      const action_frame& a = L->action[static_cast<std::size_t>(j)];
      if (a.link != stance_link || st.lower.pinned[static_cast<std::size_t>(j)]) continue;
      auto& y = why[static_cast<std::size_t>(j)];
      bool touches = frame_touches(a, ob.contact_active);
      if (pin_by == pin_contact::link)  // as pinned_frames: any frame of the foot
        for (const action_frame& o : L->action)
          touches = touches || (o.link == a.link && frame_touches(o, ob.contact_active));
      y[0] += !touches;
      y[1] += (st.lower.desired.position[j] - st.lower.current.position[j]).norm() >= eps_p;
      y[2] += st.lower.desired.velocity[j].norm() >= eps_pdot;
    }
    {
      const auto foot_touches = [&](int link) {
        for (const action_frame& o : L->action)
          if (o.link == link && frame_touches(o, ob.contact_active)) return true;
        return false;
      };
      const int tenth =
          std::clamp(static_cast<int>(10.0 * (ob.t - st.half_cycle_start) / t_h), 0, 9);
      auto& b = by_tenth[static_cast<std::size_t>(tenth)];
      ++b[0];
      b[1] += !foot_touches(stance_link);
      b[2] += foot_touches(3 - stance_link);
      for (int j = 0; j < L->num_action(); ++j) {
        if (L->action[static_cast<std::size_t>(j)].link != 3 - stance_link) continue;
        swing_speed[static_cast<std::size_t>(tenth)] += st.lower.desired.velocity[j].norm();
        swing_far[static_cast<std::size_t>(tenth)] +=
            (st.lower.desired.position[j] - st.lower.current.position[j]).norm() >= eps_p;
        ++swing_n[static_cast<std::size_t>(tenth)];
      }
    }
    bool stance_pinned = true;
    for (int j = 0; j < N; ++j)
      if (L->action[static_cast<std::size_t>(j)].link == stance_link)
        stance_pinned = stance_pinned && st.lower.pinned[static_cast<std::size_t>(j)];
    for (int foot = 1; foot <= 2; ++foot) {
      vec3 sb = vec3::Zero(), sh = vec3::Zero(), sc = vec3::Zero();
      bool any = false;
      for (int j = 0; j < N; ++j) {
        if (L->action[static_cast<std::size_t>(j)].link != foot ||
            st.lower.pinned[static_cast<std::size_t>(j)])
          continue;
        any = true;
        const vec3 h = h_qp.segment(action_row(j), 3);
        sb += qp.b.segment(action_row(j), 3);
        sh += h;
        sc += h.cwiseMax(-h_max).cwiseMin(h_max);
      }
      group_sums& G = net[foot == stance_link ? 0 : stance_pinned ? 1 : 2];
      if (!any) {
        ++G.pinned;
        continue;
      }
      ++G.n;
      G.b += sb.norm();
      G.qp += sh.norm();
      G.range += sc.norm();  // the clipped helper's net force
    }
    for (Eigen::Index i = 0; i < qp.nj; ++i)
      at_bound[i] += std::abs(qp.tau[i]) >= (1.0 - 1e-6) * tau_max[i];
  }
};

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 3) throw std::invalid_argument("usage: wu2010_qp_residuals CONTROLLER.json SECONDS");
  const char* file = argv[1];
  const double seconds = std::atof(argv[2]);
  if (!(seconds > 1.0)) throw std::invalid_argument("SECONDS must be > 1");
  const floating_model m = wu2010_biped();
  const planned_walk_saved saved = load_planned_walk(file);
  planned_walk_options po = saved_planned_walk_options(saved, file);
  po.helper_force = true;
  if (const char* pin = std::getenv("PIN_BY"); pin && std::string(pin) == "link")
    po.lower.pin_by = pin_contact::link;
  if (const char* st = std::getenv("STANCE_TARGET"); st && std::string(st) == "first_contact")
    po.stance_target = stance_foot_target::first_contact;
  const planned_walk<> c(m, flat_terrain{}, po);
  const std::vector<double> x = planned_walk_values(saved, c.parameter_names(), file);
  rollout_options o = gaitsynth_scripts::saved_rollout_options(m, saved, seconds);
  residuals res;
  res.L = &c.layout();
  res.h_max = x.back();
  res.pin_by = po.lower.pin_by;
  res.eps_p = po.lower.eps_p;
  res.eps_pdot = po.lower.eps_pdot;
  res.t_h = c.half_cycle_duration();
  res.tau_max.resize(m.num_joint_dofs());
  for (int j = 0; j < m.num_joint_dofs(); ++j) res.tau_max[j] = m.dofs[j].torque_limit;
  auto scratch = make_rollout_scratch(m);
  const rollout_result r = rollout(m, torque_actuator{}, c, distance_objective(), flat_terrain{},
                                   semi_implicit_euler{}, x, o, scratch, res);
  std::printf("%s with its helper (h_max %.2f N): %.2f s, %s; %ld commands after 1 s\n", file,
              x.back(), r.time, std::string(to_string(r.reason)).c_str(), res.commands);
  std::printf(
      "mean |.| per row group (N or N m) over the commands it is in the QP; pinned share\n");
  std::printf("%-24s %8s %8s %8s %8s %7s\n", "rows", "|b|", "free", "range", "qp", "pinned");
  const auto print = [&](const std::string& name, const group_sums& G) {
    const double n = static_cast<double>(std::max(G.n, 1L));
    std::printf("%-24s %8.2f %8.2f %8.2f %8.2f %7.2f\n", name.c_str(), G.b / n, G.free / n,
                G.range / n, G.qp / n,
                static_cast<double>(G.pinned) / static_cast<double>(std::max(G.n + G.pinned, 1L)));
  };
  print("upper-body force", res.g[0]);
  print("upper-body torque", res.g[1]);
  const int N = c.layout().num_action();
  for (int j = 0; j < N; ++j) {
    const std::string& name = c.layout().action[static_cast<std::size_t>(j)].name;
    print(name + " standing", res.g[static_cast<std::size_t>(2 + j)]);
    print(name + " swinging", res.g[static_cast<std::size_t>(2 + N + j)]);
  }
  std::printf(
      "net force over a foot's unpinned frames: |sum b|, |sum h| (QP residual), "
      "|sum clip(h)| (the helper); share of commands with all its frames pinned\n"
      "(a swinging foot's row: share of its commands among the swinging ones)\n");
  const char* net_names[3] = {"standing foot", "swinging, other pinned", "swinging, other not"};
  for (int k = 0; k < 3; ++k) {
    const group_sums& G = res.net[static_cast<std::size_t>(k)];
    const double n = static_cast<double>(std::max(G.n, 1L));
    const double swinging = static_cast<double>(std::max(res.net[1].n + res.net[2].n, 1L));
    const double share =
        k == 0 ? static_cast<double>(G.pinned) / static_cast<double>(std::max(G.n + G.pinned, 1L))
               : static_cast<double>(G.n) / swinging;
    std::printf("%-24s %8.2f %8.2f %8.2f %7.2f\n", net_names[k], G.b / n, G.qp / n, G.range / n,
                share);
  }
  std::printf(
      "a standing foot's unpinned frames, share of its standing commands: not touching, "
      "eps_p or more from the target, target moving eps_pdot or faster\n");
  for (int j = 0; j < N; ++j) {
    const auto& y = res.why[static_cast<std::size_t>(j)];
    const group_sums& G = res.g[static_cast<std::size_t>(2 + j)];
    const double n = static_cast<double>(std::max(G.n + G.pinned, 1L));
    std::printf("  %-18s %.2f %.2f %.2f\n",
                c.layout().action[static_cast<std::size_t>(j)].name.c_str(),
                static_cast<double>(y[0]) / n, static_cast<double>(y[1]) / n,
                static_cast<double>(y[2]) / n);
  }
  std::printf(
      "by tenth of the half-cycle: share of the commands whose standing foot touches nothing, "
      "whose swinging foot touches\n");
  for (int k = 0; k < 10; ++k) {
    const auto& b = res.by_tenth[static_cast<std::size_t>(k)];
    const double n = static_cast<double>(std::max(b[0], 1L));
    const double ns = static_cast<double>(std::max(res.swing_n[static_cast<std::size_t>(k)], 1L));
    std::printf(
        "  %3d-%3d %%  %.2f %.2f   swinging frames: mean |target v| %.3f m/s, %.2f eps_p or "
        "more from the target\n",
        10 * k, 10 * k + 10, static_cast<double>(b[1]) / n, static_cast<double>(b[2]) / n,
        res.swing_speed[static_cast<std::size_t>(k)] / ns,
        static_cast<double>(res.swing_far[static_cast<std::size_t>(k)]) / ns);
  }
  std::printf("share of commands with the QP's torque at its bound:\n");
  for (int j = 0; j < m.num_joint_dofs(); ++j)
    std::printf("  %-10s %.2f\n", m.dofs[static_cast<std::size_t>(j)].name.c_str(),
                res.at_bound[j] / static_cast<double>(std::max(res.commands, 1L)));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wu2010_qp_residuals: %s\n", e.what());
  return 1;
}
