#!/bin/bash
# The c_trans continuation (ours): for each lower bound LO, the start's c_trans is raised to at
# least LO and ITERATIONS iterations run with --bound c_trans=LO:0.3; it stops at the first
# stage whose 100 s check falls.
#   chain_ctrans.sh START SEED ITERATIONS ROBUST_STARTS LO...
# Stages 1-2 ran as:  chain_ctrans.sh out/up_step04/wang2009_stocky.controller.json 10 150 0 -0.05 -0.035
# Stage 2, again:     chain_ctrans.sh out/ctrans_-0.05/wang2009_stocky.controller.json 20 120 2 -0.035
# Stage 3:            chain_ctrans.sh out/ctrans2_-0.035/wang2009_stocky.controller.json 22 100 2 -0.02
# (out/up_step04/... is ../../walkers/stocky_upright_step04.controller.json.)
# Environment: HORIZON (s, default 10: the paper's) for longer evaluations, THREADS (default 2),
# WANG2009_WALK (default build/release/examples/wang2009_walk) for another build.
cd "$(dirname "$0")/../../../.."
exe=${WANG2009_WALK:-build/release/examples/wang2009_walk}
horizon=${HORIZON:-10}
prev=$1 seed=$2 iterations=$3 robust=$4
shift 4
for lo in "$@"; do
  d=out/ctrans_r${robust}${HORIZON:+_h$HORIZON}_$lo  # the folder names of the earlier stages
  mkdir -p "$d"
  python3 -c "
import json
d = json.load(open('$prev')); p = d['parameters']; p['c_trans'] = max(p['c_trans'], $lo)
json.dump(d, open('$d/init.json', 'w'), indent=1)"
  "$exe" --init "$d/init.json" --weight E_ratio=10 \
    --weight E_posture=10 --step-length 0.4 --bound "c_trans=$lo:0.3" --robust-starts "$robust" \
    --sigma 0.005 --iterations "$iterations" --seed "$seed" --horizon "$horizon" \
    --threads "${THREADS:-2}" --out "$d" > "$d/log.txt" 2>&1
  tail -1 "$d/log.txt" | grep -q '"fell":false' || { echo "stage $lo fell"; break; }
  prev=$d/wang2009_stocky.controller.json
  seed=$((seed + 1))
done
