#!/usr/bin/env python3
# crop.py OUT.png X Y W H SCALE A.png [B.png ...]: the crops side by side, each scaled by SCALE.
import subprocess, sys, zlib, struct
def ppm(path):
    d = subprocess.run(["convert", path, "ppm:-"], capture_output=True, check=True).stdout
    parts = d.split(maxsplit=4); w, h = int(parts[1]), int(parts[2])
    return w, h, parts[4][-w*h*3:]
out, x0, y0, cw, ch, sc = sys.argv[1], *map(int, sys.argv[2:7])
imgs = [ppm(p) for p in sys.argv[7:]]
rows = []
for y in range(ch*sc):
    row = bytearray()
    for (w, h, px) in imgs:
        yy = y0 + y//sc
        for x in range(cw*sc):
            i = (yy*w + x0 + x//sc)*3
            row += px[i:i+3]
        row += b'\xff\x00\x00'*2
    rows.append(b'\x00' + bytes(row))
W = (cw*sc+2)*len(imgs)
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t+d) & 0xffffffff)
open(out, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, ch*sc, 8, 2, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(b''.join(rows))) + chunk(b'IEND', b''))
