// Fuzz target: normative gait CSV (io/normative_gait.hpp). read_normative_gait is
// load_normative_gait's reader on a stream: the input is read from memory.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/io/normative_gait.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  gaitsynth_fuzz::refuse_or_load([&] { (void)gaitsynth::read_normative_gait(in, "fuzz.csv"); });
  return 0;
}
