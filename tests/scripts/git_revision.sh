#!/usr/bin/env bash
# cmake/git_revision.cmake on a throwaway repository: the file names HEAD; a change to a tracked
# file makes it "-dirty"; an unchanged revision leaves the file untouched (so nothing recompiles);
# a new commit names the new HEAD without any reconfigure; no repository gives "unknown".
#   git_revision.sh CMAKE GIT SCRIPT WORKDIR
set -uo pipefail
cmake=$1 git=$2 script=$3 work=$4
fail=0
rm -rf "$work" && mkdir -p "$work/repo" || exit 1
out=$work/revision.cpp
gen() { "$cmake" -DSOURCE_DIR="$1" -DOUT="$out" -DGIT="$git" -P "$script"; }
named() { grep -q "return \"$1\";" "$out" || { echo "FAIL: $2: want \"$1\", file has: $(grep return "$out")"; fail=1; }; }
g() { "$git" -C "$work/repo" -c user.name=t -c user.email=t@t "$@" >/dev/null; }
g init -q && echo a >"$work/repo/f" && g add f && g commit -q -m one
gen "$work/repo"
first=$("$git" -C "$work/repo" rev-parse --short=12 HEAD)
named "$first" "first commit"
touch -d '2000-01-01' "$out"
gen "$work/repo"
[[ $(stat -c %Y "$out") -eq $(date -d '2000-01-01' +%s) ]] || { echo "FAIL: unchanged revision rewrote the file"; fail=1; }
echo b >"$work/repo/f"
gen "$work/repo"
named "$first-dirty" "uncommitted change"
g commit -q -am two
gen "$work/repo"
second=$("$git" -C "$work/repo" rev-parse --short=12 HEAD)
[[ "$second" != "$first" ]] && named "$second" "second commit"
mkdir -p "$work/norepo"
GIT_CEILING_DIRECTORIES=$work gen "$work/norepo"
named unknown "no repository"
[[ $fail -eq 0 ]] && echo "ok: revision file follows HEAD, -dirty, untouched when unchanged, unknown"
exit $fail
