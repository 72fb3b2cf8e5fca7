#!/usr/bin/env bash
# Builds everything, runs raven_bench (every section, 3 repetitions) and rewrites the results
# with the date and the machine: every row in docs/benchmarks.md (bench:begin / bench:end
# markers), the rows with a target in README.md (bench-headline:begin / end). Takes about 85
# minutes on 2 cores, 70 of them the training section (both policies retrained from scratch).
# Extra flags go to raven_bench; with --only, the sections not run keep their earlier rows, under
# the line saying when and where those were measured.
#   scripts/bench.sh [--repeat N] [--only loop ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
"$root/scripts/build.sh" >/dev/null
# The viewer section needs a display: without one, run the whole benchmark inside Xvfb.
display=()
[ -n "${DISPLAY:-}" ] || ! command -v xvfb-run >/dev/null || display=(xvfb-run -a)
"${display[@]}" "$build/bench/raven_bench" --repeat 3 --out "$build/bench_results.json" \
  --markdown "$build/bench_results.md" "$@"
/usr/bin/python3 "$root/scripts/write-bench-pages.py" "$root" "$build/bench_results.json" \
  "$build/bench_results.md"
