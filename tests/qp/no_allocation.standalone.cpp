// solve_qp allocates nothing once its workspace is sized (Wu & Popovic solve one program per
// control tick inside the rollout loop): cold, warm, with a kept factorization, and on the
// failure paths.
#include "support/counting_allocations.hpp"

#include <catch2/catch.hpp>
#include <random>

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
