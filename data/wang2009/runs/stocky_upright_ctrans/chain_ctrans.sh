#!/bin/bash
# c_trans continuation: raise the lower bound of c_trans stage by stage (ours), so that the
# COM must pass further over the stance ankle before the push-off state begins.
cd /work/main
prev=out/up_step04/wang2009_stocky.controller.json
seed=10
for lb in -0.05 -0.035 -0.02 -0.005 0.01 0.025; do
  d=out/ctrans_$lb
  mkdir -p $d
  python3 -c "
import json,sys
d=json.load(open('$prev')); p=d['parameters']; p['c_trans']=max(p['c_trans'], $lb)
json.dump(d, open('$d/init.json','w'), indent=1)"
  build/release/examples/wang2009_walk --init $d/init.json --weight E_ratio=10 --weight E_posture=10 \
    --step-length 0.4 --bound c_trans=$lb:0.3 --sigma 0.005 --iterations 150 --seed $seed --threads 2 \
    --out $d > $d/log.txt 2>&1
  seed=$((seed+1))
  if ! tail -1 $d/log.txt | grep -q '"fell":false'; then echo "stage $lb fell" > $d/FELL; break; fi
  prev=$d/wang2009_stocky.controller.json
done
touch out/ctrans_done
