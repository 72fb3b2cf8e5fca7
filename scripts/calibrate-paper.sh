#!/usr/bin/env bash
# Fits the twin's tracking response to the paper's three physical replays of 2arm_ci.csv with
# raven_calibrate (leave-one-out included) and writes the profile to $1 (default
# build/calibration_paper_2arm.yaml; the shipped one is twin/config/calibration_paper_2arm.yaml).
#   scripts/calibrate-paper.sh [OUT.yaml] [raven_calibrate flags, e.g. --stand-in]
# Needs a build (scripts/build.sh) and ../shared/data.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
data="${RAVEN_SHARED_DATA_DIR:-$root/../shared/data}/recordings/paper_2arm"
[ -f "$data/2arm_ci.csv" ] || { echo "calibrate-paper: $data/2arm_ci.csv not found" >&2; exit 1; }
out="${1:-$build/calibration_paper_2arm.yaml}"
[ $# -gt 0 ] && shift
# --paper-deadzone: the released controller's deadzone test, which its recordings show.
"$build/calibration/raven_calibrate" --ci "$data/2arm_ci.csv" "$data" --paper-deadzone \
  --out "$out" "$@"
