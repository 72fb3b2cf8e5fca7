#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install dependencies, build the main job (and only
# what it needs: the tests, the bench and the Python module build with scripts/test.sh or
# scripts/build.sh), run it (the peg transfer on the twin, the rings held by friction alone; see
# the README). Arguments are passed to the main job (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
RAVEN_TARGET=raven_peg_transfer ./scripts/build.sh
exec ./build/scenario/raven_peg_transfer "$@"
