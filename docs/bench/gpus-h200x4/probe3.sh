#!/bin/bash
set -u
OUT=${OUT:-/tmp/p}; mkdir -p "$OUT"
if [ ! -d .bench/lib ]; then (cd .bench && tar xJf libs.tar.xz); fi
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export LD_LIBRARY_PATH=$PWD/.bench/lib
cp .bench/*.generated.toml config/
app() { local name=$1 config=$2; shift 2
  timeout 240 .bench/sandstorm --config "config/$config" --headless --frames 560 --stats "$OUT/$name.json" "$@" > "$OUT/$name.log" 2>&1
  echo "$name rc $? $(grep -h 'frame times' "$OUT/$name.log")"
  grep -h "GPU median" "$OUT/$name.log" | head -4 | sed 's/.*wall/  wall/; s/waits.*//'; }
app four-one-wall-each bench-cave4-stereo-eyes.toml --walls front-left-eye,front-right-eye,left-left-eye,left-right-eye
app four-per-wall four-per-wall.generated.toml
app four-tfgs four-tfgs.generated.toml
