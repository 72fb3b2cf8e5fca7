#!/usr/bin/env bash
# AMBF's rate on AMBF's scenes on THIS host, for a host other than the one issue 50 measured on
# (the bench's AMBF bounds are that host's figures). There is no AMBF build here; issue 50 gives
# AMBF's rate as a ratio to this project at commit a514963. This script builds that commit's bench
# in a git worktree, runs its AMBF section and the current one alternately (3 runs each, 1 at a
# time) and prints, per scene, AMBF's rate here (the old median / the issue's ratio) and the
# current median over it. It writes those rates, this CPU's name and the old bench's path to
# BUILD_DIR/ambf_on_this_host.json. On this CPU raven_bench then runs the old bench's AMBF section
# beside its own in every repetition and holds each row to 1.5x AMBF's rate taken so (the host's
# speed drifts by a quarter within an hour here); without the old bench, to the rates written.
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
# Both on one CPU: this host's two run the same steps some 25 % apart.
cpu=$(taskset -cp $$ | sed 's/.*: *//; s/[-,].*//')
for i in 1 2 3; do
  for side in old new; do
    bench="$old/build/bench/raven_bench"
    [ "$side" = new ] && bench="${BUILD_DIR:-$root/build}/bench/raven_bench"
    taskset -c "$cpu" "$bench" --only ambf --repeat 1 --out "$out/$side-$i.json" >/dev/null 2>&1
  done
done
/usr/bin/python3 - "$out" "${BUILD_DIR:-$root/build}/ambf_on_this_host.json" \
  "$(realpath "$old/build/bench/raven_bench")" <<'PY'
import json, statistics, sys
out, written, bench = sys.argv[1:]
# Issue 50's ratios ours/AMBF at the baseline (medians of 3 alternating runs, no soft-body sleep),
# by the start of each scene's row and its id in raven_bench.
ratios = {"raven_world + blender-raven2": 1.05, "world + puzzles/peg_and_base": 1.02,
          "world + puzzles/puzzle2": 1.07, "world + sb/cloth (386-node": 1.51,
          "the Raven with the cloth": 1.49}
ids = dict(zip(ratios, ("raven", "peg_and_base", "puzzle2", "cloth", "raven_with_cloth")))
def medians(side):
    runs = [json.load(open(f"{out}/{side}-{i}.json"))["rows"] for i in (1, 2, 3)]
    found = {}
    for key in ratios:
        # The scene's first row: AMBF's way, before any variant of it.
        values = [next(r["median"] for r in rows if r["item"].startswith(key) and "median" in r)
                  for rows in runs]
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
           "steps_per_second": {ids[key]: old[key] / ratios[key] for key in ratios},
           "baseline": {"bench": bench, "ratio": {ids[key]: r for key, r in ratios.items()},
                        "row": {ids[key]: key for key in ratios}}},
          open(written, "w"), indent=2)
print(f"wrote {written}")
PY
