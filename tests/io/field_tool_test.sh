#!/usr/bin/env bash
# sandstorm-field from the outside: good commands succeed and say what they
# did, bad ones fail with a message on stderr and a non-zero status (never a
# crash, which would show as a status above 128).
#   field_tool_test.sh TOOL DATA_DIR SCRATCH_DIR
set -u
tool=$1 data=$2 tmp=$3
mkdir -p "$tmp"
passed=0 failed=0

expect() {  # expect ok|fail PATTERN -- command args...
  local want=$1 pattern=$2
  shift 3
  local out rc
  out=$("$tool" "$@" 2>&1)
  rc=$?
  local ok=1
  if [ "$want" = ok ] && [ $rc -ne 0 ]; then ok=0; fi
  if [ "$want" = fail ] && { [ $rc -eq 0 ] || [ $rc -ge 128 ]; }; then ok=0; fi
  if ! grep -Eq -- "$pattern" <<<"$out"; then ok=0; fi
  if [ $ok = 1 ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAILED: sandstorm-field $* (status $rc, expected $want and /$pattern/):" >&2
    echo "$out" >&2
  fi
}

expect ok "dims: +40 x 40 x 24" -- info "$data/tornado.vti"
expect ok "vec3s grid" -- info "$data/downwash.vdb"
expect ok "time series of 4 frames" -- info "$data/series/series.pvd"
expect ok "wrote" -- convert "$data/downwash.vdb" "$tmp/downwash.vti"
expect ok "dims: +40 x 40 x 16" -- info "$tmp/downwash.vti"
expect ok "wrote" -- resample "$data/tornado.vti" "$tmp/small.vdb" --dims 10 10 6
expect ok "dims: +10 x 10 x 6" -- info "$tmp/small.vdb"
expect ok "wrote" -- generate gravity "$tmp/g.vti" --dims 4 4 4 --bounds -1 -1 -1 1 1 1 --param power=-2
expect ok "scalars: +'q_criterion', 'divergence'" -- info "$data/tornado.vti"
expect ok "with arrays 'q_criterion', 'divergence', 'helicity'" -- derive "$data/tornado.vti" "$tmp/derived.vdb" --quantity helicity
expect ok "scalars: +'q_criterion', 'divergence', 'helicity'" -- info "$tmp/derived.vdb"
expect fail "already has an array 'divergence'" -- derive "$data/tornado.vti" "$tmp/x.vti" --quantity divergence
expect fail "no derived quantity 'lambda2'.*q_criterion" -- derive "$data/tornado.vti" "$tmp/x.vti" --quantity lambda2
expect fail "quantity|required" -- derive "$data/tornado.vti" "$tmp/x.vti"
expect fail "no such file" -- info "$tmp/missing.vti"
expect fail "unknown option '--dimz' \\(did you mean '--dims'\\?\\)" -- resample "$data/tornado.vti" "$tmp/x.vti" --dimz 4 4 4
expect fail "unknown analytic field 'hurricane'.*tornado" -- generate hurricane "$tmp/x.vti" --dims 2 2 2 --bounds 0 0 0 1 1 1
expect fail "--dims: expected a whole number, 1 or more; got .0." -- generate gravity "$tmp/x.vti" --dims 4 0 4 --bounds 0 0 0 1 1 1
expect fail "--dims: expected a whole number, 1 or more; got .2.5." -- resample "$data/tornado.vti" "$tmp/x.vti" --dims 2.5 4 4
expect fail "--memory-budget: expected a number greater than 0; got .-1." -- info "$data/tornado.vti" --memory-budget -1
expect fail "--extent: expected a number greater than 0; got .inf." -- terrain "$tmp/x.pgm" --extent inf
expect fail "unknown parameter 'speed'" -- generate wind "$tmp/x.vti" --dims 2 2 2 --bounds 0 0 0 1 1 1 --param speed=3
expect fail "not a number" -- generate wind "$tmp/x.vti" --dims 2 2 2 --bounds 0 0 0 1 1 1 --param power=fast
expect fail "dims" -- generate wind "$tmp/x.vti" --dims 0 2 2 --bounds 0 0 0 1 1 1
expect fail "bounds" -- generate wind "$tmp/x.vti" --dims 2 2 2 --bounds 0 0 0 1 1
expect fail "span|positive extent" -- generate wind "$tmp/x.vti" --dims 2 2 2 --bounds 0 0 0 1 0 1
expect ok "wrote" -- convert "$data/tornado.vti" "$tmp/plain.vti" --compression none
expect ok "dims: +40 x 40 x 24" -- info "$tmp/plain.vti"
grep -q 'compressor=' "$tmp/plain.vti" && { echo "FAILED: --compression none wrote a compressor" >&2; failed=$((failed + 1)); }
expect ok "wrote" -- generate tornado "$tmp/lz4.vti" --dims 8 8 8 --bounds -1 -1 0 1 1 2 --compression lz4
grep -q 'vtkLZ4DataCompressor' "$tmp/lz4.vti" || { echo "FAILED: --compression lz4 wrote no LZ4" >&2; failed=$((failed + 1)); }
expect ok "dims: +8 x 8 x 8" -- info "$tmp/lz4.vti"
expect fail "--compression applies to .vti" -- convert "$data/tornado.vti" "$tmp/x.vdb" --compression lz4
expect fail "gzip not in" -- convert "$data/tornado.vti" "$tmp/x.vti" --compression gzip
expect fail "cannot write '.vtk'" -- convert "$data/tornado.vti" "$tmp/out.vtk"
expect fail "--dims" -- resample "$data/tornado.vti" "$tmp/out.vti"
expect fail "subcommand|required" --
# A bad output is refused before the input is read, never VTK's own dump.
expect fail "^sandstorm-field: writing $tmp/none/out.vti: the folder $tmp/none does not exist\$" -- convert "$data/tornado.vti" "$tmp/none/out.vti"
expect fail "^sandstorm-field: writing $tmp/none/out.vdb: the folder" -- convert "$data/tornado.vti" "$tmp/none/out.vdb"
expect fail "^sandstorm-field: writing $tmp/none/d.vti: the folder" -- derive "$data/tornado.vti" "$tmp/none/d.vti" --quantity speed
expect fail "^sandstorm-field: writing $tmp/none/g.vti: the folder" -- generate tornado "$tmp/none/g.vti" --dims 4 4 4 --bounds 0 0 0 1 1 1
expect fail "^sandstorm-field: $tmp: expected a file name ending in .vti" -- convert "$data/tornado.vti" "$tmp"
expect fail "writing $tmp/none/t.pgm: the folder" -- terrain "$tmp/none/t.pgm"
rm -f "$tmp/t.txt"
expect fail "expected a .pgm file" -- terrain "$tmp/t.txt"
[ -e "$tmp/t.txt" ] && { echo "FAILED: terrain wrote t.txt" >&2; failed=$((failed + 1)); }
expect fail "^sandstorm-field: writing $tmp/none/out.vti: the folder" -- convert "$tmp/missing.vti" "$tmp/none/out.vti"
cp "$data/tornado.vti" "$tmp/lying.vdb"
expect fail "is a VTK XML image data file" -- info "$tmp/lying.vdb"

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
