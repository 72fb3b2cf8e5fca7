#!/usr/bin/env bash
# Fits the twin's motor-level actuation to the paper's three physical replays of 2arm_ci.csv
# with raven_calibrate fit (leave-one-out, then end-to-end replays of the inputs from each
# trial's start) and writes the profile to $1 (default build/raven2_calibration.yaml; the
# shipped one is twin/config/raven2_calibration.yaml).
#   scripts/calibrate-paper.sh [OUT.yaml] [raven_calibrate fit flags, e.g. --evaluations 20]
# Needs a build (scripts/build.sh) and ../shared/data.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
data="${RAVEN_SHARED_DATA_DIR:-$root/../shared/data}/recordings/paper_2arm"
[ -f "$data/2arm_ci.csv" ] || { echo "calibrate-paper: $data/2arm_ci.csv not found" >&2; exit 1; }
out="${1:-$build/raven2_calibration.yaml}"
[ $# -gt 0 ] && shift
# --paper-deadzone: the released controller's deadzone test, which its recordings show.
"$build/calibration/raven_calibrate" fit "$data" --ci "$data/2arm_ci.csv" --paper-deadzone \
  --out "$out" "$@"
