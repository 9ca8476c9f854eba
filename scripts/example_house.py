#!/usr/bin/env python3
"""The example house of the sun study's worked example: writes examples/house.json and its OBJ
meshes in examples/models/house/.

    python3 scripts/example_house.py            # from the repository root

A small two-storey house with a gable roof on a 60 x 60 m lot, in metres, in the sun study's
orientation (the sun-study contract, sun-study.md): +Y up, north -Z, east +X, so +Z is south.
The house's main facade faces south. Every building part is an object of its own with a clear
name (wall_south, windows_south, reveals_south, roof_south, pv_array, pergola, ...), so the
study's per-object results mean something: the glass is not averaged with the wall around it,
nor the roof's sunny top with its underside. No transforms: the meshes are in scene coordinates,
so the study's areas are the files' own.

The house is a shell, as a sun study needs it: walls are single-sided polygons in the outer
plane of the masonry (no thickness, no interior), so every wall polygon is a piece of facade
that can receive sun. Roof slopes, on the other hand, are slabs, because their thickness (the
eaves' fascia, the verges) casts shadows of its own.

Rules the geometry keeps, and checks before it writes anything (check_closed and
check_no_coplanar_overlap, run by main):
- Every solid part (roof slabs, chimney, PV panels, pergola timbers, neighbour, tree, ...) is a
  closed mesh of welded vertices (faces share vertex indices), consistently oriented, normals
  outward: each directed edge is used once by one face and once, reversed, by its neighbour,
  and the signed volume is positive.
- Open surfaces (ground, walls, glass, gables) face outward or up, reveals into their opening:
  the sun study takes a polygon's front side from the right-hand rule, and a polygon is sunlit
  only from its front, so a wall facing inward would never see the sun.
- No two faces, of one object or of two, lie in one plane and overlap with positive area.
  Coincident coplanar faces make "which surface is nearer" a tie that every method breaks its
  own way, so parts that touch are made to interpenetrate instead (posts stand 0.1 m into the
  deck, the terrace deck and the balcony slab reach 0.1-0.3 m into the wall, and the two roof
  slabs leave a gap at the ridge that a ridge cap covers).
- No T-junctions inside a mesh: where a vertex of one face lies on another face's edge, that
  edge gets the vertex too (polygons keep collinear vertices), so adjacent faces share edges.

The output is deterministic: no randomness (the tree's crown is perturbed by a fixed formula),
and numbers are written with a fixed number of decimals.
"""

import json
import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = os.path.join(ROOT, "examples")
MODEL_DIR = "models/house"  # relative to examples/, as the scene file names it

# ---------------------------------------------------------------------------------------------
# Dimensions, in metres. The house is centred on the origin: x in [-5, 5] (10 m east-west),
# z in [-4, 4] (8 m north-south); floors at y = 0 and 3, eaves (top of the walls) at y = 6.

HOUSE_X = 5.0            # half width, east-west
HOUSE_Z = 4.0            # half depth, north-south
EAVE_Y = 6.0             # top of the long walls, where the roof's underside rests on them
PITCH_DEG = 35.0         # roof pitch: a common pitch, and a good one for the PV panels
OVERHANG = 0.6           # eaves and verges overhang the walls by this much (horizontally)
ROOF_T = 0.30            # roof slab thickness, measured vertically
RIDGE_GAP = 0.05         # each slab stops this far short of the ridge line (see the cap)
REVEAL = 0.15            # windows and doors sit this far behind the wall's outer plane

TAN = math.tan(math.radians(PITCH_DEG))
RIDGE_Y = EAVE_Y + HOUSE_Z * TAN          # underside of the roof at the ridge line


def roof_bottom_y(z):
    """Height of the roof slabs' underside at z: it passes through the walls' top outer edge."""
    return EAVE_Y + (HOUSE_Z - abs(z)) * TAN


def roof_top_y(z):
    return roof_bottom_y(z) + ROOF_T


# ---------------------------------------------------------------------------------------------
# Small vector helpers (tuples of three floats).

def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    return mul(a, 1.0 / norm(a))


def newell(points):
    """Newell's normal (not normalised): twice the area vector, right-hand rule."""
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(points):
        q = points[(i + 1) % len(points)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return tuple(n)


# ---------------------------------------------------------------------------------------------
# Meshes. Vertices are welded as they are added (keyed by their coordinates rounded to 1e-6 m,
# the precision the OBJ files are written with), so the faces of a box share its 8 corners.

class Mesh:
    def __init__(self, name, closed, comment):
        self.name = name
        self.closed = closed      # every component a closed, outward-oriented solid
        self.comment = comment
        self.vertices = []
        self.index = {}
        self.faces = []

    def vertex(self, p):
        key = tuple(round(c, 6) + 0.0 for c in p)  # + 0.0 turns -0.0 into 0.0
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append(key)
        return self.index[key]

    def face(self, points, facing=None):
        """Adds a polygon; with `facing`, its vertex order is reversed if its right-hand-rule
        normal points away from that direction."""
        if facing is not None and dot(newell(points), facing) < 0:
            points = points[::-1]
        self.faces.append([self.vertex(p) for p in points])

    def points(self, f):
        return [self.vertices[i] for i in f]


def grid_face(mesh, c0, eu, ev, nu, nv, facing):
    """The parallelogram c0 + s eu + t ev (s, t in [0, 1]) as nu x nv equal quads."""
    for i in range(nu):
        for j in range(nv):
            p = [add(add(c0, mul(eu, (i + a) / nu)), mul(ev, (j + b) / nv))
                 for a, b in ((0, 0), (1, 0), (1, 1), (0, 1))]
            mesh.face(p, facing)


def hexahedron(mesh, corners, top_grid=None):
    """A closed solid from 8 corners: corners[0:4] one quad, corners[4:8] the opposite one,
    corners[i + 4] joined to corners[i]. Faces are oriented outward (away from the centroid,
    which is inside for these convex solids). With top_grid = (nu, nv) the first quad is
    split into nu x nv quads (edge 0-1 into nu parts)."""
    centre = mul(corners[0], 0.0)
    for c in corners:
        centre = add(centre, mul(c, 1.0 / 8))

    def out(points):
        m = mul(points[0], 0.0)
        for p in points:
            m = add(m, mul(p, 1.0 / len(points)))
        return sub(m, centre)

    a = corners[0:4]
    b = corners[4:8]
    if top_grid:
        grid_face(mesh, a[0], sub(a[1], a[0]), sub(a[3], a[0]), top_grid[0], top_grid[1],
                  out(a))
    else:
        mesh.face(a, out(a))
    mesh.face(b, out(b))
    for i in range(4):
        j = (i + 1) % 4
        side = [a[i], a[j], b[j], b[i]]
        mesh.face(side, out(side))


def box(mesh, lo, hi):
    """Axis-aligned closed box."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    hexahedron(mesh, [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1),
                      (x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)])


def oriented_box(mesh, origin, ea, eb, ec):
    """Closed box spanned by three edge vectors from one corner."""
    o = origin
    hexahedron(mesh, [o, add(o, ea), add(add(o, ea), eb), add(o, eb),
                      add(o, ec), add(add(o, ea), ec), add(add(add(o, ea), eb), ec),
                      add(add(o, eb), ec)])


def prism(mesh, outline, y0, y1):
    """Closed vertical prism over a simple polygon `outline` of (x, z) points (convex or not):
    the concave L-shaped garage and its roof, the tree's trunk. Its top and bottom stay single
    polygons (the garage roof is one concave hexagon)."""
    top = [(x, y1, z) for x, z in outline]
    bottom = [(x, y0, z) for x, z in outline]
    mesh.face(top, (0, 1, 0))
    mesh.face(bottom, (0, -1, 0))
    # The sides: outward is the side away from the outline's interior, found from its turning
    # direction (the top, oriented up, fixes which way the outline runs).
    ring = top if dot(newell(top), (0, 1, 0)) > 0 else top[::-1]
    ring_b = [(x, y0, z) for x, _, z in ring]
    for i in range(len(ring)):
        j = (i + 1) % len(ring)
        # Top oriented up runs counter-clockwise seen from above; its side faces are then
        # (ring[j], ring[i], ring_b[i], ring_b[j]) for an outward normal.
        mesh.face([ring[j], ring[i], ring_b[i], ring_b[j]])


# ---------------------------------------------------------------------------------------------
# Facades: a wall is the outer plane of one side of the house, with rectangular openings. It is
# cut into rectangles around the openings (all in the wall's plane, facing out); each opening
# gets four reveals (the opening's sides, REVEAL deep, facing into the opening) and, at the back
# of the reveals, a pane of glass or a door leaf facing out. The reveals shade the glass: at
# low sun angles and from the side, the glass is partly in the reveals' shadow. Wall, reveals
# and glass are separate objects of each facade (wall_south, reveals_south, windows_south), so
# each one's sun hours stand on their own. Their edges meet exactly (the wall's hole is the
# reveals' outer rim, the pane the reveals' inner rim): the shell has no slits for light.

class Facade:
    def __init__(self, name, normal, origin, u_axis, length, height):
        self.name = name
        self.n = normal                # outward
        self.origin = origin           # wall point at u = 0, v = 0
        self.u = u_axis                # horizontal, u x up = outward normal
        self.length = length
        self.height = height
        self.openings = []             # (u0, u1, v0, v1, kind), kind "glass" or "door"
        assert dot(cross(self.u, (0, 1, 0)), self.n) > 0.999

    def at(self, u, v, depth=0.0):
        return add(add(add(self.origin, mul(self.u, u)), (0, v, 0)), mul(self.n, -depth))

    def opening(self, u0, u1, v0, v1, kind="glass"):
        self.openings.append((u0, u1, v0, v1, kind))

    def build(self, wall, reveals, panes, door=None):
        # Wall: columns between the openings' u-bounds; in a column, the openings that span it
        # leave the pieces between them. Openings stacked in a column share their u-bounds, so
        # this gives piers, sills, spandrels and lintels, no slivers.
        us = sorted({0.0, self.length} | {o[0] for o in self.openings}
                    | {o[1] for o in self.openings})
        for ua, ub in zip(us, us[1:]):
            cut = sorted((o[2], o[3]) for o in self.openings if o[0] <= ua and ub <= o[1])
            v = 0.0
            for v0, v1 in cut + [(self.height, self.height)]:
                if v0 > v:
                    wall.face([self.at(ua, v), self.at(ub, v), self.at(ub, v0), self.at(ua, v0)],
                              self.n)
                v = v1
        for u0, u1, v0, v1, kind in self.openings:
            # Reveals, each facing the opening's axis.
            mid = self.at((u0 + u1) / 2, (v0 + v1) / 2)
            for (ua, va), (ub, vb) in (((u0, v0), (u1, v0)), ((u1, v0), (u1, v1)),
                                       ((u1, v1), (u0, v1)), ((u0, v1), (u0, v0))):
                quad = [self.at(ua, va), self.at(ub, vb), self.at(ub, vb, REVEAL),
                        self.at(ua, va, REVEAL)]
                edge_mid = self.at((ua + ub) / 2, (va + vb) / 2)
                reveals.face(quad, sub(mid, edge_mid))
            pane = [self.at(u0, v0, REVEAL), self.at(u1, v0, REVEAL), self.at(u1, v1, REVEAL),
                    self.at(u0, v1, REVEAL)]
            (door if kind == "door" else panes).face(pane, self.n)


# ---------------------------------------------------------------------------------------------
# The scene's parts.

def house_facades():
    H = HOUSE_X
    D = HOUSE_Z
    south = Facade("south", (0, 0, 1), (-H, 0, D), (1, 0, 0), 2 * H, EAVE_Y)
    east = Facade("east", (1, 0, 0), (H, 0, D), (0, 0, -1), 2 * D, EAVE_Y)
    north = Facade("north", (0, 0, -1), (H, 0, -D), (-1, 0, 0), 2 * H, EAVE_Y)
    west = Facade("west", (-1, 0, 0), (-H, 0, -D), (0, 0, 1), 2 * D, EAVE_Y)

    # South, the garden side (u = x + 5): a terrace door under the pergola with a large window
    # above it, a small window pair in the middle, and the living room window under the balcony
    # with the balcony door above it. Sills at 0.9 m, heads at 2.35 m (ground floor) and 5.3 m
    # (first floor); door thresholds 0.15 m above the ground (0.03 m above the terrace deck).
    for u0, u1, gf, ff in ((1.2, 3.4, (0.15, 2.35), (3.9, 5.3)),
                           (4.4, 5.6, (1.0, 2.35), (3.9, 5.3)),
                           (6.8, 8.8, (0.9, 2.35), (3.1, 5.3))):
        south.opening(u0, u1, *gf)
        south.opening(u0, u1, *ff)
    # East (u = 4 - z, from the south-east corner northward): a window pair, the front door
    # (a door leaf, not glass) with a stair window above, and a second window pair.
    for u0, u1, gf, kind in ((1.2, 2.4, (0.9, 2.35), "glass"),
                             (3.5, 4.6, (0.15, 2.25), "door"),
                             (5.6, 6.8, (0.9, 2.35), "glass")):
        east.opening(u0, u1, *gf, kind)
        east.opening(u0, u1, 3.9, 5.3)
    # North: small windows (kitchen, bathroom, stairs), as north sides usually have.
    for u0, u1 in ((1.4, 2.4), (4.5, 5.5), (7.6, 8.6)):
        north.opening(u0, u1, 1.2, 2.2)
        north.opening(u0, u1, 4.2, 5.2)
    # West, facing the garage: one window per floor.
    west.opening(3.0, 5.0, 0.9, 2.35)
    west.opening(3.0, 5.0, 3.9, 5.3)
    return south, east, north, west


def gable(mesh, x, facing):
    """Triangular gable end wall at x, from the top of the end wall (EAVE_Y) up to the underside
    of the roof; its two sloping edges lie in the roof slabs' undersides."""
    mesh.face([(x, EAVE_Y, HOUSE_Z), (x, EAVE_Y, -HOUSE_Z), (x, RIDGE_Y, 0.0)], facing)


def roof_slope(mesh, sign):
    """One roof slope (sign +1 south, -1 north) as a closed slab ROOF_T thick, from RIDGE_GAP
    short of the ridge line down to the eave OVERHANG beyond the wall, and OVERHANG beyond the
    gable walls. Its top is split into 8 x 4 tiles so that the study's per-polygon results show
    where on the roof the chimney's and the PV panels' shadows fall."""
    x0, x1 = -HOUSE_X - OVERHANG, HOUSE_X + OVERHANG
    z_r = sign * RIDGE_GAP
    z_e = sign * (HOUSE_Z + OVERHANG)
    top = [(x0, roof_top_y(z_e), z_e), (x1, roof_top_y(z_e), z_e),
           (x1, roof_top_y(z_r), z_r), (x0, roof_top_y(z_r), z_r)]
    bottom = [(x, y - ROOF_T, z) for x, y, z in top]
    hexahedron(mesh, top + bottom, top_grid=(8, 4))


def roof_ridge(mesh):
    """Ridge cap: covers the gap between the slabs, sinking into both of them (its underside
    is below the slabs' top surfaces where its sides cut them)."""
    y_top = roof_top_y(0.0)
    box(mesh, (-HOUSE_X - OVERHANG - 0.05, y_top - 0.15, -0.12),
        (HOUSE_X + OVERHANG + 0.05, y_top + 0.12, 0.12))


def chimney(mesh):
    """On the south slope, west of the PV array, 0.9 m above the ridge cap: it shadows the
    roof and, in the late afternoon, the PV array's western end. Its foot is in the attic,
    below the roof slab it passes through."""
    box(mesh, (-3.5, roof_bottom_y(0.7) - 0.4, 0.7), (-2.9, roof_top_y(0.0) + 1.0, 1.3))


def pv_array(mesh):
    """12 panels, 1.0 x 1.7 m, 0.04 m thick, in two rows of six in portrait on the south slope,
    0.10 m above the roof surface (on rails, left out) and parallel to it."""
    up = unit((0.0, TAN, -1.0))             # up the south slope
    n = unit((0.0, 1.0, TAN))               # the south slope's outward normal
    eave_top = (0.0, roof_top_y(HOUSE_Z + OVERHANG), HOUSE_Z + OVERHANG)
    for row in range(2):
        s = 0.7 + row * 1.75                 # distance up the slope from the eave
        for col in range(6):
            x = -1.9 + col * 1.05
            corner = add(add((x, 0, 0), eave_top), add(mul(up, s), mul(n, 0.10)))
            oriented_box(mesh, corner, (1.0, 0, 0), mul(up, 1.7), mul(n, 0.04))


def canopy(mesh):
    """A glass canopy over the front door (east facade, z from -0.6 to 0.5), 0.25 m above the
    door's head, reaching 0.2 m into the wall."""
    box(mesh, (HOUSE_X - 0.2, 2.5, -0.9), (HOUSE_X + 1.1, 2.56, 0.8))


def terrace(mesh):
    """Timber deck south of the terrace door, 0.12 m above the ground and 0.1 m into it; it
    reaches 0.1 m into the wall (z from 3.9), so it does not touch the wall's plane face to
    face."""
    box(mesh, (-5.5, -0.10, HOUSE_Z - 0.1), (0.3, 0.12, HOUSE_Z + 4.2))


def pergola(mesh):
    """Over the terrace: 4 posts, 2 beams along x, 17 slats along z, 0.3 m apart: many thin
    boxes, a self-shading test (slats shadow the beams, each other at low sun, the terrace and
    the terrace door). Each timber reaches into the one it rests on."""
    for x in (-5.1, -0.4):
        for z in (4.5, 7.6):
            box(mesh, (x - 0.06, 0.0, z - 0.06), (x + 0.06, 2.65, z + 0.06))
    for z in (4.5, 7.6):
        box(mesh, (-5.4, 2.55, z - 0.08), (-0.1, 2.75, z + 0.08))
    for k in range(17):
        x = -5.25 + 0.3 * k
        box(mesh, (x - 0.025, 2.70, 4.2), (x + 0.025, 2.84, 7.9))


def balcony(mesh):
    """First-floor balcony on the south facade, over the living room window: a slab that
    reaches 0.3 m into the wall (it shades the window below) and a balustrade of three thin
    panels standing in the slab, inset so that no two faces are coplanar."""
    box(mesh, (1.2, 2.8, HOUSE_Z - 0.3), (4.4, 3.0, HOUSE_Z + 1.4))
    box(mesh, (1.23, 2.95, HOUSE_Z + 1.32), (4.37, 4.0, HOUSE_Z + 1.37))
    for x in (1.25, 4.29):
        box(mesh, (x, 2.93, HOUSE_Z - 0.05), (x + 0.06, 3.98, HOUSE_Z + 1.35))


# The detached garage west of the house: L-shaped in plan, its inner corner open to the
# south-east, so its walls shade each other there. The roof is a separate slab with a 0.3 m
# overhang all round, a concave L-shaped polygon on top, sinking 0.05 m into the walls' block.
GARAGE_L = [(-12.5, -4.0), (-7.0, -4.0), (-7.0, 1.0), (-10.0, 1.0), (-10.0, 5.0), (-12.5, 5.0)]


def offset_l(outline, d):
    """The L outline moved outward by d (its edges are axis-aligned)."""
    (xa, za), (xb, _), (_, zc), (xd, _), (_, ze), _ = outline
    return [(xa - d, za - d), (xb + d, za - d), (xb + d, zc + d), (xd + d, zc + d),
            (xd + d, ze + d), (xa - d, ze + d)]


def garage(mesh):
    prism(mesh, GARAGE_L, -0.1, 2.7)


def garage_roof(mesh):
    prism(mesh, offset_l(GARAGE_L, 0.3), 2.65, 2.95)


def neighbour(mesh):
    """A taller block (four storeys, 12.5 m) east-north-east of the house across the lot, 11 m
    from its east wall: it shades the east facade on summer mornings, when the sun rises in
    the north-east."""
    box(mesh, (16.0, -0.2, -13.0), (24.0, 12.5, -3.0))


def icosphere():
    """Unit icosahedron subdivided once: 42 vertices, 80 outward triangles."""
    t = (1 + math.sqrt(5)) / 2
    v = [unit(p) for p in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                           (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    mids = {}

    def mid(a, b):
        k = (min(a, b), max(a, b))
        if k not in mids:
            mids[k] = len(v)
            v.append(unit(mul(add(v[a], v[b]), 0.5)))
        return mids[k]

    out = []
    for a, b, c in f:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return v, out


def tree(mesh):
    """A deciduous tree south-west of the house, 7.6 m tall: an octagonal trunk and a crude
    polyhedral crown (a subdivided icosahedron, 80 triangles, a little wider than tall, its
    radius varied by a fixed formula so it does not look machined). The trunk's top is inside
    the crown. In the afternoon it shades the terrace and the pergola."""
    cx, cz = -8.0, 11.5
    r = 0.18
    # Corners at 0, 45, 90, ... degrees, so the sides face 22.5 + 45 k degrees: none faces
    # exactly along or across the render light's azimuth (225 degrees). A side lit exactly
    # edge-on is a tie (the light in the polygon's plane), which methods may break either way.
    ring = [(cx + r * math.cos(math.pi * k / 4), cz - r * math.sin(math.pi * k / 4))
            for k in range(8)]
    prism(mesh, ring, -0.2, 3.6)
    v, f = icosphere()
    centre = (cx, 5.2, cz)
    pts = []
    for i, p in enumerate(v):
        # Star-shaped about the centre whatever the factor, so the crown stays a closed,
        # outward-oriented polyhedron.
        k = 1.0 + 0.08 * math.sin(3.7 * i) * math.cos(1.9 * i + 0.4)
        pts.append(add(centre, (2.6 * k * p[0], 2.2 * k * p[1], 2.6 * k * p[2])))
    for a, b, c in f:
        mesh.face([pts[a], pts[b], pts[c]])


def ground(mesh):
    """The lot: 60 x 60 m facing up, in 15 x 15 tiles of 4 m so that the study's results map
    the garden's sun hours. It runs under the house (the house has no floor of its own)."""
    grid_face(mesh, (-30.0, 0.0, 30.0), (60.0, 0, 0), (0, 0, -60.0), 15, 15, (0, 1, 0))


# ---------------------------------------------------------------------------------------------
# T-junctions and checks.

def split_t_junctions(mesh):
    """Inserts into each face edge the mesh's vertices that lie inside it (e.g. a pier's edge
    gets the corners of the sill and lintel pieces beside it, a slab's side gets the corners of
    its top's tiles), so that every edge is shared by exactly the faces along it."""
    verts = mesh.vertices
    for fi, f in enumerate(mesh.faces):
        new = []
        for k, a in enumerate(f):
            b = f[(k + 1) % len(f)]
            pa, pb = verts[a], verts[b]
            e = sub(pb, pa)
            ee = dot(e, e)
            inside = []
            for vi, p in enumerate(verts):
                if vi in (a, b):
                    continue
                t = dot(sub(p, pa), e) / ee
                if 1e-9 < t < 1 - 1e-9 and norm(sub(p, add(pa, mul(e, t)))) < 1e-6:
                    inside.append((t, vi))
            new.append(a)
            new += [vi for _, vi in sorted(inside)]
        mesh.faces[fi] = new


def check_closed(mesh):
    """Each directed edge once, its reverse once (closed, manifold, consistently oriented), and
    a positive signed volume (outward)."""
    edges = {}
    for f in mesh.faces:
        for k, a in enumerate(f):
            e = (a, f[(k + 1) % len(f)])
            assert e not in edges, f"{mesh.name}: edge {e} used twice the same way"
            edges[e] = True
    for a, b in edges:
        assert (b, a) in edges, f"{mesh.name}: edge {(a, b)} is a boundary edge"
    volume = 0.0
    for f in mesh.faces:
        p = mesh.points(f)
        for k in range(1, len(p) - 1):
            volume += dot(p[0], cross(p[k], p[k + 1])) / 6
    assert volume > 0, f"{mesh.name}: inward (volume {volume})"
    return volume


def project(points, n):
    """2D coordinates in the plane of normal n, counter-clockwise about n."""
    a = max(range(3), key=lambda i: abs(n[i]))
    i, j = (a + 1) % 3, (a + 2) % 3
    pts = [(p[i], p[j]) for p in points]
    return pts if n[a] > 0 else pts[::-1]


def area2(poly):
    return sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(poly, poly[1:] + poly[:1])) / 2


def triangulate(poly):
    """Ear clipping of a simple counter-clockwise polygon (collinear vertices allowed)."""
    idx = list(range(len(poly)))
    tris = []
    guard = 0
    while len(idx) > 3 and guard < 10000:
        guard += 1
        for k in range(len(idx)):
            a, b, c = poly[idx[k - 1]], poly[idx[k]], poly[idx[(k + 1) % len(idx)]]
            cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            if cr <= 1e-12:
                if abs(cr) <= 1e-12:          # collinear: drop the middle vertex
                    idx.pop(k)
                    break
                continue
            if any(inside_tri(poly[m], a, b, c) for m in idx
                   if m not in (idx[k - 1], idx[k], idx[(k + 1) % len(idx)])):
                continue
            tris.append((a, b, c))
            idx.pop(k)
            break
    if len(idx) == 3:
        tris.append(tuple(poly[m] for m in idx))
    return tris


def inside_tri(p, a, b, c):
    def s(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    return s(a, b, p) > 1e-12 and s(b, c, p) > 1e-12 and s(c, a, p) > 1e-12


def clip(subject, clipper):
    """Sutherland-Hodgman: subject polygon clipped by a convex counter-clockwise polygon."""
    out = list(subject)
    for a, b in zip(clipper, clipper[1:] + clipper[:1]):
        inp, out = out, []
        if not inp:
            break

        def side(p):
            return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        for k, p in enumerate(inp):
            q = inp[k - 1]
            sp, sq = side(p), side(q)
            if sp >= 0:
                if sq < 0:
                    out.append(cut(q, p, sq, sp))
                out.append(p)
            elif sq >= 0:
                out.append(cut(q, p, sq, sp))
    return out


def cut(q, p, sq, sp):
    t = sq / (sq - sp)
    return (q[0] + t * (p[0] - q[0]), q[1] + t * (p[1] - q[1]))


def check_no_coplanar_overlap(meshes):
    """No two faces (any objects) in one plane overlapping with positive area."""
    faces = []
    for m in meshes:
        for fi, f in enumerate(m.faces):
            p = m.points(f)
            n = unit(newell(p))
            lo = tuple(min(q[i] for q in p) for i in range(3))
            hi = tuple(max(q[i] for q in p) for i in range(3))
            faces.append((m.name, fi, p, n, dot(n, p[0]), lo, hi))
    faces.sort(key=lambda f: f[5][0])
    bad = []
    for i, (na, fa, pa, nA, dA, loA, hiA) in enumerate(faces):
        for nb, fb, pb, nB, dB, loB, hiB in faces[i + 1:]:
            if loB[0] > hiA[0] + 1e-9:
                break
            if any(loB[k] > hiA[k] + 1e-9 or loA[k] > hiB[k] + 1e-9 for k in (1, 2)):
                continue
            c = dot(nA, nB)
            if abs(c) < 1 - 1e-9 or abs(dA - c * dB) > 1e-6:
                continue
            ta = triangulate(project(pa, nA))
            tb = triangulate(project(pb, nA))
            overlap = sum(abs(area2(clip(list(x), list(y)))) for x in ta for y in tb
                          if len(clip(list(x), list(y))) >= 3)
            if overlap > 1e-9:
                bad.append(f"{na}[{fa}] and {nb}[{fb}] overlap in one plane ({overlap:.3g} m2)")
    assert not bad, "\n".join(bad)


def polygon_area(points):
    return norm(newell(points)) / 2


# ---------------------------------------------------------------------------------------------
# Output.

def fmt(x):
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def write_obj(mesh, path):
    with open(path, "w", newline="\n") as out:
        out.write(f"# {mesh.name}: {mesh.comment}\n")
        out.write("# Written by scripts/example_house.py (do not edit: run the script). Metres;\n"
                  "# +Y up, north -Z, east +X. "
                  + ("Closed solid(s), outward normals.\n" if mesh.closed else
                     "Open surface, faces front side outward/up.\n"))
        for v in mesh.vertices:
            out.write("v " + " ".join(fmt(c) for c in v) + "\n")
        for f in mesh.faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")


def build():
    def mesh(name, closed, comment, maker=None):
        m = Mesh(name, closed, comment)
        if maker:
            maker(m)
        return m

    south, east, north, west = house_facades()
    parts = {}
    for fac in (south, east, north, west):
        parts["wall_" + fac.name] = mesh("wall_" + fac.name, False,
                                         f"the {fac.name} wall's outer plane, around the openings")
        parts["windows_" + fac.name] = mesh("windows_" + fac.name, False,
                                            f"{fac.name} glass, {REVEAL} m behind the wall plane")
        parts["reveals_" + fac.name] = mesh("reveals_" + fac.name, False,
                                            f"{fac.name} openings' sides, facing into the "
                                            "openings")
    parts["door"] = mesh("door", False, "front door leaf (east facade), behind its reveals")
    for fac in (south, east, north, west):
        fac.build(parts["wall_" + fac.name], parts["reveals_" + fac.name],
                  parts["windows_" + fac.name], parts["door"])
    parts["gable_east"] = mesh("gable_east", False, "east gable end wall, above wall_east")
    gable(parts["gable_east"], HOUSE_X, (1, 0, 0))
    parts["gable_west"] = mesh("gable_west", False, "west gable end wall, above wall_west")
    gable(parts["gable_west"], -HOUSE_X, (-1, 0, 0))
    parts["roof_south"] = mesh("roof_south", True, "south roof slope, a slab with overhang",
                               lambda m: roof_slope(m, +1))
    parts["roof_north"] = mesh("roof_north", True, "north roof slope, a slab with overhang",
                               lambda m: roof_slope(m, -1))
    parts["roof_ridge"] = mesh("roof_ridge", True, "ridge cap over the slabs' gap", roof_ridge)
    parts["chimney"] = mesh("chimney", True, "chimney through the south slope", chimney)
    parts["pv_array"] = mesh("pv_array", True, "12 PV panels on the south slope", pv_array)
    parts["canopy"] = mesh("canopy", True, "glass canopy over the front door", canopy)
    parts["terrace"] = mesh("terrace", True, "timber deck on the south terrace", terrace)
    parts["pergola"] = mesh("pergola", True, "pergola over the terrace: posts, beams, slats",
                            pergola)
    parts["balcony"] = mesh("balcony", True, "south balcony slab and balustrade", balcony)
    parts["garage"] = mesh("garage", True, "L-shaped detached garage, walls block", garage)
    parts["garage_roof"] = mesh("garage_roof", True, "garage's flat L-shaped roof slab",
                                garage_roof)
    parts["neighbour"] = mesh("neighbour", True, "taller neighbouring block to the east",
                              neighbour)
    parts["tree"] = mesh("tree", True, "trunk and polyhedral crown", tree)
    parts["ground"] = mesh("ground", False, "the 60 x 60 m lot, facing up", ground)

    # The order of the scene's objects. shadowkit's shaded image colours an object by its
    # index modulo an 8-colour palette (beige, orange, blue, green, ochre, purple, cyan, pink),
    # so the order puts the visible parts on a plausible colour: walls beige, roofs orange,
    # glass blue, ground and tree green, timber ochre. Parts the camera does not see (north
    # and west sides) fill the remaining places.
    order = ["wall_south", "roof_south", "windows_south", "ground",
             "reveals_south", "pv_array", "balcony", "chimney",
             "wall_east", "roof_north", "windows_east", "tree",
             "reveals_east", "wall_north", "canopy", "door",
             "gable_east", "roof_ridge", "windows_north", "pergola",
             "terrace", "reveals_north", "wall_west", "gable_west",
             "neighbour", "garage_roof", "windows_west", "reveals_west",
             "garage"]
    assert sorted(order) == sorted(parts)
    return [parts[n] for n in order]


# The camera looks at the south and east facades and the south roof slope from the south-east
# and above; the light (for `shadowkit render`; the sun study ignores it and uses the sun) is
# an afternoon sun from the south-west, 40 degrees high, so the pergola, the balcony, the
# reveals, the chimney and the tree all cast visible shadows on lit surfaces.
CAMERA = {"position": [22.0, 14.0, 33.0], "look_at": [1.5, 3.5, -1.5], "up": [0, 1, 0],
          "fov_y_deg": 32, "width": 1920, "height": 1080}
SUN_ELEVATION = 40.0
SUN_AZIMUTH = 225.0   # degrees clockwise from north: south-west
# Where the worked example's sun study stands (the parser of "site" is being added; the
# command line's --lat/--lon/--utc-offset/--north give the same values until then).
SITE = {"latitude": 49.0069, "longitude": 8.4037, "utc_offset": 1, "north": 0,
        "name": "Karlsruhe, Germany"}


def sun_direction():
    """The direction the light travels: the opposite of the unit vector toward the sun
    (sun-study.md: cos E (sin A east + cos A north) + sin E up, north = -Z, east = +X)."""
    e, a = math.radians(SUN_ELEVATION), math.radians(SUN_AZIMUTH)
    to_sun = (math.cos(e) * math.sin(a), math.sin(e), -math.cos(e) * math.cos(a))
    return [float(fmt(-c)) for c in to_sun]


def write_scene(meshes, path):
    def arr(v):
        return "[" + ", ".join(fmt(c) for c in v) + "]"

    cam = CAMERA
    lines = ["{",
             '  "camera": {',
             f'    "position": {arr(cam["position"])}, "look_at": {arr(cam["look_at"])}, '
             f'"up": {arr(cam["up"])},',
             f'    "fov_y_deg": {fmt(cam["fov_y_deg"])}, "width": {cam["width"]}, '
             f'"height": {cam["height"]}',
             "  },",
             '  "lights": [',
             f'    {{"type": "directional", "direction": {arr(sun_direction())}}}',
             "  ],",
             '  "site": ' + json.dumps(SITE) + ",",
             '  "objects": [']
    for k, m in enumerate(meshes):
        sep = "," if k + 1 < len(meshes) else ""
        lines.append(f'    {{"name": "{m.name}", "mesh": "{MODEL_DIR}/{m.name}.obj"}}{sep}')
    lines += ["  ]", "}"]
    text = "\n".join(lines) + "\n"
    json.loads(text)  # well-formed
    with open(path, "w", newline="\n") as out:
        out.write(text)


def main():
    meshes = build()
    for m in meshes:
        split_t_junctions(m)
    for m in meshes:
        if m.closed:
            check_closed(m)
    check_no_coplanar_overlap(meshes)

    model_dir = os.path.join(EXAMPLES, MODEL_DIR)
    os.makedirs(model_dir, exist_ok=True)
    for name in sorted(os.listdir(model_dir)):  # no stale meshes of parts that were renamed
        if name.endswith(".obj"):
            os.remove(os.path.join(model_dir, name))
    for m in meshes:
        write_obj(m, os.path.join(model_dir, m.name + ".obj"))
    write_scene(meshes, os.path.join(EXAMPLES, "house.json"))

    total = 0
    print(f"{'object':16} {'polygons':>8} {'area m2':>9}")
    for m in meshes:
        area = sum(polygon_area(m.points(f)) for f in m.faces)
        total += len(m.faces)
        print(f"{m.name:16} {len(m.faces):8d} {area:9.2f}")
    print(f"{'total':16} {total:8d}")


if __name__ == "__main__":
    main()
