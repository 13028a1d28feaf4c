#!/bin/bash
# The stride continuation (ours): from the push-off walker, for each step-length target S,
# ITERATIONS iterations with E_user weighted W_USER (E_ratio and E_posture 10, as before) and
# c_trans kept >= 0.026 m so that the push-off stays in late stance; it stops at the first stage
# whose 100 s check falls.
#   chain_stride.sh START SEED ITERATIONS ROBUST_STARTS W_USER S...
cd "$(dirname "$0")/../../../.."
prev=$1 seed=$2 iterations=$3 robust=$4 w_user=$5
shift 5
for s in "$@"; do
  d=out/stride_w${w_user}_$s
  mkdir -p "$d"
  build/release/examples/wang2009_walk --init "$prev" --weight E_ratio=10 --weight E_posture=10 \
    --weight "E_user=$w_user" --step-length "$s" --bound "c_trans=0.026:0.3" \
    --robust-starts "$robust" --sigma 0.005 --iterations "$iterations" --seed "$seed" --threads 2 \
    --out "$d" > "$d/log.txt" 2>&1
  tail -1 "$d/log.txt" | grep -q '"fell":false' || { echo "stage $s fell"; break; }
  prev=$d/wang2009_stocky.controller.json
  seed=$((seed + 1))
done
