#!/usr/bin/env bash
# Draws every saved Wang et al. 2009 walker (data/wang2009/walkers/) and the SIMBICON baseline: for
# each, the HTML player of its first 10 s (orbit and follow camera, contact points, FSM state, the
# objective's terms), filmstrips from the side (first 3 s) and the front (one gait cycle at 4 s), and
# Fig. 6's gait-cycle plot over 100 s (with the hip and ankle angles and a person's joints); then an
# index page that links them all and a table of the standard scores against that person.
#
#   bash scripts/wang2009_views.sh [OUT]        # default OUT: out/wang2009_views
#   bash scripts/wang2009_views.sh OUT --docs   # also copies the SVGs to docs/reproductions/wang2009/
#
# Replays only (nothing is optimized): about 5 s per walker on one core. The players are 2 MB each,
# so the repository keeps the SVGs (docs/reproductions/wang2009.md) and this script makes the rest.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/wang2009_views}
docs=0
[[ "${2:-}" == "--docs" ]] && docs=1
bash scripts/install_deps.sh
cmake -S . -B build/main -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DGAITSYNTH_BUILD_TESTS=OFF -DGAITSYNTH_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/main -j"$(nproc)" --target wang2009_walk
bin=build/main/examples/wang2009_walk
mkdir -p "$out"

names=(simbicon)
for f in data/wang2009/walkers/*.controller.json; do
  names+=("$(basename "$f" .controller.json)")
done

for n in "${names[@]}"; do
  echo "== $n" >&2
  d="$out/$n"
  mkdir -p "$d"
  if [[ "$n" == simbicon ]]; then
    src=(--simbicon)
  else
    src=(--replay "data/wang2009/walkers/$n.controller.json")
  fi
  # 10 s for the player and the filmstrips; 100 s for Fig. 6's mean and spread.
  "$bin" "${src[@]}" --check-seconds 10 --out "$d/10s" --html "$d/$n.html" \
    --filmstrip "$d/${n}_filmstrip.svg" --filmstrip-front "$d/${n}_front.svg" >/dev/null
  "$bin" "${src[@]}" --check-seconds 100 --out "$d/100s" --gait-svg "$d/${n}_gait.svg" \
    > "$d/summary.json"
  if [[ $docs == 1 ]]; then
    cp "$d/${n}_filmstrip.svg" "$d/${n}_front.svg" "$d/${n}_gait.svg" docs/reproductions/wang2009/
  fi
done

{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"><title>Wang et al. 2009 walkers</title>'
  echo '<style>body{font-family:sans-serif;margin:2em}td{padding:0.2em 1em}</style></head><body>'
  echo '<h1>Wang, Fleet &amp; Hertzmann 2009: the saved walkers</h1><table>'
  echo '<tr><th>walker</th><th>player (10 s)</th><th>side</th><th>front</th><th>Fig. 6 (100 s)</th></tr>'
  for n in "${names[@]}"; do
    echo "<tr><td>$n</td><td><a href=\"$n/$n.html\">player</a></td>"
    echo "<td><a href=\"$n/${n}_filmstrip.svg\">filmstrip</a></td>"
    echo "<td><a href=\"$n/${n}_front.svg\">front</a></td>"
    echo "<td><a href=\"$n/${n}_gait.svg\">gait cycles</a></td></tr>"
  done
  echo '</table></body></html>'
} > "$out/index.html"
echo "wrote $out/index.html" >&2

# The standard scores against the adult of data/normative_gait/ (each walker's summary.json, 100 s
# after the first 2), with the mean differences in brackets, as a Markdown table
# (docs/reproductions/wang2009.md, "Against a person").
if command -v python3 >/dev/null; then
  python3 - "$out" "${names[@]}" > "$out/human_scores.md" <<'PY'
import json, sys
out, names = sys.argv[1], sys.argv[2:]
keys = ["hip_flexion_angle", "knee_flexion_angle", "ankle_dorsiflexion_angle",
        "hip_flexion_moment_per_kg", "knee_flexion_moment_per_kg",
        "ankle_dorsiflexion_moment_per_kg"]
print("| walker | hip | knee | ankle | hip moment | knee moment | ankle moment | pelvis, torso pitch (deg) | speed (m/s) |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for n in names:
    d = json.load(open(f"{out}/{n}/summary.json"))
    s, m = d.get("standard_scores"), d.get("human_mean_differences")
    if not s:
        print(f"| `{n}` | no complete cycle | | | | | | | |")
        continue
    cells = [f"{s[k]:.1f} ({m[k]:+.1f})" if k.endswith("angle") else f"{s[k]:.0f} ({m[k]:+.2f})"
             for k in keys]
    pitch = f"{d['pelvis_pitch_deg']:.1f}, {d['torso_pitch_deg']:.1f}"
    print(f"| `{n}` | " + " | ".join(cells) + f" | {pitch} | {d['speed']:.2f} |")
PY
  echo "wrote $out/human_scores.md" >&2
fi
