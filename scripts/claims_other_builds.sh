#!/usr/bin/env bash
# The saved walkers' claims under builds other than CI's GCC -O3: a result must not rest on one
# compiler's rounding. Builds the claim tests (tests/sharon2005/, tests/wang2009/, tests/wang2012/)
# and runs them
#   clang   with Debian's clang (14), Release
#   fma     with GCC, Release, -ffp-contract=fast -march=x86-64-v3 (fused multiply-adds, AVX2)
#   scripts/claims_other_builds.sh [clang|fma]...   (default: both)
# Not part of .ci/run: the two extra builds and their claim runs take about 25 minutes on 2 cores,
# which CI's 90-minute budget cannot take next to the main suite. Results: docs/performance.md is
# not the place; docs/reproductions/*.md say which claims held where.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --tests
variants=("$@")
[[ ${#variants[@]} -eq 0 ]] && variants=(clang fma)
if [[ " ${variants[*]} " == *" clang "* ]] && ! command -v clang++ >/dev/null; then
  SUDO=""
  [[ $(id -u) -ne 0 ]] && SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang >/dev/null
fi
jobs=${JOBS:-$(nproc)}  # JOBS=1 leaves a core to other work
status=0
for v in "${variants[@]}"; do
  dir=build/claims_$v
  case "$v" in
    clang) flags=(-DCMAKE_CXX_COMPILER=clang++) ;;
    fma) flags=(-DCMAKE_CXX_FLAGS="-ffp-contract=fast -march=x86-64-v3") ;;
    *) echo "unknown variant $v (clang or fma)"; exit 2 ;;
  esac
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGAITSYNTH_BUILD_TESTS=ON \
    -DGAITSYNTH_BUILD_EXAMPLES=OFF -DGAITSYNTH_BUILD_BENCHMARKS=OFF -DGAITSYNTH_USE_MPI=OFF \
    "${flags[@]}" >/dev/null
  cmake --build "$dir" -j"$jobs" --target test_sharon2005 test_wang2009 test_wang2012
  echo "== claims, $v build"
  ctest --test-dir "$dir" -j"$jobs" -R '^(sharon2005|wang2009|wang2012)/' --output-on-failure \
    --timeout 1200 || status=1
done
exit $status
