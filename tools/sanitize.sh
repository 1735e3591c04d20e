#!/usr/bin/env bash
# The suite under AddressSanitizer + UBSan (issue 15): builds hilight with
# HILIGHT_SANITIZE=ON (cmake/HilightSanitizers.cmake) into build-asan/ and
# runs the test cases listed in tools/sanitize-subset.txt, which reach every
# reader of files (lights JSON, IES/EULUMDAT, PLY targets, glTF, scenes
# through assimp, illuminance criteria, light cache files, plugin modules)
# and one whole solve.
#   bash tools/sanitize.sh          the subset (the CI step of setup.sh test)
#   bash tools/sanitize.sh --all    every test case but ism-vulkan's, the painter's
#                                   included (well over an hour on 2 cores; not in CI)
# SANITIZE_BUILD_DIR (default build-asan) and JOBS (default nproc) may be set.
# Prints one JSON line: test cases, build and run seconds, sanitizer reports.
#
# Fails on any failed test case and on any sanitizer report (a heap or stack
# error, a leak, undefined behaviour) in the test binary or in any `hilight`
# process the tests start, whatever exit code that test expected: ASan and
# LeakSanitizer write each process's report to $OUT/sanitizer-logs/, which must
# stay empty; UBSan ignores log_path in GCC's combined runtime, so its
# "runtime error:" lines are looked for in the test log and in the stderr that
# each started `hilight` leaves under $OUT/tests/output/. Leaks inside
# third-party libraries only may be suppressed in tools/lsan-suppressions.txt.
#
# Built so that CI can afford it (5.3 min on 2 cores, docs/benchmarks.md):
# -O0 -g1 (half the compile time of -O1; the subset runs 69 s instead of
# 31 s), only the test files that hold the subset's cases
# (HILIGHT_TEST_FILES), no painter (its session scripts are fuzzed under the
# same sanitizers by tools/fuzz.sh) and no ism-vulkan (most of it shaders,
# which no sanitizer sees).
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${SANITIZE_BUILD_DIR:-build-asan}
JOBS=${JOBS:-$(nproc)}
SUBSET=tools/sanitize-subset.txt
ALL=0 PAINTER=OFF
if [ "${1:-}" = "--all" ]; then ALL=1 PAINTER=ON; fi

# The subset's test case names (comments and blank lines dropped), and the
# test files that hold them.
mapfile -t names < <(sed -e 's/[[:space:]]*$//' -e '/^#/d' -e '/^$/d' "$SUBSET")
files=()
if [ "$ALL" -eq 0 ]; then
  for name in "${names[@]}"; do
    mapfile -t found < <(grep -rlF --include='test_*.cpp' -- "TEST_CASE(\"$name\"" tests | sed 's#^tests/##')
    if [ "${#found[@]}" -ne 1 ]; then
      echo "sanitize: $SUBSET: \"$name\" is in ${#found[@]} test files, not one" >&2
      exit 2
    fi
    files+=("${found[0]}")
  done
fi
test_files=$(printf '%s\n' "${files[@]}" | sed '/^$/d' | sort -u | paste -sd';')

# RelWithDebInfo with its flags replaced: not Debug, which would also turn on
# TBB_USE_DEBUG through TBB's CMake package.
start=$(date +%s)
cmake -S . -B "$OUT" -G Ninja -DHILIGHT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O0 -g1" \
  -DHILIGHT_BUILD_PAINTER="$PAINTER" -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON \
  -DHILIGHT_TEST_FILES="$test_files" >/dev/null
if ! cmake --build "$OUT" --target hilight_tests -j "$JOBS" >"$OUT/sanitize-build.log" 2>&1; then
  tail -40 "$OUT/sanitize-build.log" >&2
  echo "sanitize: the build failed (log: $OUT/sanitize-build.log)" >&2
  exit 1
fi
built=$(date +%s)

logs="$OUT/sanitizer-logs"
rm -rf "$logs" "$OUT/tests/output" "$OUT/sanitize.log"
mkdir -p "$logs"
logs=$(cd "$logs" && pwd -P)
# detect_leaks: LeakSanitizer at every exit. max_allocation_size_mb with
# allocator_may_return_null: an allocation over 8 GB fails (std::bad_alloc),
# as the 8 GB address-space cap of tests/test_cli_bad_input.cpp makes it fail
# without ASan (ASan's shadow memory rules that cap out). log_path: each
# process's ASan/LSan report in a file of its own, so that none is lost in a
# test's captured stderr.
asan="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
asan="$asan:max_allocation_size_mb=8192:allocator_may_return_null=1:log_path=$logs/asan"
export ASAN_OPTIONS=$asan
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tools/lsan-suppressions.txt:print_suppressions=0"

# One run of the test binary with the given test spec, its output appended to
# $OUT/sanitize.log; its exit status is kept in `status`.
status=0
run() {
  local s=0
  echo "=== hilight_tests $*" >>"$OUT/sanitize.log"
  "${display[@]}" "$OUT/bin/hilight_tests" "$@" --warn NoTests --durations yes >>"$OUT/sanitize.log" 2>&1 || s=$?
  [ "$s" -eq 0 ] || status=$s
}
display=()
if [ "$ALL" -eq 0 ]; then
  # Catch2 reads one name a line (-f); a comma would split a name in two.
  printf '%s\n' "${names[@]}" | sed 's/,/\\,/g' >"$OUT/sanitize-subset.spec"
  # (Catch2 exits with the number of test cases it lists.)
  listed=$({ "$OUT/bin/hilight_tests" -f "$OUT/sanitize-subset.spec" --list-test-names-only || true; } | sed '/^$/d' | wc -l)
  if [ "$listed" -ne "${#names[@]}" ]; then
    echo "sanitize: $SUBSET names ${#names[@]} test cases, the test binary matches $listed" >&2
    exit 2
  fi
  rm -rf "${logs:?}"/*
  run -f "$OUT/sanitize-subset.spec"
else
  [ -n "${DISPLAY:-}" ] || display=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
  run "~[ism]~[painter-ui]"  # ism-vulkan is not built here
  # The painter's windows: every process that opened one leaks inside Mesa's
  # DRI driver, which is unloaded before LeakSanitizer looks, so its frames
  # have no module name to suppress by (and unwinding each malloc slowly, to
  # see libGLX_mesa above them, deadlocks). Leak checks off there only.
  ASAN_OPTIONS="${asan/detect_leaks=1/detect_leaks=0}" run "[painter-ui]"
fi
ran=$(date +%s)

# Reports, also from started processes whose failure a test expected.
pattern='runtime error:|ERROR: (AddressSanitizer|LeakSanitizer)'
mapfile -t ub_files < <({ grep -lE "$pattern" "$OUT/sanitize.log"; grep -rlE --include=stderr.txt "$pattern" "$OUT/tests/output"; } 2>/dev/null || true)
reports=$(($(find "$logs" -type f | wc -l) + ${#ub_files[@]}))
cases=$({ grep -oE '(test cases: *[0-9]+|in [0-9]+ test cases)' "$OUT/sanitize.log" || true; } | grep -oE '[0-9]+' | awk '{s += $1} END {print s + 0}')
grep -E '^(All tests passed|test cases:)' "$OUT/sanitize.log" || true
echo "{\"sanitize\":\"$([ "$ALL" -eq 1 ] && echo all || echo subset)\",\"test_cases\":${cases:-0},\"test_files\":$(printf '%s' "$test_files" | tr ';' '\n' | sed '/^$/d' | wc -l),\"build_s\":$((built - start)),\"run_s\":$((ran - built)),\"status\":$status,\"sanitizer_reports\":$reports}"
if [ "$status" -ne 0 ] || [ "$reports" -ne 0 ]; then
  grep -B2 -A25 -E 'FAILED|ERROR: AddressSanitizer|runtime error' "$OUT/sanitize.log" | head -150 >&2 || true
  for f in "$logs"/* "${ub_files[@]}"; do
    [ -f "$f" ] && [ "$f" != "$OUT/sanitize.log" ] || continue
    echo "--- $f" >&2
    head -60 "$f" >&2
  done
  echo "sanitize: failed (test log: $OUT/sanitize.log, reports: $logs/)" >&2
  exit 1
fi
