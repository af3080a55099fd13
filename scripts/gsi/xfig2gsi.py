#!/usr/bin/env python3
# xfig2gsi: an XFig 3.2 drawing as a gc2d gsi scene on stdout -- gc2d's gc2d_read_xfig (spec
# shared/spec/gc2d.md 6.5 "XFig import", App. D.8; checklist item 54). Polygons, polylines, boxes,
# arc-boxes, pictures' frames and regular polygons are read; a 100 %-filled object becomes a
# PARTICLE, anything else a WALL; y is negated; the drawing scale is 10:1 (the drawing is 10 times
# the real size) unless --scale says otherwise. Lengths in the gsi are [m].
"""Convert an XFig 3.2 drawing to a gc2d gsi scene (stdout).

Example:
  scripts/gsi/xfig2gsi.py examples/gc2d/sketch.fig --set DELTA_T=1e-5 --set TIME=0,0.5 > sketch.gsi
  granulab run sketch.gsi

Exit status 2 with 'file:line: message' on stderr for a malformed drawing (nothing is written to
stdout then). Skipped objects (open polylines, ellipses, splines, arcs) get a warning on stderr.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import granulab_gsi as gsi  # noqa: E402  (after the path insert)


def parse_setting(text):
    """KEY=V1[,V2]: a GENERAL keyword and its value(s) -- numbers or one word."""
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"{text!r}: give KEY=VALUE, e.g. TIME=0,0.5")
    parts = value.split(",")
    try:
        numbers = [float(p) for p in parts]
    except ValueError:
        return key, value
    return key, numbers[0] if len(numbers) == 1 else tuple(numbers)


def scale_argument(text):
    try:
        gsi.parse_scale(text)
    except ValueError as e:
        raise argparse.ArgumentTypeError(str(e)) from None
    return text


def main(argv=None):
    ap = argparse.ArgumentParser(prog="xfig2gsi.py", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("drawing", help="XFig 3.2 file (.fig)")
    ap.add_argument("--scale", default="10:1", type=scale_argument,
                    help="drawing:reality, e.g. 10:1 (default, gc2d's: 1 cm drawn = 1 mm) or 1:1")
    ap.add_argument("--resolution", type=float, default=None,
                    help="xfig units per inch (default: the file's, 1200; xfig's metric grid is 1143)")
    ap.add_argument("--particles", choices=("full", "filled"), default="full",
                    help="full: only 100%%-filled objects are particles (gc2d); filled: any fill")
    ap.add_argument("--offset", type=float, nargs=2, default=(0.0, 0.0), metavar=("DX", "DY"),
                    help="shift [m] after scaling and negating y")
    ap.add_argument("--arc-corners", type=int, default=4,
                    help="corners per quarter circle of an arc-box's rounded corners (default 4)")
    ap.add_argument("--ident", default=None, help="identification line (default: 'xfig2gsi DRAWING')")
    ap.add_argument("--set", dest="settings", action="append", default=[], type=parse_setting,
                    metavar="KEY=V1[,V2]", help="a GENERAL keyword, e.g. TIME=0,0.5 or DELTA_T=1e-5")
    a = ap.parse_args(argv)

    writer = gsi.GsiWriter(out=False)  # collect first: no partial scene on an error
    try:
        writer.general(a.ident if a.ident is not None else f"xfig2gsi {os.path.basename(a.drawing)}",
                       **dict(a.settings))
        writer.remark(f"from {a.drawing}: scale {a.scale}, y negated (gc2d spec 6.5)")
        objects = gsi.xfig_to_gsi(a.drawing, writer, scale=a.scale, resolution=a.resolution,
                                  particles=a.particles, offset=tuple(a.offset), arc_corners=a.arc_corners)
        writer.eof()
    except gsi.XfigError as e:
        sys.stderr.write(f"xfig2gsi: error: {e}\n")
        return 2
    except ValueError as e:
        sys.stderr.write(f"xfig2gsi: error: {e}\n")
        return 2
    if not objects:
        sys.stderr.write(f"xfig2gsi: warning: {a.drawing} has no polygon, polyline or box object\n")
    sys.stdout.write(writer.text())
    return 0


if __name__ == "__main__":
    sys.exit(main())
