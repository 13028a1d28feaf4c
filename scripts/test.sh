#!/usr/bin/env bash
# The test command (README): installs what is missing on Debian 12, builds everything (library
# tests, examples, benchmarks) in Release and runs the whole test suite with CTest.
#   scripts/test.sh              Release build in build/release, all tests
#   scripts/test.sh --sanitize   -fsanitize=address,undefined build in build/sanitize, all tests
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --tests
jobs=$(nproc)
if [[ "${1:-}" == "--sanitize" ]]; then
  dir=build/sanitize
  # Debug keeps Eigen's and the library's assertions on; -O1 keeps the instrumented suite fast
  # enough to run in full.
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1" \
    -DGAITSYNTH_SANITIZE=ON -DGAITSYNTH_BUILD_TESTS=ON \
    -DGAITSYNTH_BUILD_BENCHMARKS=OFF -DGAITSYNTH_BUILD_EXAMPLES=OFF
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  dir=build/release
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGAITSYNTH_BUILD_TESTS=ON
fi
cmake --build "$dir" -j"$jobs"
ctest --test-dir "$dir" -j"$jobs" --output-on-failure --timeout 900
