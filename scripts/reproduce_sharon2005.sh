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

# Fig. 5a/b, stage 1: the main job (flat ground, 4 start states, episodes 0.2 .. 2 s).
log "normal walk, stage 1 (the main job)"
"$bin"/sharon2005_normal_walk --out "$out/normal_walk_1" | tee "$out/normal_walk_1.json"
# Stages 2-4: the same controller also evaluated blindly on 4, then 8 bumpy training terrains
# (seeds 1..8, never the test terrain's), over longer episodes (section VII's "disturbances during
# the controller evaluation"), each stage starting from the previous result.
log "normal walk, stage 2 (bumpy training, 4 terrains, episodes 2..5 s)"
"$bin"/sharon2005_normal_walk --out "$out/normal_walk_2" \
  --initial-controller "$out/normal_walk_1/sharon2005_normal_walk.controller.json" \
  --bumpy-training 4 --horizons 2,3,4,5 --evaluations-per-episode 300 | tee "$out/normal_walk_2.json"
log "normal walk, stage 3 (8 terrains, episodes 2..8 s)"
"$bin"/sharon2005_normal_walk --out "$out/normal_walk_3" \
  --initial-controller "$out/normal_walk_2/sharon2005_normal_walk.controller.json" \
  --bumpy-training 8 --horizons 2,4,6,8 --evaluations-per-episode 200 | tee "$out/normal_walk_3.json"
log "normal walk, stage 4 (8 terrains, episodes 10, 15 s)"
"$bin"/sharon2005_normal_walk --out "$out/normal_walk_4" \
  --initial-controller "$out/normal_walk_3/sharon2005_normal_walk.controller.json" \
  --bumpy-training 8 --horizons 10,15 --evaluations-per-episode 200 | tee "$out/normal_walk_4.json"

log "16-link human (Fig. 5c/d)"
"$bin"/sharon2005_human16 --out "$out/human16" | tee "$out/human16.json"
log "high knee (Fig. 6a/b)"
"$bin"/sharon2005_high_knee --out "$out/high_knee" | tee "$out/high_knee.json"
log "back swing (Fig. 6c/d)"
"$bin"/sharon2005_backswing --out "$out/backswing" | tee "$out/backswing.json"
log "uphill (Fig. 7)"
"$bin"/sharon2005_uphill --out "$out/uphill" | tee "$out/uphill.json"

if (( install )); then
  cp "$out/normal_walk_4/sharon2005_normal_walk.controller.json" data/sharon2005/normal_walk.controller.json
  cp "$out/human16/sharon2005_human16.controller.json" data/sharon2005/human16_walk.controller.json
  cp "$out/high_knee/sharon2005_high_knee.controller.json" data/sharon2005/high_knee.controller.json
  cp "$out/backswing/sharon2005_backswing.controller.json" data/sharon2005/backswing.controller.json
  cp "$out/uphill/sharon2005_uphill.controller.json" data/sharon2005/uphill.controller.json
fi

# Replays of the saved controllers (data/sharon2005/) with filmstrips and players.
for r in normal_walk human16 high_knee backswing uphill torso_28kg shin_0.25_thigh_0.6 shin_0.8 bumpy; do
  log "replay $r"
  "$bin"/sharon2005_replay --result "$r" --out "$out/replay" \
    --filmstrip "$out/replay/$r.svg" --html "$out/replay/$r.html" | tee -a "$out/replays.jsonl"
done
"$bin"/sharon2005_keyframes --out "$out/keyframes" >/dev/null
log "done: $out"
