#!/usr/bin/env python3
# pngdiff A.png B.png: mean |difference| over pixels and RGB (/255), and the
# 99th / 99.9th percentile and largest of a pixel's largest channel difference.
import subprocess, sys
def ppm(path):
    d = subprocess.run(["convert", path, "ppm:-"], capture_output=True, check=True).stdout
    parts = d.split(maxsplit=4)
    w, h = int(parts[1]), int(parts[2])
    return w, h, parts[4][-w*h*3:]
wa, ha, a = ppm(sys.argv[1]); wb, hb, b = ppm(sys.argv[2])
assert (wa, ha) == (wb, hb), "sizes differ"
hist = [0]*256; total = 0
for i in range(0, len(a), 3):
    d0 = abs(a[i]-b[i]); d1 = abs(a[i+1]-b[i+1]); d2 = abs(a[i+2]-b[i+2])
    total += d0+d1+d2; hist[max(d0,d1,d2)] += 1
n = wa*ha
def pct(p):
    c = 0
    for v in range(256):
        c += hist[v]
        if c >= p*n: return v
print(f"mean {total/(3*n):.3f} 99th {pct(0.99)} 99.9th {pct(0.999)} largest {max(v for v in range(256) if hist[v])} >16: {100*sum(hist[17:])/n:.3f}%")
