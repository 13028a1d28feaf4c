#!/usr/bin/env bash
# Runs the MPI evaluator's test program (tests/optimizers/mpi_evaluator.mpi.cpp) under mpirun.
#   run_mpi_test.sh MPIEXEC EXE WORKDIR identical PROBLEM   1, 2 and 4 ranks (1 and 2 threads per
#                                                            rank) against one process's thread pool
#   run_mpi_test.sh MPIEXEC EXE WORKDIR failures             exceptions, NaN, misuse, on 1-3 ranks
#   run_mpi_test.sh MPIEXEC EXE WORKDIR interrupt            Ctrl-C ends every rank
#   run_mpi_test.sh MPIEXEC WALK WORKDIR example             wang2009_walk --mpi on 1 and 3 ranks
#                                                            writes what its thread pool writes
# This machine has 2 cores and runs the tests as root: --oversubscribe and --allow-run-as-root are
# set here, for the tests only, not in the library or the documented launch lines.
set -uo pipefail
mpiexec=$1 exe=$2 work=$3 mode=$4
mkdir -p "$work"
launch=("$mpiexec" --oversubscribe --bind-to none)
[[ $(id -u) -eq 0 ]] && launch+=(--allow-run-as-root)
fail=0
case "$mode" in
  identical)
    problem=$5
    "$exe" optimize "$problem" "$work/reference.txt" 2 --reference || exit 1
    for layout in "1 1" "2 1" "4 1" "2 2" "3 2"; do
      set -- $layout
      out="$work/ranks$1_threads$2.txt"
      rm -f "$out"
      if ! timeout 300 "${launch[@]}" -np "$1" "$exe" optimize "$problem" "$out" "$2"; then
        echo "FAIL: $1 ranks x $2 threads: the run failed"; fail=1; continue
      fi
      if cmp -s "$work/reference.txt" "$out"; then
        echo "ok: $1 ranks x $2 threads: bit-identical to the thread pool"
      else
        echo "FAIL: $1 ranks x $2 threads differ from the thread pool:"; diff "$work/reference.txt" "$out" | head -8; fail=1
      fi
    done
    # Negative control: workers whose costs differ by 1e-12 must change the fingerprint.
    out="$work/skewed.txt"
    if timeout 300 "${launch[@]}" -np 2 "$exe" optimize "$problem" "$out" 1 --skew-workers &&
       ! cmp -s "$work/reference.txt" "$out"; then
      echo "ok: costs 1e-12 off on the workers change the fingerprint"
    else
      echo "FAIL: the comparison did not see workers whose costs are 1e-12 off"; fail=1
    fi
    ;;
  failures)
    for ranks in 1 2 3; do
      if timeout 120 "${launch[@]}" -np "$ranks" "$exe" failures; then
        echo "ok: failures on $ranks ranks"
      else
        echo "FAIL: failures on $ranks ranks"; fail=1
      fi
    done
    ;;
  interrupt)
    flag="$work/running.txt"
    rm -f "$flag"
    setsid "${launch[@]}" -np 3 "$exe" forever "$flag" &
    pid=$!
    for _ in $(seq 1 300); do [[ -f "$flag" ]] && break; sleep 0.1; done
    [[ -f "$flag" ]] || { echo "FAIL: the endless optimization did not start"; kill -9 -- -"$pid"; exit 1; }
    kill -INT "$pid"
    for _ in $(seq 1 150); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      echo "FAIL: mpirun still runs 15 s after Ctrl-C"; kill -9 -- -"$pid"; fail=1
    fi
    wait "$pid" 2>/dev/null
    sleep 0.5
    if pgrep -f "$exe forever $flag" >/dev/null; then
      echo "FAIL: ranks left behind after Ctrl-C"; pkill -9 -f "$exe forever $flag"; fail=1
    else
      echo "ok: Ctrl-C ended mpirun and every rank"
    fi
    ;;
  example)
    # A short optimization (3 iterations of 1 s rollouts, a 1 s check) with the example's own
    # files compared: the controller (but for the command line it records), the convergence log
    # (but for its elapsed-time column) and the check rollout's trajectory.
    flags=(--iterations 3 --horizon 1 --check-seconds 1)
    "$exe" "${flags[@]}" --threads 2 --out "$work/pool" >/dev/null 2>&1 || { echo "FAIL: thread pool run"; exit 1; }
    same() {  # $1, $2: output folders
      local a=$1/wang2009_stocky b=$2/wang2009_stocky
      diff -q <(grep -v '"command"' "$a.controller.json") <(grep -v '"command"' "$b.controller.json") >/dev/null &&
        diff -q <(cut -d, -f1-12 "$a.convergence.csv") <(cut -d, -f1-12 "$b.convergence.csv") >/dev/null &&
        cmp -s "$a.csv" "$b.csv"
    }
    for ranks in 1 3; do
      if ! timeout 300 "${launch[@]}" -np "$ranks" "$exe" --mpi "${flags[@]}" --threads 1 \
          --out "$work/mpi$ranks" >/dev/null 2>"$work/mpi$ranks.log"; then
        echo "FAIL: wang2009_walk --mpi on $ranks ranks failed:"; tail -5 "$work/mpi$ranks.log"; fail=1; continue
      fi
      if same "$work/pool" "$work/mpi$ranks"; then
        echo "ok: wang2009_walk --mpi on $ranks ranks writes what its thread pool writes"
      else
        echo "FAIL: wang2009_walk --mpi on $ranks ranks differs from its thread pool"; fail=1
      fi
    done
    # Negative control: another seed must give other files.
    "$exe" "${flags[@]}" --threads 2 --seed 2 --out "$work/seed2" >/dev/null 2>&1
    if same "$work/pool" "$work/seed2"; then
      echo "FAIL: the comparison does not see another seed"; fail=1
    fi
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
exit $fail
