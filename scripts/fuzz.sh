#!/usr/bin/env bash
# Runs every libFuzzer target for a bounded time, then replays the saved regression inputs.
# Usage: scripts/fuzz.sh [build dir with RAVEN_FUZZ=ON] [seconds per target] [targets...]
# Seeds: the committed corpus (fuzz/corpus/<target>), the project's own files and, when present,
# ../shared/data (copied to a temporary folder, never into the tree). A finding stops the run
# with its input's path: once fixed, commit that input under fuzz/regressions/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-sanitize}
seconds=${2:-30}
shift $(($# > 2 ? 2 : $#))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(adf adf_world urdf mesh articulations recordings ros_messages)
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan-suppressions.txt"
shared=../shared/data
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# seed TARGET PREFIX-BYTE(or "") FILES...: copies files into TARGET's seed folder, at most 64 KiB
# each, behind a first byte that selects the reader where the target has several.
seed() {
  local target=$1 prefix=$2
  shift 2
  mkdir -p "$work/$target-seeds"
  local file n=0
  for file in "$@"; do
    [ -f "$file" ] || continue
    n=$((n + 1))
    { [ -z "$prefix" ] || printf "\\x$prefix"; head -c 65536 "$file"; } \
      > "$work/$target-seeds/$prefix$n-$(basename "$file")"
  done
}
[ -d "$shared" ] || echo "fuzz: $shared is absent; seeding from the project's own files only"
project_files() { find raven_description ambf_like/examples tests/data -type f -iname "$1"; }
shared_files() { [ -d "$shared" ] && find "$shared" -type f -iname "$1" -size -256k || true; }

mapfile -t adf < <(project_files '*.yaml'; shared_files '*.yaml')
seed adf "" "${adf[@]}"
# adf_world: 00 and a multibody file (the loader's corpus among them), 01 and a world file.
seed adf_world 00 "${adf[@]}" fuzz/corpus/adf/*
seed adf_world 01 $(project_files 'world*.yaml') $(shared_files 'world*.yaml')
seed urdf "" $(project_files '*.urdf') $(shared_files '*.urdf')
seed mesh 00 $(project_files '*.stl') $(shared_files '*.stl')
seed mesh 01 $(project_files '*.obj') $(shared_files '*.obj')
seed mesh 02 $(project_files '*.dae') $(shared_files '*.dae')
seed mesh 03 $(project_files '*.vtk') $(shared_files '*.vtk')
seed mesh 04 $(project_files '*.3ds') $(shared_files '*.3ds')
# The shared recordings are large: their first 64 KiB (cut mid-row, a seed in itself).
[ -d "$shared" ] && seed recordings 00 $(find "$shared/recordings" -name '*_ambf_1.csv' -o -name '*_physical_1.csv')
[ -d "$shared" ] && seed recordings 01 $(find "$shared/recordings" -name '*_ci.csv')
seed recordings 01 $(project_files '*_ci.csv')
mkdir -p "$work/ros_messages-seeds" "$work/articulations-seeds"

# Seconds an input may take: a user waits 20 s for a file of 20,000 links to load and step (7 s
# in a release build here); under the sanitizers it takes 30-60 s.
declare -A timeout=([articulations]=150)
declare -A max_len=([adf]=262144 [adf_world]=262144 [urdf]=65536 [mesh]=131072 [recordings]=131072
  [ros_messages]=4096 [articulations]=65536)
status=0
for target in "${targets[@]}"; do
  binary="$build/fuzz/fuzz_$target"
  [ -x "$binary" ] || { echo "fuzz: $binary is not built (cmake -DRAVEN_FUZZ=ON, CXX=clang++)"; exit 1; }
  mkdir -p "$work/$target-corpus" "$work/findings"
  echo "fuzz: $target for $seconds s"
  if ! "$binary" -max_total_time="$seconds" -timeout="${timeout[$target]:-10}" -rss_limit_mb=2048 \
      -max_len="${max_len[$target]}" -print_final_stats=1 \
      -artifact_prefix="$work/findings/$target-" \
      "$work/$target-corpus" "fuzz/corpus/$target" "$work/$target-seeds" \
      > "$work/$target.log" 2>&1; then
    # The report from its first line (the sanitizer's or libFuzzer's), else the log's end.
    report=$(awk '/ERROR:|deadly signal|timeout after|out-of-memory/{found=1} found' "$work/$target.log" | head -n 80)
    if [ -n "$report" ]; then echo "$report"; else tail -n 60 "$work/$target.log"; fi
    mkdir -p fuzz-findings
    cp "$work"/findings/* fuzz-findings/ 2>/dev/null || true
    echo "fuzz: FINDING in $target; the input is in fuzz-findings/"
    status=1
    continue
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$work/$target.log" | tr '\n' ' '
  echo
  regressions=(fuzz/regressions/$target/*)
  if [ -e "${regressions[0]}" ]; then
    echo "fuzz: replaying ${#regressions[@]} saved $target regression inputs"
    "$binary" -timeout="${timeout[$target]:-10}" -rss_limit_mb=2048 "${regressions[@]}" > "$work/$target-regressions.log" 2>&1 ||
      { tail -n 40 "$work/$target-regressions.log"; status=1; }
  fi
done
exit $status
