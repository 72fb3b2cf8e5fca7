#!/usr/bin/env bash
# Configures and builds the project (Release, warnings as errors) into build/. Extra arguments
# are passed to CMake's configure step. RAVEN_TARGET builds one target (and what it needs)
# instead of everything: the quick start builds the main job alone first.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRAVEN_WERROR=ON "$@" > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"${RAVEN_JOBS:-2}" ${RAVEN_TARGET:+--target "$RAVEN_TARGET"}
