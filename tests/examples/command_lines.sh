#!/usr/bin/env bash
# The examples' command lines (examples/command_line.hpp), run as a user would:
#   command_lines.sh bad_values EXE...   each example refuses a bad value of each kind with a
#                                        message naming the flag and the value, and exit status 2;
#                                        --help exits 0 and lists the flags with their defaults
#   command_lines.sh revision EXE SOURCE_DIR DIR FLAGS...
#                                        EXE FLAGS --out DIR writes options.json whose
#                                        build.git_revision is SOURCE_DIR's HEAD (at build time)
#   command_lines.sh h_max_cap EXE DIR CAP FLAGS...
#                                        wu2010_walk FLAGS --h-max-cap CAP --out DIR: the saved
#                                        best's and CMA mean's h_max are at or below CAP, though
#                                        the run starts from the middle of the bounds, above it
#   command_lines.sh continuation EXE DIR FLAGS...
#                                        wu2010_walk FLAGS --out DIR, then --resume DIR
#                                        --helper-weight 0.05 (Sec. 8.2's continuation): options.json
#                                        takes the weight and lists the continuation with its
#                                        iteration, the saved controller records the weight, and a
#                                        second --resume keeps it
#   command_lines.sh init_body EXE DIR INIT FLAGS...
#                                        wang2012_walk --init INIT FLAGS: the saved controller
#                                        keeps INIT's weakness and colliding legs (the body it was
#                                        made for), and options.json lists that body; with
#                                        --weaken HAM=1 --leg-collisions off too it takes those
#                                        instead
#   command_lines.sh init_settings EXE DIR INIT FLAGS...
#                                        wu2010_walk --init INIT FLAGS --out DIR: options.json lists
#                                        the controller rate, stance target, pinning, half-cycle end
#                                        and terrain sampling taken from INIT, not the defaults
#   command_lines.sh saved_ground EXE WALKERS_DIR
#                                        wang2009_push_test --controller pushes a saved walker on
#                                        the slope and friction it was made for (its file's info),
#                                        and --slope and --mu override them
#   command_lines.sh push_starts_threads EXE DIR WALKER
#                                        wang2012_walk --replay WALKER --check-pushes 100
#                                        --check-push-starts 2 gives the same pushed walks on 1
#                                        and 2 threads
#   command_lines.sh keep_means EXE DIR STEM FLAGS...
#                                        EXE FLAGS --iterations 20 --keep-means keeps CMA's mean at
#                                        10 and 20 as STEM.mean10.json and STEM.mean20.json (the
#                                        last STEM.mean.json, the first another), and without it
#                                        none is kept and the best is the same
#   command_lines.sh resume EXE DIR STEM WAIT_FOR FLAGS... -- OTHER_FLAGS...
#                                        EXE killed (SIGKILL) after its first checkpoint, then 3
#                                        times at seeded random moments while resuming, and
#                                        resumed with --resume DIR ends as the uninterrupted run
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
runs() {  # runs EXE ARGS...: EXE ARGS exits 0, else a FAIL line naming the command
  local exe=$1
  shift
  "$exe" "$@" >/dev/null 2>&1 && return 0
  echo "FAIL: $(basename "$exe") $* failed"
  fail=1
  return 1
}
case "$mode" in
  bad_values)
    for exe in "$@"; do
      name=$(basename "$exe")
      before=$fail
      fail=0
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
      if grep -q -- "--stance-target" <<<"$help"; then
        expect 2 "--stance-target: sideways not in \{planned_landing,touchdown,first_contact\}" -- \
          "$exe" --stance-target sideways
        expect 2 "--pin-by: heel not in \{frame_geometry,link\}" -- "$exe" --pin-by heel
        expect 2 "--half-cycle: early not in \{fixed,touchdown\}" -- "$exe" --half-cycle early
        expect 2 "--implicit-damping: yes not in \{on,off\}" -- "$exe" --implicit-damping yes
        expect 2 "--divergence: nan not in \{fall,infinite\}" -- "$exe" --divergence nan
        expect 2 "--cost-timestep: must be in .*, got -1" -- "$exe" --cost-timestep -1
        expect 2 "--cost-timestep: must be in .*, got nan" -- "$exe" --cost-timestep nan
        expect 2 "--body: bird not in \{normal,inverted_knees,frozen_left_knee\}" -- \
          "$exe" --body bird
        expect 2 "--push-force: must be in .*, got -350" -- "$exe" --push-force -350
        expect 2 "--helper-weight: must be in .*, got -1" -- "$exe" --helper-weight -1
        expect 2 "--terrain: stairs not in \{fields,boxes,mixed\}" -- "$exe" --terrain stairs
        expect 2 "--robust-starts: must be in .*, got -1" -- "$exe" --robust-starts -1
        expect 2 "--robust-starts: '2.5' is not a whole number" -- "$exe" --robust-starts 2.5
        expect 2 "--start-sigma: must be in .*, got nan" -- "$exe" --start-sigma nan
        expect 2 "--leg-collisions: maybe not in \{on,off\}" -- "$exe" --leg-collisions maybe
        expect 2 "--task: sideways not in \{f,b,l,r,s\}" -- "$exe" --task sideways
        expect 2 "--h-max-cap: must be in .*, got -500" -- "$exe" --h-max-cap -500
        expect 2 "--h-max-cap: must be in .*, got nan" -- "$exe" --h-max-cap nan
      fi
      if grep -qE -- "--mu\b" <<<"$help"; then
        expect 2 "--mu: must be in .*, got -1" -- "$exe" --mu -1
        expect 2 "--mu: must be in .*, got nan" -- "$exe" --mu nan
        expect 2 "--slope: must be in .*, got 50" -- "$exe" --slope 50
      fi
      if grep -q -- "--perturbed" <<<"$help"; then
        expect 2 "--perturbed: must be in \[0, 1000\], got -1" -- "$exe" --perturbed -1
        expect 2 "--required: must be in \[1, 1000\], got 0" -- "$exe" --required 0
        expect 1 "--required 11 is more than --perturbed 10" -- "$exe" --perturbed 10 --required 11
        expect 1 "--required needs --perturbed" -- "$exe" --required 3
      fi
      if grep -q -- "--ratio-within" <<<"$help"; then
        expect 2 "--ratio-within: must be in .*, got 0" -- "$exe" --ratio-within 0
        expect 2 "--ratio-within: must be in .*, got nan" -- "$exe" --ratio-within nan
        expect 2 "--step-at-least: must be in .*, got 0" -- "$exe" --step-at-least 0
        expect 2 "--step-at-least: must be in .*, got nan" -- "$exe" --step-at-least nan
      fi
      if grep -q -- "--seed" <<<"$help"; then
        expect 2 "--seed: must be in .*, got -3" -- "$exe" --seed -3
      fi
      if grep -q -- "--weaken" <<<"$help"; then
        expect 2 "--effort: .*metabolism" -- "$exe" --effort metabolism
        expect 2 "--weaken: wants NAME=VALUE, got 'GAS'" -- "$exe" --weaken GAS
        expect 2 "--check-pushes: must be in .*, got -100" -- "$exe" --check-pushes -100
        expect 2 "--check-pushes: must be in .*, got nan" -- "$exe" --check-pushes nan
        expect 2 "--check-push-starts: must be in \[0, 1000\], got -1" -- "$exe" \
          --check-push-starts -1
        expect 1 "--check-push-starts needs --check-pushes" -- "$exe" --check-push-starts 10
        expect 2 "--leg-collisions: maybe not in \{off,on\}" -- "$exe" --leg-collisions maybe
        expect 1 "no MTU named 'QUAD'" -- "$exe" --weaken QUAD=0.5 --iterations 0 --horizon 0.01 \
          --check-seconds 0.01 --out "${TMPDIR:-/tmp}/gaitsynth_cli_weaken"
        expect 1 "factor for 'GAS' must be finite and > 0, got 0" -- "$exe" --weaken GAS=0 \
          --iterations 0 --horizon 0.01 --check-seconds 0.01 --out "${TMPDIR:-/tmp}/gaitsynth_cli_weaken"
      fi
      if grep -q -- "--push-phase" <<<"$help"; then
        expect 2 "--push-direction-step: must be in \[-1, 7\], got 8" -- "$exe" \
          --push-direction-step 8
        expect 2 "--push-period: must be in .*, got 0" -- "$exe" --push-period 0
        expect 2 "--push-phase: sometimes not in \{fixed,random\}" -- "$exe" --push-phase sometimes
        expect 2 "--push-directions: must be in \[0, 7\], got 8" -- "$exe" --push-directions 0,8
        expect 1 "--push-directions: 3 given, --robust-pushes 2: give one direction per pushed" \
          -- "$exe" --robust-pushes 2 --push-directions 4,4,7
      fi
      if grep -q -- "--sigma" <<<"$help"; then
        expect 2 "--sigma: must be in .*, got 0" -- "$exe" --sigma 0
        expect 2 "--sigma: must be in .*, got nan" -- "$exe" --sigma nan
      fi
      if grep -q -- "--controller-rate" <<<"$help"; then
        expect 2 "--controller-rate: must be in .*, got -5" -- "$exe" --controller-rate -5
        expect 1 "--controller-rate must be 0 .* or above 2 Hz.*got 1" -- "$exe" --controller-rate 1
      fi
      case "$name" in
        # The normal walk's training flags, which the other Sharon examples used to ignore.
        sharon2005_high_knee | sharon2005_backswing | sharon2005_human16 | sharon2005_uphill)
          expect 2 "unknown option '--bumpy-training'" -- "$exe" --bumpy-training 2
          expect 2 "unknown option '--stage1-only'" -- "$exe" --stage1-only
          ;;
        sharon2005_normal_walk)
          expect 2 "--bumpy-training: must be in .*, got 65" -- "$exe" --bumpy-training 65
          ;;
      esac
      case "$name" in
        # Disturbance training: the 7-link styles only.
        sharon2005_high_knee | sharon2005_backswing)
          expect 2 "--min-progress-speed: must be in .*, got -1" -- "$exe" --min-progress-speed -1
          ;;
        sharon2005_normal_walk | sharon2005_human16 | sharon2005_uphill)
          expect 2 "unknown option '--disturbance-training'" -- "$exe" --disturbance-training
          ;;
      esac
      if grep -q -- "--html" <<<"$help"; then
        expect 2 "--html" -- "$exe" --html
      fi
      [[ $fail -eq 0 ]] && echo "ok: $name"
      [[ $before -ne 0 ]] && fail=1
    done
    ;;
  keep_means)
    exe=$1 dir=$2 stem=$3
    shift 3
    rm -rf "$dir"
    if runs "$exe" "$@" --iterations 20 --keep-means --out "$dir/kept" &&
       runs "$exe" "$@" --iterations 20 --out "$dir/plain"; then
      k=$dir/kept/$stem
      if [[ ! -f $k.mean10.json || ! -f $k.mean20.json ]]; then
        echo "FAIL: $(basename "$exe") --keep-means kept no $stem.mean10.json or .mean20.json"
        fail=1
      else
        cmp -s "$k.mean20.json" "$k.mean.json" ||
          { echo "FAIL: $stem.mean20.json is not the last mean"; fail=1; }
        cmp -s "$k.mean10.json" "$k.mean20.json" &&
          { echo "FAIL: the means kept at 10 and 20 are the same"; fail=1; }
      fi
      compgen -G "$dir/plain/$stem.mean[0-9]*.json" >/dev/null &&
        { echo "FAIL: means kept without --keep-means"; fail=1; }
      # (but for the command the saved best records)
      kept() { grep -v '"command"' "$1"; }
      diff -q <(kept "$k.controller.json") <(kept "$dir/plain/$stem.controller.json") >/dev/null ||
        { echo "FAIL: --keep-means changed the best"; fail=1; }
      [[ $fail -eq 0 ]] && echo "ok: $(basename "$exe") --keep-means"
    fi
    ;;
  resume)
    # resume EXE DIR STEM WAIT_FOR FLAGS...: EXE with FLAGS, whole and killed (SIGKILL) once
    # DIR/cut/WAIT_FOR exists, then resumed from DIR/cut; STEM.controller.json (but for the
    # command, wall times and thread count it records) and STEM.csv must match.
    exe=$1 dir=$2 stem=$3 wait_for=$4
    shift 4
    flags=() other=()
    while [[ $# -gt 0 && $1 != "--" ]]; do flags+=("$1"); shift; done
    [[ $# -gt 0 ]] && shift
    other=("$@")
    rm -rf "$dir"
    "$exe" "${flags[@]}" --out "$dir/whole" >/dev/null 2>&1 || { echo "FAIL: the whole run"; exit 1; }
    "$exe" "${flags[@]}" --out "$dir/cut" >/dev/null 2>&1 &
    pid=$!
    for _ in $(seq 1 3000); do [[ -f "$dir/cut/$wait_for" ]] && break; sleep 0.01; done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    [[ -f "$dir/cut/$wait_for" ]] || { echo "FAIL: no checkpoint to resume from"; exit 1; }
    # Then killed again while resuming, at seeded random moments (0.05 to 0.8 s in).
    RANDOM=2026
    for k in 1 2 3; do
      "$exe" --resume "$dir/cut" --threads 2 >/dev/null 2>&1 &
      pid=$!
      sleep "0.$(printf '%02d' $((5 + RANDOM % 75)))"
      kill -9 "$pid" 2>/dev/null
      wait "$pid" 2>/dev/null
    done
    "$exe" --resume "$dir/cut" --threads 2 >/dev/null 2>"$dir/resume.log" ||
      { echo "FAIL: --resume"; tail -3 "$dir/resume.log"; exit 1; }
    kept() { grep -v -E '"(command|wall_seconds|threads)"' "$1"; }
    same() { diff -q <(kept "$1/$stem.controller.json") <(kept "$2/$stem.controller.json") >/dev/null &&
             cmp -s "$1/$stem.csv" "$2/$stem.csv"; }
    if same "$dir/whole" "$dir/cut"; then
      echo "ok: $(basename "$exe") killed after its first checkpoint and 3 times more while resuming: the same result"
    else
      echo "FAIL: $(basename "$exe"): the resumed run differs from the whole one"; fail=1
    fi
    # The comparison can fail: another run (OTHER_FLAGS) gives another controller.
    if ! "$exe" "${other[@]}" --out "$dir/other" >/dev/null 2>&1 || same "$dir/whole" "$dir/other"; then
      echo "FAIL: the comparison does not see another run"; fail=1
    fi
    # --resume takes the recorded options; others are refused, a missing folder is named.
    expect 1 "cannot be given with it" -- "$exe" --resume "$dir/cut" --check-seconds 3
    expect 1 "no run folder" -- "$exe" --resume "$dir/none"
    ;;
  continuation)
    exe=$1 dir=$2
    shift 2
    rm -rf "$dir"
    weights() {  # options.json's weight, the continuations' iterations, the controller's weight
      python3 -c 'import json, sys
o = json.load(open(sys.argv[1] + "/options.json"))
c = json.load(open(sys.argv[1] + "/wu2010_walk.controller.json"))
print(o["options"]["helper-weight"], [e["from_iteration"] for e in o.get("continuations", [])],
      c["helper_weight"])' "$dir"
    }
    if runs "$exe" "$@" --out "$dir" && runs "$exe" --resume "$dir" --helper-weight 0.05; then
      first=$(weights)
      "$exe" --resume "$dir" >/dev/null 2>&1
      second=$(weights)
      for got in "$first" "$second"; do
        if [[ "$got" =~ ^0\.05\ \[[1-9][0-9]*\]\ 0\.05$ ]]; then
          echo "ok: helper weight, continuation iteration, saved weight: $got"
        else
          echo "FAIL: after --resume --helper-weight 0.05 (and a plain --resume): $got"; fail=1
        fi
      done
    fi
    ;;
  h_max_cap)
    exe=$1 dir=$2 cap=$3
    shift 3
    rm -rf "$dir"
    if runs "$exe" "$@" --h-max-cap "$cap" --out "$dir"; then
      for f in wu2010_walk.controller.json wu2010_walk.mean.json; do
        h=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["h_max"])' "$dir/$f")
        if python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) <= float(sys.argv[2]) else 1)' \
          "$h" "$cap"; then
          echo "ok: $f: h_max $h <= $cap"
        else
          echo "FAIL: $f: h_max $h above --h-max-cap $cap"; fail=1
        fi
      done
    fi
    ;;
  revision)
    exe=$1 src=$2 dir=$3
    shift 3
    rm -rf "$dir"
    if ! command -v git >/dev/null || ! head=$(git -C "$src" rev-parse --short=12 HEAD 2>/dev/null); then
      echo "ok: no git or no repository at $src: nothing to compare"
    elif runs "$exe" "$@" --out "$dir"; then
      rev=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["build"]["git_revision"])' \
        "$dir/options.json")
      # -dirty: the tree had uncommitted changes when the program was built.
      if [[ "$rev" == "$head" || "$rev" == "$head-dirty" ]]; then
        echo "ok: options.json records revision $rev"
      else
        echo "FAIL: options.json records revision '$rev', the source tree is at $head"; fail=1
      fi
    fi
    ;;
  init_body)
    exe=$1 dir=$2 init=$3
    shift 3
    body() {  # a controller file's weakness and colliding legs
      python3 -c 'import json, sys
i = json.load(open(sys.argv[1]))["info"]
print(json.dumps(i.get("weaken", {}), sort_keys=True), i.get("leg_collisions", False))' "$1"
    }
    want=$(body "$init")
    rm -rf "$dir"
    listed() {  # the body options.json lists, in body's form
      python3 -c 'import json, sys
o = json.load(open(sys.argv[1]))["options"]
w = {k: float(v) for k, v in (e.split("=") for e in o["weaken"])}
print(json.dumps(w, sort_keys=True), o["leg-collisions"] == "on")' "$1"
    }
    if runs "$exe" --init "$init" "$@" --out "$dir/kept"; then
      got=$(body "$dir/kept/wang2012_walk.controller.json")
      if [[ "$got" == "$want" ]]; then
        echo "ok: --init keeps the body: $got"
      else
        echo "FAIL: --init $init: the saved body is '$got', the init's '$want'"; fail=1
      fi
      got=$(listed "$dir/kept/options.json")
      if [[ "$got" == "$want" ]]; then
        echo "ok: options.json lists the body: $got"
      else
        echo "FAIL: --init $init: options.json lists the body '$got', the init's '$want'"; fail=1
      fi
    fi
    if runs "$exe" --init "$init" "$@" --weaken HAM=1 --leg-collisions off --out "$dir/told"; then
      got=$(body "$dir/told/wang2012_walk.controller.json")
      if [[ "$got" == '{"HAM": 1.0} False' ]]; then
        echo "ok: --weaken and --leg-collisions override the init's body: $got"
      else
        echo "FAIL: --init $init --weaken HAM=1 --leg-collisions off: the saved body is '$got'"
        fail=1
      fi
      got=$(listed "$dir/told/options.json")
      if [[ "$got" != '{"HAM": 1.0} False' ]]; then
        echo "FAIL: --init $init --weaken HAM=1 --leg-collisions off: options.json lists '$got'"
        fail=1
      fi
    fi
    ;;
  init_settings)
    exe=$1 dir=$2 init=$3
    shift 3
    rm -rf "$dir"
    if runs "$exe" --init "$init" "$@" --out "$dir"; then
      cmp_out=$(python3 -c 'import json, sys
saved = json.load(open(sys.argv[1]))
listed = json.load(open(sys.argv[2]))["options"]
pairs = [("controller-rate", "controller_rate"), ("stance-target", "stance_target"),
         ("pin-by", "pin_by"), ("half-cycle", "half_cycle_timing"),
         ("terrain-blind", "terrain_blind")]
for flag, key in pairs:
    got, want = listed[flag], saved[key]
    same = float(got) == float(want) if flag == "controller-rate" else got == want
    print(("ok" if same else "FAIL") + ": options.json --%s %s, %s has %s" % (flag, got, sys.argv[1], want))' \
        "$init" "$dir/options.json")
      echo "$cmp_out"
      grep -q FAIL <<<"$cmp_out" && fail=1
    fi
    ;;
  saved_ground)
    exe=$1 dir=$2
    ground() {  # ground WANT FLAGS...: the push test's ground line for FLAGS is WANT
      local want=$1 out
      shift
      out=$("$exe" "$@" 2>&1 | head -1)
      if [[ "$out" == "$want" ]]; then
        echo "ok: $* -> $out"
      else
        echo "FAIL: $(basename "$exe") $* -> '$out' (want '$want')"; fail=1
      fi
    }
    # One 5 N step: the ground line comes first whatever the walker survives.
    f=(--resolution 5 --max-force 5)
    ground "ground: slope 0 deg, mu 0.3" --controller "$dir/stocky_mu03.controller.json" "${f[@]}"
    ground "ground: slope 12 deg, mu 10" --controller "$dir/stocky_slope12.controller.json" "${f[@]}"
    ground "ground: slope 3 deg, mu 0.8" --controller "$dir/stocky_slope12.controller.json" \
      --slope 3 --mu 0.8 "${f[@]}"
    ground "ground: slope 0 deg, mu 10" "${f[@]}"  # SIMBICON
    ;;
  push_starts_threads)
    exe=$1 dir=$2 walker=$3
    # The same pushed walks on 1 and 2 threads: every (direction, start) walk is its own task.
    for t in 1 2; do
      rm -rf "$dir/threads$t"
      runs "$exe" --replay "$walker" --check-seconds 1 --check-pushes 100 --check-push-starts 2 \
        --threads $t --out "$dir/threads$t" || exit 1
    done
    out=$(python3 -c 'import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
keys = ("pushes", "pushes_survived", "push_directions_from_starts", "push_starts_walked")
if any(a.get(k) != b.get(k) for k in keys):
    print("FAIL: --check-push-starts differs between 1 and 2 threads:", [(a.get(k), b.get(k)) for k in keys[1:]])
elif len(a["pushes"]) != 8 or any(len(p["perturbed_start_times"]) != 2 for p in a["pushes"]):
    print("FAIL: want 8 directions with 2 perturbed starts each, got", a["pushes"])
else:
    print("ok: --check-push-starts 2 on 1 and 2 threads:", a["push_starts_walked"], "of 16 walks")' \
      "$dir/threads1/summary.json" "$dir/threads2/summary.json" 2>&1)
    echo "$out"
    grep -q "^ok:" <<<"$out" || fail=1
    ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
exit $fail
