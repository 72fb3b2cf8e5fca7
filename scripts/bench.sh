#!/usr/bin/env bash
# Builds everything, runs raven_bench (every section, 3 repetitions) and rewrites the results
# block of README.md (between the bench:begin / bench:end markers) with the table, the date and
# the machine. Takes about 5 minutes on 2 cores. Extra flags go to raven_bench.
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
/usr/bin/python3 - "$root/README.md" "$build/bench_results.json" "$build/bench_results.md" <<'PY'
import json, re, sys
readme, results, table = sys.argv[1:]
m = json.load(open(results))["machine"]
block = (f"Measured {m['date']} on {m['cpu']}, {m['cores']} cores, {m['kernel']}, {m['compiler']}, "
         f"Release build (RAVEN_NATIVE on, the default: -march=native), with `scripts/bench.sh` (medians of 3 runs, range in brackets).\n\n"
         + open(table).read())
text = open(readme).read()
new = re.sub(r"(<!-- bench:begin -->\n).*?(<!-- bench:end -->)", lambda g: g.group(1) + block + g.group(2),
             text, flags=re.S)
if new == text and "<!-- bench:begin -->" not in text:
    sys.exit("README.md has no <!-- bench:begin --> / <!-- bench:end --> markers")
open(readme, "w").write(new)
print(f"README.md: results of {m['date']} written")
PY
