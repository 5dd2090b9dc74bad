#!/usr/bin/env bash
# Every fuzz regression input of a one-file field format, opened by the
# release build's sandstorm-field: refused with a message, never a crash.
# The sanitized replay (scripts/sanitize) cannot see out-of-bounds reads
# inside the uninstrumented libraries (VTK's Exodus reader read past its
# tables on blocks sharing an id: a crash only in some heap layouts under
# the fuzzer, a segmentation fault every time in the release build).
#   fuzz_regressions_release_test.sh TOOL REGRESSIONS_DIR SCRATCH_DIR
set -u
tool=$1 regressions=$2 tmp=$3
mkdir -p "$tmp"
passed=0 failed=0
for dir in "$regressions"/fuzz_field_*/; do
  ext=$(basename "$dir")
  ext=${ext#fuzz_field_}
  case $ext in vti | vtk | vtp | vtr | vts | vtu | nc | vdb | fga | vf | e) ;; *) continue ;; esac
  for input in "$dir"*; do
    [ -f "$input" ] || continue
    cp "$input" "$tmp/input.$ext"
    out=$(timeout 120 "$tool" info "$tmp/input.$ext" 2>&1)
    rc=$?
    if [ $rc -ge 124 ] || { [ $rc -ne 0 ] && ! grep -q "input.$ext" <<<"$out"; }; then
      failed=$((failed + 1))
      echo "FAILED: $input as .$ext: status $rc (expected success or an error naming the file):" >&2
      echo "$out" | tail -5 >&2
    else
      passed=$((passed + 1))
    fi
  done
done
echo "$passed passed, $failed failed"
[ $passed -gt 0 ] && [ $failed -eq 0 ]
