#!/usr/bin/env python3
"""Writes the two textures Meristem ships: public/textures/bark.png and public/textures/leaf.png.

Procedural and reproducible (fixed seeds, no dependencies beyond the standard library), so the
images are ours and license-clean. Both are light (the vertex colours of the plant multiply them,
so a texture only adds structure, not a colour of its own):

- bark.png, 256 x 256 RGB, tileable in both directions: vertical fibres (stretched periodic value
  noise) with darker furrows. u runs around the tube, v along it.
- leaf.png, 256 x 256 RGBA: a broad pointed leaf on a transparent background with a midrib and
  side veins. Row 0 (the top of the image) is v = 0, the leaf's base, as in glTF; the tip is at
  the bottom. u runs across the leaf. The outline is broad so that a leaf whose own outline is
  already drawn (a polygon or a predefined leaf) keeps its shape; a rectangle becomes a leaf.

Usage: python3 scripts/make-textures.py  (from the repository root)
"""

import math
import os
import random
import struct
import zlib

SIZE = 256


def png(path, width, height, rows, channels):
    """Writes 8-bit rows (lists of ints) as a PNG with colour type 2 (RGB) or 6 (RGBA)."""
    raw = b"".join(b"\x00" + bytes(row) for row in rows)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    colour_type = 6 if channels == 4 else 2
    header = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    data = (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", zlib.compress(raw, 9))
        + chunk(b"IEND", b"")
    )
    with open(path, "wb") as f:
        f.write(data)


def periodic_noise(seed, cells_x, cells_y):
    """Smooth value noise on a lattice that wraps, sampled at (x, y) in 0..1."""
    rng = random.Random(seed)
    lattice = [[rng.random() for _ in range(cells_x)] for _ in range(cells_y)]

    def smooth(t):
        return t * t * (3 - 2 * t)

    def sample(x, y):
        fx, fy = x * cells_x, y * cells_y
        ix, iy = int(math.floor(fx)), int(math.floor(fy))
        tx, ty = smooth(fx - ix), smooth(fy - iy)
        a = lattice[iy % cells_y][ix % cells_x]
        b = lattice[iy % cells_y][(ix + 1) % cells_x]
        c = lattice[(iy + 1) % cells_y][ix % cells_x]
        d = lattice[(iy + 1) % cells_y][(ix + 1) % cells_x]
        return (a * (1 - tx) + b * tx) * (1 - ty) + (c * (1 - tx) + d * tx) * ty

    return sample


def bark():
    fibres = periodic_noise(1, 32, 4)
    furrows = periodic_noise(2, 8, 2)
    grain = periodic_noise(3, 64, 64)
    rows = []
    for j in range(SIZE):
        row = []
        y = j / SIZE
        for i in range(SIZE):
            x = i / SIZE
            f = fibres(x, y)
            furrow = furrows(x + 0.05 * f, y)
            ridge = max(0.0, 1.0 - abs(furrow - 0.5) * 9.0)  # dark cracks along the axis
            value = 0.62 + 0.28 * f + 0.1 * grain(x, y) - 0.35 * ridge
            value = min(1.0, max(0.0, value))
            row += [int(255 * value), int(255 * value * 0.93), int(255 * value * 0.84)]
        rows.append(row)
    png("public/textures/bark.png", SIZE, SIZE, rows, 3)


def leaf():
    grain = periodic_noise(4, 32, 32)
    rows = []
    for j in range(SIZE):
        v = (j + 0.5) / SIZE
        # Half-width of the outline at v: full over most of the length, rounding off only near
        # the base and the tip, so a leaf's own drawn outline is never cut into.
        half = 0.5 * min(1.0, 1.6 * math.sin(math.pi * v) ** 0.5)
        row = []
        for i in range(SIZE):
            u = (i + 0.5) / SIZE
            across = abs(u - 0.5)
            # Antialiased edge, one pixel wide.
            alpha = min(1.0, max(0.0, (half - across) * SIZE + 0.5))
            # Midrib and side veins running out towards the tip.
            midrib = max(0.0, 1.0 - across * SIZE / 2.5)
            phase = (v - 1.2 * across) * 9.0
            vein = max(0.0, 1.0 - abs(phase - round(phase)) * 14.0) * (across < half - 0.02)
            value = 0.86 + 0.12 * grain(u, v) - 0.3 * midrib - 0.18 * vein
            value = min(1.0, max(0.0, value))
            row += [
                int(255 * value * 0.96),
                int(255 * value),
                int(255 * value * 0.9),
                int(255 * alpha),
            ]
        rows.append(row)
    png("public/textures/leaf.png", SIZE, SIZE, rows, 4)


if __name__ == "__main__":
    os.makedirs("public/textures", exist_ok=True)
    bark()
    leaf()
