#!/usr/bin/env bash
# Fuzzes hilight's readers of untrusted files with libFuzzer (issue 15):
# lights JSON, IES/EULUMDAT, painter session scripts, PLY, glTF, scenes, light cache files.
#   bash tools/fuzz.sh [SECONDS]    each target for SECONDS (default 8: the CI step)
# Builds fuzz/ with clang-14 into build-fuzz/ (FUZZ_BUILD_DIR), starts each
# target from its corpus in fuzz/corpus/ (new inputs go to build-fuzz/corpus/,
# findings to build-fuzz/findings/), and fails on any crash, leak, timeout or
# sanitizer report. Prints one JSON line per target: executions and findings.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-8}
OUT=${FUZZ_BUILD_DIR:-build-fuzz}
cmake -S fuzz -B "$OUT" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
mkdir -p "$OUT"
if ! cmake --build "$OUT" -j "$(nproc)" >"$OUT/fuzz-build.log" 2>&1; then
  grep -E -A3 'error|undefined reference' "$OUT/fuzz-build.log" | head -40 >&2
  echo "fuzz: the build failed (log: $OUT/fuzz-build.log)" >&2
  exit 1
fi
# Leaks that live inside a Debian library, not in hilight (each one named
# and explained in the file).
export LSAN_OPTIONS="suppressions=$(pwd -P)/fuzz/lsan-suppressions.txt${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
failed=0
for target in lights_json photometry session ply gltf scene light_cache; do
  corpus="$OUT/corpus/$target" findings="$OUT/findings/$target"
  mkdir -p "$corpus" "$findings"
  log="$OUT/$target.log"
  set +e
  (cd "$findings" && "../../fuzz_$target" -max_total_time="$SECONDS_EACH" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      "../../corpus/$target" "$(pwd -P)/../../../fuzz/corpus/$target" >"../../$target.log" 2>&1)
  status=$?
  set -e
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  found=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  echo "{\"fuzz\":\"$target\",\"seconds\":$SECONDS_EACH,\"executions\":${runs:-0},\"findings\":$found,\"status\":$status}"
  if [ "$status" -ne 0 ] || [ "$found" -ne 0 ]; then
    failed=1
    tail -30 "$log" >&2
  fi
done
exit $failed
