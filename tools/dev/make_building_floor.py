#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates worlds/building_floor.toml (a 64 x 40 m office floor) and its place graph worlds/building_floor.places.toml, then checks both.
"""Usage:
  tools/dev/make_building_floor.py            write both files into worlds/, then check them
  tools/dev/make_building_floor.py --check    only check the files already there
  --dir DIR                                   read/write DIR instead of the repository's worlds/

The layout is data (ROOMS, FURNITURE below); everything else is derived from it, so the output
is the same on every run. The checks parse the written files back with tomllib and rebuild the
obstacles the way hal/sim/world_toml.cpp does (wall pieces squared off half a thickness beyond
their ends, door jambs not extended); any failure prints what and where, and exits 1.
"""
import argparse
import math
import pathlib
import re
import sys
import tomllib

WORLD_FILE = "building_floor.toml"
PLACES_FILE = "building_floor.places.toml"

# ----------------------------------------------------------------------------------------------
# Layout (wall centre lines, m). Clear widths are centre-line spacings minus the wall thickness.
T = 0.10            # wall thickness
H = T / 2
SIZE_X, SIZE_Y = 64.0, 40.0
EW_S, EW_N = 18.8, 21.3    # east-west corridor walls: 2.40 m clear
A_W, A_E = 20.0, 22.3      # north-south corridor A: 2.20 m clear
B_W, B_E = 42.0, 44.2      # north-south corridor B: 2.10 m clear

# name, what, (x0, y0, x1, y1) centre-line rectangle, doors: (side, coordinate along the wall, width)
ROOMS = [
    ("room-01", "office", (0.0, 10.8, 6.5, EW_S), [("N", 3.25, 0.90)]),
    ("room-02", "office", (6.5, 10.8, 13.0, EW_S), [("N", 9.75, 1.00)]),
    ("room-03", "office", (13.0, 10.8, A_W, EW_S), [("N", 16.5, 0.90)]),
    ("room-04", "workshop", (0.0, 0.0, A_W, 10.8), [("E", 5.4, 1.20)]),
    ("room-05", "lecture room", (0.0, EW_N, 12.0, SIZE_Y), [("S", 3.0, 1.20), ("S", 9.0, 1.00)]),
    ("room-06", "laboratory", (12.0, EW_N, A_W, SIZE_Y), [("S", 16.0, 0.90), ("E", 34.0, 1.00)]),
    ("room-07", "office", (A_E, 10.8, 32.2, EW_S), [("N", 27.25, 1.00)]),
    ("room-08", "office", (32.2, 10.8, B_W, EW_S), [("N", 37.1, 0.90)]),
    ("room-09", "store", (A_E, 0.0, B_W, 10.8), [("W", 5.4, 1.20), ("E", 5.4, 1.00)]),
    ("room-10", "office", (A_E, EW_N, 28.8, 29.3), [("S", 25.55, 0.90)]),
    ("room-11", "office", (28.8, EW_N, 35.3, 29.3), [("S", 32.05, 1.00)]),
    ("room-12", "office", (35.3, EW_N, B_W, 29.3), [("S", 38.65, 0.90)]),
    ("room-13", "meeting room", (A_E, 29.3, B_W, SIZE_Y), [("W", 34.65, 1.20), ("E", 34.65, 1.00)]),
    ("room-14", "laboratory", (B_E, 0.0, 54.2, EW_S), [("N", 49.2, 1.20)]),
    ("room-15", "laboratory", (54.2, 0.0, SIZE_X, EW_S), [("N", 59.1, 1.00)]),
    ("room-16", "hall", (B_E, EW_N, SIZE_X, SIZE_Y),
     [("S", 49.0, 1.20), ("S", 59.0, 0.90), ("W", 30.65, 1.00)]),
]

# Furniture per room: ("rect", name, (min x, min y), (max x, max y)) or
# ("box", name, (centre x, centre y), (size x, size y), angle_deg).
FURNITURE = {
    "room-01": [("rect", "r01-desk", (0.05, 10.85), (1.65, 11.65)),
                ("rect", "r01-cabinet", (5.95, 12.0), (6.45, 13.2))],
    "room-02": [("box", "r02-desk", (8.2, 11.6), (1.6, 0.8), 0.0),
                ("box", "r02-crate", (12.2, 17.6), (0.6, 0.6), 15.0)],
    "room-03": [("rect", "r03-shelf", (19.45, 11.5), (19.95, 14.0))],
    "room-04": [("rect", "r04-bench-sw", (2.0, 0.05), (8.0, 0.85)),
                ("rect", "r04-bench-se", (12.0, 0.05), (18.0, 0.85)),
                ("rect", "r04-bench-w", (0.05, 3.0), (0.85, 8.0)),
                ("box", "r04-lathe", (15.0, 8.6), (1.2, 1.0), 10.0),
                ("box", "r04-crate", (4.0, 9.6), (0.8, 0.8), 25.0)],
    "room-05": [("rect", "r05-row-1", (2.0, 33.4), (10.0, 34.0)),
                ("rect", "r05-row-2", (2.0, 35.4), (10.0, 36.0)),
                ("rect", "r05-row-3", (2.0, 37.4), (10.0, 38.0)),
                ("box", "r05-lectern", (6.0, 26.0), (0.6, 0.5), 0.0)],
    "room-06": [("rect", "r06-bench-w", (12.05, 24.0), (12.85, 29.0)),
                ("rect", "r06-bench-n", (13.5, 39.15), (18.5, 39.95)),
                ("box", "r06-cart", (18.5, 25.0), (0.8, 0.5), -30.0)],
    "room-09": [("rect", "r09-shelf-1", (25.0, 2.0), (31.0, 2.6)),
                ("rect", "r09-shelf-2", (33.5, 2.0), (39.5, 2.6)),
                ("rect", "r09-shelf-3", (25.0, 8.2), (31.0, 8.8)),
                ("rect", "r09-shelf-4", (33.5, 8.2), (39.5, 8.8))],
    "room-12": [("rect", "r12-desk", (35.35, 28.45), (37.15, 29.25)),
                ("box", "r12-cabinet", (41.6, 23.5), (0.6, 1.0), 0.0)],
    "room-13": [("box", "r13-table", (32.15, 37.6), (4.0, 1.2), 0.0),
                ("box", "r13-crate", (25.0, 31.0), (0.8, 0.8), 30.0)],
    "room-14": [("rect", "r14-bench-e", (53.35, 2.0), (54.15, 8.0)),
                ("box", "r14-crate", (46.0, 3.0), (1.2, 0.8), 0.0)],
    "room-16": [("box", "r16-crate-1", (47.0, 37.0), (1.0, 1.0), 20.0),
                ("box", "r16-crate-2", (61.0, 25.0), (0.8, 1.2), -15.0),
                ("rect", "r16-bench", (52.0, 39.15), (58.0, 39.95))],
}

START = (3.0, (EW_S + EW_N) / 2, 0.0)   # west end of the east-west corridor, facing east
GOAL_ROOM = "room-16"                   # the goal is that room's centre

# Corridors, as interior rectangles (inside the walls) split into places; split coordinates
# are chosen away from the doors.
EW_Y = (EW_S + H, EW_N - H)
A_X = (A_W + H, A_E - H)
B_X = (B_W + H, B_E - H)


def corridor_places():
    """(name, (x0, y0, x1, y1)) of every corridor place, west to east then south to north."""
    out = []
    ew = [(H, 12.0), (12.0, A_X[0]),                     # west of corridor A
          (A_X[1], 30.0), (30.0, B_X[0]),                # between A and B
          (B_X[1], 54.2), (54.2, SIZE_X - H)]            # east of B
    for i, (x0, x1) in enumerate(ew, 1):
        out.append((f"corridor-ew-{i}", (x0, EW_Y[0], x1, EW_Y[1])))
    for tag, (x0, x1) in (("a", A_X), ("b", B_X)):
        out.append((f"junction-{tag}", (x0, EW_Y[0], x1, EW_Y[1])))
        ys = [(H, 10.8), (10.8, EW_Y[0]), (EW_Y[1], 29.3), (29.3, SIZE_Y - H)]
        for i, (y0, y1) in enumerate(ys, 1):
            out.append((f"corridor-{tag}-{i}", (x0, y0, x1, y1)))
    return out


# Open doors between consecutive corridor places (corridor width, middle of the shared edge).
OPEN_LINKS = [("corridor-ew-1", "corridor-ew-2"), ("corridor-ew-2", "junction-a"),
              ("junction-a", "corridor-ew-3"), ("corridor-ew-3", "corridor-ew-4"),
              ("corridor-ew-4", "junction-b"), ("junction-b", "corridor-ew-5"),
              ("corridor-ew-5", "corridor-ew-6"),
              ("corridor-a-1", "corridor-a-2"), ("corridor-a-2", "junction-a"),
              ("junction-a", "corridor-a-3"), ("corridor-a-3", "corridor-a-4"),
              ("corridor-b-1", "corridor-b-2"), ("corridor-b-2", "junction-b"),
              ("junction-b", "corridor-b-3"), ("corridor-b-3", "corridor-b-4")]


# ----------------------------------------------------------------------------------------------
# Derivation


def num(v, digits=4):
    """A TOML float: rounded, trailing zeros dropped, at least one decimal."""
    s = f"{round(v, digits) + 0.0:.{digits}f}".rstrip("0")
    return s + "0" if s.endswith(".") else s


def width_str(w):
    return f"{w:.2f}"


def pt(p):
    return f"[{num(p[0])}, {num(p[1])}]"


def rect_poly(r):
    x0, y0, x1, y1 = r
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def shrink(r, d):
    x0, y0, x1, y1 = r
    return (x0 + d, y0 + d, x1 - d, y1 - d)


def merge_walls():
    """Maximal straight walls: the union of all room edges and the outer rectangle, per line.

    Returns a list of dicts {name, axis ('h' or 'v'), c (line coordinate), lo, hi, doors: []}."""
    segs = {}  # (axis, c) -> [(lo, hi)]

    def add(axis, c, lo, hi):
        segs.setdefault((axis, round(c, 6)), []).append((round(lo, 6), round(hi, 6)))

    rects = [(0.0, 0.0, SIZE_X, SIZE_Y)] + [r for _, _, r, _ in ROOMS]
    for x0, y0, x1, y1 in rects:
        add("h", y0, x0, x1)
        add("h", y1, x0, x1)
        add("v", x0, y0, y1)
        add("v", x1, y0, y1)
    walls = []
    for (axis, c) in sorted(segs, key=lambda k: (k[0] == "v", k[1])):
        runs = []
        for lo, hi in sorted(segs[(axis, c)]):
            if runs and lo <= runs[-1][1] + 1e-9:
                runs[-1][1] = max(runs[-1][1], hi)
            else:
                runs.append([lo, hi])
        for lo, hi in runs:
            walls.append({"axis": axis, "c": c, "lo": lo, "hi": hi, "doors": []})
    for i, w in enumerate(walls, 1):
        w["name"] = f"wall-{i:02d}"
    return walls


def build():
    """Everything both files need: walls with doors, furniture, places, doors of the graph."""
    walls = merge_walls()
    corridors = corridor_places()
    places = []
    for name, what, r, _ in ROOMS:
        ir = shrink(r, H)
        places.append({"name": name, "what": f"{what}, {num(ir[2] - ir[0], 2)} x {num(ir[3] - ir[1], 2)} m",
                       "area": rect_poly(ir), "centre": ((ir[0] + ir[2]) / 2, (ir[1] + ir[3]) / 2)})
    for name, r in corridors:
        what = "corridor junction" if name.startswith("junction") else "corridor"
        places.append({"name": name, "what": f"{what}, {num(r[2] - r[0], 2)} x {num(r[3] - r[1], 2)} m",
                       "area": rect_poly(r), "centre": ((r[0] + r[2]) / 2, (r[1] + r[3]) / 2)})

    def corridor_at(p):
        hits = [n for n, (x0, y0, x1, y1) in corridors if x0 < p[0] < x1 and y0 < p[1] < y1]
        if len(hits) != 1:
            raise SystemExit(f"make_building_floor: point {p} is in {len(hits)} corridor places")
        return hits[0]

    gdoors = []
    k = 0
    for name, _, (x0, y0, x1, y1), doors in ROOMS:
        for side, s, width in doors:
            k += 1
            dname = f"d-{k:02d}"
            if side in "NS":
                axis, c = "h", (y1 if side == "N" else y0)
                at = (s, c)
                outward = (0.0, 0.3 if side == "N" else -0.3)
            else:
                axis, c = "v", (x1 if side == "E" else x0)
                at = (c, s)
                outward = (0.3 if side == "E" else -0.3, 0.0)
            wall = [w for w in walls if w["axis"] == axis and abs(w["c"] - c) < 1e-9
                    and w["lo"] < s < w["hi"]]
            assert len(wall) == 1, (dname, wall)
            wall[0]["doors"].append((dname, s - wall[0]["lo"], width))
            other = corridor_at((at[0] + outward[0], at[1] + outward[1]))
            gdoors.append({"name": dname, "between": (other, name), "at": at, "width": width})
    rect_of = dict(corridors)
    for i, (a, b) in enumerate(OPEN_LINKS, 1):
        ra, rb = rect_of[a], rect_of[b]
        # The shared edge of two touching axis-aligned rectangles.
        if abs(ra[2] - rb[0]) < 1e-9 or abs(rb[2] - ra[0]) < 1e-9:
            x = ra[2] if abs(ra[2] - rb[0]) < 1e-9 else ra[0]
            y0, y1 = max(ra[1], rb[1]), min(ra[3], rb[3])
            at, width = (x, (y0 + y1) / 2), y1 - y0
        else:
            y = ra[3] if abs(ra[3] - rb[1]) < 1e-9 else ra[1]
            x0, x1 = max(ra[0], rb[0]), min(ra[2], rb[2])
            at, width = ((x0 + x1) / 2, y), x1 - x0
        gdoors.append({"name": f"open-{i:02d}", "between": (a, b), "at": at, "width": width})
    goal = next(p["centre"] for p in places if p["name"] == GOAL_ROOM)
    return walls, places, gdoors, goal


def write_world(path, walls, goal):
    n_doors = sum(len(w["doors"]) for w in walls)
    L = []
    L.append(f"# worlds/{WORLD_FILE} — a {SIZE_X:.0f} × {SIZE_Y:.0f} m building floor: "
             f"{len(ROOMS)} rooms off a 2.40 m east-west corridor and two north-south corridors "
             f"(2.20, 2.10 m), {n_doors} doors of 0.90–1.20 m; start in the west corridor, goal in the "
             f"north-east hall.")
    L.append(f"# Generated by tools/dev/make_building_floor.py: edit the script, not this file. "
             f"Its place graph is {PLACES_FILE}.")
    L.append("[world]")
    L.append('name = "building_floor"')
    L.append('units = "m"')
    L.append(f"wall_thickness = {T:.2f}")
    L.append("")
    L.append("# The robot's wheel-axle midpoint and heading.")
    L.append("[start]")
    L.append(f"x = {num(START[0])}")
    L.append(f"y = {num(START[1])}")
    L.append(f"heading_deg = {num(START[2])}")
    L.append("")
    L.append(f"# The centre of {GOAL_ROOM}.")
    L.append("[goal]")
    L.append(f"x = {num(goal[0])}")
    L.append(f"y = {num(goal[1])}")
    L.append("")
    L.append("# Walls on the room and corridor outlines, merged into straight runs; doors are named as")
    L.append(f"# the doors of {PLACES_FILE}, at = from `from` to the door centre.")
    for w in walls:
        if w["axis"] == "h":
            a, b = (w["lo"], w["c"]), (w["hi"], w["c"])
        else:
            a, b = (w["c"], w["lo"]), (w["c"], w["hi"])
        L.append("")
        L.append("[[wall]]")
        L.append(f'name = "{w["name"]}"')
        L.append(f"from = {pt(a)}")
        L.append(f"to = {pt(b)}")
        if w["doors"]:
            ds = ", ".join(f'{{ name = "{n}", at = {num(s)}, width = {width_str(wd)} }}'
                           for n, s, wd in sorted(w["doors"], key=lambda d: d[1]))
            L.append(f"doors = [{ds}]")
    L.append("")
    L.append("# Furniture, clear of each room's centre and of every door's approach.")
    for name, what, _, _ in ROOMS:
        items = FURNITURE.get(name, [])
        if not items:
            continue
        L.append("")
        L.append(f"# {name} ({what})")
        for it in items:
            if it[0] == "rect":
                L.append("[[rectangle]]")
                L.append(f'name = "{it[1]}"')
                L.append(f"min = {pt(it[2])}")
                L.append(f"max = {pt(it[3])}")
            else:
                L.append("[[box]]")
                L.append(f'name = "{it[1]}"')
                L.append(f"center = {pt(it[2])}")
                L.append(f"size = {pt(it[3])}")
                if it[4] != 0.0:
                    L.append(f"angle_deg = {num(it[4])}")
    path.write_text("\n".join(L) + "\n", encoding="utf-8")


def write_places(path, places, gdoors):
    L = [f"# worlds/{PLACES_FILE} — the place graph of {WORLD_FILE} (seed 003's topological map); "
         f"generated by tools/dev/make_building_floor.py",
         "[places]",
         'format = "robuter-places 1"',
         f'world = "{WORLD_FILE}"',
         'units = "m"']
    for p in places:
        L.append("")
        L.append(f"[[place]]  # {p['what']}")
        L.append(f'name = "{p["name"]}"')
        L.append("area = [" + ", ".join(pt(v) for v in p["area"]) + "]")
        L.append(f"centre = {pt(p['centre'])}")
    for d in gdoors:
        L.append("")
        L.append("[[door]]" + ("  # open: corridor to corridor" if d["name"].startswith("open") else ""))
        L.append(f'name = "{d["name"]}"')
        L.append(f'between = ["{d["between"][0]}", "{d["between"][1]}"]')
        L.append(f"at = {pt(d['at'])}")
        L.append(f"width = {width_str(d['width'])}")
    path.write_text("\n".join(L) + "\n", encoding="utf-8")


# ----------------------------------------------------------------------------------------------
# Geometry for the checks

EPS = 1e-7


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def edges(poly):
    return [(poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly))]


def seg_point_dist(p, a, b):
    ab, ap = sub(b, a), sub(p, a)
    L2 = dot(ab, ab)
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, dot(ap, ab) / L2))
    q = (a[0] + t * ab[0], a[1] + t * ab[1])
    return math.hypot(p[0] - q[0], p[1] - q[1])


def inside(p, poly):
    """Ray casting (even-odd)."""
    c = False
    for a, b in edges(poly):
        if (a[1] > p[1]) != (b[1] > p[1]):
            x = a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            if p[0] < x:
                c = not c
    return c


def boundary_dist(p, poly):
    return min(seg_point_dist(p, a, b) for a, b in edges(poly))


def poly_dist(p, poly):
    return 0.0 if inside(p, poly) else boundary_dist(p, poly)


def signed_area(poly):
    return 0.5 * sum(cross(a, b) for a, b in edges(poly))


def segs_intersect(a, b, c, d, proper):
    """Do segments ab and cd meet? proper=True: only a crossing at a point interior to both."""
    d1, d2 = cross(sub(b, a), sub(c, a)), cross(sub(b, a), sub(d, a))
    d3, d4 = cross(sub(d, c), sub(a, c)), cross(sub(d, c), sub(b, c))
    if ((d1 > EPS and d2 < -EPS) or (d1 < -EPS and d2 > EPS)) and \
       ((d3 > EPS and d4 < -EPS) or (d3 < -EPS and d4 > EPS)):
        return True
    if proper:
        return False
    def on(p, q, r):  # r on segment pq (collinear assumed)
        return min(p[0], q[0]) - EPS <= r[0] <= max(p[0], q[0]) + EPS and \
               min(p[1], q[1]) - EPS <= r[1] <= max(p[1], q[1]) + EPS
    return (abs(d1) <= EPS and on(a, b, c)) or (abs(d2) <= EPS and on(a, b, d)) or \
           (abs(d3) <= EPS and on(c, d, a)) or (abs(d4) <= EPS and on(c, d, b))


def polys_touch(p, q):
    """Do two convex-or-not polygons share any point (edges meet, or one inside the other)?"""
    if any(segs_intersect(a, b, c, d, False) for a, b in edges(p) for c, d in edges(q)):
        return True
    return inside(p[0], q) or inside(q[0], p)


def seg_poly_dist(a, b, poly):
    if inside(a, poly) or inside(b, poly):
        return 0.0
    if any(segs_intersect(a, b, c, d, False) for c, d in edges(poly)):
        return 0.0
    return min([seg_point_dist(v, a, b) for v in poly] +
               [seg_point_dist(a, c, d) for c, d in edges(poly)] +
               [seg_point_dist(b, c, d) for c, d in edges(poly)])


def ray_contact(p, d, polys, limit=100.0):
    """First t >= 0 where p + t d touches an edge of any polygon (collinear edges included)."""
    best = limit
    for poly in polys:
        for a, b in edges(poly):
            e = sub(b, a)
            den = cross(d, e)
            ap = sub(a, p)
            if abs(den) > EPS:
                t, s = cross(ap, e) / den, cross(ap, d) / den
                if t >= -EPS and -EPS <= s <= 1 + EPS:
                    best = min(best, max(t, 0.0))
            elif abs(cross(ap, d)) <= EPS:
                ta, tb = dot(ap, d), dot(sub(b, p), d)
                if max(ta, tb) >= -EPS:
                    best = min(best, max(0.0, min(ta, tb)))
    return best


# ----------------------------------------------------------------------------------------------
# Reading the files back


class CheckFailed(Exception):
    pass


def world_obstacles(world):
    """Obstacles as the loader builds them: [(name, kind, polygon)], kind 'wall' or 'furniture';
    and the wall doors: [(door name, wall name, centre, unit direction, width)]."""
    units = world.get("world", {}).get("units", "m")
    if units != "m":
        raise CheckFailed(f"{WORLD_FILE}: units = {units!r}; the checker only reads metres")
    th0 = world.get("world", {}).get("wall_thickness", 0.0)
    obs, doors = [], []

    def piece(name, a, u, s0, s1, th):
        n = (-u[1], u[0])
        h = th / 2
        p0 = (a[0] + s0 * u[0], a[1] + s0 * u[1])
        p1 = (a[0] + s1 * u[0], a[1] + s1 * u[1])
        obs.append((name, "wall", [(p0[0] - h * n[0], p0[1] - h * n[1]), (p1[0] - h * n[0], p1[1] - h * n[1]),
                                   (p1[0] + h * n[0], p1[1] + h * n[1]), (p0[0] + h * n[0], p0[1] + h * n[1])]))

    for i, w in enumerate(world.get("wall", []), 1):
        name = w.get("name", f"wall {i}")
        th = w.get("thickness", th0)
        if "points" in w:
            pts = [tuple(p) for p in w["points"]]
            if w.get("closed"):
                pts.append(pts[0])
            for a, b in zip(pts, pts[1:]):
                L = math.dist(a, b)
                piece(name, a, ((b[0] - a[0]) / L, (b[1] - a[1]) / L), -th / 2, L + th / 2, th)
            continue
        a, b = tuple(w["from"]), tuple(w["to"])
        L = math.dist(a, b)
        u = ((b[0] - a[0]) / L, (b[1] - a[1]) / L)
        gaps = sorted((d["at"] - d["width"] / 2, d["at"] + d["width"] / 2, d) for d in w.get("doors", []))
        s = -th / 2
        for g0, g1, d in gaps:
            piece(name, a, u, s, g0, th)
            s = g1
            doors.append((d.get("name", ""), name, (a[0] + d["at"] * u[0], a[1] + d["at"] * u[1]), u,
                          d["width"]))
        piece(name, a, u, s, L + th / 2, th)
    for i, bx in enumerate(world.get("box", []), 1):
        c, (sx, sy) = bx["center"], bx["size"]
        ang = math.radians(bx.get("angle_deg", 0.0))
        u, v = (math.cos(ang), math.sin(ang)), (-math.sin(ang), math.cos(ang))
        poly = [(c[0] + i * sx / 2 * u[0] + j * sy / 2 * v[0], c[1] + i * sx / 2 * u[1] + j * sy / 2 * v[1])
                for i, j in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        obs.append((bx.get("name", f"box {i}"), "furniture", poly))
    for i, r in enumerate(world.get("rectangle", []), 1):
        obs.append((r.get("name", f"rectangle {i}"), "furniture",
                    rect_poly((r["min"][0], r["min"][1], r["max"][0], r["max"][1]))))
    for i, p in enumerate(world.get("polygon", []), 1):
        obs.append((p.get("name", f"polygon {i}"), "furniture", [tuple(v) for v in p["points"][:-1]]))
    return obs, doors


def check(dirpath):
    """Checks both files; returns a summary dict, raises CheckFailed on the first failure."""
    wpath, ppath = dirpath / WORLD_FILE, dirpath / PLACES_FILE
    try:
        world = tomllib.loads(wpath.read_text(encoding="utf-8"))
        graph = tomllib.loads(ppath.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise CheckFailed(f"cannot read: {e}")
    obs, wdoors = world_obstacles(world)
    walls = [o for o in obs if o[1] == "wall"]
    furniture = [o for o in obs if o[1] == "furniture"]
    allpolys = [o[2] for o in obs]

    # World size and thickness.
    xs = [v[0] for o in walls for v in o[2]]
    ys = [v[1] for o in walls for v in o[2]]
    size = (max(xs) - min(xs) - T, max(ys) - min(ys) - T)
    if size[0] < 60 - 1e-6 or size[1] < 40 - 1e-6:
        raise CheckFailed(f"{WORLD_FILE}: outer size {size[0]:.2f} x {size[1]:.2f} m, need >= 60 x 40")
    if abs(world["world"]["wall_thickness"] - 0.10) > 1e-9:
        raise CheckFailed(f"{WORLD_FILE}: wall_thickness is not 0.10 m")

    # Header and names.
    hdr = graph.get("places", {})
    if hdr.get("format") != "robuter-places 1" or hdr.get("world") != WORLD_FILE or hdr.get("units") != "m":
        raise CheckFailed(f"{PLACES_FILE}: [places] must give format, world = {WORLD_FILE!r}, units = 'm'")
    places, gdoors = graph.get("place", []), graph.get("door", [])
    seen = set()
    for kind, items in (("place", places), ("door", gdoors)):
        for it in items:
            n = it.get("name", "")
            if not re.fullmatch(r"[A-Za-z0-9_-]{1,15}", n):
                raise CheckFailed(f"{PLACES_FILE}: {kind} name {n!r} is not 1..15 of letters, digits, '-', '_'")
            if n in seen:
                raise CheckFailed(f"{PLACES_FILE}: duplicate name {n!r}")
            seen.add(n)
    if len(places) < 20:
        raise CheckFailed(f"{PLACES_FILE}: {len(places)} places, need >= 20")
    P = {}
    for p in places:
        n, area, c = p["name"], [tuple(v) for v in p["area"]], tuple(p["centre"])
        if len(area) < 3:
            raise CheckFailed(f"place {n}: area has {len(area)} vertices, need >= 3")
        if signed_area(area) <= 0:
            raise CheckFailed(f"place {n}: area is not counter-clockwise")
        es = edges(area)
        for i in range(len(es)):
            for j in range(i + 1, len(es)):
                if j == i + 1 or (i == 0 and j == len(es) - 1):
                    continue
                if segs_intersect(*es[i], *es[j], False):
                    raise CheckFailed(f"place {n}: area is not simple (edges {i} and {j} meet)")
        if not inside(c, area):
            raise CheckFailed(f"place {n}: centre {c} is outside its area")
        for on, kind, poly in obs:
            d = poly_dist(c, poly)
            need = 1.5 if (kind == "furniture" and n.startswith("room")) else 1.0
            if d < need:
                raise CheckFailed(f"place {n}: centre {c} is {d:.2f} m from {kind} {on!r} (need >= {need} m)")
        P[n] = (area, c)
    rooms = [n for n in P if n.startswith("room")]
    if len(rooms) < 12:
        raise CheckFailed(f"{len(rooms)} rooms, need >= 12")
    for n, (area, _) in P.items():
        if not n.startswith("room"):
            w = min(max(v[0] for v in area) - min(v[0] for v in area), max(v[1] for v in area) - min(v[1] for v in area))
            length = max(max(v[0] for v in area) - min(v[0] for v in area), max(v[1] for v in area) - min(v[1] for v in area))
            if not 2.0 - 1e-6 <= w <= 2.5 + 1e-6:
                raise CheckFailed(f"place {n}: corridor {w:.2f} m wide, need 2.0..2.5 m")
            if length > 16.0 + 1e-6:
                raise CheckFailed(f"place {n}: corridor place {length:.2f} m long, need <= 16 m")

    # Overlaps.
    names = list(P)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            pa, pb = P[a][0], P[b][0]
            for e in edges(pa):
                for f in edges(pb):
                    if segs_intersect(*e, *f, True):
                        raise CheckFailed(f"places {a} and {b} overlap (edges cross near {e[0]})")
            if inside(P[a][1], pb) or inside(P[b][1], pa):
                raise CheckFailed(f"places {a} and {b} overlap (a centre inside the other)")
            # As modules/places does: a vertex, or a point 5 mm inside an edge, of one place
            # strictly inside the other (shared edges and vertices are allowed).
            for p, q in ((pa, pb), (pb, pa)):
                probes = list(p)
                for e0, e1 in edges(p):
                    L = math.dist(e0, e1)
                    inward = (-(e1[1] - e0[1]) / L, (e1[0] - e0[0]) / L)
                    probes += [(e0[0] + t * (e1[0] - e0[0]) + 0.005 * inward[0],
                                e0[1] + t * (e1[1] - e0[1]) + 0.005 * inward[1]) for t in (0.25, 0.5, 0.75)]
                if any(inside(v, q) and boundary_dist(v, q) > 1e-3 for v in probes):
                    raise CheckFailed(f"places {a} and {b} overlap (share floor)")

    # Doors of the graph.
    wd_by_at = {}
    for dn, wn, c, u, w in wdoors:
        wd_by_at[(round(c[0], 3), round(c[1], 3))] = (dn, wn, c, u, w)
    used_world_doors = set()
    adj = {n: set() for n in P}
    widths = []
    for d in gdoors:
        n, (a, b), at, width = d["name"], d["between"], tuple(d["at"]), d["width"]
        if a == b or a not in P or b not in P:
            raise CheckFailed(f"door {n}: between {a!r} and {b!r}: need two different known places")
        for q in (a, b):
            bd = boundary_dist(at, P[q][0])
            if bd > 0.15:
                raise CheckFailed(f"door {n}: at {at} is {bd:.2f} m from the boundary of {q} (need <= 0.15)")
        # The opening's direction: along the edge of the first place nearest to `at`.
        e = min(edges(P[a][0]), key=lambda e: seg_point_dist(at, *e))
        L = math.dist(*e)
        u = ((e[1][0] - e[0][0]) / L, (e[1][1] - e[0][1]) / L)
        wd = wd_by_at.get((round(at[0], 3), round(at[1], 3)))
        if wd is not None:
            used_world_doors.add(wd[0])
            if not 0.90 - 1e-9 <= width <= 1.20 + 1e-9:
                raise CheckFailed(f"door {n}: width {width} m, need 0.90..1.20 m")
            if abs(wd[4] - width) > 1e-6:
                raise CheckFailed(f"door {n}: width {width} m but the world's door {wd[0]!r} is {wd[4]} m")
            u = wd[3]
            widths.append(width)
        measured = ray_contact(at, u, allpolys) + ray_contact(at, (-u[0], -u[1]), allpolys)
        if abs(measured - width) > 0.005:
            raise CheckFailed(f"door {n}: width {width} m but the opening in the world at {at} is {measured:.3f} m")
        if wd is not None:
            nrm = (-u[1], u[0])
            hw = width / 2 - 0.001
            appr = [(at[0] + s * hw * u[0] + t * 1.5 * nrm[0], at[1] + s * hw * u[1] + t * 1.5 * nrm[1])
                    for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            for on, kind, poly in obs:
                if polys_touch(appr, poly):
                    raise CheckFailed(f"door {n}: its approach (1.5 m either side) meets {kind} {on!r}")
            j0 = (at[0] - width / 2 * u[0], at[1] - width / 2 * u[1])
            j1 = (at[0] + width / 2 * u[0], at[1] + width / 2 * u[1])
            for on, kind, poly in walls:
                if on != wd[1] and seg_poly_dist(j0, j1, poly) < 0.6 - 1e-6:
                    raise CheckFailed(f"door {n}: less than 0.6 m from wall {on!r} (a corner or junction)")
        adj[a].add(b)
        adj[b].add(a)
    missing = sorted({w[0] for w in wdoors} - used_world_doors)
    if missing:
        raise CheckFailed(f"world doors with no [[door]] in the place graph: {', '.join(missing)}")
    if sum(1 for w in widths if abs(w - 0.90) < 1e-9) < 3:
        raise CheckFailed("fewer than three 0.90 m doors")
    for r in rooms:
        if not any(q.startswith(("corridor", "junction")) for q in adj[r]):
            raise CheckFailed(f"{r} has no door into a corridor")

    # Connected.
    todo, reach = [names[0]], {names[0]}
    while todo:
        for q in adj[todo.pop()]:
            if q not in reach:
                reach.add(q)
                todo.append(q)
    if len(reach) != len(P):
        raise CheckFailed(f"the place graph is not connected: {', '.join(sorted(set(P) - reach))} unreachable")

    # Farthest centres, start and goal.
    far = max(((a, b) for i, a in enumerate(names) for b in names[i + 1:]),
              key=lambda ab: math.dist(P[ab[0]][1], P[ab[1]][1]))
    far_d = math.dist(P[far[0]][1], P[far[1]][1])
    if far_d < 30.0:
        raise CheckFailed(f"the farthest place centres ({far[0]}, {far[1]}) are {far_d:.1f} m apart, need >= 30")
    start, goal = (world["start"]["x"], world["start"]["y"]), (world["goal"]["x"], world["goal"]["y"])
    where = lambda p: next((n for n, (area, _) in P.items() if inside(p, area)), None)
    ws, wg = where(start), where(goal)
    if ws is None or not ws.startswith(("corridor", "junction")):
        raise CheckFailed(f"start {start} is not in a corridor place (in {ws})")
    if wg is None or not wg.startswith("room"):
        raise CheckFailed(f"goal {goal} is not in a room (in {wg})")
    if math.dist(start, goal) < 30.0:
        raise CheckFailed(f"start and goal are {math.dist(start, goal):.1f} m apart, need >= 30")

    # Coverage: every sample of the floor not in a wall or a door gap is in some place.
    gaps = []
    for dn, wn, c, u, w in wdoors:
        gaps.append([(c[0] + s * w / 2 * u[0] - t * H * u[1], c[1] + s * w / 2 * u[1] + t * H * u[0])
                     for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1))])
    step, uncovered = 0.25, []
    y = 0.113
    while y < SIZE_Y:
        x = 0.107
        while x < SIZE_X:
            p = (x, y)
            if not any(inside(p, a) for a, _ in P.values()) and \
               not any(poly_dist(p, o[2]) < 1e-3 for o in walls) and \
               not any(poly_dist(p, g) < 1e-3 for g in gaps):
                uncovered.append(p)
            x += step
        y += step
    if uncovered:
        raise CheckFailed(f"{len(uncovered)} floor samples in no place, e.g. {uncovered[:3]}")

    return {"size": size, "rooms": len(rooms), "places": len(P), "doors": len(gdoors),
            "wall_doors": len(widths), "widths": sorted(set(widths)),
            "n090": sum(1 for w in widths if abs(w - 0.90) < 1e-9), "far": far, "far_d": far_d,
            "start": (start, ws), "goal": (goal, wg), "start_goal": math.dist(start, goal)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="only check the files already written")
    ap.add_argument("--dir", type=pathlib.Path,
                    default=pathlib.Path(__file__).resolve().parents[2] / "worlds",
                    help="directory of the two files (default: the repository's worlds/)")
    args = ap.parse_args()
    if not args.check:
        walls, places, gdoors, goal = build()
        write_world(args.dir / WORLD_FILE, walls, goal)
        write_places(args.dir / PLACES_FILE, places, gdoors)
    try:
        s = check(args.dir)
    except CheckFailed as e:
        print(f"make_building_floor: check failed: {e}", file=sys.stderr)
        return 1
    print(f"{WORLD_FILE}: {s['size'][0]:.1f} x {s['size'][1]:.1f} m, {s['rooms']} rooms; "
          f"{PLACES_FILE}: {s['places']} places, {s['doors']} doors ({s['wall_doors']} in walls, "
          f"widths {', '.join(f'{w:.2f}' for w in s['widths'])} m, {s['n090']} of 0.90 m); "
          f"farthest centres {s['far'][0]} - {s['far'][1]} {s['far_d']:.2f} m; "
          f"start {s['start'][0]} in {s['start'][1]}, goal {s['goal'][0]} in {s['goal'][1]}, "
          f"{s['start_goal']:.2f} m apart: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
