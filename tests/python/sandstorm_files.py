"""Readers for the files the application writes, independent of Sandstorm's
own code: PNG (zlib and the five PNG filters), VTK XML PolyData with raw
appended arrays (--dump-particles) and with ASCII arrays (--dump-streamlines)."""
import re
import struct
import zlib

import numpy as np


def read_png(path):
    """An 8-bit RGB or RGBA PNG as an (h, w, channels) uint8 array."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and color in (2, 6) and interlace == 0, (depth, color, interlace)
            channels = 4 if color == 6 else 3
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, 1 + width * channels)
    out = np.zeros((height, width * channels), np.int32)
    bpp = channels
    for y in range(height):
        kind, line = raw[y, 0], raw[y, 1:].astype(np.int32)
        prior = out[y - 1] if y > 0 else np.zeros(width * channels, np.int32)
        row = out[y]
        if kind == 0:
            row[:] = line
        elif kind == 2:
            row[:] = (line + prior) & 255
        else:
            for x in range(width * channels):
                left = row[x - bpp] if x >= bpp else 0
                up = prior[x]
                corner = prior[x - bpp] if x >= bpp else 0
                if kind == 1:
                    pred = left
                elif kind == 3:
                    pred = (left + up) // 2
                else:  # Paeth
                    p = left + up - corner
                    pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                    pred = left if pa <= pb and pa <= pc else (up if pb <= pc else corner)
                row[x] = (line[x] + pred) & 255
    return out.astype(np.uint8).reshape(height, width, channels)


_ARRAY = re.compile(rb'<DataArray type="(\w+)" Name="([^"]+)"(?: NumberOfComponents="(\d+)")?'
                    rb' format="appended" offset="(\d+)"/>')


def read_appended_vtp(path):
    """The named arrays of a raw-appended .vtp (UInt64 headers), as numpy arrays."""
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData encoding=\"raw\">")
    start = data.index(b"_", start) + 1
    arrays = {}
    for kind, name, comps, offset in _ARRAY.findall(data[:start]):
        at = start + int(offset)
        size = struct.unpack("<Q", data[at:at + 8])[0]
        dtype = {b"Float32": np.float32, b"Int64": np.int64}[kind]
        a = np.frombuffer(data[at + 8:at + 8 + size], dtype)
        arrays[name.decode()] = a.reshape(-1, int(comps)) if comps else a
    return arrays


def read_ascii_vtp_lines(path):
    """A polyline .vtp with ASCII arrays: its lines' points, one array each."""
    text = open(path).read()
    def array(name, dtype):
        m = re.search(r'<DataArray type="\w+" Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return np.array(m.group(1).split(), dtype)
    points = array("Points", np.float32).reshape(-1, 3)
    offsets = array("offsets", np.int64)
    starts = np.concatenate([[0], offsets[:-1]])
    return [points[a:b] for a, b in zip(starts, offsets)]
