#!/usr/bin/env bash
# Builds everything, runs raven_bench (every section, 3 repetitions) and rewrites the results
# with the date and the machine: every row in docs/benchmarks.md (bench:begin / bench:end
# markers), the rows with a target in README.md (bench-headline:begin / end). Takes about 85
# minutes on 2 cores, 70 of them the training section (both policies retrained from scratch).
# Extra flags go to raven_bench.
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
/usr/bin/python3 - "$root" "$build/bench_results.json" "$build/bench_results.md" <<'PY'
import json, re, sys
root, results, table = sys.argv[1:]
m = json.load(open(results))["machine"]
block = (f"Measured {m['date']} on {m['cpu']}, {m['cores']} cores, {m['kernel']}, {m['compiler']}, "
         f"Release build (RAVEN_NATIVE on, the default: -march=native), with `scripts/bench.sh` (medians of 3 runs, range in brackets).\n\n"
         + open(table).read())
# The README shows the rows with a target; docs/benchmarks.md every row.
headline = "\n".join(line for line in block.split("\n")
                     if not line.startswith("|") or line.startswith(("| section", "|---"))
                     or re.search(r"\d", line.split("|")[4]))
for page, marker, text in (("README.md", "bench-headline", headline),
                           ("docs/benchmarks.md", "bench", block)):
    path = f"{root}/{page}"
    old = open(path).read()
    begin, end = f"<!-- {marker}:begin -->\n", f"<!-- {marker}:end -->"
    if begin not in old or end not in old:
        sys.exit(f"{page} has no {begin.strip()} / {end} markers")
    new = re.sub(re.escape(begin) + r".*?" + re.escape(end), lambda g: begin + text.rstrip("\n") + "\n" + end,
                 old, flags=re.S)
    open(path, "w").write(new)
    print(f"{page}: results of {m['date']} written")
PY
