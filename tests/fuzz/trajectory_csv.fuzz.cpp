// Fuzz target: trajectory CSV (io/trajectory_csv.hpp). read_trajectory_csv is
// load_trajectory_csv's reader on a stream: the input is read from memory.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/io/trajectory_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  gaitsynth_fuzz::refuse_or_load([&] { (void)gaitsynth::read_trajectory_csv(in, "fuzz.csv"); });
  return 0;
}
