#!/bin/bash
# c_trans continuation with 2 perturbed starts in every candidate's cost (ours).
cd /work/main
prev=out/ctrans_-0.05/wang2009_stocky.controller.json
seed=20
for lb in -0.035 -0.02 -0.005 0.01; do
  d=out/ctrans2_$lb
  mkdir -p $d
  python3 -c "
import json,sys
d=json.load(open('$prev')); p=d['parameters']; p['c_trans']=max(p['c_trans'], $lb)
json.dump(d, open('$d/init.json','w'), indent=1)"
  build/release/examples/wang2009_walk --init $d/init.json --weight E_ratio=10 --weight E_posture=10 \
    --step-length 0.4 --bound c_trans=$lb:0.3 --robust-starts 2 --sigma 0.005 --iterations 120 \
    --seed $seed --threads 2 --out $d > $d/log.txt 2>&1
  seed=$((seed+1))
  if ! tail -1 $d/log.txt | grep -q '"fell":false'; then echo "stage $lb fell" > $d/FELL; break; fi
  prev=$d/wang2009_stocky.controller.json
done
touch out/ctrans2_done
