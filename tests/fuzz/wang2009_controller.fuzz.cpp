// Fuzz target: Wang 2009 controller JSON (controllers/fsm/wang2009_json.hpp). Its two readers
// take only a path, so the input goes through a file of this process. The parameter names are
// the same for every body shape: the stocky humanoid's controller reads them all.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/controllers/fsm/wang2009_json.hpp"
#include "gaitsynth/models/wang2009.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gaitsynth;
  static const floating_model stocky = wang2009_humanoid(wang2009_shape::stocky);
  static const wang2009_controller controller(stocky);
  static gaitsynth_fuzz::input_file file(".json");
  const std::string path = file.write(data, size).string();
  gaitsynth_fuzz::refuse_or_load([&] { (void)wang2009_saved_shape(path); });
  gaitsynth_fuzz::refuse_or_load([&] { (void)load_wang2009_controller(path, controller); });
  return 0;
}
