# granulab_gsi: gc2d scene generators in Python 3 -- the successor of gc2d's Perl `gsi.pm` and its
# macro libraries (gc2d spec, shared/spec/gc2d.md):
#   9.8  Perl/preprocessor interface (App. D.1-D.2: gsi.pm): General first, one function per object,
#        Comment ('$' line), Macro (no-op), Corners([xs], [ys]), EOF;
#   9.2  gsi syntax, 9.3 keywords (tables below);
#   2.1  polygons are convex and counter-clockwise;
#   2.3  "Deterministic shapes (Perl macro libraries, App. D.3-D.5)": spheres, ellipses, rectangles
#        (cut, round), squares;
#   6    "Perl heap library (heap.pm, App. D.6)": regular hexagonal / rectangular piles;
#   6.2  rotating drum (App. D.7, drum.pm): gc2d_drum(r, d, x, y, v, N);
#   6.5  XFig import (gc2d_read_xfig, App. D.8), "Drawing scale 10:1";
#   10   checklist item 54.
# Standard library only. Units: lengths [m], velocities [m/s], angles [rad]. Rotation angles (phi,
# gsi ANGLE) turn CLOCKWISE, as in gc2d (spec 2.1); direction angles are counter-clockwise from +x.
# granulab runs a script that prints gsi with `granulab run --allow-script scene.gsi.py -P "args"`.
# The reference of every function: docs/coming-from-gc2d.md "Generator scripts and the macro
# library".
"""gc2d scene generation (gsi writer, shape/heap/drum macros, XFig import) for granulab."""

import difflib
import math
import sys

__all__ = [
    # writer (gsi.pm)
    "GsiWriter", "default_writer", "set_default_writer",
    "General", "Particle", "Wall", "GenerateBlock", "DropSource", "Display", "Keyword",
    "Corners", "Comment", "Remark", "Macro", "EOF",
    # geometry
    "polygon_area", "polygon_centroid", "convex_ccw", "is_counter_clockwise",
    # shapes (App. D.3-D.5)
    "sphere_corners", "ellipse_corners", "rectangle_corners", "rectangle_cut_corners",
    "rectangle_round_corners", "square_corners", "square_cut_corners", "square_round_corners",
    "sphere", "sphere_wall", "sphere7", "sphere10", "sphere20", "sphere50",
    "ellipse", "ellipse_wall", "ellipse7", "ellipse10", "ellipse20", "ellipse50",
    "rectangle", "rectangle_cut", "rectangle_round", "square", "square_cut", "square_round",
    # drum (App. D.7)
    "drum_corners", "drum_velocity", "drum",
    # heaps (App. D.6)
    "heap_rows_hexagonal", "heap_rows_rectangular", "heap_hexagonal", "heap_rectangular",
    "heap_discs", "heap_rectangles", "heap_squares",
    # XFig (App. D.8)
    "XfigError", "XfigObject", "parse_scale", "read_xfig", "xfig_to_gsi",
]

GSI_VERSION_LINE = "PARAMETER v1.4"  # spec 9.2: line 1, the version check
MAX_LINE = 1023  # spec 9.2: gc2d's longest line [characters]


# ------------------------------------------------------------------------------------------------
# Keyword tables (spec 9.3; the same as granulab's reader, src/io/gsi_syntax.cpp)
# ------------------------------------------------------------------------------------------------

# A keyword's parameters: ("num", n) n numbers; ("whole", n) n whole numbers; ("text",) one word,
# case kept; ("choice", words); ("flag",) no parameter; ("gravity",) one or two numbers.
_DISTRIBUTION = ("CONST", "EQUAL", "GAUSS")
_GRAIN_SHAPE = {
    "PART_SIZE": ("num", 2), "PART_VAR_SIZE": ("num", 1), "RANDOM_SIZE": ("choice", _DISTRIBUTION),
    "PART_NUM_CORNERS": ("whole", 1), "PART_VAR_CORNERS": ("whole", 1),
    "RANDOM_NUM_CORNERS": ("choice", _DISTRIBUTION), "PART_RANDOM_NUM_CORNERS": ("choice", _DISTRIBUTION),
    "PART_RANDOM_POS_CORNERS": ("choice", ("SPECIAL_RECTANGLE", "REGULAR", "RAND1", "RAND2", "FULL")),
    "RANDOM_POS_CORNERS": ("choice", ("SPECIAL_RECTANGLE", "REGULAR", "RAND1", "RAND2", "FULL")),
    "PART_ROT": ("num", 1), "RANDOM_ROT": ("choice", _DISTRIBUTION),
}
KEYWORDS = {
    "GENERAL": {
        "DELTA_T": ("num", 1), "TIME": ("num", 2), "MUE_STATISCH": ("num", 1),
        "MUE_DYNAMISCH": ("num", 1), "E_MODUL": ("num", 1), "GAMMA": ("num", 1),
        "COHESION": ("num", 1), "STEPS_DATA": ("whole", 1), "STEPS_CHECKPOINT": ("whole", 1),
        "STEPS_SETUP": ("whole", 1), "STEPS_DUMPLINE": ("whole", 1), "SEED": ("num", 2),
        "BASENAME": ("text",), "EMAIL": ("text",), "NEXT_DATA_FILENUMBER": ("whole", 1),
        "NEXT_SETUP_FILENUMBER": ("whole", 1), "G": ("gravity",), "G_TIME": ("num", 2),
        "G_PARAMETER": ("num", 2), "G_TYPE": ("choice", ("CONSTANT", "LINEAR", "STEP", "SMOOTH_STEP")),
        "HEAT_TIME": ("num", 2), "HEAT_AMPLITUDE": ("num", 1), "HEAT_FREQUENCE": ("num", 1),
        "HEAT_SLOPE": ("num", 1),
    },
    "DISPLAY": {
        "X_RANGE": ("num", 2), "Y_RANGE": ("num", 2), "SCREEN": ("num", 2),
        "INTERVAL": ("whole", 1), "MODUS": ("whole", 1),
    },
    "PARTICLE": {
        "COM": ("num", 2), "POSITION_ABSOLUT": ("flag",), "ANGLE": ("num", 1), "OMEGA": ("num", 1),
        "OMEGA_DOT": ("num", 1), "VELOCITY": ("num", 2), "ACCELERATION": ("num", 2),
        "PC_TRANS3": ("num", 2), "PC_TRANS4": ("num", 2), "PC_TRANS5": ("num", 2),
        "PC_ROT3": ("num", 1), "PC_ROT4": ("num", 1), "PC_ROT5": ("num", 1), "ID": ("whole", 1),
        "DRAG_ANGLE": ("num", 1), "DRAG_VELOCITY": ("num", 1), "DRAG_K": ("num", 1),
        "DRAG_TIME": ("num", 2), "DRAG_FIXING_POINT": ("num", 2), "DRAG_PULLING_POINT": ("num", 2),
    },
    "WALL": {
        "OFFSET": ("num", 2), "ANGLE": ("num", 1), "VELOCITY": ("num", 2), "ID": ("whole", 1),
        "PISTON_ANGLE": ("num", 1), "PISTON_FORCE": ("num", 1), "PISTON_V_MAX": ("num", 1),
        "VIB_ANGLE": ("num", 1), "VIB_TIME": ("num", 2), "VIB_WIDTH": ("num", 1),
        "VIB_FREQUENCE": ("num", 1), "VIB_TYPE": ("choice", ("COSINUS", "SAWTOOTH", "TAPPING", "TRIANGLE")),
    },
    "GENERATE_BLOCK": dict(_GRAIN_SHAPE, **{
        "X_RANGE": ("num", 2), "Y_RANGE": ("num", 2), "GRID_DISTANCE": ("num", 2),
        "GRID_TYPE": ("choice", ("RECT", "RECT_GAUSS", "RECT_EQUAL", "FCC", "FCC_GAUSS", "FCC_EQUAL")),
        "ANGLE_RANGE": ("num", 2), "VELOCITY_RANGE": ("num", 2),
    }),
    "DROPSOURCE": dict(_GRAIN_SHAPE, **{
        "POS": ("num", 2), "WIDTH": ("num", 1), "TYPE": ("choice", ("ABS", "REL")),
        "TIME": ("num", 2), "DELTA_T": ("num", 1),
    }),
}
_OBJECTS_WITH_CORNERS = ("PARTICLE", "WALL")


# ------------------------------------------------------------------------------------------------
# Number formatting
# ------------------------------------------------------------------------------------------------

def format_number(value, whole=False, keyword="value"):
    """gsi text of one number: repr-exact for floats (the shortest text that reads back to the same
    double), plain digits for integers. Refuses NaN, infinities and non-numbers (ValueError)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        try:
            value = float(value)  # e.g. fractions.Fraction, decimal.Decimal
        except (TypeError, ValueError):
            raise ValueError(f"{keyword}: {value!r} is not a number") from None
    if isinstance(value, int):
        return str(value)
    if not math.isfinite(value):
        raise ValueError(f"{keyword}: {value!r} is not a finite number")
    if whole:
        if value != math.floor(value):
            raise ValueError(f"{keyword}: {value!r} is not a whole number")
        return str(int(value))
    return repr(float(value))


# ------------------------------------------------------------------------------------------------
# Polygon geometry (spec 2.1: convex, counter-clockwise)
# ------------------------------------------------------------------------------------------------

def polygon_area(corners):
    """Signed area [m^2] by the shoelace formula: > 0 for counter-clockwise corners."""
    n = len(corners)
    if n == 0:
        return 0.0
    ox, oy = corners[0]  # relative to a corner: less round-off far from the origin
    twice = 0.0
    for k in range(n):
        x0, y0 = corners[k][0] - ox, corners[k][1] - oy
        x1, y1 = corners[(k + 1) % n][0] - ox, corners[(k + 1) % n][1] - oy
        twice += x0 * y1 - x1 * y0
    return 0.5 * twice


def polygon_centroid(corners):
    """Area centroid (x, y) [m] of a simple polygon (spec 2.2)."""
    n = len(corners)
    area2 = cx = cy = 0.0
    ox, oy = corners[0]  # relative to a corner: less round-off far from the origin
    for k in range(n):
        x0, y0 = corners[k][0] - ox, corners[k][1] - oy
        x1, y1 = corners[(k + 1) % n][0] - ox, corners[(k + 1) % n][1] - oy
        c = x0 * y1 - x1 * y0
        area2 += c
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    if area2 == 0:
        raise ValueError("the polygon has zero area")
    return ox + cx / (3 * area2), oy + cy / (3 * area2)


def is_counter_clockwise(corners):
    """True when the corners run counter-clockwise (positive signed area)."""
    return polygon_area(corners) > 0


def _as_points(corners, what):
    """The corners as a list of float pairs; ValueError for anything else."""
    points = []
    for k, c in enumerate(corners):
        try:
            x, y = c
            x, y = float(x), float(y)
        except (TypeError, ValueError):
            raise ValueError(f"{what}: corner {k} is not an (x, y) pair: {c!r}") from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"{what}: corner {k} is not finite: ({x!r}, {y!r})")
        points.append((x, y))
    return points


def _drop_repeats(points, eps2):
    """The points without consecutive repeats (also last == first), a closed ring."""
    out = []
    for p in points:
        if not out or (p[0] - out[-1][0]) ** 2 + (p[1] - out[-1][1]) ** 2 > eps2:
            out.append(p)
    while len(out) > 1 and (out[0][0] - out[-1][0]) ** 2 + (out[0][1] - out[-1][1]) ** 2 <= eps2:
        out.pop()
    return out


def _tolerance(points):
    """Squared-length tolerance [m^2] of granulab's convexity check (geom/polygon.cpp)."""
    scale = max(max(abs(x), abs(y)) for x, y in points)
    return 1e-12 * max(scale * scale, 1e-300)


def convex_ccw(corners, what="polygon", drop_repeats=False):
    """The corners as a counter-clockwise convex polygon: reversed when given clockwise.

    ValueError (naming `what` and the corner index as given) for fewer than 3 corners, repeated
    or collinear corners, a non-convex or self-intersecting polygon -- the checks granulab makes
    (a gsi file with such a polygon is refused). drop_repeats=True first removes consecutive
    repeated corners (a closing corner equal to the first one too)."""
    points = _as_points(corners, what)
    if len(points) >= 1 and drop_repeats:
        points = _drop_repeats(points, _tolerance(points))
    n = len(points)
    if n < 3:
        raise ValueError(f"{what}: a polygon needs at least 3 corners, got {n}")
    eps = _tolerance(points)
    for k in range(n):
        (x0, y0), (x1, y1) = points[k], points[(k + 1) % n]
        if (x1 - x0) ** 2 + (y1 - y0) ** 2 <= eps:
            raise ValueError(f"{what}: corner {(k + 1) % n} repeats its neighbour (duplicate corner)")
    area = polygon_area(points)
    if area == 0:
        raise ValueError(f"{what}: the polygon has zero area")
    clockwise = area < 0
    ring = list(reversed(points)) if clockwise else points
    turning = 0.0
    for k in range(n):
        (ax, ay), (bx, by), (cx, cy) = ring[k - 1], ring[k], ring[(k + 1) % n]
        turn = (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
        index = n - 1 - k if clockwise else k
        if abs(turn) <= eps:
            raise ValueError(f"{what}: corner {index} lies on the line through its neighbours (collinear)")
        if turn < 0:
            raise ValueError(f"{what}: the polygon is not convex at corner {index}")
        turning += math.atan2(turn, (bx - ax) * (cx - bx) + (by - ay) * (cy - by))
    if turning > 2 * math.pi + 1e-6:
        raise ValueError(f"{what}: the corners wind around more than once (self-intersecting)")
    return ring


def _rotate_clockwise(points, phi):
    """Points turned clockwise by phi [rad] about the origin (spec 2.1, Eq. 2.35)."""
    if phi == 0:
        return list(points)
    c, s = math.cos(phi), math.sin(phi)
    return [(x * c + y * s, -x * s + y * c) for x, y in points]


def _translate(points, x, y):
    return [(px + x, py + y) for px, py in points]


# ------------------------------------------------------------------------------------------------
# The writer (gsi.pm, spec 9.8)
# ------------------------------------------------------------------------------------------------

class GsiWriter:
    """Builds gsi text, one object at a time, and writes it to `out` (a text stream; None: the
    sys.stdout of the moment of writing) or, with out=False, only keeps it (see text()).

    Order (spec 9.2): general() first (lines 1-2 and the GENERAL keywords), then any number of
    particle / wall / generate_block / drop_source / display objects, then eof(). Keywords are
    Python keyword arguments in any case (Delta_T=1e-5 is DELTA_T); a tuple or list gives several
    parameters (TIME=(0, 0.5)), True a flag (POSITION_ABSOLUT=True), False or None leaves the
    keyword out. Unknown keywords, wrong parameter counts, non-finite numbers and bad choice words
    raise ValueError before anything of the object is written."""

    def __init__(self, out=None):
        self._out = out
        self._lines = []
        self._object = None  # None before general(); then the current object's name
        self._has_corners = False  # the current object has its CORNERS block
        self._finished = False

    # -- output ----------------------------------------------------------------------------------
    def _emit(self, line):
        if len(line) > MAX_LINE:
            raise ValueError(f"a gsi line holds at most {MAX_LINE} characters; this one has {len(line)}")
        self._lines.append(line)
        if self._out is not False:
            stream = sys.stdout if self._out is None else self._out
            stream.write(line + "\n")

    def text(self):
        """Everything written so far, as one string."""
        return "".join(line + "\n" for line in self._lines)

    def _require_open(self, what):
        if self._object is None:
            raise RuntimeError(f"{what}: General() must come first (it writes the gsi header)")
        if self._finished:
            raise RuntimeError(f"{what}: EOF() was already written")

    # -- keywords --------------------------------------------------------------------------------
    def _keyword_line(self, obj, name, value):
        """The gsi line of one keyword of object `obj`, or None to leave it out."""
        key = name.upper()
        table = KEYWORDS[obj]
        if key not in table:
            hint = difflib.get_close_matches(key, table, n=1)
            extra = f" (did you mean {hint[0]}?)" if hint else ""
            if key == "CORNERS":
                extra = " (give corners=[(x, y), ...] or call Corners(xs, ys))"
            raise ValueError(f"unknown keyword {key} in {obj}{extra}")
        spec = table[key]
        kind = spec[0]
        if value is None or value is False:
            return None
        if kind == "flag":
            if value is not True:
                raise ValueError(f"{key} is a flag: give True (or False/None to leave it out)")
            return key
        if kind == "text":
            text = str(value)
            if not text or any(ch.isspace() for ch in text):
                raise ValueError(f"{key} takes one word without spaces, got {text!r}")
            return f"{key} {text}"
        if kind == "choice":
            word = str(value).upper()
            if word not in spec[1]:
                raise ValueError(f"{key}: {value!r} is not one of {', '.join(spec[1])}")
            return f"{key} {word}"
        values = list(value) if isinstance(value, (tuple, list)) else [value]
        count = 2 if kind == "gravity" else spec[1]
        if not 1 <= len(values) <= count:
            wanted = "1 or 2" if kind == "gravity" else str(count)
            raise ValueError(f"{key} takes {wanted} number(s), got {len(values)}")
        whole = kind == "whole"
        return key + " " + " ".join(format_number(v, whole, key) for v in values)

    def _keywords(self, obj, keywords):
        lines = [self._keyword_line(obj, name, value) for name, value in keywords.items()]
        return [line for line in lines if line is not None]

    def keyword(self, name, *values):
        """One keyword line in the current object, like gsi.pm's one function per keyword:
        keyword("TIME", 0, 0.5); keyword("POSITION_ABSOLUT")."""
        self._require_open(name)
        value = True if not values else values[0] if len(values) == 1 else tuple(values)
        line = self._keyword_line(self._object, name, value)
        if line is not None:
            self._emit(("  " if self._object != "GENERAL" else "") + line)

    # -- corners ---------------------------------------------------------------------------------
    def _corner_lines(self, corners, what):
        ring = convex_ccw(corners, what)
        return ["CORNERS"] + [f"    {format_number(x)} {format_number(y)}" for x, y in ring] + ["END"]

    def corners(self, xs, ys):
        """A CORNERS block (Perl's Corners([xs], [ys])) in the current PARTICLE or WALL: one 'x y'
        line per corner, counter-clockwise (a clockwise list is reversed), then END."""
        self._require_open("Corners")
        if self._object not in _OBJECTS_WITH_CORNERS:
            raise RuntimeError(f"Corners: CORNERS belongs to a PARTICLE or WALL, not to {self._object}")
        if self._has_corners:
            raise RuntimeError(f"Corners: this {self._object} has its CORNERS block already")
        xs, ys = list(xs), list(ys)
        if len(xs) != len(ys):
            raise ValueError(f"Corners: {len(xs)} x values but {len(ys)} y values")
        lines = self._corner_lines(list(zip(xs, ys)), f"{self._object} corners")
        self._has_corners = True
        for line in lines:
            self._emit("  " + line if line[0] != " " else line)

    # -- objects ---------------------------------------------------------------------------------
    def general(self, ident="", **keywords):
        """Line 1 'PARAMETER v1.4', line 2 the identification text `ident` (may be empty; gc2d
        writes 'date time --- host --- user'), then the GENERAL keywords (spec 9.2-9.3)."""
        if self._object is not None:
            raise RuntimeError("General() comes once, first (GENERAL cannot be re-entered, spec 9.2)")
        ident = str(ident)
        if "\n" in ident or "\r" in ident:
            raise ValueError("General: the identification text is one line")
        lines = self._keywords("GENERAL", keywords)
        self._object = "GENERAL"
        self._emit(GSI_VERSION_LINE)
        self._emit(ident)
        for line in lines:
            self._emit(line)

    def _object_block(self, obj, corners, keywords):
        self._require_open(obj)
        lines = self._keywords(obj, keywords)
        if corners is not None:
            lines = self._corner_lines(corners, f"{obj} corners") + lines
        self._object = obj
        self._has_corners = corners is not None
        self._emit(obj)
        for line in lines:
            self._emit(line if line.startswith("    ") else "  " + line)

    def particle(self, corners=None, **keywords):
        """A PARTICLE: CORNERS (relative to the centroid unless POSITION_ABSOLUT=True; placed by
        COM=(x, y) [m]) and keywords (ANGLE [rad, clockwise], VELOCITY [m/s], OMEGA [1/s], ...)."""
        self._object_block("PARTICLE", corners, keywords)

    def wall(self, corners=None, **keywords):
        """A WALL: CORNERS absolute [m] and keywords (OFFSET [m], ANGLE [rad, clockwise about the
        wall's centroid], VELOCITY [m/s] (belt), PISTON_*, VIB_*)."""
        self._object_block("WALL", corners, keywords)

    def generate_block(self, **keywords):
        """A GENERATE_BLOCK (spec 6.5): X_RANGE, Y_RANGE, GRID_DISTANCE [m], GRID_TYPE, PART_* ..."""
        self._object_block("GENERATE_BLOCK", None, keywords)

    def drop_source(self, **keywords):
        """A DROPSOURCE (spec 6.5): POS [m], WIDTH [m], TYPE, TIME [s], DELTA_T [s], PART_* ..."""
        self._object_block("DROPSOURCE", None, keywords)

    def display(self, **keywords):
        """A DISPLAY: X_RANGE, Y_RANGE [m], SCREEN, INTERVAL, MODUS (read, not used by granulab)."""
        self._object_block("DISPLAY", None, keywords)

    def comment(self, text):
        """A '$' line per line of text (gc2d echoes them; spec 9.2)."""
        for line in str(text).splitlines() or [""]:
            self._emit(f"$ {line}".rstrip())

    def remark(self, text):
        """A '#' comment line per line of text (ignored by the readers)."""
        for line in str(text).splitlines() or [""]:
            self._emit(f"# {line}".rstrip())

    def eof(self):
        """END_OF_FILE: the end of the scene."""
        self._require_open("EOF")
        self._emit("END_OF_FILE")
        self._finished = True


_default = GsiWriter()


def default_writer():
    """The writer that the module-level functions (General, Particle, ..., the macros) use: by
    default one that prints to sys.stdout."""
    return _default


def set_default_writer(writer):
    """Replaces the default writer (e.g. GsiWriter(out=False) to collect text); returns the old."""
    global _default
    old, _default = _default, writer
    return old


def _w(writer):
    return _default if writer is None else writer


# Module-level functions in gsi.pm's style (spec 9.8): a script reads like the Perl ones.
def General(ident="", **keywords):
    """gsi.pm General: the header (PARAMETER v1.4, identification) and GENERAL keywords."""
    _default.general(ident, **keywords)


def Particle(corners=None, **keywords):
    """gsi.pm Particle: a PARTICLE object."""
    _default.particle(corners, **keywords)


def Wall(corners=None, **keywords):
    """gsi.pm Wall: a WALL object."""
    _default.wall(corners, **keywords)


def GenerateBlock(**keywords):
    """gsi.pm Generate_Block: a GENERATE_BLOCK object."""
    _default.generate_block(**keywords)


def DropSource(**keywords):
    """gsi.pm Dropsource: a DROPSOURCE object."""
    _default.drop_source(**keywords)


def Display(**keywords):
    """gsi.pm Display: a DISPLAY object."""
    _default.display(**keywords)


def Keyword(name, *values):
    """One keyword in the current object (gsi.pm's one function per keyword)."""
    _default.keyword(name, *values)


def Corners(xs, ys):
    """gsi.pm Corners([xs], [ys]): a CORNERS block in the current PARTICLE or WALL."""
    _default.corners(xs, ys)


def Comment(text):
    """gsi.pm Comment: a '$' line."""
    _default.comment(text)


def Remark(text):
    """A '#' comment line (an extension)."""
    _default.remark(text)


def Macro(*_args, **_kw):
    """gsi.pm Macro: a no-op that marks structure in a script."""


def EOF():
    """gsi.pm EOF: END_OF_FILE."""
    _default.eof()


# ------------------------------------------------------------------------------------------------
# Shapes (spec 2.3 "Deterministic shapes", App. D.3-D.5). The *_corners functions return the
# corners [m], counter-clockwise, absolute; the emitting macros write a PARTICLE (corners about
# the centre, COM = the centre; wall=True: a WALL with absolute corners) and return the corners.
# phi [rad] turns the shape clockwise about its centre, as gsi ANGLE does.
# ------------------------------------------------------------------------------------------------

def _positive(name, value):
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")


def _corner_count(name, n, least=3):
    if isinstance(n, bool) or not isinstance(n, int) or n < least:
        raise ValueError(f"{name} must be a whole number >= {least}, got {n!r}")


def _unit(num, den):
    """(cos, sin) of the angle 2 pi num / den: exact 0 and +-1 at multiples of pi/2 (no 1e-17)."""
    quarter, rest = divmod(4 * num, den)
    if rest == 0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[quarter % 4]
    angle = 2 * math.pi * num / den
    return math.cos(angle), math.sin(angle)


def _regular_ring(rx, ry, n):
    """n corners at angles 2 pi i / n on the ellipse (rx cos, ry sin), first at angle 0."""
    return [(rx * c, ry * s) for c, s in (_unit(i, n) for i in range(n))]


def _sphere_local(r, n):
    _positive("r", r)
    _corner_count("N", n)
    return _regular_ring(r, r, n)


def _ellipse_local(r1, r2, n, phi):
    _positive("r1", r1)
    _positive("r2", r2)
    _corner_count("N", n)
    return _rotate_clockwise(_regular_ring(r1, r2, n), phi)


def _rectangle_local(a, b, phi):
    _positive("a", a)
    _positive("b", b)
    h, k = 0.5 * a, 0.5 * b
    return _rotate_clockwise([(-h, -k), (h, -k), (h, k), (-h, k)], phi)


def _rectangle_cut_local(a, b, phi, c):
    """Octagon: the a edges shortened to a (1 - 2c), the b edges to b (1 - 2c) (0 <= c <= 1/2)."""
    _positive("a", a)
    _positive("b", b)
    if not (isinstance(c, (int, float)) and 0 <= c <= 0.5):
        raise ValueError(f"the cut fraction c must be in [0, 0.5], got {c!r}")
    h, k, ca, cb = 0.5 * a, 0.5 * b, c * a, c * b
    ring = [(-h + ca, -k), (h - ca, -k), (h, -k + cb), (h, k - cb),
            (h - ca, k), (-h + ca, k), (-h, k - cb), (-h, -k + cb)]
    return _rotate_clockwise(_drop_repeats(ring, 1e-24 * max(a, b) ** 2), phi)


def _rectangle_round_local(a, b, phi, r, n):
    """Each corner of the a x b rectangle replaced by a quarter circle of radius r through n
    corners (both ends included, n >= 2); 0 < r <= min(a, b) / 2."""
    _positive("a", a)
    _positive("b", b)
    _positive("r", r)
    _corner_count("N", n, least=2)
    if r > 0.5 * min(a, b) * (1 + 1e-12):
        raise ValueError(f"the corner radius r = {r!r} exceeds half the shorter side {0.5 * min(a, b)!r}")
    r = min(r, 0.5 * min(a, b))  # round-off above the half side: a stadium
    h, k = 0.5 * a - r, 0.5 * b - r
    ring = []
    for quarter, (cx, cy) in enumerate(((h, -k), (h, k), (-h, k), (-h, -k))):
        for j in range(n):  # from angle (quarter - 1) pi/2 to quarter pi/2
            c, s = _unit((quarter - 1) * (n - 1) + j, 4 * (n - 1))
            ring.append((cx + r * c, cy + r * s))
    return _rotate_clockwise(_drop_repeats(ring, 1e-24 * max(a, b) ** 2), phi)


def sphere_corners(x, y, r, n):
    """Regular n-gon inscribed in the circle of radius r [m] about (x, y) [m], first corner at
    angle 0 (gc2d_sphere's polygon)."""
    return _translate(_sphere_local(r, n), x, y)


def ellipse_corners(x, y, r1, r2, n, phi=0.0):
    """n-gon inscribed in the ellipse of semi-axes r1 (x), r2 (y) [m] about (x, y): corners at
    parameter angles 2 pi i / n, then turned clockwise by phi [rad]."""
    return _translate(_ellipse_local(r1, r2, n, phi), x, y)


def rectangle_corners(x, y, a, b, phi=0.0):
    """a x b [m] rectangle centred at (x, y), turned clockwise by phi [rad]."""
    return _translate(_rectangle_local(a, b, phi), x, y)


def rectangle_cut_corners(x, y, a, b, phi, c):
    """Chamfered a x b rectangle (octagon; edges shortened to a(1-2c), b(1-2c))."""
    return _translate(_rectangle_cut_local(a, b, phi, c), x, y)


def rectangle_round_corners(x, y, a, b, phi, r, n):
    """Rounded a x b rectangle: corners replaced by quarter circles of radius r [m], n corners each."""
    return _translate(_rectangle_round_local(a, b, phi, r, n), x, y)


def square_corners(x, y, a, phi=0.0):
    """a x a square [m]."""
    return rectangle_corners(x, y, a, a, phi)


def square_cut_corners(x, y, a, phi, c):
    """Chamfered a x a square."""
    return rectangle_cut_corners(x, y, a, a, phi, c)


def square_round_corners(x, y, a, phi, r, n):
    """Rounded a x a square."""
    return rectangle_round_corners(x, y, a, a, phi, r, n)


def _emit_shape(local, x, y, wall, writer, keywords):
    """Writes the shape (local corners about (x, y)) as a PARTICLE or WALL; the absolute corners."""
    absolute = _translate(local, x, y)
    w = _w(writer)
    if wall:
        w.wall(absolute, **keywords)
    else:
        w.particle(local, COM=(x, y), **keywords)
    return absolute


def sphere(x, y, r, n, wall=False, writer=None, **keywords):
    """gc2d_sphere(x, y, r, N): a regular N-gon particle of circumradius r [m] at (x, y) [m]."""
    return _emit_shape(_sphere_local(r, n), x, y, wall, writer, keywords)


def sphere_wall(x, y, r, n, writer=None, **keywords):
    """gc2d_sphere_wall: the same N-gon as a WALL."""
    return sphere(x, y, r, n, wall=True, writer=writer, **keywords)


def ellipse(x, y, r1, r2, n, phi=0.0, wall=False, writer=None, **keywords):
    """gc2d_ellipse(x, y, r1, r2, N): an N-gon particle inscribed in an ellipse (semi-axes [m])."""
    return _emit_shape(_ellipse_local(r1, r2, n, phi), x, y, wall, writer, keywords)


def ellipse_wall(x, y, r1, r2, n, phi=0.0, writer=None, **keywords):
    """The ellipse N-gon as a WALL."""
    return ellipse(x, y, r1, r2, n, phi, wall=True, writer=writer, **keywords)


def rectangle(x, y, a, b, phi=0.0, wall=False, writer=None, **keywords):
    """gc2d_rectangle(x, y, a, b, phi): an a x b [m] rectangle."""
    return _emit_shape(_rectangle_local(a, b, phi), x, y, wall, writer, keywords)


def rectangle_cut(x, y, a, b, phi, c, wall=False, writer=None, **keywords):
    """gc2d_rectangle_cut(x, y, a, b, phi, c): a chamfered rectangle (octagon)."""
    return _emit_shape(_rectangle_cut_local(a, b, phi, c), x, y, wall, writer, keywords)


def rectangle_round(x, y, a, b, phi, r, n, wall=False, writer=None, **keywords):
    """gc2d_rectangle_round(x, y, a, b, phi, r, N): a rounded rectangle."""
    return _emit_shape(_rectangle_round_local(a, b, phi, r, n), x, y, wall, writer, keywords)


def square(x, y, a, phi=0.0, wall=False, writer=None, **keywords):
    """gc2d_square: an a x a square."""
    return rectangle(x, y, a, a, phi, wall, writer, **keywords)


def square_cut(x, y, a, phi, c, wall=False, writer=None, **keywords):
    """gc2d_square_cut: a chamfered square."""
    return rectangle_cut(x, y, a, a, phi, c, wall, writer, **keywords)


def square_round(x, y, a, phi, r, n, wall=False, writer=None, **keywords):
    """gc2d_square_round: a rounded square."""
    return rectangle_round(x, y, a, a, phi, r, n, wall, writer, **keywords)


def sphere7(x, y, r, **kw):
    """gc2d_sphere7: sphere(x, y, r, 7)."""
    return sphere(x, y, r, 7, **kw)


def sphere10(x, y, r, **kw):
    """gc2d_sphere10: sphere(x, y, r, 10)."""
    return sphere(x, y, r, 10, **kw)


def sphere20(x, y, r, **kw):
    """gc2d_sphere20: sphere(x, y, r, 20)."""
    return sphere(x, y, r, 20, **kw)


def sphere50(x, y, r, **kw):
    """gc2d_sphere50: sphere(x, y, r, 50)."""
    return sphere(x, y, r, 50, **kw)


def ellipse7(x, y, r1, r2, **kw):
    """gc2d_ellipse7: ellipse(x, y, r1, r2, 7), phi = 0."""
    return ellipse(x, y, r1, r2, 7, **kw)


def ellipse10(x, y, r1, r2, **kw):
    """gc2d_ellipse10: ellipse(x, y, r1, r2, 10), phi = 0."""
    return ellipse(x, y, r1, r2, 10, **kw)


def ellipse20(x, y, r1, r2, **kw):
    """gc2d_ellipse20: ellipse(x, y, r1, r2, 20), phi = 0."""
    return ellipse(x, y, r1, r2, 20, **kw)


def ellipse50(x, y, r1, r2, **kw):
    """gc2d_ellipse50: ellipse(x, y, r1, r2, 50), phi = 0."""
    return ellipse(x, y, r1, r2, 50, **kw)


# ------------------------------------------------------------------------------------------------
# Rotating drum (spec 6.2, App. D.7, drum.pm): a fixed ring of N walls lined with a belt.
# ------------------------------------------------------------------------------------------------

def drum_corners(r, d, x, y, n):
    """The N trapezoids of a drum of inner radius r [m] and wall thickness d [m] about (x, y):
    segment k spans the angles [2 pi k / N, 2 pi (k+1) / N]; its inner edge is a chord whose
    distance from the centre is exactly r (the corners lie at r / cos(pi / N)), its outer edge
    at r + d. The same ring as granulab's [[drum]]."""
    _positive("r", r)
    _positive("d", d)
    _corner_count("N", n)
    step = 2 * math.pi / n
    stretch = 1 / math.cos(0.5 * step)  # corners beyond r, so that the edge lies at r
    ri, ro = r * stretch, (r + d) * stretch

    def at(radius, k):
        c, s = _unit(k, n)
        return (x + radius * c, y + radius * s)

    return [[at(ri, k), at(ro, k), at(ro, k + 1), at(ri, k + 1)] for k in range(n)]


def drum_velocity(k, n, v):
    """VELOCITY (vx, vy) [m/s] of drum segment k of N: magnitude |v|, along the segment's inner
    edge (perpendicular to the radius through its middle); v > 0 moves the belt
    counter-clockwise (the bed is dragged up on the right), v < 0 clockwise."""
    c, s = _unit(2 * k + 1, 2 * n)  # the middle angle 2 pi (k + 1/2) / N
    return (-s * v, c * v)


def drum(r, d, x, y, v, n, writer=None, **keywords):
    """gc2d_drum(r, d, x, y, v, N): writes N WALLs forming a drum of inner radius r [m] and wall
    thickness d [m] centred at (x, y) [m]; the walls rest, each with the tangential surface
    velocity VELOCITY of magnitude v [m/s] (a fixed drum lined with a conveyor belt, spec 6.2).
    Extra keywords go to every WALL. Returns the N corner lists."""
    rings = drum_corners(r, d, x, y, n)
    w = _w(writer)
    for k, corners in enumerate(rings):
        w.wall(corners, VELOCITY=drum_velocity(k, n, v), **keywords)
    return rings


# ------------------------------------------------------------------------------------------------
# Regular heaps (spec 6 "Perl heap library", heap.pm, App. D.6; the piles of spec 8.4)
# ------------------------------------------------------------------------------------------------

def _heap_rows(x_l, x_r, y0, psi, dx, dy, hexagonal, max_rows):
    """Grain centres, row by row from the bottom. Row k lies at height y0 + k dy; its grains sit
    symmetrically about (x_l + x_r) / 2, dx apart, inside the pile's outline: the base [x_l, x_r]
    narrowed by k dy / tan(psi) on each side (a grain's whole width dx inside). Hexagonal rows
    have one grain less (or 3, 5, ...) than the row below, so each grain rests on two below;
    rectangular rows 0, 2, 4, ... less, so columns stay aligned. No grain ever overhangs."""
    for name, value in (("dx", dx), ("dy", dy)):
        _positive(name, value)
    if not x_r > x_l:
        raise ValueError(f"the base needs x_l < x_r, got {x_l!r}, {x_r!r}")
    if not 0 < psi <= 0.5 * math.pi:
        raise ValueError(f"the slope psi must be in (0, pi/2] [rad], got {psi!r}")
    if not hexagonal and psi >= 0.5 * math.pi:
        raise ValueError("a rectangular stack with vertical flanks (psi = pi/2) never ends")
    inset = dy / math.tan(psi) if psi < 0.5 * math.pi else 0.0  # per row and side [m]
    if hexagonal and inset < 0.5 * dx * (1 - 1e-12):
        sys.stderr.write(f"granulab_gsi: warning: psi = {psi:.4g} rad is steeper than a hexagonal stack's "
                         f"flank atan(2 dy / dx) = {math.atan(2 * dy / dx):.4g} rad; the pile is built "
                         "with that flank (no overhanging grains)\n")
    middle = 0.5 * (x_l + x_r)
    rows, previous = [], None
    for k in range(max_rows + 1):
        width = (x_r - x_l) - 2 * k * inset
        fit = math.floor(width / dx + 1e-9)
        if previous is not None:
            most = previous - 1 if hexagonal else previous
            fit = min(fit, most)
            if (most - fit) % 2:  # keep the lattice: hexagonal rows shift dx/2, rectangular none
                fit -= 1
        if fit <= 0:
            return rows
        if k == max_rows:
            raise ValueError(f"the heap has more than max_rows = {max_rows} rows")
        y = y0 + k * dy
        rows.append([(middle + (j - 0.5 * (fit - 1)) * dx, y) for j in range(fit)])
        previous = fit
    return rows


def heap_rows_hexagonal(x_l, x_r, y0, psi, dx, dy, max_rows=10000):
    """Centres [m] of a hexagonal (staggered) pile between x_l and x_r whose bottom row's centres
    are at height y0, flank slope psi [rad], spacing dx within a row and dy between rows: a list
    of rows, each a list of (x, y). Flanks steeper than atan(2 dy / dx) cannot be stacked without
    overhang (spec: keep psi < atan 2 for discs and squares, atan(2b/a) for rectangles); the pile
    then takes that flank."""
    return _heap_rows(x_l, x_r, y0, psi, dx, dy, True, max_rows)


def heap_rows_rectangular(x_l, x_r, y0, psi, dx, dy, max_rows=10000):
    """Centres [m] of a rectangular (column) pile; as heap_rows_hexagonal, rows aligned."""
    return _heap_rows(x_l, x_r, y0, psi, dx, dy, False, max_rows)


def heap_hexagonal(x_l, x_r, y0, psi, dx, dy, cmd):
    """gc2d_heap_hexagonal(x_l, x_r, y0, psi, dx, dy, cmd): calls cmd(x, y) for every grain
    centre of heap_rows_hexagonal, bottom row first, left to right; returns the rows."""
    rows = heap_rows_hexagonal(x_l, x_r, y0, psi, dx, dy)
    for row in rows:
        for x, y in row:
            cmd(x, y)
    return rows


def heap_rectangular(x_l, x_r, y0, psi, dx, dy, cmd):
    """gc2d_heap_rectangular: as heap_hexagonal, for a rectangular stack."""
    rows = heap_rows_rectangular(x_l, x_r, y0, psi, dx, dy)
    for row in rows:
        for x, y in row:
            cmd(x, y)
    return rows


def _stacking_rows(stacking):
    if stacking not in ("hexagonal", "rectangular"):
        raise ValueError(f"stacking must be 'hexagonal' or 'rectangular', got {stacking!r}")
    return heap_rows_hexagonal if stacking == "hexagonal" else heap_rows_rectangular


def _heap_of(local, rows, writer, keywords):
    """Writes one PARTICLE of the local corners at every centre; the absolute corner lists."""
    placed = []
    for row in rows:
        for x, y in row:
            placed.append(_emit_shape(local, x, y, False, writer, keywords))
    return placed


def heap_discs(x_l, x_r, y0, psi, r, n=20, stacking="hexagonal", gap=0.0, writer=None, **keywords):
    """A pile of discs (regular n-gons of circumradius r [m]) on the floor y = y0 [m] between x_l
    and x_r [m], flank slope psi [rad]. Hexagonal: dx = 2r + gap, dy = sqrt(3)/2 dx; rectangular:
    dx = dy = 2r + gap. The bottom row's centres are at y0 + r + gap/2. Writes the PARTICLEs
    (extra keywords go to each) and returns their corner lists."""
    dx = 2 * r + gap
    dy = 0.5 * math.sqrt(3) * dx if stacking == "hexagonal" else dx
    rows = _stacking_rows(stacking)(x_l, x_r, y0 + r + 0.5 * gap, psi, dx, dy)
    return _heap_of(_sphere_local(r, n), rows, writer, keywords)


def heap_rectangles(x_l, x_r, y0, psi, a, b, stacking="hexagonal", cut=0.0, round_r=0.0, round_n=4,
                    gap=0.0, writer=None, **keywords):
    """A pile of a x b [m] rectangles (cut > 0: chamfered, rectangle_cut; round_r > 0: rounded with
    round_n corners per quarter) on the floor y = y0 between x_l and x_r, slope psi [rad]:
    dx = a + gap, dy = b + gap, bottom centres at y0 + b/2 + gap/2. Plain rectangles touch along
    whole edges; the spec recommends the cut or round variants for regular stacks."""
    if cut and round_r:
        raise ValueError("give either cut or round_r, not both")
    if round_r:
        local = _rectangle_round_local(a, b, 0.0, round_r, round_n)
    elif cut:
        local = _rectangle_cut_local(a, b, 0.0, cut)
    else:
        local = _rectangle_local(a, b, 0.0)
    rows = _stacking_rows(stacking)(x_l, x_r, y0 + 0.5 * b + 0.5 * gap, psi, a + gap, b + gap)
    return _heap_of(local, rows, writer, keywords)


def heap_squares(x_l, x_r, y0, psi, a, stacking="hexagonal", cut=0.0, round_r=0.0, round_n=4, gap=0.0,
                 writer=None, **keywords):
    """A pile of a x a squares; as heap_rectangles."""
    return heap_rectangles(x_l, x_r, y0, psi, a, a, stacking, cut, round_r, round_n, gap, writer, **keywords)


# ------------------------------------------------------------------------------------------------
# XFig import (spec 6.5 "XFig import", gc2d_read_xfig, App. D.8)
# ------------------------------------------------------------------------------------------------
# Read: object code 2 (polyline) with sub_type 1 polyline, 2 box, 3 polygon (xfig's regular
# polygons are written as polygons), 4 arc-box, 5 picture (its frame). An object filled 100 %
# (area_fill 20, xfig's "100 %" fill: full saturation of the fill colour) becomes a free PARTICLE,
# anything else a WALL (spec; particles="filled" makes every filled object, area_fill != -1, a
# particle). y is negated (the drawing lies in the 4th quadrant). Scale "10:1" (spec): the drawing
# is 10 times the real size (the technical-drawing notation drawing:reality), so with xfig's
# 1200 units per inch one unit is 0.0254 / 1200 / 10 m; 1 cm drawn is 1 mm in the scene.
# Open polylines: the spec makes no thin walls of them and gsi objects are closed convex polygons,
# so an open one is skipped with a warning; a polyline whose last point repeats the first is closed.

FULL_FILL = 20  # xfig area_fill of a 100 % fill
PICTURE, ARC_BOX, BOX, POLYGON, POLYLINE = 5, 4, 2, 3, 1
_SUBTYPE_NAMES = {1: "polyline", 2: "box", 3: "polygon", 4: "arc-box", 5: "picture"}


class XfigError(ValueError):
    """A malformed or unusable XFig file: str() is 'path:line: message' ('path: message' when the
    file cannot be read)."""

    def __init__(self, path, line, message):
        super().__init__(f"{path}:{line}: {message}" if line else f"{path}: {message}")
        self.path, self.line, self.message = path, line, message


class XfigObject:
    """One imported object: kind 'PARTICLE' or 'WALL', corners [m] (counter-clockwise, absolute),
    line (of its header in the .fig file), subtype (xfig's polyline sub_type name)."""

    def __init__(self, kind, corners, line, subtype):
        self.kind, self.corners, self.line, self.subtype = kind, corners, line, subtype

    def __repr__(self):
        return f"XfigObject({self.kind}, line {self.line}, {self.subtype}, {len(self.corners)} corners)"


def parse_scale(text):
    """The drawing scale 'D:R' (drawing length : real length) or a number D (= 'D:1') as the factor
    drawing / reality: '10:1' -> 10 (the drawing is 10 x the real size), '1:10' -> 0.1."""
    s = str(text).strip()
    try:
        if ":" in s:
            d, r = s.split(":", 1)
            factor = float(d) / float(r)
        else:
            factor = float(s)
    except (ValueError, ZeroDivisionError):
        raise ValueError(f"scale {text!r}: give 'D:R' (e.g. 10:1) or a number") from None
    if not (math.isfinite(factor) and factor > 0):
        raise ValueError(f"scale {text!r}: must be positive")
    return factor


class _FigLines:
    """The .fig file's lines with their numbers; skips blank and '#' comment lines."""

    def __init__(self, path, text):
        self.path = path
        self.lines = text.splitlines()
        self.next = 0
        self.line = 0  # number of the line last read (1-based)
        self.units_per_inch = 1200.0

    def error(self, message, line=None):
        return XfigError(self.path, self.line if line is None else line, message)

    def read(self):
        """The next non-blank, non-comment line (stripped), or None at the end."""
        while self.next < len(self.lines):
            raw = self.lines[self.next]
            self.next += 1
            self.line = self.next
            s = raw.strip()
            if s and not s.startswith("#"):
                return s
        return None

    def require(self, what):
        s = self.read()
        if s is None:
            raise self.error(f"the file ends where {what} was expected", len(self.lines))
        return s

    def fields(self, s, what, count, floats=()):
        """The count numeric fields of line s: whole numbers, except at the indices `floats`."""
        words = s.split()
        if len(words) != count:
            raise self.error(f"{what} has {len(words)} fields, expected {count}")
        values = []
        for k, w in enumerate(words):
            try:
                values.append(float(w) if k in floats else int(w))
            except ValueError:
                kind = "a number" if k in floats else "a whole number"
                raise self.error(f"{what}: field {k + 1} '{w}' is not {kind}") from None
        return values

    def numbers(self, count, what, kind=int):
        """count numbers, read over as many lines as they take."""
        values = []
        while len(values) < count:
            s = self.require(what)
            for w in s.split():
                try:
                    values.append(kind(w))
                except ValueError:
                    raise self.error(f"{what}: '{w}' is not a number") from None
            if len(values) > count:
                raise self.error(f"{what}: this line takes the count to {len(values)} numbers, but "
                                 f"{count} were declared (points missing, or the header's count wrong)")
        return values


def _fig_header(fig):
    """Checks the '#FIG 3.2' header; the resolution [units per inch] of its coordinate line."""
    first = fig.lines[0].strip() if fig.lines else ""
    fig.line = 1
    if not first.startswith("#FIG 3."):
        raise fig.error(f"not an XFig 3.x file: the first line is {first[:40]!r}, expected '#FIG 3.2'")
    fig.next = 1
    version = first.split()[1] if len(first.split()) > 1 else ""
    if version != "3.2":
        raise fig.error(f"XFig format {version} is not read; save the drawing as FIG 3.2")
    orientation = fig.require("the orientation (Landscape or Portrait)")
    if orientation.lower() not in ("landscape", "portrait"):
        raise fig.error(f"'{orientation}' is not an orientation (Landscape or Portrait)")
    fig.require("the justification (Center or Flush Left)")
    units = fig.require("the units (Metric or Inches)")
    if units.lower() not in ("metric", "inches"):
        raise fig.error(f"'{units}' is not a unit system (Metric or Inches)")
    for what in ("the paper size", "the magnification", "Single or Multiple", "the transparent colour"):
        fig.require(what)
    resolution, _coord_system = fig.fields(fig.require("the resolution line"), "the resolution line", 2)
    if resolution <= 0:
        raise fig.error(f"resolution {resolution} must be positive [units per inch]")
    return resolution


def _arrows(fig, header, forward_at, backward_at):
    """Skips the arrow lines that the header's forward/backward flags announce."""
    for flag in (header[forward_at], header[backward_at]):
        if flag:
            _arrow_line(fig)


def _arrow_line(fig):
    """One arrow line: arrow_type arrow_style thickness width height."""
    words = fig.require("an arrow line").split()
    if len(words) != 5:
        raise fig.error(f"an arrow line has {len(words)} fields, expected 5")
    for w in words:
        try:
            float(w)
        except ValueError:
            raise fig.error(f"arrow line: '{w}' is not a number") from None


def _skip_spline(fig, s, warn):
    header = fig.fields(s, "the spline header", 14, floats=(9,))
    line = fig.line
    _arrows(fig, header, 11, 12)
    n = header[13]
    fig.numbers(2 * n, "the spline points", float)
    fig.numbers(n, "the spline control factors", float)
    warn(f"{fig.path}:{line}: spline skipped (gc2d reads polygon, polyline, box and regular-polygon objects)")


def _skip_arc(fig, s, warn):
    header = fig.fields(s, "the arc header", 22, floats=(9, 14, 15))
    line = fig.line
    _arrows(fig, header, 12, 13)
    warn(f"{fig.path}:{line}: arc skipped (gc2d reads polygon, polyline, box and regular-polygon objects)")


def _polyline_points(fig, s):
    """Header fields, the points and the header's line of one object-code-2 object."""
    header = fig.fields(s, "the polyline header", 16, floats=(9,))
    line = fig.line
    if header[1] not in _SUBTYPE_NAMES:
        raise fig.error(f"polyline sub_type {header[1]} is none of 1-5")
    _arrows(fig, header, 13, 14)
    if header[1] == PICTURE:
        fig.require("the picture's 'flipped file' line")
    n = header[15]
    if n < 1:
        raise fig.error(f"the polyline declares {n} points", line)
    flat = fig.numbers(2 * n, f"the {n} points of the {_SUBTYPE_NAMES[header[1]]} at line {line}", float)
    return header, [(flat[2 * i], flat[2 * i + 1]) for i in range(n)], line


def _arc_box_points(points, radius_units, corners_per_quarter):
    """The rounded box of an arc-box (xfig radius in units) as a ring in fig units."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    a, b = max(xs) - min(xs), max(ys) - min(ys)
    if a <= 0 or b <= 0 or radius_units <= 0:
        return points
    r = min(radius_units, 0.5 * min(a, b))
    local = _rectangle_round_local(a, b, 0.0, r, corners_per_quarter)
    return _translate(local, 0.5 * (max(xs) + min(xs)), 0.5 * (max(ys) + min(ys)))


def read_xfig(path, scale="10:1", resolution=None, particles="full", offset=(0.0, 0.0), arc_corners=4,
              warn=None):
    """Reads an XFig 3.2 drawing (gc2d_read_xfig, spec 6.5): a list of XfigObject in file order.

    scale:      drawing : reality ('10:1', the spec's; or a number = drawing / reality);
    resolution: units per inch (None: the file's own, 1200 as xfig writes it);
    particles:  'full' (spec: area_fill 20, a 100 % fill, is a PARTICLE) or 'filled' (any fill);
    offset:     (dx, dy) [m] added after scaling and negating y;
    arc_corners: corners per quarter circle of an arc-box's rounded corners;
    warn:       callable(message) for skipped objects (default: a line on stderr).
    Raises XfigError ('path:line: message') for malformed input and non-convex polygons."""
    if particles not in ("full", "filled"):
        raise ValueError(f"particles must be 'full' or 'filled', got {particles!r}")
    factor = parse_scale(scale)
    if warn is None:
        def warn(message):
            sys.stderr.write(f"warning: {message}\n")
    try:
        with open(path, encoding="latin-1") as f:  # xfig writes ISO 8859-1 text
            text = f.read()
    except OSError as e:
        raise XfigError(path, 0, e.strerror or str(e)) from None
    fig = _FigLines(path, text)
    file_resolution = _fig_header(fig)
    units_per_inch = file_resolution if resolution is None else float(resolution)
    if not units_per_inch > 0:
        raise ValueError(f"resolution must be positive, got {resolution!r}")
    fig.units_per_inch = units_per_inch
    metres = 0.0254 / units_per_inch / factor  # [m] per xfig unit
    dx, dy = offset
    objects = []
    while True:
        s = fig.read()
        if s is None:
            return objects
        code = s.split()[0]
        if code == "2":
            header, points, line = _polyline_points(fig, s)
            obj = _polyline_object(fig, header, points, line, metres, dx, dy, particles, arc_corners, warn)
            if obj is not None:
                objects.append(obj)
        elif code in ("0", "1", "4", "6", "-6"):
            if code == "1":
                warn(f"{path}:{fig.line}: ellipse skipped (gc2d reads polygon, polyline, box and "
                     "regular-polygon objects; draw a regular polygon)")
        elif code == "3":
            _skip_spline(fig, s, warn)
        elif code == "5":
            _skip_arc(fig, s, warn)
        else:
            raise fig.error(f"'{code}' is no XFig object code (0-6, -6)")


def _polyline_object(fig, header, points, line, metres, dx, dy, particles, arc_corners, warn):
    """The XfigObject of one polyline-family object, or None (skipped, with a warning)."""
    subtype, area_fill = header[1], header[8]
    name = _SUBTYPE_NAMES[subtype]
    closed = subtype != POLYLINE or (len(points) >= 4 and points[0] == points[-1])
    if not closed:
        warn(f"{fig.path}:{line}: open polyline skipped (gsi walls and particles are closed convex "
             "polygons; close it or draw a polygon)")
        return None
    if subtype == ARC_BOX:
        radius_units = header[12] * fig.units_per_inch / 80.0  # xfig's radius is in 1/80 inch
        points = _arc_box_points(_drop_repeats(points, 0), radius_units, arc_corners)
    filled = area_fill == FULL_FILL if particles == "full" else area_fill != -1
    corners = [(x * metres + dx, -y * metres + dy) for x, y in points]
    try:
        ring = convex_ccw(corners, f"xfig {name}", drop_repeats=True)
    except ValueError as e:
        raise XfigError(fig.path, line, f"{e}; gsi objects are convex polygons") from None
    return XfigObject("PARTICLE" if filled else "WALL", ring, line, name)


def xfig_to_gsi(path, writer=None, **options):
    """Writes every object of read_xfig(path, **options): a PARTICLE (absolute corners,
    POSITION_ABSOLUT) or a WALL. Returns the objects."""
    w = _w(writer)
    objects = read_xfig(path, **options)
    for obj in objects:
        if obj.kind == "PARTICLE":
            w.particle(obj.corners, POSITION_ABSOLUT=True)
        else:
            w.wall(obj.corners)
    return objects


# The Perl names (gc2d_*) as aliases, for porting scripts line by line.
gc2d_sphere, gc2d_sphere_wall = sphere, sphere_wall
gc2d_sphere7, gc2d_sphere10, gc2d_sphere20, gc2d_sphere50 = sphere7, sphere10, sphere20, sphere50
gc2d_ellipse = ellipse
gc2d_ellipse7, gc2d_ellipse10, gc2d_ellipse20, gc2d_ellipse50 = ellipse7, ellipse10, ellipse20, ellipse50
gc2d_rectangle, gc2d_rectangle_cut, gc2d_rectangle_round = rectangle, rectangle_cut, rectangle_round
gc2d_square, gc2d_square_cut, gc2d_square_round = square, square_cut, square_round
gc2d_drum = drum
gc2d_heap_hexagonal, gc2d_heap_rectangular = heap_hexagonal, heap_rectangular
gc2d_read_xfig = xfig_to_gsi
