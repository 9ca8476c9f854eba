#!/usr/bin/env python3
"""Mismatch sweep: random contract scenes, each method's interior mismatch against raytrace.

Writes --count seeded random scene files (contract keys only: camera, point and directional
lights, mesh files, transforms) under --out, runs `shadowkit compare SCENE --methods ...
--json` on each and prints one line per (scene, light, method) over its threshold, then a
summary table. The meshes are the models of examples/models (open, non-manifold and
Catmull-Clark control meshes read as plain polygon meshes) and small ones written here: a
ground quad, a box, a floating quad, a fin of three quads on one edge, coplanar touching boxes
and a closed room. With --shrink every failure is reduced greedily (objects, then the other
lights) to the smallest scene that still fails, written next to it as
NAME.METHOD.L<light>.min.json.

    python3 scripts/mismatch_sweep.py --seed 1 --count 500 --out out/sweep --shrink

With --lights N it writes scenes until at least N lights are compared, e.g. the automatic R's
proof (docs/papers/thakur-cheng-miura.md):

    python3 scripts/mismatch_sweep.py --methods angular --seed 20000 --lights 5000 \\
        --out out/angular-proof
"""

import argparse
import copy
import json
import math
import os
import random
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Interior mismatch thresholds against raytrace, percent (the issue's; svbsp is exact in
# object space, so anything above 0.05% is suspect).
THRESHOLDS = {"volume": 0.05, "angular": 0.2, "svbsp": 0.05}

# Models read as plain polygon meshes (no "subdivision"); all are about unit size.
MODELS = ["pebble.obj", "pebble.off", "pebble.ply", "pebble.stl", "open-sheet.obj",
          "torus-knot.obj", "cc-open-box.obj", "cc-torus.obj", "cc-pentagonal-prism.obj"]
GENERATED = ["box", "quad", "fin", "touching-boxes"]
SCALES = [1e-3, 1e-2, 1.0, 1.0, 1.0, 1.0, 100.0, 1e4]
FORMATS = ["obj", "off", "ply", "stl"]


# ---------------------------------------------------------------------------------------------
# Mesh files written by the sweep itself: (vertices, polygons), polygons as 0-based index lists.

def box_mesh(lo, hi, inward=False):
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [0, 4, 7, 3], [1, 2, 6, 5]]
    if inward:
        faces = [f[::-1] for f in faces]
    return v, faces


def quad_mesh(size=1.0):
    h = size / 2
    return [(-h, 0, -h), (-h, 0, h), (h, 0, h), (h, 0, -h)], [[0, 1, 2, 3]]


def fin_mesh():
    """Three quads on the edge from (-0.5, 0, 0) to (0.5, 0, 0): one non-manifold edge."""
    v = [(-0.5, 0, 0), (0.5, 0, 0), (0.5, 0, 1), (-0.5, 0, 1), (0.5, 1, 0), (-0.5, 1, 0),
         (0.5, 0.7, -0.7), (-0.5, 0.7, -0.7)]
    return v, [[0, 3, 2, 1], [0, 1, 4, 5], [1, 0, 7, 6]]


def touching_boxes_mesh():
    """Two boxes sharing the face x = 0 and a third standing on both: coplanar touching faces."""
    parts = [box_mesh((-1, 0, -0.5), (0, 1, 0.5)), box_mesh((0, 0, -0.5), (1, 1, 0.5)),
             box_mesh((-0.5, 1, -0.5), (0.5, 1.6, 0.5))]
    verts, faces = [], []
    for v, f in parts:
        faces += [[i + len(verts) for i in face] for face in f]
        verts += v
    return verts, faces


def write_mesh(path, mesh):
    verts, faces = mesh
    ext = path.rsplit(".", 1)[1]
    with open(path, "w") as out:
        if ext == "obj":
            out.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in verts)
            out.writelines("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)
        elif ext == "off":
            out.write(f"OFF\n{len(verts)} {len(faces)} 0\n")
            out.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in verts)
            out.writelines(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces)
        elif ext == "ply":
            out.write("ply\nformat ascii 1.0\n"
                      f"element vertex {len(verts)}\nproperty double x\nproperty double y\n"
                      f"property double z\nelement face {len(faces)}\n"
                      "property list uchar int vertex_indices\nend_header\n")
            out.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in verts)
            out.writelines(f"{len(f)} " + " ".join(map(str, f)) + "\n" for f in faces)
        else:  # ASCII STL: a triangle fan per polygon
            out.write("solid sweep\n")
            for f in faces:
                for k in range(1, len(f) - 1):
                    out.write("facet normal 0 0 0\nouter loop\n")
                    for i in (f[0], f[k], f[k + 1]):
                        out.write("vertex %r %r %r\n" % verts[i])
                    out.write("endloop\nendfacet\n")
            out.write("endsolid sweep\n")


def write_meshes(out_dir):
    """The generated meshes in every format, and the example models, under out_dir."""
    meshes = {"ground": quad_mesh(1.0), "box": box_mesh((-0.5, 0, -0.5), (0.5, 1, 0.5)),
              "quad": quad_mesh(1.0), "fin": fin_mesh(), "touching-boxes": touching_boxes_mesh(),
              "room-in": box_mesh((-1, 0, -1), (1, 1, 1), inward=True),
              "room-out": box_mesh((-1, 0, -1), (1, 1, 1))}
    os.makedirs(os.path.join(out_dir, "meshes"), exist_ok=True)
    for name, mesh in meshes.items():
        for ext in FORMATS:
            write_mesh(os.path.join(out_dir, "meshes", f"{name}.{ext}"), mesh)
    models = os.path.join(out_dir, "models")
    os.makedirs(models, exist_ok=True)
    for name in MODELS:
        shutil.copy(os.path.join(ROOT, "examples", "models", name), models)


# ---------------------------------------------------------------------------------------------
# Random scenes. Every length is in units of the scene scale s.

def rounded(values, s):
    return [float("%.6g" % (x * s)) for x in values]


def on_sphere(rng, radius, min_elev_deg, max_elev_deg, centre=(0, 0, 0)):
    az = rng.uniform(0, 2 * math.pi)
    el = math.radians(rng.uniform(min_elev_deg, max_elev_deg))
    return [centre[0] + radius * math.cos(el) * math.cos(az), centre[1] + radius * math.sin(el),
            centre[2] + radius * math.cos(el) * math.sin(az)]


def random_object(rng, s, half_extent, fmt, planes):
    kind = rng.choice(MODELS + GENERATED * 2)
    mesh = f"models/{kind}" if kind in MODELS else f"meshes/{kind}.{fmt}"
    size = rng.uniform(0.6, 1.8)
    pos = [rng.uniform(-half_extent, half_extent), rng.uniform(0.0, 1.2),
           rng.uniform(-half_extent, half_extent)]
    if kind in ("box", "touching-boxes") and rng.random() < 0.5:
        pos[1] = 0.0  # standing on the ground: its bottom face coplanar with the ground
    rot = [rng.choice([0, 0, 90, rng.uniform(-180, 180)]) for _ in range(3)]
    if kind in ("box", "touching-boxes") and pos[1] == 0.0:
        rot[0] = rot[2] = 0
        planes.append(size * (1.0 if kind == "box" else 1.6))
    return {"mesh": mesh, "transform": {"scale": float("%.6g" % (size * s)),
                                        "rotate_deg": [round(a, 3) for a in rot],
                                        "translate": rounded(pos, s)}}


def random_lights(rng, s, room, planes):
    """1-3 lights; `planes` are heights of horizontal faces (ground, floor, ceiling, box tops)."""
    lights = []
    for _ in range(rng.choice([1, 1, 2, 3])):
        kind = rng.random()
        if kind < 0.25:
            d = on_sphere(rng, 1.0, -85, -3)  # downward, sometimes grazing
            lights.append({"type": "directional", "direction": [round(c, 6) for c in d]})
        elif kind < 0.4:
            # in, or just off, the plane of a horizontal face, on the inner side of a room
            plane = rng.choice(planes)
            offset = rng.choice([0.0, 1e-4, 1e-3, 0.02]) * (-1 if plane >= 3.0 else 1)
            xz = on_sphere(rng, rng.uniform(0.3, 2.5), 0, 0)
            lights.append({"type": "point", "position": rounded([xz[0], plane + offset, xz[2]], s)})
        elif room:
            lights.append({"type": "point", "position": rounded(
                [rng.uniform(-2.5, 2.5), rng.uniform(0.5, 2.8), rng.uniform(-2.5, 2.5)], s)})
        else:
            p = on_sphere(rng, rng.uniform(2.5, 8.0), 10, 85)
            lights.append({"type": "point", "position": rounded(p, s)})
    return lights


def random_scene(rng):
    s = rng.choice(SCALES)
    fmt = rng.choice(FORMATS)
    room = rng.random() < 0.3
    width, height = rng.choice([(320, 180), (320, 240), (256, 256)])
    objects = []
    if room:
        # a closed room 6 x 3 x 6, faces inward or outward; camera and light inside
        objects.append({"mesh": f"meshes/room-{rng.choice(['in', 'out'])}.{fmt}",
                        "transform": {"scale": rounded([3, 3, 3], s)}})
        cam = [rng.uniform(-2.5, 2.5), rng.uniform(0.5, 2.5), rng.uniform(-2.5, 2.5)]
        look = [rng.uniform(-2.8, 2.8), rng.uniform(0.1, 2.0), rng.uniform(-2.8, 2.8)]
        if math.dist(cam, look) < 0.5:
            look[0] += 1.0 if cam[0] < 0 else -1.0
        half = 2.0
    else:
        if rng.random() < 0.85:
            objects.append({"mesh": f"meshes/ground.{fmt}",
                            "transform": {"scale": float("%.6g" % (12 * s))}})
        cam = on_sphere(rng, rng.uniform(4.0, 9.0), 5, 70)
        look = [rng.uniform(-0.5, 0.5), rng.uniform(0.0, 1.0), rng.uniform(-0.5, 0.5)]
        half = 1.8
    planes = [0.0, 3.0] if room else [0.0]
    for _ in range(rng.randint(1, 4)):
        objects.append(random_object(rng, s, half, rng.choice(FORMATS), planes))
    return {
        "camera": {"position": rounded(cam, s), "look_at": rounded(look, s), "up": [0, 1, 0],
                   "fov_y_deg": rng.choice([40, 50, 65]), "width": width, "height": height},
        "lights": random_lights(rng, s, room, planes),
        "objects": objects,
    }


# ---------------------------------------------------------------------------------------------
# Running compare.

def compare(shadowkit, path, methods, settings, timeout):
    """{(method, light): interior %}, or an error string when the run fails."""
    cmd = [shadowkit, "compare", path, "--methods", ",".join(methods), "--json"]
    for setting in settings:
        cmd += ["--set", setting]
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"timed out after {timeout} s"
    if run.returncode != 0:
        return f"exit {run.returncode}: {run.stderr.strip().splitlines()[-1:]}"
    return {(r["method"], r["light"]): (r["mismatch_interior_pct"], r["interior_pixels"])
            for r in json.loads(run.stdout) if r["method"] in methods}


def failures_of(result):
    return [(m, l, pct, n) for (m, l), (pct, n) in sorted(result.items()) if pct > THRESHOLDS[m]]


def save(scene, path):
    """One line per light and object, so that scenes read and diff well."""
    lines = [f' "camera": {json.dumps(scene["camera"])},', ' "lights": [']
    lines += [f"  {json.dumps(l)}," for l in scene["lights"]]
    lines[-1] = lines[-1].rstrip(",")
    lines += [" ],", ' "objects": [']
    lines += [f"  {json.dumps(o)}," for o in scene["objects"]]
    lines[-1] = lines[-1].rstrip(",")
    with open(path, "w") as out:
        out.write("{\n" + "\n".join(lines) + "\n ]\n}\n")


def still_fails(shadowkit, scene, path, method, light, settings, timeout):
    save(scene, path)
    result = compare(shadowkit, path, [method], settings, timeout)
    return isinstance(result, dict) and result.get((method, light), (0.0,))[0] > THRESHOLDS[method]


def shrink(shadowkit, scene, path, method, light, settings, timeout):
    """Greedily drops objects, then the other lights, while the failure stays."""
    best = copy.deepcopy(scene)
    i = 0
    while i < len(best["objects"]) and len(best["objects"]) > 1:
        trial = copy.deepcopy(best)
        del trial["objects"][i]
        if still_fails(shadowkit, trial, path, method, light, settings, timeout):
            best = trial
        else:
            i += 1
    trial = copy.deepcopy(best)
    trial["lights"] = [best["lights"][light]]
    if len(best["lights"]) > 1 and still_fails(shadowkit, trial, path, method, 0, settings,
                                               timeout):
        best, light = trial, 0
    still_fails(shadowkit, best, path, method, light, settings, timeout)  # the minimum on disk
    return best, light


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=500)
    parser.add_argument("--lights", type=int, default=0,
                        help="instead of --count: as many scenes as it takes to compare at "
                             "least this many lights")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "sweep"))
    parser.add_argument("--shadowkit", default=os.path.join(ROOT, "build", "shadowkit"))
    parser.add_argument("--methods", default="volume,angular,svbsp")
    parser.add_argument("--set", action="append", default=[], metavar="METHOD.KEY=VALUE",
                        help="passed to compare, e.g. angular.saturated=0 (repeatable)")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per compare")
    parser.add_argument("--shrink", action="store_true", help="reduce every failing scene")
    args = parser.parse_args()
    methods = args.methods.split(",")
    unknown = [m for m in methods if m not in THRESHOLDS]
    if unknown:
        parser.error(f"--methods: no threshold for {', '.join(unknown)}")

    write_meshes(args.out)
    rng = random.Random(args.seed)
    stats = {m: {"runs": 0, "fail": 0, "worst": 0.0, "worst_at": ""} for m in methods}
    every = {m: [] for m in methods}  # (pct, scene light) of every light
    errors = []
    start = time.monotonic()
    lights = 0
    index = -1
    while lights < args.lights if args.lights > 0 else index + 1 < args.count:
        index += 1
        scene = random_scene(rng)
        name = f"s{args.seed}-{index:03d}"
        path = os.path.join(args.out, name + ".json")
        save(scene, path)
        result = compare(args.shadowkit, path, methods, args.set, args.timeout)
        lights += len(scene["lights"])
        if isinstance(result, str):
            errors.append(name)
            print(f"ERROR {name}: {result}", flush=True)
            continue
        for (m, l), (pct, _) in result.items():
            stats[m]["runs"] += 1
            every[m].append((pct, f"{name} L{l}"))
            if pct > stats[m]["worst"]:
                stats[m]["worst"], stats[m]["worst_at"] = pct, f"{name} L{l}"
        for m, l, pct, interior in failures_of(result):
            stats[m]["fail"] += 1
            print(f"FAIL {name} L{l} {scene['lights'][l]['type']} {m} interior {pct:.4f}% "
                  f"(threshold {THRESHOLDS[m]}%, about {round(pct * interior / 100)} of "
                  f"{interior} pixels)", flush=True)
            if args.shrink:
                small, light = shrink(args.shadowkit, scene,
                                      os.path.join(args.out, f"{name}.{m}.L{l}.min.json"), m, l,
                                      args.set, args.timeout)
                print(f"  shrunk to {len(small['objects'])} objects, {len(small['lights'])} "
                      f"lights: {name}.{m}.L{l}.min.json L{light}", flush=True)

    print(f"\n{index + 1} scenes, {lights} lights (seed {args.seed}), {len(errors)} errors, "
          f"{time.monotonic() - start:.0f} s")
    print(f"{'method':8} {'threshold %':>11} {'lights':>7} {'fail':>5} {'worst %':>9}  worst at")
    for m in methods:
        st = stats[m]
        print(f"{m:8} {THRESHOLDS[m]:11} {st['runs']:7} {st['fail']:5} {st['worst']:9.4f}  "
              f"{st['worst_at']}")
    for m in methods:
        worst = sorted(every[m], reverse=True)[:5]
        print(f"{m} worst lights: " + ", ".join(f"{at} {pct:.4f}%" for pct, at in worst))
    return 1 if errors or any(st["fail"] for st in stats.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
