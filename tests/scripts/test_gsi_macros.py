#!/usr/bin/env python3
# Tests of scripts/gsi/granulab_gsi.py and xfig2gsi.py, the Python successor of gc2d's gsi.pm and
# macro libraries (gc2d spec 9.8, 2.3 deterministic shapes, 6 heap.pm, 6.2 drum, 6.5 XFig import;
# checklist item 54). The expected values come from the geometry (closed-form areas, radii,
# angles, counts), not from the code's own output. The last test feeds every example generator
# (examples/gc2d/*.gsi.py, sketch.fig through xfig2gsi.py) to `granulab info`.
# Usage: python3 tests/scripts/test_gsi_macros.py [GRANULAB_BINARY]   (or env GRANULAB_BINARY)
# Exit 77 (CTest SKIP_RETURN_CODE) when no binary is given and all else passed.
import io
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCRIPTS = os.path.join(ROOT, "scripts", "gsi")
XFIG_DATA = os.path.join(ROOT, "tests", "data", "xfig")
EXAMPLES = os.path.join(ROOT, "examples", "gc2d")
sys.path.insert(0, SCRIPTS)
import granulab_gsi as gsi  # noqa: E402

SKIP = 77
BINARY = None  # set in __main__


def collect(fn):
    """The gsi text that fn(writer) writes."""
    w = gsi.GsiWriter(out=False)
    fn(w)
    return w.text()


def edge_distance(centre, p, q):
    """Distance [m] from centre to the line through p and q."""
    (cx, cy), (px, py), (qx, qy) = centre, p, q
    return abs((qx - px) * (py - cy) - (px - cx) * (qy - py)) / math.hypot(qx - px, qy - py)


def corners_of(text):
    """The corner lists of the CORNERS blocks in gsi text."""
    blocks, current = [], None
    for line in text.splitlines():
        word = line.strip()
        if word == "CORNERS":
            current = []
        elif word == "END" and current is not None:
            blocks.append(current)
            current = None
        elif current is not None:
            x, y = word.split()
            current.append((float(x), float(y)))
    return blocks


def values_of(text, keyword):
    """The parameter lists of every `keyword` line."""
    return [[float(v) for v in line.split()[1:]] for line in text.splitlines()
            if line.strip().split()[:1] == [keyword]]


def close(a, b, rel=1e-12):
    """a equals b to round-off (relative)."""
    return abs(a - b) <= rel * max(abs(a), abs(b))


class Writer(unittest.TestCase):
    def test_header_lines_and_end(self):
        text = collect(lambda w: (w.general("run 1", DELTA_T=1.5e-5, TIME=(0, 0.2), BASENAME="data/x"),
                                  w.eof()))
        lines = text.splitlines()
        self.assertEqual(lines[0], "PARAMETER v1.4")
        self.assertEqual(lines[1], "run 1")
        self.assertEqual(lines[2:5], ["DELTA_T 1.5e-05", "TIME 0 0.2", "BASENAME data/x"])
        self.assertEqual(lines[-1], "END_OF_FILE")

    def test_empty_identification_is_line_2(self):
        self.assertEqual(collect(lambda w: w.general()).splitlines(), ["PARAMETER v1.4", ""])

    def test_general_must_come_first_and_once(self):
        w = gsi.GsiWriter(out=False)
        with self.assertRaises(RuntimeError):
            w.particle(gsi.square_corners(0, 0, 1))
        w.general()
        with self.assertRaises(RuntimeError):
            w.general()

    def test_floats_read_back_exactly(self):
        values = [0.1, 1 / 3, 2.5e-7, -math.pi, 6.02214076e23]
        text = collect(lambda w: w.general(SEED=(values[0], values[1]), DELTA_T=values[2],
                                           HEAT_AMPLITUDE=values[3], HEAT_SLOPE=values[4]))
        read = [v for line in text.splitlines()[2:] for v in map(float, line.split()[1:])]
        self.assertEqual(read, values)  # exact, not approximate

    def test_bad_keywords_are_refused(self):
        w = gsi.GsiWriter(out=False)
        w.general()
        with self.assertRaisesRegex(ValueError, "DELTA_T"):
            gsi.GsiWriter(out=False).general(DELTA_TT=1)  # did you mean
        with self.assertRaises(ValueError):
            w.particle(gsi.square_corners(0, 0, 1), VELOCITY=(1, 2, 3))
        with self.assertRaises(ValueError):
            w.particle(gsi.square_corners(0, 0, 1), COM=(0, float("nan")))
        with self.assertRaises(ValueError):
            w.wall(gsi.square_corners(0, 0, 1), VIB_TYPE="wobble")
        with self.assertRaises(ValueError):
            gsi.GsiWriter(out=False).general(STEPS_DATA=10.5)

    def test_comment_is_a_dollar_line(self):
        text = collect(lambda w: (w.general(), w.comment("hello world")))
        self.assertIn("$ hello world", text.splitlines())

    def test_corners_from_xs_ys_counter_clockwise(self):
        # Perl's Corners([xs], [ys]) given clockwise: written counter-clockwise
        def build(w):
            w.general()
            w.wall()
            w.corners([0, 0, 1, 1], [0, 1, 1, 0])
            with self.assertRaises(RuntimeError):  # one CORNERS block per object
                w.corners([0, 1, 1], [0, 0, 1])
        ring = corners_of(collect(build))[0]
        self.assertGreater(gsi.polygon_area(ring), 0)
        self.assertEqual(sorted(ring), [(0, 0), (0, 1), (1, 0), (1, 1)])

    def test_non_convex_and_degenerate_polygons_are_refused(self):
        w = gsi.GsiWriter(out=False)
        w.general()
        with self.assertRaisesRegex(ValueError, "not convex"):
            w.particle([(0, 0), (2, 0), (2, 2), (1, 0.5), (0, 2)])
        with self.assertRaisesRegex(ValueError, "collinear"):
            w.wall([(0, 0), (1, 0), (2, 0), (2, 2)])
        with self.assertRaisesRegex(ValueError, "at least 3"):
            w.wall([(0, 0), (1, 0)])

    def test_module_functions_print_to_stdout(self):
        buffer, old_stdout = io.StringIO(), sys.stdout
        old = gsi.set_default_writer(gsi.GsiWriter())
        sys.stdout = buffer
        try:
            gsi.General("x")
            gsi.Particle(gsi.sphere_corners(0, 0, 1, 5), COM=(1, 2))
            gsi.EOF()
        finally:
            sys.stdout = old_stdout
            gsi.set_default_writer(old)
        lines = buffer.getvalue().splitlines()
        self.assertEqual((lines[0], lines[1], lines[2], lines[-1]),
                         ("PARAMETER v1.4", "x", "PARTICLE", "END_OF_FILE"))
        self.assertIn("  COM 1 2", lines)


class Shapes(unittest.TestCase):
    def test_regular_polygon_area_and_radius(self):
        r = 0.003
        for n in (3, 7, 10, 20, 50, 64):
            ring = gsi.sphere_corners(0.1, -0.2, r, n)
            self.assertEqual(len(ring), n)
            self.assertTrue(close(gsi.polygon_area(ring), 0.5 * n * r * r * math.sin(2 * math.pi / n)))
            for x, y in ring:
                self.assertAlmostEqual(math.hypot(x - 0.1, y + 0.2), r, delta=1e-15)
        # the inscribed N-gon approaches pi r^2 from below: 1 - A/(pi r^2) ~ (2 pi / N)^2 / 6
        a50 = gsi.polygon_area(gsi.sphere_corners(0, 0, r, 50))
        self.assertLess(a50, math.pi * r * r)
        self.assertAlmostEqual(1 - a50 / (math.pi * r * r), (2 * math.pi / 50) ** 2 / 6, delta=1e-5)

    def test_every_shape_is_counter_clockwise_and_convex(self):
        shapes = [gsi.sphere_corners(0, 0, 1, 7), gsi.ellipse_corners(0, 0, 2, 1, 9, 0.4),
                  gsi.rectangle_corners(0, 0, 2, 1, 1.0), gsi.rectangle_cut_corners(0, 0, 2, 1, 0.2, 0.25),
                  gsi.rectangle_round_corners(0, 0, 2, 1, 0.3, 0.4, 5), gsi.square_corners(1, 1, 1),
                  gsi.square_cut_corners(0, 0, 1, 0, 0.5), gsi.square_round_corners(0, 0, 1, 0, 0.5, 4)]
        for ring in shapes:
            self.assertGreater(gsi.polygon_area(ring), 0)
            n = len(ring)
            for k in range(n):  # every turn is to the left
                (ax, ay), (bx, by), (cx, cy) = ring[k - 1], ring[k], ring[(k + 1) % n]
                self.assertGreater((bx - ax) * (cy - by) - (by - ay) * (cx - bx), 0)

    def test_ellipse_area_and_semi_axes(self):
        n, r1, r2 = 20, 0.004, 0.0015
        ring = gsi.ellipse_corners(0, 0, r1, r2, n)
        # affine image of the regular n-gon: area (n/2) r1 r2 sin(2 pi / n)
        self.assertTrue(close(gsi.polygon_area(ring), 0.5 * n * r1 * r2 * math.sin(2 * math.pi / n)))
        self.assertAlmostEqual(max(x for x, _ in ring), r1, delta=1e-18)
        self.assertAlmostEqual(max(y for _, y in ring), r2, delta=1e-18)

    def test_angle_turns_clockwise(self):
        # gsi ANGLE convention (spec 2.1): the ellipse's first corner (r1, 0) turned by pi/2
        # clockwise lies at (0, -r1)
        x, y = gsi.ellipse_corners(0, 0, 2.0, 1.0, 8, math.pi / 2)[0]
        self.assertAlmostEqual(x, 0, delta=1e-15)
        self.assertAlmostEqual(y, -2.0, delta=1e-15)

    def test_rectangle_area_and_turned_extent(self):
        a, b = 0.004, 0.002
        self.assertTrue(close(gsi.polygon_area(gsi.rectangle_corners(0.5, 0.5, a, b)), a * b))
        ring = gsi.rectangle_corners(0, 0, a, b, math.pi / 2)
        self.assertAlmostEqual(max(x for x, _ in ring) - min(x for x, _ in ring), b, delta=1e-15)
        self.assertAlmostEqual(max(y for _, y in ring) - min(y for _, y in ring), a, delta=1e-15)

    def test_cut_rectangle(self):
        a, b, c = 0.004, 0.002, 0.2
        ring = gsi.rectangle_cut_corners(0, 0, a, b, 0, c)
        self.assertEqual(len(ring), 8)
        # four corner triangles (c a) x (c b) / 2 removed
        self.assertTrue(close(gsi.polygon_area(ring), a * b * (1 - 2 * c * c)))
        lengths = sorted(math.dist(ring[k], ring[(k + 1) % 8]) for k in range(8))
        self.assertAlmostEqual(lengths[-1], a * (1 - 2 * c), delta=1e-15)  # the shortened a edges
        self.assertIn(round(b * (1 - 2 * c), 12), [round(v, 12) for v in lengths])

    def test_round_rectangle(self):
        a, b, r = 0.004, 0.002, 0.0005
        for n in (2, 3, 6, 200):
            ring = gsi.rectangle_round_corners(0, 0, a, b, 0, r, n)
            # corners: each quarter circle is a fan of (n - 1) triangles of angle pi / (2 (n - 1))
            exact = a * b - 4 * r * r + 2 * (n - 1) * r * r * math.sin(math.pi / (2 * (n - 1)))
            self.assertTrue(close(gsi.polygon_area(ring), exact))
            self.assertAlmostEqual(max(x for x, _ in ring), a / 2, delta=1e-18)
            self.assertAlmostEqual(max(y for _, y in ring), b / 2, delta=1e-18)
        # many corners: a b - (4 - pi) r^2
        self.assertAlmostEqual(gsi.polygon_area(ring), a * b - (4 - math.pi) * r * r, delta=1e-11)

    def test_squares_are_rectangles_with_equal_sides(self):
        self.assertEqual(gsi.square_corners(1, 2, 0.5, 0.3), gsi.rectangle_corners(1, 2, 0.5, 0.5, 0.3))
        self.assertAlmostEqual(gsi.polygon_area(gsi.square_cut_corners(0, 0, 1, 0, 0.5)), 0.5, delta=1e-15)

    def test_emitted_particle_sits_at_its_centre(self):
        text = collect(lambda w: (w.general(), gsi.sphere(0.01, 0.02, 0.001, 6, writer=w, VELOCITY=(0.5, 0))))
        self.assertEqual(values_of(text, "COM"), [[0.01, 0.02]])
        self.assertEqual(values_of(text, "VELOCITY"), [[0.5, 0.0]])
        ring = corners_of(text)[0]  # corners about the centroid
        cx, cy = gsi.polygon_centroid(ring)
        self.assertAlmostEqual(cx, 0, delta=1e-18)
        self.assertAlmostEqual(cy, 0, delta=1e-18)

    def test_wall_variant_has_absolute_corners(self):
        text = collect(lambda w: (w.general(), gsi.sphere_wall(0.01, 0.02, 0.001, 4, writer=w)))
        self.assertIn("WALL", text.splitlines())
        expected = sorted([(0.011, 0.02), (0.01, 0.021), (0.009, 0.02), (0.01, 0.019)])
        for (x, y), (ex, ey) in zip(sorted(corners_of(text)[0]), expected):
            self.assertAlmostEqual(x, ex, delta=1e-15)
            self.assertAlmostEqual(y, ey, delta=1e-15)


class Drum(unittest.TestCase):
    R, D, X, Y, V, N = 0.05, 0.01, 0.1, -0.2, 0.25, 36

    def test_ring_of_n_walls_closes_at_inner_radius(self):
        rings = gsi.drum_corners(self.R, self.D, self.X, self.Y, self.N)
        self.assertEqual(len(rings), self.N)
        centre = (self.X, self.Y)
        swept = 0.0
        for k, ring in enumerate(rings):
            inner0, outer0, outer1, inner1 = ring
            self.assertGreater(gsi.polygon_area(ring), 0)
            self.assertAlmostEqual(edge_distance(centre, inner0, inner1), self.R, delta=1e-15)
            self.assertAlmostEqual(edge_distance(centre, outer0, outer1), self.R + self.D, delta=1e-15)
            a0 = math.atan2(inner0[1] - self.Y, inner0[0] - self.X)
            a1 = math.atan2(inner1[1] - self.Y, inner1[0] - self.X)
            swept += (a1 - a0) % (2 * math.pi)
            following = rings[(k + 1) % self.N]  # neighbours share their radial edge
            self.assertAlmostEqual(math.dist(inner1, following[0]), 0, delta=1e-15)
            self.assertAlmostEqual(math.dist(outer1, following[1]), 0, delta=1e-15)
        self.assertAlmostEqual(swept, 2 * math.pi, delta=1e-12)

    def test_surface_velocity_is_tangential_with_magnitude_v(self):
        text = collect(lambda w: (w.general(),
                                  gsi.drum(self.R, self.D, self.X, self.Y, self.V, self.N, writer=w)))
        self.assertEqual(text.splitlines().count("WALL"), self.N)
        velocities = values_of(text, "VELOCITY")
        rings = corners_of(text)
        self.assertEqual((len(velocities), len(rings)), (self.N, self.N))
        for (vx, vy), ring in zip(velocities, rings):
            self.assertAlmostEqual(math.hypot(vx, vy), self.V, delta=1e-15)
            inner = [p for p in ring if math.hypot(p[0] - self.X, p[1] - self.Y) < self.R * 1.1]
            self.assertEqual(len(inner), 2)
            (px, py), (qx, qy) = inner
            mx, my = 0.5 * (px + qx) - self.X, 0.5 * (py + qy) - self.Y
            self.assertAlmostEqual(vx * mx + vy * my, 0, delta=1e-15)  # perpendicular to the radius
            self.assertAlmostEqual(vx * (qy - py) - vy * (qx - px), 0, delta=1e-15)  # along the edge
            self.assertGreater(mx * vy - my * vx, 0)  # v > 0: counter-clockwise

    def test_negative_speed_turns_the_belt_around(self):
        self.assertEqual(gsi.drum_velocity(3, 12, -1.0), tuple(-v for v in gsi.drum_velocity(3, 12, 1.0)))


class Heaps(unittest.TestCase):
    dx, dy = 1.0, 0.8

    def test_hexagonal_at_the_steepest_flank_loses_one_grain_per_row(self):
        # 10 grains on the base; psi = atan(2 dy / dx): each row half a grain narrower per side
        rows = gsi.heap_rows_hexagonal(0, 10, 0.5, math.atan(2 * self.dy / self.dx), self.dx, self.dy)
        self.assertEqual([len(r) for r in rows], list(range(10, 0, -1)))
        self.assertEqual(sum(len(r) for r in rows), 55)

    def test_hexagonal_grains_rest_on_two_below(self):
        rows = gsi.heap_rows_hexagonal(0, 12, 0, math.radians(40), self.dx, self.dy)
        for k in range(1, len(rows)):
            below = [x for x, _ in rows[k - 1]]
            for x, y in rows[k]:
                self.assertAlmostEqual(y - rows[k - 1][0][1], self.dy)
                self.assertEqual(sum(1 for b in below if abs(abs(x - b) - self.dx / 2) < 1e-9), 2)

    def test_hexagonal_gentle_flank(self):
        # tan psi = dy / dx: the outline narrows by dx per side and row, widths 10, 8, 6, 4, 2 dx.
        # A hexagonal row has an odd number less than the row below (it sits in the gaps): 10,
        # then the largest of 9, 7, ... fitting 8 dx -> 7; then <= 6 dx of 6, 4, .. -> 6; 3; 2.
        rows = gsi.heap_rows_hexagonal(0, 10, 0, math.atan(self.dy / self.dx), self.dx, self.dy)
        self.assertEqual([len(r) for r in rows], [10, 7, 6, 3, 2])

    def test_rectangular_columns(self):
        # tan psi = dy / dx: widths 10, 8, 6, 4, 2 dx; columns stay aligned
        rows = gsi.heap_rows_rectangular(0, 10, 0, math.atan(self.dy / self.dx), self.dx, self.dy)
        self.assertEqual([len(r) for r in rows], [10, 8, 6, 4, 2])
        columns = {round(x, 9) for x, _ in rows[0]}
        for row in rows:
            self.assertTrue({round(x, 9) for x, _ in row} <= columns)

    def test_rows_are_symmetric_and_inside_the_outline(self):
        psi = math.radians(35)
        for rows in (gsi.heap_rows_hexagonal(-3, 7, 0, psi, 1, 0.9),
                     gsi.heap_rows_rectangular(-3, 7, 0, psi, 1, 0.9)):
            for k, row in enumerate(rows):
                inset = k * 0.9 / math.tan(psi)
                self.assertGreaterEqual(row[0][0] - 0.5, -3 + inset - 1e-9)
                self.assertLessEqual(row[-1][0] + 0.5, 7 - inset + 1e-9)
                self.assertAlmostEqual(row[0][0] + row[-1][0], 4.0)  # symmetric about x = 2

    def test_disc_heap_writes_one_particle_per_grain_on_the_floor(self):
        r, n0 = 0.002, 8
        text = collect(lambda w: (w.general(),
                                  gsi.heap_discs(0, 2 * r * n0, 0.01, math.radians(60), r, 10, writer=w)))
        # discs: dy = sqrt(3) r, dx = 2 r, so tan 60 deg = 2 dy / dx exactly: 8 + 7 + ... + 1
        self.assertEqual(text.splitlines().count("PARTICLE"), 36)
        heights = sorted({round(y, 12) for _, y in values_of(text, "COM")})
        self.assertAlmostEqual(heights[0], 0.01 + r)  # the bottom row rests on y0
        self.assertAlmostEqual(heights[1] - heights[0], math.sqrt(3) * r)

    def test_core_routine_calls_cmd_per_grain(self):
        seen = []
        gsi.heap_rectangular(0, 4, 0, math.radians(80), 1, 1, lambda x, y: seen.append((x, y)))
        rows = gsi.heap_rows_rectangular(0, 4, 0, math.radians(80), 1, 1)
        self.assertEqual(len(seen), sum(len(r) for r in rows))


class Xfig(unittest.TestCase):
    UNIT = 0.0254 / 1200 / 10  # [m] per xfig unit at 1200 units per inch and scale 10:1

    def read(self, name, **options):
        warnings = []
        objects = gsi.read_xfig(os.path.join(XFIG_DATA, name), warn=warnings.append, **options)
        return objects, warnings

    def test_kinds_lines_and_warnings(self):
        objects, warnings = self.read("small.fig")
        self.assertEqual([(o.kind, o.line) for o in objects],
                         [("PARTICLE", 12), ("WALL", 15), ("WALL", 22), ("PARTICLE", 29)])
        self.assertEqual(len(warnings), 4)
        for warning, where in zip(warnings, ("18: open polyline", "27: ellipse", "35: spline", "39: arc")):
            self.assertIn(f"small.fig:{where}", warning)

    def test_any_fill_makes_a_particle_on_request(self):
        objects, _ = self.read("small.fig", particles="filled")
        self.assertEqual([o.kind for o in objects], ["PARTICLE", "WALL", "PARTICLE", "PARTICLE"])

    def test_y_negated_and_scaled(self):
        box = self.read("small.fig")[0][0].corners
        u = self.UNIT
        self.assertEqual(len(box), 4)  # the closing point is dropped
        expected = {(1200 * u, -1200 * u), (2400 * u, -1200 * u),
                    (2400 * u, -2400 * u), (1200 * u, -2400 * u)}
        for x, y in box:
            self.assertTrue(any(abs(x - ex) < 1e-15 and abs(y - ey) < 1e-15 for ex, ey in expected), (x, y))
        self.assertAlmostEqual(2400 * u, 0.00508, delta=1e-15)  # 2 inches drawn = 5.08 mm real
        self.assertGreater(gsi.polygon_area(box), 0)  # counter-clockwise after the flip

    def test_scale_resolution_and_offset(self):
        base = self.read("small.fig")[0][1].corners
        one = self.read("small.fig", scale="1:1")[0][1].corners
        self.assertEqual([(round(x * 10, 15), round(y * 10, 15)) for x, y in base],
                         [(round(x, 15), round(y, 15)) for x, y in one])
        coarse = self.read("small.fig", resolution=600, offset=(1.0, 2.0))[0][1].corners
        self.assertEqual([(round(2 * x + 1, 12), round(2 * y + 2, 12)) for x, y in base],
                         [(round(x, 12), round(y, 12)) for x, y in coarse])
        self.assertEqual(gsi.parse_scale("10:1"), 10)
        self.assertEqual(gsi.parse_scale("1:10"), 0.1)

    def test_malformed_files_name_their_line(self):
        cases = {"bad_points.fig": 13, "bad_number.fig": 11, "nonconvex.fig": 11}
        for name, line in cases.items():
            with self.assertRaises(gsi.XfigError) as caught:
                self.read(name)
            self.assertEqual(caught.exception.line, line, name)
            self.assertIn(f"{name}:{line}:", str(caught.exception))

    def test_bad_header_and_truncated_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = os.path.join(tmp, "old.fig")
            with open(bad, "w") as f:
                f.write("#FIG 2.1\n80 2\n")
            with self.assertRaisesRegex(gsi.XfigError, r"old\.fig:1:"):
                gsi.read_xfig(bad)
            cut = os.path.join(tmp, "cut.fig")
            with open(os.path.join(XFIG_DATA, "small.fig")) as f:
                lines = f.read().splitlines()[:12]  # ends after the first box's header
            with open(cut, "w") as f:
                f.write("\n".join(lines) + "\n")
            with self.assertRaisesRegex(gsi.XfigError, r"cut\.fig:12: the file ends"):
                gsi.read_xfig(cut)

    def test_cli_exit_status_and_output(self):
        cli = os.path.join(SCRIPTS, "xfig2gsi.py")
        bad = subprocess.run([sys.executable, cli, os.path.join(XFIG_DATA, "bad_points.fig")],
                             capture_output=True, text=True)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("bad_points.fig:13:", bad.stderr)
        self.assertEqual(bad.stdout, "")
        good = subprocess.run([sys.executable, cli, os.path.join(XFIG_DATA, "small.fig"),
                               "--set", "TIME=0,0.5"], capture_output=True, text=True)
        self.assertEqual(good.returncode, 0, good.stderr)
        lines = good.stdout.splitlines()
        self.assertEqual((lines[0], lines[-1]), ("PARAMETER v1.4", "END_OF_FILE"))
        self.assertIn("TIME 0.0 0.5", lines)
        self.assertEqual((lines.count("PARTICLE"), lines.count("WALL")), (2, 2))
        self.assertEqual(lines.count("  POSITION_ABSOLUT"), 2)


class Examples(unittest.TestCase):
    def generators(self):
        """(name, argv) of every example: the scripts with and without arguments, the sketch."""
        py = sys.executable
        return [
            ("drum.gsi.py", [py, os.path.join(EXAMPLES, "drum.gsi.py")]),
            ("drum.gsi.py --speed -0.2 --time 0.05", [py, os.path.join(EXAMPLES, "drum.gsi.py"),
                                                      "--speed", "-0.2", "--time", "0.05"]),
            ("heap.gsi.py", [py, os.path.join(EXAMPLES, "heap.gsi.py")]),
            ("heap.gsi.py --shape squares --stacking rectangular --slope 70",
             [py, os.path.join(EXAMPLES, "heap.gsi.py"), "--shape", "squares", "--stacking", "rectangular",
              "--slope", "70"]),
            ("xfig2gsi.py sketch.fig", [py, os.path.join(SCRIPTS, "xfig2gsi.py"),
                                        os.path.join(EXAMPLES, "sketch.fig"),
                                        "--set", "TIME=0,0.05", "--set", "DELTA_T=1e-5"]),
        ]

    def test_scripts_are_executable_python(self):
        for name in ("drum.gsi.py", "heap.gsi.py"):
            path = os.path.join(EXAMPLES, name)
            self.assertTrue(os.access(path, os.X_OK), f"{path} is not executable (chmod +x)")
            with open(path) as f:
                self.assertEqual(f.readline().strip(), "#!/usr/bin/env python3")

    def test_granulab_accepts_every_example(self):
        if not BINARY:
            self.skipTest("no granulab binary given (argv[1] or GRANULAB_BINARY)")
        with tempfile.TemporaryDirectory() as tmp:
            for k, (name, argv) in enumerate(self.generators()):
                made = subprocess.run(argv, capture_output=True, text=True, timeout=60)
                self.assertEqual(made.returncode, 0, f"{name}: {made.stderr}")
                scene = os.path.join(tmp, f"scene{k}.gsi")
                with open(scene, "w") as f:
                    f.write(made.stdout)
                info = subprocess.run([BINARY, "info", scene], capture_output=True, text=True, timeout=60)
                self.assertEqual(info.returncode, 0, f"{name}: granulab info: {info.stdout}{info.stderr}")


if __name__ == "__main__":
    if len(sys.argv) > 1:
        BINARY = sys.argv.pop(1)
    else:
        BINARY = os.environ.get("GRANULAB_BINARY") or None
    result = unittest.main(exit=False, verbosity=1).result
    if not result.wasSuccessful():
        sys.exit(1)
    sys.exit(SKIP if not BINARY else 0)
