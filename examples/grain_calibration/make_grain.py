#!/usr/bin/env python3
"""Writes grain.data: a bonded grain of ten 1 mm sub-spheres stacked as a close-packed pyramid
(six touching on the floor, three in their hollows, one on top), for grain_compression.toml.
Run: python3 make_grain.py  (writes next to this script)."""
import math
import pathlib

R = 5e-4  # m, sub-sphere radius
DENSITY = 1450.0  # kg/m3


def layer(n, z, shift):
    """Centres of a triangle of n rows of touching spheres at height z."""
    out = []
    for row in range(n):
        for k in range(row + 1):
            x = 2 * R * (k - row / 2)
            y = 2 * R * math.sqrt(3) / 2 * row
            out.append((x + shift[0], y + shift[1], z))
    return out


h = 2 * R * math.sqrt(2 / 3)  # height between close-packed layers
base = layer(3, R, (0, 0))
# each upper layer sits in the hollows of the one below: its first sphere over the centroid of the
# lower layer's first three, 2/3 of a row pitch further along y
hollow = 2 * R * math.sqrt(3) / 3
middle = layer(2, R + h, (0, hollow))
top = layer(1, R + 2 * h, (0, 2 * hollow))
spheres = base + middle + top
# centre the grain on the axis x = y = 0
cx = sum(s[0] for s in spheres) / len(spheres)
cy = sum(s[1] for s in spheres) / len(spheres)
lines = [
    "# a close-packed pyramid of ten 1 mm sub-spheres resting on z = 0 (make_grain.py)",
    "",
    f"{len(spheres)} atoms",
    "1 atom types",
    "",
    "Atoms # sphere",
    "",
]
for i, (x, y, z) in enumerate(spheres, start=1):
    lines.append(f"{i} 1 {2 * R:.6g} {DENSITY:.6g} {x - cx:.15g} {y - cy:.15g} {z:.15g}")
out = pathlib.Path(__file__).with_name("grain.data")
out.write_text("\n".join(lines) + "\n")
print(f"wrote {out}; top of the grain at z = {R + 2 * h + R:.9g} m")
