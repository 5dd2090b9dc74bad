#!/bin/bash
# Where the four-GPU frame goes: two GPUs on the same machine, and 10^6 particles.
set -u
OUT=${OUT:-/tmp/p}; mkdir -p "$OUT"
if [ ! -d .bench/lib ]; then (cd .bench && tar xJf libs.tar.xz); fi
for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig
export LD_LIBRARY_PATH=$PWD/.bench/lib
cp .bench/two-gpus.generated.toml config/
printf 'include = "bench-cave4-stereo-eyes.toml"\n[run]\ngpus = "first"\n' > config/bench-eyes-first.generated.toml
app() { local name=$1 config=$2; shift 2
  timeout 240 .bench/sandstorm --config "config/$config" --headless --frames 560 --stats "$OUT/$name.json" "$@" > "$OUT/$name.log" 2>&1
  echo "$name rc $? $(grep -h 'frame times' "$OUT/$name.log")"
  grep -h "GPU median" "$OUT/$name.log" | head -4 | sed 's/.*wall/  wall/; s/waits.*//'; }
app two-gpus two-gpus.generated.toml
app four-gpus bench-cave4-stereo-eyes.toml
app four-gpus-1e6 bench-cave4-stereo-eyes.toml --set sim.maximum=1000000
app one-gpu-1e6 bench-eyes-first.generated.toml --set sim.maximum=1000000
