#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install dependencies, build, run the main job (the
# peg transfer on the twin, the rings held by friction alone; see the README).
# Arguments are passed to the main job (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
exec ./build/scenario/raven_peg_transfer "$@"
