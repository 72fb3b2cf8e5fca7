#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install what the main job needs, build the main job
# alone (a unity build, as scripts/build.sh makes by default; the tests, the bench and the Python
# module build with scripts/test.sh, which installs the rest), run it (the peg transfer on the
# twin, the rings held by friction alone; see the README). Arguments are passed to the main job
# (see --help). Timed from nothing in docs/install.md.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --main-job
RAVEN_MAIN_JOB_ONLY=ON RAVEN_TARGET=raven_peg_transfer ./scripts/build.sh
exec ./build/scenario/raven_peg_transfer "$@"
