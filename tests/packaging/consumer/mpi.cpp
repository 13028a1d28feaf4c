// Uses the installed gaitsynth::mpi target: the MPI evaluator on a toy objective.
#include <gaitsynth/optimizers/mpi_evaluator.hpp>
#include <iostream>
#include <vector>

int main(int argc, char** argv) {
  gaitsynth::mpi_environment env(argc, argv);
  gaitsynth::mpi_evaluator eval;
  auto f = [](const Eigen::VectorXd& x) { return x.squaredNorm(); };
  if (!eval.is_root()) {
    eval.serve(f);
    return 0;
  }
  const std::vector<Eigen::VectorXd> xs{Eigen::Vector2d(1, 2), Eigen::Vector2d(3, 4)};
  std::vector<double> out(xs.size());
  eval.evaluate(f, std::span<const Eigen::VectorXd>(xs), std::span<double>(out));
  eval.release();
  std::cout << "gaitsynth mpi consumer ok: " << out[0] << " " << out[1] << "\n";
  return out[0] == 5.0 && out[1] == 25.0 ? 0 : 1;
}
