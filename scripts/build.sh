#!/usr/bin/env bash
# Configures and builds the project (Release, warnings as errors) into build/. Extra arguments
# are passed to CMake's configure step. RAVEN_TARGET builds one target (and what it needs)
# instead of everything: the quick start builds the main job alone first. RAVEN_UNITY (ON by
# default) compiles each target's files as a few large ones, CMake's unity build: a clean build
# of everything takes half the time on 2 cores (the headers are read once per eight files);
# RAVEN_UNITY=OFF compiles file by file, for quicker rebuilds after a one-file change. Each file
# still compiles on its own in the suite: the sanitizer build (the engine) and the robot-side
# build (the interface, controller, recordings, analysis) are not unity builds.
# RAVEN_MAIN_JOB_ONLY=ON configures without the tests, the bench and the Python module (and so
# without GoogleTest, Google Benchmark and pybind11): the quick start's packages.
# A new build tree uses Ninja when it is installed (it keeps both cores busy across targets).
set -euo pipefail
cd "$(dirname "$0")/.."
generator=()
if [ ! -f build/CMakeCache.txt ] && command -v ninja > /dev/null; then generator=(-G Ninja); fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DRAVEN_WERROR=ON \
  -DCMAKE_UNITY_BUILD="${RAVEN_UNITY:-ON}" -DRAVEN_MAIN_JOB_ONLY="${RAVEN_MAIN_JOB_ONLY:-OFF}" "$@" \
  > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"${RAVEN_JOBS:-2}" ${RAVEN_TARGET:+--target "$RAVEN_TARGET"}
