#!/usr/bin/env python3
"""Writes seed inputs for fuzz_trajectory into DIR (see trajectory_fuzz.cpp for the layout:
one mode byte, then the file). Generated, not committed: records of a few made-up states."""
import os
import struct
import sys

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


def state(n, t):
    x = [0.1 * k + t for k in range(2 * n)]
    v = [-0.5 * k + 2 * t for k in range(2 * n)]
    return struct.pack("<%dd" % (4 * n), *(x + v))


def impulses(items):
    b = struct.pack("<i", len(items))
    for kind, i, j, nx, ny, t in items:
        b += struct.pack("<iiiddd", kind, i, j, nx, ny, t)
    return b


def polynomials(polys):
    b = struct.pack("<i", len(polys))
    for p in polys:
        b += struct.pack("<i%dd" % len(p), len(p), *p)
    return b


def write(name, mode, body):
    with open(os.path.join(out, name), "wb") as f:
        f.write(bytes([mode]) + body)


for n in range(1, 5):
    m = (n - 1) << 2
    write("plain_n%d" % n, m, b"".join(state(n, 0.01 * r) for r in range(3)))
    write("impulses_n%d" % n, m | 1, b"".join(state(n, r) + impulses([(r % 3, 0, 1, 0.5, -0.5, 0.25)] * r)
                                              for r in range(3)))
    write("polys_n%d" % n, m | 3, b"".join(state(n, r) + impulses([]) +
                                           polynomials([[1.0, -2.0, 1.0], [3.0] * (r + 1)]) for r in range(3)))
# The fixed scene of the grading mode has 3 particles, simple collisions and 5 steps.
write("grade_fixed_scene", 0x80, b"".join(state(3, 0.01 * r) + impulses([(2, 2, 0, 0, 1, 0)] if r == 2 else [])
                                          for r in range(6)))
write("grade_short", 0x80, state(3, 0) + impulses([]))
