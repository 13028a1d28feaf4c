// Fuzz target: the finished stages of a continuation (optimizers/continuation.hpp), the file
// `continuation` reads back when it resumes (run_options::checkpoint_file). Its reader,
// detail::read_stage_results, takes only a path: the input goes through a file of this process.
#include <cstddef>
#include <cstdint>

// GCC 12 at -O2 inlines std::string's operator+ in checkpoint_reader::require_text and warns of
// an overlap that cannot happen (-Wrestrict false positive, GCC bug 105329).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/optimizers/continuation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static gaitsynth_fuzz::input_file file(".stages");
  const auto& path = file.write(data, size);
  gaitsynth_fuzz::refuse_or_load([&] { (void)gaitsynth::detail::read_stage_results(path); });
  return 0;
}
