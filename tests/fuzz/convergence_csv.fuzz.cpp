// Fuzz target: optimizer convergence logs (viz/convergence_plot_svg.hpp), which the plot reads
// back. read_convergence_csv is load_convergence_csv's reader on a stream; the plot is drawn too,
// since it is what consumes the numbers read (NaN cells, one-row logs, odd columns).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/viz/convergence_plot_svg.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  gaitsynth_fuzz::refuse_or_load([&] {
    const gaitsynth::convergence_log log = gaitsynth::read_convergence_csv(in, "fuzz.csv");
    std::ostringstream svg;
    gaitsynth::write_convergence_plot_svg(log, svg);
  });
  return 0;
}
