// solve_qp allocates nothing once its workspace is sized (Wu & Popovic solve one program per
// control tick inside the rollout loop): cold, warm, with a kept factorization, and on the
// failure paths; and one tick of the lower level that builds and solves it
// (controllers/end_effector/lower_level.hpp).
#include "support/counting_allocations.hpp"

#include <catch2/catch.hpp>
#include <random>

#include "gaitsynth/controllers/end_effector/lower_level.hpp"
#include "gaitsynth/models/wu2010.hpp"
#include "gaitsynth/qp/goldfarb_idnani.hpp"
#include "qp/random_programs.hpp"

using namespace gaitsynth;

TEST_CASE("solve_qp does not allocate after set-up", "[qp][allocation]") {
  CHECK(counters_see_allocations());
  std::mt19937 rng(46);
  const test::random_program_sizes sizes{46, 6, 40};
  std::vector<dense_qp> programs;
  for (int k = 0; k < 4; ++k) programs.push_back(test::random_program(sizes, rng));
  programs[3].c_lower[0] = std::nan("");  // an invalid one
  dense_qp indefinite = programs[0];
  indefinite.H(0, 0) = -1.0;
  qp_workspace ws(sizes.n, sizes.me, sizes.mi);
  qp_options keep;
  keep.reuse_factorization = true;
  solve_qp(programs[0], ws);  // the first solve fills the warm-start list to its capacity
  int optimal = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  for (const dense_qp& qp : programs) optimal += solve_qp(qp, ws).status == qp_status::optimal;
  solve_qp(programs[1], ws);  // factorizes programs[1].H, which the next solve keeps
  optimal += solve_qp(programs[1], ws, keep).status == qp_status::optimal;
  const bool failed = solve_qp(indefinite, ws).status == qp_status::not_strictly_convex;
  const long news_in_solves = g_news.load() - news,
             eigen_in_solves = g_eigen_asserts.load() - eigen;
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(optimal == 4);  // three valid programs and the kept factorization
  CHECK(failed);
  CHECK(news_in_solves == 0);
  CHECK(eigen_in_solves == 0);
}

TEST_CASE("a tick of Wu & Popovic's lower level does not allocate after set-up",
          "[qp][allocation][end_effector]") {
  // Frames, ideal forces, J, its QR, eq. 5's QP and appendix B's canceling QP, at a pose with
  // bent knees, with all feet frames touching (pinned) and with none touching.
  const floating_model m = wu2010_biped();
  const end_effector_layout L = biped_end_effector_layout(m);
  auto ws = make_lower_level_workspace(m, L);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nq());
  q[2] = 1.1;
  q[3] = 1.0;
  q[7 + m.dof_index("lknee")] = 0.4;
  q[7 + m.dof_index("rknee")] = 0.3;
  Eigen::VectorXd v = Eigen::VectorXd::Constant(m.nv(), 0.1);
  std::vector<link_target> targets(3);
  for (int i = 0; i < 3; ++i) targets[i].position = vec3(0.02 * i, 0.1 * (i == 1), 0.5 * (i == 0));
  std::vector<unsigned char> touching(m.contact_points.size(), 1), none(touching.size(), 0);
  const end_effector_gains g;
  const lower_level_options opt;
  lower_level_torques(m, L, g, opt, q, v, targets, touching, ws);  // fills the warm-start lists
  lower_level_torques(m, L, g, opt, q, v, targets, none, ws);
  Eigen::internal::set_is_malloc_allowed(false);
  const long news = g_news.load(), eigen = g_eigen_asserts.load();
  double sum = 0.0;
  for (int k = 0; k < 10; ++k) {
    q[7 + 3] += 0.01;
    sum += lower_level_torques(m, L, g, opt, q, v, targets, k % 2 ? touching : none, ws).sum();
  }
  const long news_in_ticks = g_news.load() - news, eigen_in_ticks = g_eigen_asserts.load() - eigen;
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(std::isfinite(sum));
  CHECK(ws.qp.status == qp_status::optimal);
  CHECK(news_in_ticks == 0);
  CHECK(eigen_in_ticks == 0);
}
