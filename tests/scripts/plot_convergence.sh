#!/usr/bin/env bash
# scripts/plot_convergence.py run as a user would:
#   plot_convergence.sh PYTHON SCRIPT LOG WORK_DIR
# LOG (two continuation stages, a restart, a resumed iteration, an inf cell) gives a non-empty SVG;
# a CSV that is not an optimizer log is refused with a non-zero status and a message naming it.
set -uo pipefail
python=$1 script=$2 log=$3 work=$4
fail=0
rm -rf "$work" && mkdir -p "$work"

out=$work/convergence.svg
err=$("$python" "$script" "$log" --label test --title "test log" -o "$out" 2>&1)
rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: $script $log -o $out exited with status $rc: ${err:0:500}"
  fail=1
elif [[ ! -s $out ]] || ! grep -q "<svg" "$out"; then
  echo "FAIL: $out is empty or not an SVG"
  fail=1
fi

bad=$work/not_a_log.csv
printf 'time,hip,knee\n0,0.1,0.2\n0.01,0.11,0.19\n' >"$bad"
err=$("$python" "$script" "$bad" -o "$work/bad.svg" 2>&1)
rc=$?
if [[ $rc -eq 0 ]] || ! grep -qF -- "$bad" <<<"$err"; then
  echo "FAIL: $script $bad -> status $rc (want non-zero), output: ${err:0:500} (want the file name)"
  fail=1
fi

((fail)) || echo "plot_convergence.py: SVG written, non-log CSV refused"
exit $fail
