#!/usr/bin/env bash
# The whole test suite: install dependencies, build, run every test, then rebuild the model
# loader tests with Clang, AddressSanitizer and UndefinedBehaviorSanitizer and run them again,
# and run every fuzz target for a bounded time (RAVEN_FUZZ_SECONDS, 30 each) and its saved
# regression inputs.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j"${RAVEN_JOBS:-2}"

CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRAVEN_SANITIZE=ON -DRAVEN_FUZZ=ON -DRAVEN_WERROR=ON -DRAVEN_BUILD_BENCH=OFF \
  > build-sanitize.log 2>&1 || { cat build-sanitize.log; exit 1; }
cmake --build build-sanitize -j"${RAVEN_JOBS:-2}" --target ambf_like_loader_tests fuzz_targets
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -L loader -j"${RAVEN_JOBS:-2}"
./scripts/fuzz.sh build-sanitize "${RAVEN_FUZZ_SECONDS:-30}"
