#!/usr/bin/env bash
# Reproduces every optimized controller of docs/reproductions/sharon2005.md from scratch (Sharon &
# van de Panne 2005), then replays each saved result for 70 s and draws its filmstrip.
#
#   bash scripts/reproduce_sharon2005.sh            # outputs in out/sharon2005/
#   bash scripts/reproduce_sharon2005.sh --install  # also copies the controllers to data/sharon2005/
#
# The optimizations are deterministic (SDS draws no random numbers; results do not depend on the
# thread count), so on the same build they give the same controllers. Wall times depend on the
# machine; docs/reproductions/sharon2005.md lists the evaluation counts and times we measured.
set -euo pipefail
cd "$(dirname "$0")/.."
install=0
[[ "${1:-}" == "--install" ]] && install=1
bash scripts/install_deps.sh
cmake -S . -B build/main -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DGAITSYNTH_BUILD_TESTS=OFF -DGAITSYNTH_BUILD_BENCHMARKS=OFF >/dev/null
examples=(sharon2005_normal_walk sharon2005_human16 sharon2005_high_knee sharon2005_backswing
          sharon2005_uphill sharon2005_replay sharon2005_keyframes)
cmake --build build/main -j"$(nproc)" --target "${examples[@]}"
bin=build/main/examples
out=out/sharon2005
mkdir -p "$out"
log() { echo "== $*" >&2; }

# Fig. 5a/b, stages 1-2: the main job (stage 1: flat ground, 4 start states, episodes 0.2 .. 2 s;
# stage 2: also 4 bumpy training profiles, episodes 2 .. 5 s).
nw() { "$bin"/sharon2005_normal_walk --out "$out/normal_walk_$1" "${@:2}" | tee "$out/normal_walk_$1.json"; }
prev() { echo "$out/normal_walk_$1/sharon2005_normal_walk.controller.json"; }
log "normal walk, stages 1-2 (the main job)"
nw 2
# Stages 3-6: the same controller also evaluated blindly on more bumpy training terrains (seeds
# 1..n, never a test terrain's) and then also on 12 training bodies around the Figure 8 changes,
# over longer episodes (section VII's "disturbances during the controller evaluation"), each stage
# starting from the previous result. The body stages compare shapes only (--align-style): over
# 10 s a small speed difference from the keyframes would otherwise dominate eq. 2 and make falling
# cheaper than walking on unusual bodies.
log "normal walk, stages 3-6 (robustness)"
nw 3 --initial-controller "$(prev 2)" --bumpy-training 8 --horizons 2,4,6,8 --evaluations-per-episode 200
nw 4 --initial-controller "$(prev 3)" --bumpy-training 12 --horizons 20 --evaluations-per-episode 200
nw 5 --initial-controller "$(prev 4)" --align-style --bumpy-training 12 --body-training 12 \
  --horizons 10 --evaluations-per-episode 250
nw 6 --initial-controller "$(prev 5)" --align-style --bumpy-training 12 --body-training 12 \
  --horizons 10 --evaluations-per-episode 250

# Fig. 5c/d: the example's run, then two stages over longer episodes, then five with noisy starts.
log "16-link human (Fig. 5c/d)"
h16() { "$bin"/sharon2005_human16 --out "$out/human16_$1" "${@:2}" | tee "$out/human16_$1.json"; }
h16 1
h16 2 --initial-controller "$out/human16_1/sharon2005_human16.controller.json" --horizons 1,1.5,2 \
  --evaluations-per-episode 400
h16 3 --initial-controller "$out/human16_2/sharon2005_human16.controller.json" --horizons 3,4,5 \
  --evaluations-per-episode 300
# Robustness (issue 15): more starts whose joint velocities are perturbed by N(0, 0.05 rad/s),
# over longer episodes, so the walk does not rest on one start and one rounding.
h16 4 --initial-controller "$out/human16_3/sharon2005_human16.controller.json" --horizons 2,3,5 \
  --noisy-starts 8
h16 5 --initial-controller "$out/human16_4/sharon2005_human16.controller.json" --horizons 3,5,10 \
  --noisy-starts 16
h16 6 --initial-controller "$out/human16_5/sharon2005_human16.controller.json" --horizons 2,3,5 \
  --noisy-starts 24
h16 7 --initial-controller "$out/human16_6/sharon2005_human16.controller.json" --horizons 3,5,10 \
  --noisy-starts 24
h16 8 --initial-controller "$out/human16_7/sharon2005_human16.controller.json" --horizons 5,10 \
  --noisy-starts 24
log "high knee (Fig. 6a/b)"
"$bin"/sharon2005_high_knee --out "$out/high_knee" | tee "$out/high_knee.json"
log "back swing (Fig. 6c/d)"
"$bin"/sharon2005_backswing --out "$out/backswing" | tee "$out/backswing.json"
# Robustness (issue 15): four stages with the training disturbances in the cost (slopes, low
# friction, pushes, torso masses), shapes only, a walk slower than 0.5 m/s charged like a fall.
bs() {
  "$bin"/sharon2005_backswing --out "$out/backswing_$1" --initial-controller "$2" \
    --disturbance-training --align-style --min-progress-speed 0.5 "${@:3}" |
    tee "$out/backswing_$1.json"
}
bsc() { echo "$out/backswing_$1/sharon2005_backswing.controller.json"; }
bs d1 "$out/backswing/sharon2005_backswing.controller.json" --horizons 5,10,20 \
  --evaluations-per-episode 300
bs d2 "$(bsc d1)" --horizons 3,5,10,20 --evaluations-per-episode 500
bs d3 "$(bsc d2)" --horizons 2,3,5,10 --evaluations-per-episode 700
bs d4 "$(bsc d3)" --horizons 3,5,10,20 --evaluations-per-episode 400
log "uphill (Fig. 7)"
"$bin"/sharon2005_uphill --out "$out/uphill" | tee "$out/uphill.json"

if (( install )); then
  cp "$(prev 6)" data/sharon2005/normal_walk.controller.json
  cp "$out/human16_8/sharon2005_human16.controller.json" data/sharon2005/human16_walk.controller.json
  cp "$out/high_knee/sharon2005_high_knee.controller.json" data/sharon2005/high_knee.controller.json
  cp "$(bsc d4)" data/sharon2005/backswing.controller.json
  cp "$out/uphill/sharon2005_uphill.controller.json" data/sharon2005/uphill.controller.json
fi

# Replays of the saved controllers (data/sharon2005/) with filmstrips and players.
for r in normal_walk human16 high_knee backswing uphill torso_28kg shin_0.25_thigh_0.6 shin_0.8 bumpy; do
  log "replay $r"
  from=0
  [[ "$r" == bumpy ]] && from=10  # the bumps start after the first metre
  "$bin"/sharon2005_replay --result "$r" --out "$out/replay" --filmstrip-from "$from" \
    --filmstrip "$out/replay/walk_$r.svg" --html "$out/replay/$r.html" | tee -a "$out/replays.jsonl"
done
"$bin"/sharon2005_keyframes --out "$out/keyframes" >/dev/null
log "done: $out"
