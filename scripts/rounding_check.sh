#!/usr/bin/env bash
# Checks that the working tree simulates planar characters with exactly the floating-point
# operations of another revision (default: HEAD): builds scripts/rounding_probe.cpp against both
# include trees with the tests' flags (Release, baseline x86-64, no FMA contraction) and compares
# the hexfloat outputs. Use it for any change to the planar dynamics, contact or rollout loop that
# is meant to be a pure speed-up (the probe runs the 3D walkers too); docs/performance.md
# ("Rounding") says why it matters.
#   scripts/rounding_check.sh [REV]
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-HEAD}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
git archive "$rev" include examples | tar -x -C "$tmp"
flags=(-std=gnu++20 -O3 -DNDEBUG -I/usr/include/eigen3)
g++ "${flags[@]}" -I"$tmp/include" -I"$tmp/examples" scripts/rounding_probe.cpp -o "$tmp/probe_rev" &
rev_build=$!
g++ "${flags[@]}" -Iinclude -Iexamples scripts/rounding_probe.cpp -o "$tmp/probe_tree" &
tree_build=$!
wait "$rev_build"
wait "$tree_build"
"$tmp/probe_rev" "$PWD" >"$tmp/rev.txt"
"$tmp/probe_tree" "$PWD" >"$tmp/tree.txt"
if diff -u "$tmp/rev.txt" "$tmp/tree.txt"; then
  echo "rounding_check: identical to $rev ($(wc -l <"$tmp/tree.txt") rollouts)"
else
  echo "rounding_check: the working tree rounds differently from $rev (diff above)" >&2
  exit 1
fi
