#!/usr/bin/env bash
# Soak test: the twin node in lock-step driven at 1 kHz by raven_controller over a private
# rosmaster (O5, recorded), then a nominal peg-transfer batch (500 runs per simulated hour of
# the session), each watched for RSS and step-time growth from its first tenth to its last; ends
# with one line "rss growth X %, step time growth Y %" and fails when either is 5 % or more or the
# session's recording is not whole. About ten minutes by default (a 10-minute session, 83 runs).
#   scripts/soak.sh [--hours H | --minutes M] [--only session|batch] [--interval S] [--keep DIR]
#                    [--json FILE] [--run-seconds S (each batch run's simulated seconds; default
#                    30, 0 for whole runs)]
# Needs a build (scripts/build.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
for program in twin/ros/raven_twin_node controller/raven_controller scenario/raven_peg_transfer; do
  [ -x "$build/$program" ] || { echo "soak: $build/$program not built; run scripts/build.sh" >&2; exit 1; }
done
export PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}"
exec /usr/bin/python3 "$root/scripts/soak.py" --build "$build" "$@"
