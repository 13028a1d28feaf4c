#!/usr/bin/env bash
# The examples' command lines (examples/command_line.hpp), run as a user would:
#   command_lines.sh bad_values EXE...   each example refuses a bad value of each kind with a
#                                        message naming the flag and the value, and exit status 2;
#                                        --help exits 0 and lists the flags with their defaults
#   command_lines.sh resume WALK DIR     wang2009_walk killed (SIGKILL) after its first checkpoint
#                                        and resumed with --resume DIR ends as the uninterrupted run
set -uo pipefail
mode=$1
shift
fail=0
expect() {  # expect STATUS PATTERN -- command...: the status and a line of stderr matching PATTERN
  local status=$1 pattern=$2
  shift 3
  local err rc
  err=$("$@" 2>&1 >/dev/null)
  rc=$?
  if [[ $rc -ne $status ]] || ! grep -qE -- "$pattern" <<<"$err"; then
    echo "FAIL: $* -> status $rc (want $status), stderr: ${err:0:300} (want /$pattern/)"
    fail=1
  fi
}
case "$mode" in
  bad_values)
    for exe in "$@"; do
      name=$(basename "$exe")
      help=$("$exe" --help 2>&1)
      rc=$?
      if [[ $rc -ne 0 ]] || ! grep -q -- "--help" <<<"$help"; then
        echo "FAIL: $name --help: status $rc"; fail=1
      fi
      expect 2 "unknown option '--no-such-flag'" -- "$exe" --no-such-flag
      expect 2 "unexpected argument 'stray'" -- "$exe" stray
      # Each of these flags, where the example has it, with a bad value of each kind.
      if grep -q -- "--threads" <<<"$help"; then
        expect 2 "--threads: must be in \[0, 4096\], got -1" -- "$exe" --threads -1
        expect 2 "--threads: '2x' is not a whole number" -- "$exe" --threads 2x
        expect 2 "did you mean '--threads'" -- "$exe" --thread 2
      fi
      if grep -q -- "--check-seconds" <<<"$help"; then
        expect 2 "--check-seconds: '5x' is not a number" -- "$exe" --check-seconds 5x
        expect 2 "--check-seconds: must be in .*, got nan" -- "$exe" --check-seconds nan
        expect 2 "--check-seconds: must be in .*, got -5" -- "$exe" --check-seconds -5
      fi
      if grep -q -- "--seed" <<<"$help"; then
        expect 2 "--seed: must be in .*, got -3" -- "$exe" --seed -3
      fi
      if grep -q -- "--html" <<<"$help"; then
        expect 2 "--html" -- "$exe" --html
      fi
      echo "ok: $name"
    done
    ;;
  resume)
    walk=$1 dir=$2
    rm -rf "$dir"
    flags=(--iterations 25 --horizon 1 --check-seconds 1 --threads 1)
    "$walk" "${flags[@]}" --out "$dir/whole" >/dev/null 2>&1 || { echo "FAIL: the whole run"; exit 1; }
    "$walk" "${flags[@]}" --out "$dir/cut" >/dev/null 2>&1 &
    pid=$!
    for _ in $(seq 1 3000); do [[ -f "$dir/cut/wang2009_stocky.checkpoint" ]] && break; sleep 0.01; done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    [[ -f "$dir/cut/wang2009_stocky.checkpoint" ]] || { echo "FAIL: no checkpoint to resume from"; exit 1; }
    rows=$(($(wc -l <"$dir/cut/wang2009_stocky.convergence.csv") - 1))
    "$walk" --resume "$dir/cut" --threads 2 >/dev/null 2>"$dir/resume.log" ||
      { echo "FAIL: --resume"; tail -3 "$dir/resume.log"; exit 1; }
    a=$dir/whole/wang2009_stocky b=$dir/cut/wang2009_stocky
    if diff -q <(grep -v '"command"' "$a.controller.json") <(grep -v '"command"' "$b.controller.json") >/dev/null &&
       cmp -s "$a.csv" "$b.csv"; then
      echo "ok: killed after $rows logged iterations and resumed: the same controller and check rollout"
    else
      echo "FAIL: the resumed run differs from the whole one"; fail=1
    fi
    # Every iteration up to the checkpoint is in the log (the rest are logged again).
    if [[ $(cut -d, -f3 "$b.convergence.csv" | sort -n -u | grep -c .) -lt 26 ]]; then
      echo "FAIL: the resumed log lacks iterations"; fail=1
    fi
    # Another seed gives another controller: the comparison can fail.
    "$walk" "${flags[@]}" --seed 2 --out "$dir/seed2" >/dev/null 2>&1
    if diff -q <(grep -v '"command"' "$a.controller.json") \
               <(grep -v '"command"' "$dir/seed2/wang2009_stocky.controller.json") >/dev/null; then
      echo "FAIL: the comparison does not see another seed"; fail=1
    fi
    # --resume takes the recorded options; others are refused.
    expect 1 "cannot be given with it" -- "$walk" --resume "$dir/cut" --iterations 3
    expect 1 "no run folder" -- "$walk" --resume "$dir/none"
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
exit $fail
