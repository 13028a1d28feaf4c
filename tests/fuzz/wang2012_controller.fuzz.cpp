// Fuzz target: Wang 2012 reflex controller JSON (controllers/reflex/wang2012_json.hpp). Its reader
// takes only a path, so the input goes through a file of this process. The parameter names are
// static (wang2012_reflex_controller::parameter_names()): no model is needed.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/controllers/reflex/wang2012_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gaitsynth;
  static gaitsynth_fuzz::input_file file(".json");
  const std::string path = file.write(data, size).string();
  gaitsynth_fuzz::refuse_or_load([&] { (void)load_wang2012_controller(path); });
  return 0;
}
