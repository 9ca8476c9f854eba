#!/usr/bin/env python3
"""Lai & Cheng 2007, reproduced: regenerates the figures and the measured tables of
docs/papers/lai-cheng-2007.md (between its 'results' markers) from build/shadowkit.

    python3 scripts/papers/lai_cheng_2007.py [--shadowkit build/shadowkit]

Fig. 5's objects are examples/subdivision.json. Masks are compared pixel by pixel in
Python: interior pixels are those whose 3x3 neighbourhood in the reference mask is uniform.
"""
import argparse
import json
import re
import struct
import subprocess
import tempfile
import time
import zlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "subdivision.json"
PAGE = ROOT / "docs" / "papers" / "lai-cheng-2007.md"
IMAGES = ROOT / "docs" / "images"


def read_gray_png(path):
    """Width, height and pixel rows of an 8-bit grayscale PNG (the masks)."""
    data = Path(path).read_bytes()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        kind, chunk = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            width, height = struct.unpack(">II", chunk[:8])
        elif kind == b"IDAT":
            idat += chunk
    raw, rows, prev, i = zlib.decompress(idat), [], bytearray(width), 0
    for _ in range(height):
        kind, line = raw[i], bytearray(raw[i + 1:i + 1 + width])
        i += 1 + width
        for x in range(width):
            a = line[x - 1] if x else 0
            b, c = prev[x], (prev[x - 1] if x else 0)
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, rows


def compare(reference, mask):
    """Raw and interior mismatch (percent of surface pixels) and the isolated wrong pixels:
    dark specks (shadow where the reference is lit) and light ones, each alone in a 3x3
    neighbourhood uniform in the reference and right everywhere else."""
    w, h, ref = read_gray_png(reference)
    _, _, got = read_gray_png(mask)
    surface = raw = interior = interior_wrong = dark = light = 0
    for y in range(h):
        for x in range(w):
            r, g = ref[y][x], got[y][x]
            if r == 0:
                continue
            surface += 1
            raw += r != g
            if not (0 < x < w - 1 and 0 < y < h - 1):
                continue
            block = [(ref[y + dy][x + dx], got[y + dy][x + dx])
                     for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
            if any(rr != r for rr, _ in block):
                continue
            interior += 1
            interior_wrong += r != g
            if r != g and sum(gg != rr for rr, gg in block) == 1:
                dark += g == 128
                light += g == 255
    return {"raw": 100 * raw / max(surface, 1), "interior": 100 * interior_wrong / max(interior, 1),
            "dark": dark, "light": light}


class Runner:
    def __init__(self, shadowkit, work):
        self.shadowkit, self.work = shadowkit, Path(work)

    def run(self, *args):
        start = time.perf_counter()
        out = subprocess.run([str(self.shadowkit), *map(str, args)], check=True,
                             capture_output=True, text=True).stdout
        return out, time.perf_counter() - start

    def variant(self, name, tessellation=None, size=None):
        """examples/subdivision.json with every Catmull-Clark object at that tessellation and
        the camera at that size (width, height)."""
        scene = json.loads(SCENE.read_text())
        for obj in scene["objects"]:
            if "mesh" in obj:
                obj["mesh"] = str((SCENE.parent / obj["mesh"]).resolve())
            if tessellation is not None and obj.get("subdivision"):
                obj["tessellation"] = tessellation
        if size:
            scene["camera"]["width"], scene["camera"]["height"] = size
        path = self.work / f"{name}.json"
        path.write_text(json.dumps(scene))
        return path

    def mask(self, scene, method, name, *settings):
        sets = [a for s in settings for a in ("--set", s)]
        _, seconds = self.run("render", scene, "--method", method, "--mask", self.work / name, *sets)
        return self.work / f"{name}.L0.png", seconds

    def triangles(self, scene):
        out, _ = self.run("info", scene)
        return int(re.search(r"(\d+) polygons", out).group(1))


# The reference tessellation: fine, and not a multiple of the ones measured, so that no
# tessellation shares its edges (and its faceted terminators) with it.
REFERENCE_SEGMENTS = 100


def tessellation_table(r):
    """raytrace on tessellations of the limit surface against a fine one."""
    reference, _ = r.mask(r.variant("fine", REFERENCE_SEGMENTS), "raytrace", "fine")
    rows = ["| tessellation | triangles | load and raytrace (s) | raw mismatch | interior mismatch |",
            "|---|---|---|---|---|"]
    for t in (8, 16, 32, "view"):
        scene = r.variant(f"t{t}", t)
        mask, seconds = r.mask(scene, "raytrace", f"t{t}")
        c = compare(reference, mask)
        label = '`"view"`' if t == "view" else f"{t} (fixed)"
        rows.append(f"| {label} | {r.triangles(scene):,} | {seconds:.2f} | {c['raw']:.4f}% "
                    f"| {c['interior']:.4f}% |")
    return rows


def voxel_table(r):
    """voxel against raytrace on Fig. 5's objects, by test and resolution."""
    scene = r.variant("voxel", None)
    reference, _ = r.mask(scene, "raytrace", "ref")
    rows = ["| test | M | time (s) | raw mismatch | interior mismatch | dark specks | light specks |",
            "|---|---|---|---|---|---|---|"]
    for test in ("topology", "offset"):
        for m in (128, 256, 512):
            mask, seconds = r.mask(scene, "voxel", f"v-{test}-{m}", f"voxel.test={test}",
                                   f"voxel.resolution={m}")
            c = compare(reference, mask)
            rows.append(f"| {test} | {m} | {seconds:.2f} | {c['raw']:.4f}% | {c['interior']:.4f}% "
                        f"| {c['dark']} | {c['light']} |")
    return rows


def paper_table(r):
    """voxel.paper=1 (§3-§4 as written) against shadowkit's default, on Fig. 5's objects."""
    scene = r.variant("voxel", None)
    reference = r.work / "ref.L0.png"
    rows = ["| test | M | mode | raw mismatch | interior mismatch | dark specks | light specks |",
            "|---|---|---|---|---|---|---|"]
    for test in ("topology", "offset"):
        for m in (256, 512):
            for paper in (0, 1):
                mask, _ = r.mask(scene, "voxel", f"p-{test}-{m}-{paper}", f"voxel.test={test}",
                                 f"voxel.resolution={m}", f"voxel.paper={paper}")
                c = compare(reference, mask)
                mode = "paper" if paper else "default"
                rows.append(f"| {test} | {m} | {mode} | {c['raw']:.4f}% | {c['interior']:.4f}% "
                            f"| {c['dark']} | {c['light']} |")
    return rows


def tunnel_voxels(r):
    """Voxels of the N = 6 voxelization at M = 256, with and without the closed tunnels."""
    scene = r.variant("voxel", None)
    counts = []
    for paper in (1, 0):
        out, _ = r.run("compare", scene, "--methods", "voxel", "--json", "--set", "voxel.adjacency=6",
                       "--set", f"voxel.paper={paper}")
        counts.append(int(json.loads(out)[0]["counters"]["voxels"]))
    return [f"N = 6 at M = 256: {counts[0]:,} voxels from the corners (the paper), "
            f"{counts[1]:,} with the tunnels closed (+{counts[1] - counts[0]})."]


def figures(r):
    """Fig. 5's kind of image (voxel-render) at 480 x 270 for the docs, and §5.1 at 2048."""
    small = r.variant("small", None, (480, 270))
    runs = [("voxel-fig5-topology-256.png", ["voxel.resolution=256"], None),
            ("voxel-fig5-topology-512.png", ["voxel.resolution=512"], "voxel-fig5-topology-512-turned.png"),
            ("voxel-fig5-offset-256.png", ["voxel.resolution=256", "voxel.test=offset"], None)]
    for image, settings, turned in runs:
        args = ["voxel-render", small, "--image", IMAGES / image]
        if turned:
            args += ["--turned-image", IMAGES / turned, "--turn", "60"]
        r.run(*args, *[a for s in settings for a in ("--set", s)])
    r.run("voxel-render", SCENE, "--image", IMAGES / "voxel-5.1-offset-2048.png", "--set",
          "voxel.resolution=2048", "--set", "voxel.test=offset", "--set", "voxel.framebuffer=0")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shadowkit", default=str(ROOT / "build" / "shadowkit"))
    parser.add_argument("--skip-figures", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        r = Runner(args.shadowkit, work)
        if not args.skip_figures:
            figures(r)
        sections = [
            "Tessellation for the other methods (`raytrace` masks against the limit surface "
            f"tessellated {REFERENCE_SEGMENTS} x {REFERENCE_SEGMENTS} a patch):", "",
            *tessellation_table(r), "",
            "`voxel` against `raytrace`, light L0:", "", *voxel_table(r), "",
            "`voxel.paper=1` against the default, light L0:", "", *paper_table(r), "",
            *tunnel_voxels(r)]
    text = PAGE.read_text()
    begin, end = "<!-- results:begin -->", "<!-- results:end -->"
    head, rest = text.split(begin)
    _, tail = rest.split(end)
    PAGE.write_text(head + begin + "\n" + "\n".join(sections) + "\n" + end + tail)
    print("\n".join(sections))


if __name__ == "__main__":
    main()
