#!/usr/bin/env python3
"""Writes a large synthetic viseme set as binary little-endian PLY (float x,y,z; uchar/int faces):
OUT/neutral.ply and OUT/v00.ply .. OUT/v<N-1>.ply on a W x W grid (about VERTICES vertices).
Each viseme moves the grid by a mix of 4 smooth fields, so the reduction has structure.

usage: generate-large-ply.py OUT [VERTICES=1000000] [VISEMES=16]
Keep the output out of the repository (1M x 16 is about 650 MB): generate into /tmp."""
import array
import math
import os
import random
import sys


def faces_bytes(w):
    rows = []
    for y in range(w - 1):
        row = array.array("i")
        for x in range(w - 1):
            a = y * w + x
            row.extend((a, a + 1, a + w + 1, a, a + w + 1, a + w))
        rows.append(row)
    out = bytearray()
    for row in rows:
        raw = row.tobytes()
        for t in range(0, len(raw), 12):  # uchar 3 before each triangle's three ints
            out += b"\x03" + raw[t:t + 12]
    return bytes(out)


def write(path, w, positions, faces):
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
              "property float y\nproperty float z\nelement face %d\n"
              "property list uchar int vertex_indices\nend_header\n") % (w * w, 2 * (w - 1) ** 2)
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(positions.tobytes())
        f.write(faces)


def main():
    out = sys.argv[1]
    w = max(2, int(math.isqrt(int(sys.argv[2]) if len(sys.argv) > 2 else 1000000)))
    n = int(sys.argv[3]) if len(sys.argv) > 3 else 16
    if sys.byteorder != "little":
        sys.exit("little-endian host required")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(33)
    faces = faces_bytes(w)
    xs = [x / (w - 1) for x in range(w)]
    fields = [[math.sin(math.pi * (k + 1) * x) for x in xs] for k in range(4)]
    neutral = array.array("f")
    for y in range(w):
        for x in range(w):
            neutral.extend((xs[x], xs[y], 0.0))
    write(os.path.join(out, "neutral.ply"), w, neutral, faces)
    for i in range(n):
        mix = [rng.uniform(-0.05, 0.05) for _ in fields]
        column = [sum(m * f[x] for m, f in zip(mix, fields)) for x in range(w)]
        scale = [math.sin(math.pi * y / (w - 1)) for y in range(w)]
        p = array.array("f", neutral)
        for y in range(w):
            s = scale[y]
            base = 3 * y * w + 2
            p[base:base + 3 * w:3] = array.array("f", [c * s for c in column])
        write(os.path.join(out, "v%02d.ply" % i), w, p, faces)


main()
