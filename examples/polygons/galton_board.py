#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Galton board (gc2d spec section 8.2 item 7): writes galton_board.toml, or evaluates a run.

    python3 galton_board.py > galton_board.toml        # the bundled scene (same defaults)
    granulab run galton_board.toml --out out/galton --quiet
    python3 galton_board.py --evaluate out/galton       # bin counts, binomial, chi-square

The scene holds 2 x 23 identical boards side by side (they do not interact), each with 10 rows of
hexagonal nails and fed with 100 balls (16-gons, r = 1.5 mm) one at a time: 2300 balls with
p = 1/2 (boards 0-22) and 2300 with p = 2/3 (boards 23-45, nail tips shifted sideways).
Splitting the 2300 balls over 23 boards only makes the run 23 times shorter; the balls of
one board pass it one by one, 0.1 s apart (gc2d used a DROPSOURCE for this; granulab has no
particle source yet, so each board's balls wait in a row on a frictionless shelf, all sliding at
the same speed, and drop off its end in turn).

Board (all lengths in m; the same nails as the CI test PolygonScenes.GaltonBoard):
  nail    hexagon standing on a corner: 45-degree roof of half-width w = 2 mm, vertical flanks
          of length L = 20 mm, 45-degree bottom; neighbours leave a 4 mm channel
  rows    spaced h = roof + L + gap = 25 mm; row k has k + 1 nails d = 8 mm apart
  entry   two nails above the top one form an entry channel, so the first split is made like
          every other one (a ball bouncing down a channel meets the next tip at an unpredictable
          offset; the balls differ only by their random initial orientation)
  shell   one polyline per board: the inner halves of a column of guard nails left and right of
          the triangle, the bins (11, 60 mm deep) with thin dividers under the last row's nails
  p       the top corner of every nail in rows 0-9 is moved sideways by TIP_SHIFT * w; with the
          tip moved left (negative) more balls go right. TIP_SHIFT = -0.09 gives p = 2/3: on the
          6-row CI board 1800 single balls gave p = 0.667 +- 0.005 per row below the first
          (-0.08: 0.644, -0.096: 0.674); a full run of this scene with -0.10 measured 0.682.
          The run measures p itself (the mean bin / 10), see --evaluate.

Runs 14 s of simulated time (4600 balls, 1.4 million steps): roughly 15-20 minutes on one
core; --boards 2 (400 balls) about 80 s.
"""
import argparse
import csv
import math
import sys

ROWS = 10
D = 0.008          # nail spacing in a row
W = 0.002          # nail half-width
ROOF = 0.002       # roof height (45 degrees)
L = 0.020          # flank (channel) length
GAP = 0.003        # channel exit above the next tip
H = ROOF + L + GAP  # row spacing
R = 0.0015         # ball circumradius (16-gon)
BOARDS_PER_P = 23
BALLS_PER_BOARD = 100
SPACING = 0.6      # board to board
FEED_SPEED = 0.05  # shelf sliding speed [m/s]
FEED_PITCH = 0.005  # ball spacing on the shelf [m]: one ball every 0.1 s
FEED_DROP = 0.004  # shelf height above the entry nails' tips
FEED_EDGE = -0.0015  # shelf end relative to the board centre
TIP_SHIFT = {0.5: 0.0, 2.0 / 3.0: -0.09}
BIN_TOP = -(ROWS - 1) * H - 2 * ROOF - L
BIN_DEPTH = 0.06
END_TIME = 14.0    # last ball leaves the shelf at ~10 s, then ~3 s through the board


def nail(x, y, shift):
    return [(x + shift * W, y), (x - W, y - ROOF), (x - W, y - ROOF - L), (x, y - 2 * ROOF - L),
            (x + W, y - ROOF - L), (x + W, y - ROOF)]


def num(v):
    """Shortest text for v rounded to 10 um (all nail corners lie on a 0.1 mm grid)."""
    t = f"{v:.5f}".rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t


def points(pts):
    return "[" + ", ".join(f"[{num(x)}, {num(y)}]" for x, y in pts) + "]"


def board_walls(xc, shift):
    out = []
    for k in range(-1, ROWS):  # row -1: the two nails of the entry channel
        xs = [-D / 2, D / 2] if k < 0 else [(j - k / 2) * D for j in range(k + 1)]
        for x in xs:
            out.append(("closed", [(xc + px, py) for px, py in nail(x, -k * H, shift if k >= 0 else 0.0)]))
    left = []
    for k in range(ROWS):
        gx, y = -(k / 2 + 1) * D, -k * H
        if k == 0:
            left.append((gx, H + FEED_DROP - 0.002))
        left += [(gx, y), (gx + W, y - ROOF), (gx + W, y - ROOF - L), (gx, y - 2 * ROOF - L)]
    xl, bottom, thin = -(ROWS / 2 + 0.5) * D, BIN_TOP - BIN_DEPTH, 0.0002
    left.append((xl, bottom))
    shell = list(left)
    for m in range(1, ROWS + 1):
        x = xl + m * D
        shell += [(x - thin, bottom), (x - thin, BIN_TOP), (x + thin, BIN_TOP), (x + thin, bottom)]
    shell += [(-x, y) for x, y in reversed(left)]
    out.append(("open", [(xc + x, y) for x, y in shell]))
    edge = xc + FEED_EDGE
    out.append(("shelf", [(edge - (BALLS_PER_BOARD + 2) * FEED_PITCH, H + FEED_DROP), (edge, H + FEED_DROP)]))
    return out


def write_scene(seed):
    ps = sorted(TIP_SHIFT)
    print(f"""# Galton board, full size (gc2d spec section 8.2 item 7): 10 rows of hexagonal nails,
# 2300 balls with p = 1/2 and 2300 with p = 2/3. Generated by galton_board.py (see there and
# README.md for the geometry and how to evaluate a run). Boards 0-{BOARDS_PER_P - 1}: p = 1/2,
# boards {BOARDS_PER_P}-{2 * BOARDS_PER_P - 1}: p = 2/3; board b is centred at x = {SPACING} b m, its
# top nail's tip at y = 0, the bins between y = {BIN_TOP - BIN_DEPTH:.3f} and {BIN_TOP:.3f} m.
[run]
title = "Galton board, 10 rows, p = 1/2 and 2/3"
seed = {seed}
end_time = {END_TIME}

[dem]
dt = 1e-5
gravity = [0.0, -9.81]

[[material]]
name = "ball"
density = 5000

[[material]]
name = "nail"

[[contact]]
materials = ["*", "*"]    # frictionless: spinning balls would remember their direction
normal = "area"
E = 1e7
damping = "gamma"
gamma = 0.7

[[shape]]
name = "ball"
kind = "regular"
corner_count = 16
radius = {R}
rotation_mode = "equal"   # every ball gets a random orientation (from run.seed)

[output]
snapshot_interval = 0.5
series_interval = 0.05
""")
    y = H + FEED_DROP + R + 1e-5  # 10 um above the shelf
    for b in range(2 * BOARDS_PER_P):  # one row of balls per shelf, random orientations
        edge = b * SPACING + FEED_EDGE
        print(f"""[[block]]
shape = "ball"
lattice = "square"
region = [{num(edge - BALLS_PER_BOARD * FEED_PITCH)}, {num(y - 0.001)}, {num(edge)}, {num(y + 0.001)}]
origin = [{num(edge - 0.5 * FEED_PITCH)}, {num(y)}]
spacing = {FEED_PITCH}
velocity = [{FEED_SPEED}, 0]
material = "ball"
""", end="")
    for b in range(2 * BOARDS_PER_P):
        p = ps[0] if b < BOARDS_PER_P else ps[1]
        for kind, pts in board_walls(b * SPACING, TIP_SHIFT[p]):
            print('[[wall]]\nmaterial = "nail"' + ("\nclosed = true" if kind == "closed" else "") +
                  f"\npoints = {points(pts)}")


def binomial(n, k, p):
    return math.comb(n, k) * p ** k * (1 - p) ** (n - k)


def evaluate(folder):
    counts = {p: [0] * (ROWS + 1) for p in TIP_SHIFT}
    elsewhere = 0
    with open(f"{folder}/final.csv") as f:
        for row in csv.DictReader(f):
            x, y = float(row["x"]), float(row["y"])
            b = round(x / SPACING)
            k = math.floor((x - b * SPACING) / D + ROWS / 2 + 0.5)
            if 0 <= b < 2 * BOARDS_PER_P and 0 <= k <= ROWS and y < BIN_TOP:
                counts[sorted(TIP_SHIFT)[0 if b < BOARDS_PER_P else 1]][k] += 1
            else:
                elsewhere += 1
    # chi-square 1 % quantiles for 1..10 degrees of freedom
    crit = [6.635, 9.210, 11.345, 13.277, 15.086, 16.812, 18.475, 20.090, 21.666, 23.209]
    for p, obs in sorted(counts.items()):
        n = sum(obs)
        if n == 0:
            continue
        exp = [n * binomial(ROWS, k, p) for k in range(ROWS + 1)]
        mean = sum(k * c for k, c in enumerate(obs)) / n
        print(f"p = {p:.4f}: {n} balls; measured p = mean bin / {ROWS} = {mean / ROWS:.4f}")
        print("  bin       " + " ".join(f"{k:6d}" for k in range(ROWS + 1)))
        print("  counts    " + " ".join(f"{c:6d}" for c in obs))
        print("  binomial  " + " ".join(f"{e:6.1f}" for e in exp))
        po, pe, o, e = [], [], 0, 0
        for c, x in zip(obs, exp):  # pool bins until each expectation is >= 5
            o, e = o + c, e + x
            if e >= 5:
                po.append(o)
                pe.append(e)
                o = e = 0
        if e > 0:
            po[-1] += o
            pe[-1] += e
        chi = sum((a - b) ** 2 / b for a, b in zip(po, pe))
        dof = len(po) - 1
        verdict = "consistent with" if chi < crit[dof - 1] else "REJECTS"
        print(f"  chi2 = {chi:.2f} with {dof} dof; 1 % critical value {crit[dof - 1]}: {verdict} b_{{{ROWS},{p:.3f}}}")
    if elsewhere:
        print(f"{elsewhere} balls are not in a bin (run not finished?)")


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--evaluate", metavar="DIR", help="read DIR/final.csv and compare with b_{10,p}")
    ap.add_argument("--seed", type=int, default=1, help="run.seed: the balls' initial orientations")
    ap.add_argument("--boards", type=int, default=BOARDS_PER_P, help="boards per p (default %(default)s)")
    ap.add_argument("--balls", type=int, default=BALLS_PER_BOARD, help="balls per board (default %(default)s)")
    a = ap.parse_args()
    BOARDS_PER_P, BALLS_PER_BOARD = a.boards, a.balls
    END_TIME = round(BALLS_PER_BOARD * FEED_PITCH / FEED_SPEED + 4.0, 1)
    if a.evaluate:
        evaluate(a.evaluate)
    else:
        write_scene(a.seed)
        sys.stdout.flush()
