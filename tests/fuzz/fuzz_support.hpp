#pragma once
/// Shared by the fuzz targets (tests/fuzz/*.fuzz.cpp, docs/fuzzing.md): what counts as a correct
/// refusal, and a file for loaders that only read paths.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <typeinfo>

namespace gaitsynth_fuzz {

/// Runs a load. The library's loaders refuse bad input with std::invalid_argument or
/// std::runtime_error (and their subclasses: keyframes_error, checkpoint_error, ...): those are
/// correct answers. Any other exception (std::bad_alloc from a size read off the file,
/// std::out_of_range from an unchecked index, nlohmann::json's own errors escaping without the
/// file's name) is a loader bug and aborts, like a crash, so libFuzzer keeps the input.
template <class Load>
void refuse_or_load(Load&& load) {
  try {
    load();
  } catch (const std::invalid_argument&) {
  } catch (const std::runtime_error&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: undocumented exception %s: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
}

/// A file of this process holding the input (loaders that only take a path); removed at exit.
class input_file {
 public:
  explicit input_file(const std::string& extension)
      : path_(std::filesystem::temp_directory_path() /
              ("gaitsynth_fuzz_" + std::to_string(::getpid()) + extension)) {}
  ~input_file() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  input_file(const input_file&) = delete;
  input_file& operator=(const input_file&) = delete;
  /// Writes the bytes (replacing the last input) and returns the path.
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      std::fprintf(stderr, "fuzz: cannot write %s\n", path_.c_str());
      std::abort();
    }
    return path_;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace gaitsynth_fuzz
