#!/usr/bin/env bash
# Retrains the shipped image policy (python/policies/bc_rgb.pt), as measured in docs/learning.md:
# the expert's demonstrations with both task cameras (40 clean, 20 with DART noise, on two
# processes), the ring locator trained on their images, joined to the state policy, then the
# policy on 20 randomised scenes it never saw. Usage:
#   scripts/retrain-image-policy.sh [BUILD_DIR] [WORK_DIR] [STATE_POLICY]
set -euo pipefail
build=$(realpath "${1:-build}")
work=${2:-/tmp/raven-image-policy}
state_policy=$(realpath "${3:-$(dirname "$0")/../python/policies/bc_state.pt}")
mkdir -p "$work"
cd "$work"
export PYTHONPATH="$build/python"
learn() { /usr/bin/python3 -m raven_sim.learn "$@"; }
# The shipped policies are trained and measured on ideal servos: on the motor twin (the twin's
# default) the cloned policy does not yet work (docs/learning.md). ACTUATION=motors tries it there.
twin=(--actuation "${ACTUATION:-ideal}")
cameras=(--obs state,rgb --camera left-task,right-task --image-size 128x96)
start=$(date +%s)
(learn record "${twin[@]}" --episodes 20 --seeds 3000-3019 "${cameras[@]}" --out clean.hdf5 &&
  learn record "${twin[@]}" --episodes 20 --seeds 3020-3039 "${cameras[@]}" --out clean2.hdf5) > clean.log 2>&1 &
learn record "${twin[@]}" --episodes 20 --seeds 4000-4019 --noise 0.3 "${cameras[@]}" --out dart.hdf5 > dart.log 2>&1 &
wait
recorded=$(date +%s)
tail -n 1 clean.log dart.log
learn train --obs rgb --demos clean.hdf5 clean2.hdf5 dart.hdf5 --state-policy "$state_policy" \
  --epochs 16 --batch 128 --lr 1e-3 --out bc_rgb.pt | tail -n 1
trained=$(date +%s)
echo "recorded in $((recorded - start)) s, trained in $((trained - recorded)) s: $work/bc_rgb.pt"
learn evaluate "${twin[@]}" --policy bc_rgb.pt --seeds 1-20 --workers 2 2>/dev/null | tee evaluate.log | tail -n 1
