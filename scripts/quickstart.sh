#!/usr/bin/env bash
# One command on a fresh Debian 12 machine: install dependencies, build, run the main job.
# Arguments are passed to the main job (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
exec ./build/ambf_like/ambf_like "$@"
