#!/usr/bin/env python3
"""Writes the full-size silo scenes of gc2d spec 8.3 (straight, stepped, slanted, parabolic) into
this folder. Walls and the stacked fill blocks follow r(z); run once after editing a parameter:
    python3 examples/studies/silos/make_scenes.py
Coordinates: y up; the design free surface (z = 0) of the stepped, slanted and parabolic silos is
at y = 0, so z = -y there. The straight silo stands on y = 0."""
import math, os

HERE = os.path.dirname(os.path.abspath(__file__))


def grain_block(r):
    return f'''[[shape]]
name = "grain"
kind = "grain"            # gc2d random grain inscribed in an ellipse (App. B.1.6)
size = [{r:g}, {r:g}]   # [m] semi-axes
size_mode = "equal"       # each semi-axis uniform in [0.85 r, 1.15 r]: r +-15 %
size_variation = 0.15
corner_count = 9
corner_count_mode = "equal"
corner_variation = 1      # 8 to 10 corners
corner_angles = "rand1"
rotation_mode = "equal"
'''


def common(title, end, dt, seed, r, mu):
    return f'''[run]
title = "{title}"
end_time = {end:g}            # [s]
seed = {seed}

[dem]
dt = {dt:g}               # [s] below the face dt advised by granulab info
gravity = [0.0, -9.81]    # [m/s^2]

[[material]]
name = "sand"
density = 5000.0          # [kg/m^2] areal density (gc2d spec 2.2)

{grain_block(r)}
[[contact]]
materials = ["*", "*"]    # grains and walls alike
normal = "area"           # gc2d area law F_n = E A / l
E = 1.0e7                 # [N/m]
damping = "gamma"
gamma = 0.5               # thesis default
tangential = "gc2d"       # Cundall-Strack spring k_t = 2/7 E, Coulomb cap mu F_n
mu = {mu:g}
'''


def block(region, spacing, count=None):
    s = f'''
[[block]]
shape = "grain"
lattice = "hexagonal"
spacing = {spacing:g}
region = [{region[0]:.5f}, {region[1]:.5f}, {region[2]:.5f}, {region[3]:.5f}]
material = "sand"
'''
    if count is not None:
        s += f'count = {count}\n'
    return s


def pts(p):
    return '[' + ', '.join(f'[{x:.5f}, {y:.5f}]' for x, y in p) + ']'


def wall_polyline(name, p):
    return f'''
[[wall]]
name = "{name}"
points = {pts(p)}
material = "sand"
'''


def wall_body(name, x0, y0, x1, y1):
    return f'''
[[wall]]
name = "{name}"
kind = "polygon"
points = {pts([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])}
material = "sand"
'''


def output(interval):
    return f'''
[output]
snapshot_interval = {interval:g}
'''


def funnel_blocks(radius, ybot, ytop_funnel, spacing, band, total_top_count, top_region_top):
    """Hexagonal bands stacked in a funnel of half-width radius(y): each band's region is 2 mm
    inside the wall at its lowest (narrowest) height, with a 4 mm gap between bands."""
    s = ''
    y0 = ybot + 0.002
    while y0 + band < ytop_funnel:
        hw = radius(y0) - 0.002
        s += block((-hw, y0, hw, y0 + band - 0.004), spacing)
        y0 += band
    hw = radius(y0) - 0.002
    s += block((-hw, y0, hw, top_region_top), spacing, total_top_count)
    return s


def write(name, header, body):
    with open(os.path.join(HERE, name), 'w') as f:
        f.write(header.strip() + '\n' + body)


HEADERS = {}
for key in ('straight', 'stepped', 'slanted', 'parabolic'):
    with open(os.path.join(HERE, f'{key}.header')) as f:
        HEADERS[key] = f.read()

# Straight silo: half-width 45 mm (9 cm wide), 10,000 grains of r = 1 mm, mu = 0.5.
body = common('straight silo, 10000 grains, 9 cm wide', 0.5, 5e-6, 1, 1e-3, 0.5)
body += block((-0.0438, 0.002, 0.0438, 0.75), 2.4e-3, 10000)
body += wall_polyline('silo', [(-0.045, 0.8), (-0.045, 0.0), (0.045, 0.0), (0.045, 0.8)])
body += output(0.05)
write('straight.toml', HEADERS['straight'], body)

# Stepped silo: r1 = 40 mm above the step at depth h0 = 250 mm (y = -0.25), r2 = 20 mm below,
# bottom at y = -0.575 (10,000 grains reach y ~ 0); mu = 0.4. Shoulders and floor are convex
# wall bodies (no grain meets the convex corner of a polyline).
body = common('stepped silo, 10000 grains, r1 = 40 mm, r2 = 20 mm, h0 = 250 mm', 0.55, 5e-6, 1, 1e-3, 0.4)
body += block((-0.0188, -0.573, 0.0188, -0.252), 2.4e-3)
body += block((-0.0388, -0.248, 0.0388, 0.55), 2.4e-3, 7536)  # + 2464 in the narrow part = 10,000
body += wall_polyline('left', [(-0.04, 0.6), (-0.04, -0.25)])
body += wall_polyline('right', [(0.04, -0.25), (0.04, 0.6)])
body += wall_body('left_step', -0.05, -0.585, -0.02, -0.25)
body += wall_body('right_step', 0.02, -0.585, 0.05, -0.25)
body += wall_body('floor', -0.02, -0.585, 0.02, -0.575)
body += output(0.05)
write('stepped.toml', HEADERS['stepped'], body)

# Slanted silo r(z) = a z + b, a = -0.1087, b = 65 mm; grains r = 1.5 mm, mu = 0.4; tip cut at
# r = 15 mm (10 grains across), z = 0.46 m; the walls continue straight above y = 0.
A, B = -0.1087, 0.065
zcut = (0.015 - B) / A
rs = lambda y: B + A * (-y)
ytop = 0.3
body = common('slanted silo r = a z + b, a = -0.1087, b = 65 mm', 0.6, 7e-6, 1, 1.5e-3, 0.4)
body += funnel_blocks(rs, -zcut, 0.0, 3.6e-3, 0.06, 2600, 0.28)
body += wall_polyline('left', [(-rs(ytop), ytop), (-rs(-zcut), -zcut)])
body += wall_polyline('right', [(rs(-zcut), -zcut), (rs(ytop), ytop)])
body += wall_body('floor', -0.02, -zcut - 0.01, 0.02, -zcut)
body += output(0.05)
write('slanted.toml', HEADERS['slanted'], body)

# Parabolic silo r(z) = sqrt((b - z)/a), a = 100 1/m, b = 0.46 m; grains r = 1.5 mm, mu = 0.4;
# vertex cut at r = 15 mm, z = b - a r^2 = 0.4375 m. Wall polylines with 5 mm steps in y.
PA, PB = 100.0, 0.46
zcut = PB - PA * 0.015 ** 2
rp = lambda y: math.sqrt((PB + y) / PA)
ys = [-zcut + 0.005 * i for i in range(int(round((zcut + 0.3) / 0.005)) + 1)]
body = common('parabolic silo r = sqrt((b - z)/a), a = 100 1/m, b = 0.46 m', 0.6, 7e-6, 1, 1.5e-3, 0.4)
body += funnel_blocks(rp, -zcut, 0.0, 3.6e-3, 0.06, 2850, 0.28)
body += wall_polyline('left', [(-rp(y), y) for y in reversed(ys)])
body += wall_polyline('right', [(rp(y), y) for y in ys])
body += wall_body('floor', -0.02, -zcut - 0.01, 0.02, -zcut)
body += output(0.05)
write('parabolic.toml', HEADERS['parabolic'], body)
