#!/bin/bash
cd "$(dirname "$0")"
f=/tmp/rbfile.bin
t=$(date +%s.%N); ./readbench $f write 1610613457; echo "write: $(echo "$(date +%s.%N) - $t" | bc) s"
free -g | head -2; df -h /tmp | tail -1; cat /sys/block/*/queue/rotational 2>/dev/null | head -3; ls /sys/block; cat /sys/block/vda/queue/read_ahead_kb 2>/dev/null
nproc
for round in 1 2; do
  sync; echo 3 > /proc/sys/vm/drop_caches; t=$(date +%s.%N); cat $f > /dev/null; echo "cat cold: $(echo "$(date +%s.%N) - $t" | bc) s"
  t=$(date +%s.%N); cat $f > /dev/null; echo "cat warm: $(echo "$(date +%s.%N) - $t" | bc) s"
  sync; echo 3 > /proc/sys/vm/drop_caches; t=$(date +%s.%N); dd if=$f of=/dev/null bs=8M iflag=direct 2>&1 | tail -1
  for spec in "buffered 16 8" "buffered 4 8" "buffered 1 8" "seq 16 8" "buffered 32 2" "direct 16 8" "direct 8 8" "direct 32 4" "direct 4 16" "direct 64 2"; do
    ./readbench $f $spec cold
  done
  ./readbench $f buffered 16 8 warm
  ./readbench $f direct 16 8 warm
done
