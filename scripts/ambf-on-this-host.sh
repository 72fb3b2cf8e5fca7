#!/usr/bin/env bash
# AMBF's rate on AMBF's scenes on THIS host, for a host other than the one issue 50 measured on
# (the bench's AMBF bounds are that host's figures). There is no AMBF build here; issue 50 gives
# AMBF's rate as a ratio to this project at commit a514963. This script builds that commit's bench
# in a git worktree, runs its AMBF section and the current one alternately (3 runs each, 1 at a
# time) and prints, per scene, AMBF's rate here (the old median / the issue's ratio) and the
# current median over it. It writes those rates, with this CPU's name, to
# BUILD_DIR/ambf_on_this_host.json, where raven_bench takes its AMBF bounds from on this CPU.
# Takes about 25 minutes on 2 cores, most of it the old build. Usage:
#   scripts/ambf-on-this-host.sh [OLD_WORKTREE]   (default /tmp/raven-issue50-baseline)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
old="${1:-/tmp/raven-issue50-baseline}"
baseline=a514963
[ -d "$old" ] || git -C "$root" worktree add --detach "$old" "$baseline" >/dev/null
# The bench reads ../shared/data next to its sources.
[ -e "$old/../shared" ] || ln -s "$root/../shared" "$old/../shared"
cmake -S "$old" -B "$old/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$old/build" -j2 --target raven_bench >/dev/null
"$root/scripts/build.sh" >/dev/null
out=$(mktemp -d)
for i in 1 2 3; do
  for side in old new; do
    bench="$old/build/bench/raven_bench"
    [ "$side" = new ] && bench="${BUILD_DIR:-$root/build}/bench/raven_bench"
    "$bench" --only ambf --repeat 1 --out "$out/$side-$i.json" >/dev/null 2>&1
  done
done
/usr/bin/python3 - "$out" "${BUILD_DIR:-$root/build}/ambf_on_this_host.json" <<'PY'
import json, statistics, sys
out, written = sys.argv[1:]
# Issue 50's ratios ours/AMBF at the baseline (medians of 3 alternating runs, no soft-body sleep),
# by the start of each scene's row and its id in raven_bench.
ratios = {"raven_world + blender-raven2": 1.05, "puzzles/peg_and_base": 1.02,
          "puzzles/puzzle2": 1.07, "sb/cloth (386-node": 1.51, "the Raven with the cloth": 1.49}
ids = dict(zip(ratios, ("raven", "peg_and_base", "puzzle2", "cloth", "raven_with_cloth")))
def medians(side):
    runs = [json.load(open(f"{out}/{side}-{i}.json"))["rows"] for i in (1, 2, 3)]
    found = {}
    for key in ratios:
        # The scene's first row: AMBF's way, before any variant of it.
        values = [next(r["median"] for r in rows if key in r["item"] and "median" in r) for rows in runs]
        found[key] = statistics.median(values)
    return found
old, new = medians("old"), medians("new")
print("| scene | baseline here | AMBF here (baseline / issue ratio) | now | now / AMBF |")
print("|---|---|---|---|---|")
for key, ratio in ratios.items():
    ambf = old[key] / ratio
    print(f"| {key} | {old[key]:,.0f} | {ambf:,.0f} | {new[key]:,.0f} | {new[key] / ambf:.2f} |")
machine = json.load(open(f"{out}/new-1.json"))["machine"]
json.dump({"cpu": machine["cpu"], "date": machine["date"],
           "steps_per_second": {ids[key]: old[key] / ratios[key] for key in ratios}},
          open(written, "w"), indent=2)
print(f"wrote {written}")
PY
