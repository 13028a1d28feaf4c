// Fuzz target: keyframes JSON (motion/keyframes_json.hpp). parse_keyframes is load_keyframes
// without the file: the same parse and checks, from memory. Each input is read for both planar
// humans of Sharon & van de Panne 2005, whose files are the seeds
// (data/sharon2005/*.keyframes.json).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/models/sharon2005.hpp"
#include "gaitsynth/motion/keyframes_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const gaitsynth::planar_model human7 = gaitsynth::sharon2005_human7();
  static const gaitsynth::planar_model human16 = gaitsynth::sharon2005_human16();
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const gaitsynth::planar_model* m : {&human7, &human16})
    gaitsynth_fuzz::refuse_or_load(
        [&] { (void)gaitsynth::parse_keyframes(*m, text, "fuzz.json"); });
  return 0;
}
