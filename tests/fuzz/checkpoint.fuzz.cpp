// Fuzz target: optimizer checkpoints (optimizers/checkpoint.hpp). load_checkpoint takes only a
// path, so the input goes through a file of this process. It is loaded into a fresh optimizer of
// each kind that checkpoints (SDS, CMA-ES, CMA-ES with restarts) over the two parameters x0, x1
// of the seeds (tests/bad_inputs/checkpoint/, tests/fuzz/corpus/checkpoint/); the kind named in
// the file is the one that reads past its header. Fresh optimizers: a load that succeeds must
// not change what the next input is loaded into.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/optimizers/optimizers.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gaitsynth;
  static gaitsynth_fuzz::input_file file(".ckpt");
  const auto& path = file.write(data, size);
  const auto space = parameter_space::unbounded(Eigen::Vector2d(0.5, -0.25));
  cmaes_options o;
  o.sigma0 = 0.3;
  o.seed = 3;
  sds s(space, sds_options{});
  cmaes c(space, o);
  cmaes_restarts r(space, o, restart_options{.strategy = restart_strategy::ipop});
  gaitsynth_fuzz::refuse_or_load([&] { load_checkpoint(s, path); });
  gaitsynth_fuzz::refuse_or_load([&] { load_checkpoint(c, path); });
  gaitsynth_fuzz::refuse_or_load([&] { load_checkpoint(r, path); });
  return 0;
}
