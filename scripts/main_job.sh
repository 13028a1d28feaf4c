#!/usr/bin/env bash
# The main job (README): installs what is missing on Debian 12, builds the flagship example and
# runs it end to end on built-in defaults: the Sharon & van de Panne 2005 normal-walk synthesis
# (7-link planar human, nearest-neighbor controller, bootstrapped SDS). Outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build/main -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DGAITSYNTH_BUILD_TESTS=OFF -DGAITSYNTH_BUILD_BENCHMARKS=OFF >/dev/null
target=sharon2005_normal_walk
cmake --build build/main -j"$(nproc)" --target "$target"
mkdir -p out
./build/main/examples/"$target" --out out \
  --html out/"$target".html --filmstrip out/"$target".svg "$@"
