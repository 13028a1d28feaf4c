// Replays a fuzz target (tests/fuzz/<loader>.fuzz.cpp) without libFuzzer, for CI: every corpus
// file, then a fixed number of deterministic mutants of them, each fed to
// LLVMFuzzerTestOneInput. Builds with any C++20 compiler; under GAITSYNTH_SANITIZE the same inputs
// run with AddressSanitizer and UBSan. The long, coverage-guided runs are scripts/fuzz.sh's
// (clang's libFuzzer, docs/fuzzing.md).
//
//   fuzz_replay_<loader> [--mutants N] [--seed S] [--max-len BYTES] PATH...
//
// PATH: corpus files, or folders (read recursively). Mutants come from a std::mt19937_64 seeded
// with S (default 1): a failing run is reproduced by the same command. A crash ends the process;
// to get the input that crashed, rerun with GAITSYNTH_FUZZ_LAST=FILE (each input is written there
// before it runs, so FILE holds the crashing one; it is a reproducer for the libFuzzer build too).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using bytes = std::vector<std::uint8_t>;

bytes read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) {
    std::cerr << "fuzz_replay: cannot read " << p << "\n";
    std::exit(2);
  }
  return bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Tokens the loaders' grammars care about (JSON, CSV, checkpoints), inserted or written over
/// the input: a random byte rarely makes one.
const std::vector<std::string_view> tokens = {"{",           "}",
                                              "[",           "]",
                                              "\"",          ",",
                                              ":",           "\n",
                                              "\r\n",        "#",
                                              " ",           "\t",
                                              ";",           "0",
                                              "-1",          "1e999",
                                              "nan",         "inf",
                                              "-0",          "1e-400",
                                              "99999999999", "18446744073709551616",
                                              "null",        "true",
                                              "0x1p+0",      "\\u0000",
                                              "\xff"};

/// One to four of: bit flip, byte insert, byte delete, byte overwrite, token insert, token
/// overwrite, chunk duplicate, chunk delete, truncation, splice with another corpus file.
bytes mutate(const std::vector<bytes>& corpus, std::mt19937_64& g, std::size_t max_len) {
  auto pick = [&](std::size_t n) {  // uniform in [0, n) without std distributions (portable)
    return n == 0 ? std::size_t{0} : static_cast<std::size_t>(g() % n);
  };
  bytes b = corpus[pick(corpus.size())];
  const std::size_t edits = 1 + pick(4);
  for (std::size_t e = 0; e < edits; ++e) {
    const std::size_t at = pick(b.size() + 1);
    switch (pick(10)) {
      case 0:
        if (!b.empty()) b[pick(b.size())] ^= static_cast<std::uint8_t>(1u << pick(8));
        break;
      case 1:
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::uint8_t>(g()));
        break;
      case 2:
        if (!b.empty()) b.erase(b.begin() + static_cast<std::ptrdiff_t>(pick(b.size())));
        break;
      case 3:
        if (!b.empty()) b[pick(b.size())] = static_cast<std::uint8_t>(g());
        break;
      case 4:
      case 5: {
        const std::string_view t = tokens[pick(tokens.size())];
        if (pick(2) == 0 || at + t.size() > b.size()) {
          b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), t.begin(), t.end());
        } else {
          std::copy(t.begin(), t.end(), b.begin() + static_cast<std::ptrdiff_t>(at));
        }
        break;
      }
      case 6: {  // duplicate a chunk in place
        const std::size_t len = pick(std::min<std::size_t>(b.size() - at, 256) + 1);
        const bytes chunk(b.begin() + static_cast<std::ptrdiff_t>(at),
                          b.begin() + static_cast<std::ptrdiff_t>(at + len));
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), chunk.begin(), chunk.end());
        break;
      }
      case 7: {  // delete a chunk
        const std::size_t len = pick(std::min<std::size_t>(b.size() - at, 256) + 1);
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(at),
                b.begin() + static_cast<std::ptrdiff_t>(at + len));
        break;
      }
      case 8:
        b.resize(at);
        break;
      default: {  // splice: this input's head, another one's tail
        const bytes& other = corpus[pick(corpus.size())];
        const std::size_t from = pick(other.size() + 1);
        b.resize(at);
        b.insert(b.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
        break;
      }
    }
  }
  if (b.size() > max_len) b.resize(max_len);
  return b;
}

const char* last_input = std::getenv("GAITSYNTH_FUZZ_LAST");

void run(const bytes& b) {
  if (last_input != nullptr)
    std::ofstream(last_input, std::ios::binary)
        .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  LLVMFuzzerTestOneInput(b.data(), b.size());
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t mutants = 0;
  std::uint64_t seed = 1;
  std::size_t max_len = 1 << 20;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--mutants" || a == "--seed" || a == "--max-len") && i + 1 < argc) {
      const auto v = std::stoull(argv[++i]);
      if (a == "--mutants") {
        mutants = static_cast<std::size_t>(v);
      } else if (a == "--seed") {
        seed = v;
      } else {
        max_len = static_cast<std::size_t>(v);
      }
    } else if (std::filesystem::is_directory(a)) {
      for (const auto& e : std::filesystem::recursive_directory_iterator(a))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (std::filesystem::is_regular_file(a)) {
      files.push_back(a);
    } else {
      std::cerr << "fuzz_replay: not a file, folder or option: " << a << "\n"
                << "usage: " << argv[0] << " [--mutants N] [--seed S] [--max-len BYTES] PATH...\n";
      return 2;
    }
  }
  if (files.empty()) {
    std::cerr << "fuzz_replay: no corpus files\n";
    return 2;
  }
  std::sort(files.begin(), files.end());  // the same order (and mutants) on every machine
  const auto start = std::chrono::steady_clock::now();
  std::vector<bytes> corpus;
  for (const auto& f : files) {
    corpus.push_back(read_file(f));
    run(corpus.back());
  }
  std::mt19937_64 g(seed);
  for (std::size_t k = 0; k < mutants; ++k) {
    const bytes m = mutate(corpus, g, max_len);
    run(m);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "fuzz_replay: ran " << corpus.size() + mutants << " inputs (" << corpus.size()
            << " corpus files, " << mutants << " mutants, seed " << seed << ") in " << s
            << " s without a crash\n";
  return 0;
}
