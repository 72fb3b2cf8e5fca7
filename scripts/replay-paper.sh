#!/usr/bin/env bash
# Replays the paper's recorded gamepad inputs (2arm_ci.csv) with O3 on the twin, in lock-step,
# records the twin, and writes the disparity report of the twin, AMBF and the physical robot
# (raven_analyze: ../shared/reference/recordings.md's figures per joint, correlating factors and
# figures) to $OUT_DIR/report (default build/replay/report).
#   scripts/replay-paper.sh [raven_controller flags, e.g. --actuation ideal, --start-from
#     ../shared/data/recordings/paper_2arm/2arm_physical_1.csv, or
#     --calibration twin/config/raven2_calibration.yaml (the recording controller's timing too)]
# Needs a build (scripts/build.sh) and ../shared/data.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
data="${RAVEN_SHARED_DATA_DIR:-$root/../shared/data}/recordings/paper_2arm"
[ -f "$data/2arm_ci.csv" ] || { echo "replay-paper: $data/2arm_ci.csv not found" >&2; exit 1; }
out="${OUT_DIR:-$build/replay}"
# --paper-deadzone: the released controller's deadzone test, which its recordings show
# (docs/controller.md: "Replaying the paper's recordings").
"$build/controller/raven_controller" --lock-step --paper-deadzone --replay-ci "$data/2arm_ci.csv" \
  --record yes --name twin_2arm --out "$out" "$@"
latest="$(ls -t "$out"/twin_2arm_*_rs.csv | head -1)"
"$build/analysis/raven_analyze" "$data" "$latest" --out "$out/report"
