#!/usr/bin/env bash
# Replays every input in a regression folder through a fuzz target (libFuzzer
# runs each file once when given files). An empty or missing folder passes.
set -euo pipefail
target="$1"
folder="$2"
shopt -s nullglob
inputs=("$folder"/*)
[ ${#inputs[@]} -eq 0 ] && { echo "no regression inputs in $folder"; exit 0; }
# VTK readers' leaks on malformed input (tests/sanitize/lsan-suppressions.txt).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(cd "$(dirname "$0")/../.." && pwd)/tests/sanitize/lsan-suppressions.txt}"
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0"
exec "$target" -rss_limit_mb=2560 -malloc_limit_mb=2048 -timeout=30 "${inputs[@]}"
