#!/usr/bin/env bash
# Retrains the shipped state policy (python/policies/bc_state.pt) from scratch, as measured in
# docs/learning.md: expert demonstrations (clean and with DART noise, on two processes), behaviour
# cloning, then DAgger rounds (the policy drives, the expert labels). Usage:
#   scripts/retrain-policy.sh [BUILD_DIR] [WORK_DIR] [ROUNDS]
set -euo pipefail
build=$(realpath "${1:-build}")
work=${2:-/tmp/raven-policy}
rounds=${3:-2}
mkdir -p "$work"
cd "$work"
export PYTHONPATH="$build/python"
learn() { /usr/bin/python3 -m raven_sim.learn "$@"; }
start=$(date +%s)
learn record --episodes 30 --seeds 1000-1029 --out clean.hdf5 > clean.log 2>&1 &
learn record --episodes 30 --seeds 2000-2029 --noise 0.3 --out dart.hdf5 > dart.log 2>&1 &
wait
tail -n 1 clean.log dart.log
demos=(clean.hdf5 dart.hdf5)
learn train --demos "${demos[@]}" --out policy_0.pt --epochs 40 | tail -n 1
for round in $(seq 1 "$rounds"); do
  first=$((3000 + 100 * round))
  learn dagger --policy "policy_$((round - 1)).pt" --episodes 8 --seeds "$first-$((first + 7))" \
    --collect "dagger_${round}a.hdf5" > "dagger_${round}a.log" 2>&1 &
  learn dagger --policy "policy_$((round - 1)).pt" --episodes 8 \
    --seeds "$((first + 50))-$((first + 57))" --noise-seed 1 \
    --collect "dagger_${round}b.hdf5" > "dagger_${round}b.log" 2>&1 &
  wait
  tail -n 1 "dagger_${round}a.log" "dagger_${round}b.log"
  demos+=("dagger_${round}a.hdf5" "dagger_${round}b.hdf5")
  learn train --demos "${demos[@]}" --out "policy_${round}.pt" --epochs 40 | tail -n 1
done
cp "policy_${rounds}.pt" bc_state.pt
echo "retrained in $(($(date +%s) - start)) s: $work/bc_state.pt"
