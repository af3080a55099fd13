#!/usr/bin/env python3
# A rotating drum half filled with polygon grains, written as a gc2d generator script (gc2d spec
# 6.2 gc2d_drum, 2.3 deterministic shapes, 9.8 Perl interface; the macro library is
# scripts/gsi/granulab_gsi.py). The drum rests; its 30 walls carry a belt of surface speed v
# that drags the grains up on the right. Prints the gsi scene on stdout.
#   granulab run --allow-script examples/gc2d/drum.gsi.py --out out/drum_gsi
#   examples/gc2d/drum.gsi.py --speed 0.2 --time 0.5 > drum.gsi
#   granulab run --allow-script examples/gc2d/drum.gsi.py -P "--speed 0.2 --time 0.5"
# Units: [m], [m/s], [s].
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "gsi"))
from granulab_gsi import EOF, Comment, Display, General, drum, sphere  # noqa: E402

DRUM_RADIUS = 0.03  # [m] inner radius r
DRUM_WALL = 0.005  # [m] wall thickness d
DRUM_WALLS = 30  # N
GRAIN_RADIUS = 0.0015  # [m] circumradius of the grains (7 to 9 corners, gc2d's "8 +- 1")
GAP = 0.0002  # [m] clearance between neighbouring grains on the start lattice


def grain_centres(fill_height):
    """Hexagonal lattice points inside the drum, below y = fill_height [m], clear of the wall."""
    dx = 2 * GRAIN_RADIUS + GAP
    dy = dx * math.sqrt(3) / 2
    room = DRUM_RADIUS - GRAIN_RADIUS - GAP  # centres stay this far from the drum's centre
    centres = []
    row = 0
    y = -room
    while y <= fill_height:
        shift = 0.5 * dx if row % 2 else 0.0
        x = -room + shift
        while x <= room:
            if x * x + y * y <= room * room:
                centres.append((x, y))
            x += dx
        row += 1
        y += dy
    return centres


def main():
    ap = argparse.ArgumentParser(description="rotating drum (gc2d_drum) as gsi on stdout")
    ap.add_argument("--speed", type=float, default=0.1, help="belt speed v [m/s] (> 0: counter-clockwise)")
    ap.add_argument("--time", type=float, default=1.0,
                    help="end time [s] (about 10 s of computing per simulated second)")
    ap.add_argument("--fill", type=float, default=0.0, help="fill height [m] above the drum's centre")
    a = ap.parse_args()

    General("granulab example: rotating drum (gc2d_drum)",
            DELTA_T=1e-5, TIME=(0, a.time), E_MODUL=1e7, GAMMA=0.5, MUE_STATISCH=0.6,
            STEPS_DATA=1000, STEPS_CHECKPOINT=100000, BASENAME="drum", G=9.81)
    Comment(f"drum r = {DRUM_RADIUS} m, {DRUM_WALLS} walls, belt speed {a.speed} m/s")
    drum(DRUM_RADIUS, DRUM_WALL, 0.0, 0.0, a.speed, DRUM_WALLS)
    for i, (x, y) in enumerate(grain_centres(a.fill)):
        # 7, 8, 9 corners in turn, each grain turned a little (clockwise, gsi's sense) [rad]
        sphere(x, y, GRAIN_RADIUS, 7 + i % 3, ANGLE=0.37 * i % (2 * math.pi))
    Display(X_RANGE=(-0.04, 0.04), Y_RANGE=(-0.04, 0.04), SCREEN=(640, 0))
    EOF()


if __name__ == "__main__":
    main()
