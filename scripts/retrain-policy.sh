#!/usr/bin/env bash
# Retrains the shipped state policy (python/policies/bc_state.pt) from scratch, as measured in
# docs/learning.md: the expert's demonstrations (30 clean, 30 with DART noise, on two processes),
# behaviour cloning, then the policy on 20 randomised scenes it never saw. Usage:
#   scripts/retrain-policy.sh [BUILD_DIR] [WORK_DIR]
set -euo pipefail
build=$(realpath "${1:-build}")
work=${2:-/tmp/raven-policy}
mkdir -p "$work"
cd "$work"
export PYTHONPATH="$build/python"
learn() { /usr/bin/python3 -m raven_sim.learn "$@"; }
# The shipped policies are trained and measured on ideal servos: on the motor twin (the twin's
# default) the cloned policy does not yet work (docs/learning.md). ACTUATION=motors tries it there.
twin=(--actuation "${ACTUATION:-ideal}")
start=$(date +%s)
learn record "${twin[@]}" --episodes 30 --seeds 1000-1029 --out clean.hdf5 > clean.log 2>&1 &
learn record "${twin[@]}" --episodes 30 --seeds 2000-2029 --noise 0.3 --out dart.hdf5 > dart.log 2>&1 &
wait
recorded=$(date +%s)
tail -n 1 clean.log dart.log
learn train --demos clean.hdf5 dart.hdf5 --out bc_state.pt | tail -n 1
trained=$(date +%s)
echo "recorded in $((recorded - start)) s, trained in $((trained - recorded)) s: $work/bc_state.pt"
learn evaluate "${twin[@]}" --policy bc_state.pt --seeds 1-20 --workers 2 2>/dev/null | tee evaluate.log | tail -n 1
