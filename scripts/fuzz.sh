#!/usr/bin/env bash
# Fuzzes every loader of the library with libFuzzer (docs/fuzzing.md): builds each target of
# tests/fuzz/*.fuzz.cpp with clang++-14 -fsanitize=fuzzer,address,undefined into build/fuzz/,
# seeds its corpus with the repository's real files (tests/fuzz/seeds.txt) and runs it for
# RUNS executions (default 1e6). One target at a time, each build and run under `nice`.
#
#   bash scripts/fuzz.sh                      every target, 1e6 executions each
#   bash scripts/fuzz.sh keyframes checkpoint those targets only
#   RUNS=100000 bash scripts/fuzz.sh          fewer executions
#   MAX_TIME=180 bash scripts/fuzz.sh         also stop each target after 180 s (a busy machine)
#
# Per target X: build/fuzz/X (the fuzzer), build/fuzz/seeds/X/ (the seeds, copied afresh),
# build/fuzz/corpus/X/ (what libFuzzer added, kept between runs), build/fuzz/X.log (its output:
# executions, exec/s, coverage, and any crash, leak or timeout), build/fuzz/artifacts/X/ (the
# inputs that failed: rerun one with `build/fuzz/X FILE`, or with build/release's
# tests/fuzz_replay_X FILE). The summary line of each target goes to build/fuzz/summary.txt.
# Exit status: 1 if any target failed (crash, sanitizer report, leak, timeout or out of memory).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/fuzz
runs=${RUNS:-1000000}
max_time=${MAX_TIME:-0}  # libFuzzer's -max_total_time, s; 0: no limit
cxx=${CXX_FUZZ:-clang++-14}
mkdir -p "$out"

# The longest input per target: a little above its largest seed (larger seeds are cut).
declare -A max_len=(
  [keyframes]=32768 [nearest_neighbor]=32768 [wang2009_controller]=32768
  [trajectory_csv]=65536 [checkpoint]=16384 [normative_gait]=65536
  [stage_results]=4096 [convergence_csv]=32768)

targets=("$@")
if ((${#targets[@]} == 0)); then
  for f in tests/fuzz/*.fuzz.cpp; do
    t=$(basename "$f" .fuzz.cpp)
    targets+=("$t")
  done
fi

status=0
for t in "${targets[@]}"; do
  src=tests/fuzz/$t.fuzz.cpp
  [[ -f $src ]] || { echo "fuzz.sh: no target $src" >&2; exit 2; }
  echo "== $t: building"
  # -O1 -g: the sanitizers' usual build; the warnings of the project's own builds.
  nice "$cxx" -std=c++20 -O1 -g -fno-omit-frame-pointer \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -Wall -Wextra -Wpedantic -Wno-missing-field-initializers \
    -Iinclude -Itests -isystem /usr/include/eigen3 -pthread \
    "$src" -o "$out/$t"

  # Seeds: every file tests/fuzz/seeds.txt names for this target, its path flattened into its name.
  seeds=$out/seeds/$t
  rm -rf "$seeds"
  mkdir -p "$seeds" "$out/corpus/$t" "$out/artifacts/$t"
  while read -r target dir pattern; do
    [[ $target == "$t" ]] || continue
    while IFS= read -r -d '' f; do
      cp "$f" "$seeds/$(echo "${f#./}" | tr '/' '_')"
    done < <(find "$dir" -type f -name "$pattern" -print0)
  done < <(grep -E '^[a-z]' tests/fuzz/seeds.txt)
  echo "== $t: $(ls "$seeds" | wc -l) seeds, $runs runs, max_len ${max_len[$t]:-65536}"

  # New inputs go to the first folder (corpus/), the seeds are read from the second.
  set +e
  (cd "$out" && nice "./$t" -runs="$runs" -seed=1 -max_len="${max_len[$t]:-65536}" \
    -max_total_time="$max_time" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="artifacts/$t/" "corpus/$t" "seeds/$t") >"$out/$t.log" 2>&1
  rc=$?
  set -e
  line=$(grep -a -E '^#[0-9]+\s+DONE' "$out/$t.log" | tail -1 || true)
  execs=$(grep -a -E 'stat::number_of_executed_units' "$out/$t.log" | awk '{print $2}' || true)
  speed=$(grep -a -E 'stat::average_exec_per_sec' "$out/$t.log" | awk '{print $2}' || true)
  if ((rc == 0)); then
    summary="$t: ok, ${execs:-?} executions (of $runs), ${speed:-?} exec/s, ${line:-no DONE line}"
  else
    status=1
    summary="$t: FAILED (exit $rc), see $out/$t.log and $out/artifacts/$t/: $(grep -a -m1 -E 'ERROR|SUMMARY|undocumented' "$out/$t.log" || true)"
  fi
  echo "$summary" | tee -a "$out/summary.txt"
done
exit $status
