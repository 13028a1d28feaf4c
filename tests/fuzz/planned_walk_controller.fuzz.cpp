// Fuzz target: a saved planned_walk (Wu & Popovic 2010) as JSON
// (controllers/end_effector/planned_walk_json.hpp): load it, match its values to the helper-force
// controller's names and read the options it records. Its reader takes only a path, so the input
// goes through a file of this process. The names come from one controller on the Table 3 biped,
// built once.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "gaitsynth/controllers/end_effector/planned_walk_json.hpp"
#include "gaitsynth/models/wu2010.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gaitsynth;
  static gaitsynth_fuzz::input_file file(".json");
  static const std::vector<std::string> names = [] {
    planned_walk_options o;
    o.helper_force = true;
    return planned_walk<>(wu2010_biped(), flat_terrain{}, o).parameter_names();
  }();
  const std::string path = file.write(data, size).string();
  gaitsynth_fuzz::refuse_or_load([&] {
    const planned_walk_saved s = load_planned_walk(path);
    (void)saved_planned_walk_options(s, path);
    (void)planned_walk_values(s, names, path);
  });
  return 0;
}
