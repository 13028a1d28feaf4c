// Fuzz target: nearest-neighbor controller JSON (controllers/nearest_neighbor_json.hpp).
// load_nearest_neighbor reads the file into a string, parses it with detail::parse_json_text and
// builds the controller with nearest_neighbor_from_json: the same two calls here, from memory.
// Each input is read for both planar humans (the seeds, data/sharon2005/*.controller.json, are
// controllers of both).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/controllers/nearest_neighbor_json.hpp"
#include "gaitsynth/models/sharon2005.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gaitsynth;
  static const planar_model human7 = sharon2005_human7();
  static const planar_model human16 = sharon2005_human16();
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const planar_model* m : {&human7, &human16})
    gaitsynth_fuzz::refuse_or_load([&] {
      (void)nearest_neighbor_from_json(
          *m, detail::parse_json_text<keyframes_error>(text, "fuzz.json"), "fuzz.json");
    });
  return 0;
}
