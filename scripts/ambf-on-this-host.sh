#!/usr/bin/env bash
# Holds AMBF's scenes to 1.5x AMBF's rate on THIS host. There is no AMBF build here: issue 50
# gives AMBF's rate as a ratio to this project at commit a514963, measured on an Intel Xeon.
# This script builds a514963's bench in a git worktree and names it in
# BUILD_DIR/ambf_baseline.json; from then on raven_bench's AMBF section runs that old section
# beside its own in every repetition (both on one CPU) and takes AMBF's rate here as the old
# rate over issue 50's ratio. Then it runs that section (3 repetitions) and prints its rows.
# Takes about 25 minutes on 2 cores, most of it the old build. Usage:
#   scripts/ambf-on-this-host.sh [OLD_WORKTREE]   (default /tmp/raven-issue50-baseline)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
old="${1:-/tmp/raven-issue50-baseline}"
[ -d "$old" ] || git -C "$root" worktree add --detach "$old" a514963 >/dev/null
# The bench reads ../shared/data next to its sources.
[ -e "$old/../shared" ] || ln -s "$root/../shared" "$old/../shared"
cmake -S "$old" -B "$old/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$old/build" -j2 --target raven_bench >/dev/null
"$root/scripts/build.sh" >/dev/null
printf '{"bench": "%s"}\n' "$(realpath "$old/build/bench/raven_bench")" > "$build/ambf_baseline.json"
"$build/bench/raven_bench" --only ambf --repeat 3 --out "$build/ambf_on_this_host.json" 2>/dev/null
