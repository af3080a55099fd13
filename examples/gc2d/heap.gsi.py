#!/usr/bin/env python3
# A regular heap on a floor, written as a gc2d generator script (gc2d spec 6 "Perl heap library"
# heap.pm, 8.4 ordered piles, 9.8 Perl interface; the macro library is
# scripts/gsi/granulab_gsi.py): hexagonally stacked discs (regular polygons) or squares on a flat
# floor, with fixed walls two grains high at both feet (Oron's case c) unless --no-feet. Prints gsi
# on stdout. The default heap (78 discs) settles within 0.5 s.
#   granulab run --allow-script examples/gc2d/heap.gsi.py --out out/heap_gsi
#   examples/gc2d/heap.gsi.py --base 20 --shape squares > heap.gsi     (gc2d: -P "--base 20")
# Units: [m], [s]; --slope in degrees (converted to psi [rad]).
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "gsi"))
from granulab_gsi import EOF, Comment, General, heap_discs, heap_squares, rectangle  # noqa: E402

GRAIN = 0.002  # [m] disc circumradius r, or half the square's side
FLOOR_Y = 0.0  # [m] the floor's top


def main():
    ap = argparse.ArgumentParser(description="regular heap (heap.pm) as gsi on stdout")
    ap.add_argument("--base", type=int, default=12, help="grains in the bottom row")
    ap.add_argument("--corners", type=int, default=12, help="corners of a disc")
    ap.add_argument("--shape", choices=("discs", "squares"), default="discs")
    ap.add_argument("--stacking", choices=("hexagonal", "rectangular"), default="hexagonal")
    ap.add_argument("--slope", type=float, default=60.0,
                    help="flank slope psi [degrees]; hexagonal stacks take at most atan(2 dy/dx)")
    ap.add_argument("--no-feet", action="store_true", help="leave out the walls at the feet")
    ap.add_argument("--time", type=float, default=1.0, help="end time [s] (the heap settles within ~0.5 s)")
    a = ap.parse_args()
    if a.base < 1:
        ap.error("--base must be at least 1")

    width = a.base * 2 * GRAIN  # [m] the base: grains side by side, touching
    x_l, x_r = -0.5 * width, 0.5 * width
    psi = math.radians(a.slope)
    General("granulab example: regular heap (heap.pm)",
            DELTA_T=1e-5, TIME=(0, a.time), MUE_STATISCH=0.6, STEPS_DATA=1000, STEPS_CHECKPOINT=100000,
            BASENAME="heap", G=9.81)
    Comment(f"{a.stacking} heap of {a.shape}, {a.base} grains at the base, slope {a.slope} degrees")
    rectangle(0.0, FLOOR_Y - 0.0025, width + 0.04, 0.005, wall=True)  # the floor, 5 mm thick
    if not a.no_feet:  # 2 grains high, touching the outermost grains of the bottom row
        for side in (-1, 1):
            rectangle(side * (0.5 * width + 0.0025), FLOOR_Y + 2 * GRAIN, 0.005, 4 * GRAIN, wall=True)
    if a.shape == "discs":
        heap_discs(x_l, x_r, FLOOR_Y, psi, GRAIN, a.corners, stacking=a.stacking)
    else:  # squares of side 2 GRAIN with chamfered corners (regular stacks: spec 2.3)
        heap_squares(x_l, x_r, FLOOR_Y, psi, 2 * GRAIN, stacking=a.stacking, cut=0.1)
    EOF()


if __name__ == "__main__":
    main()
