#!/usr/bin/env python3
"""Helper of scripts/benchmarks.sh (standard library only).

  benchmarks_report.py widen SRC DST WIDTH HEIGHT
      copies a scene file with its camera set to WIDTH x HEIGHT and its mesh paths made
      absolute (the copy lives elsewhere), so example scenes run at the benchmark's size.
  benchmarks_report.py report WORK OUT SUMMARY
      reads WORK/meta.json and the JSON that benchmarks.sh saved under WORK (bench per pass
      and scene, compare and info per scene) and writes the page OUT and the summary SUMMARY
      (the lines README.md can quote); prints the summary to stdout.
"""
import json
import os
import statistics
import sys

METHODS = ["raytrace", "shadowmap", "volume", "svbsp", "angular", "voxel"]
# The scenes whose ratios the summary and the spread table quote.
MAIN_SCENES = ["cubes:2000", "cubes:8000", "tetra:4", "room", "examples/default.json",
               "examples/subdivision.json"]
HEADLINE_SCENE = "cubes:2000"
# voxel's own scene: the Catmull-Clark surfaces of Lai & Cheng's Fig. 5.
CATMULL_CLARK_SCENE = "examples/subdivision.json"

METHOD_NOTES = {
    "raytrace": "Embree 3 shadow rays, the exact reference. *prepare* builds the BVH (once per "
                "scene); *shade* traces one shadow ray per surface pixel facing the light.",
    "shadowmap": "Williams 1978 at its defaults (2048² texels a map, a cube map for a point "
                 "light, `shadowmap.tiles=looked_up`): *build* sets the maps up, *shade* finds "
                 "every surface pixel's texel, draws the map tiles they look up, then tests "
                 "them ([methods/shadowmap.md](methods/shadowmap.md)).",
    "volume": "Crow 1977 shadow volumes at their defaults (`volume.count=auto`): *prepare* is "
              "the light-independent set-up, *build* the contour edges and shadow polygons, "
              "*shade* counts them per pixel.",
    "svbsp": "Chin & Feiner 1989: *prepare* builds the scene BSP tree (once per scene), *build* "
             "the light's SVBSP tree and lit/shadowed fragments, *shade* scan-converts the "
             "fragments into the mask ([methods/svbsp.md](methods/svbsp.md)).",
    "angular": "Thakur, Cheng & Miura at automatic R (eq. 4): *build* is the angular lookup "
               "table, *shade* its lookups scan line by scan line.",
    "voxel": "Lai & Cheng 2007 at its defaults (M = 256, N = 26, topology test, frame buffer "
             "bound to the view): *prepare* is the voxelization, *build* the shadow "
             "determination for the light, *shade* reads the frame buffer per pixel. Every "
             "scene runs: polygons are voxelized as bilinear patches. Only "
             "`examples/subdivision.json` holds Catmull-Clark surfaces, which `voxel` alone "
             "voxelizes on the limit surface while the others (`raytrace` too) see their "
             "tessellation ([methods/voxel.md](methods/voxel.md)).",
}


def load(path):
    with open(path) as f:
        return json.load(f)


# ---------------------------------------------------------------------------- widen

def absolute_meshes(node, base):
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "mesh" and isinstance(value, str) and not os.path.isabs(value):
                node[key] = os.path.normpath(os.path.join(base, value))
            else:
                absolute_meshes(value, base)
    elif isinstance(node, list):
        for value in node:
            absolute_meshes(value, base)


def widen(src, dst, width, height):
    scene = load(src)
    absolute_meshes(scene, os.path.dirname(os.path.abspath(src)))
    if "camera" in scene:
        scene["camera"]["width"] = int(width)
        scene["camera"]["height"] = int(height)
    with open(dst, "w") as f:
        json.dump(scene, f, indent=1)


# ---------------------------------------------------------------------------- figures

def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


class Cell:
    """One method on one scene in one pass: sums over the scene's lights."""

    def __init__(self, rows, reference):
        self.failed = [f"L{r['light']}: {r['failed']}" for r in rows if "failed" in r]
        ok = [r for r in rows if "failed" not in r]
        self.prepare = ok[0]["prepare_ms"] if ok else None
        self.build = sum(r["build_ms"] for r in ok) if ok else None
        self.shade = sum(r["shade_ms"] for r in ok) if ok else None
        self.frame = self.build + self.shade if ok else None
        self.memory = max(r["memory_bytes"] for r in ok) if ok else None
        # raytrace's shade on the same lights, in the same process: the mean of its runs there
        # (one before the method and one after).
        ref = {}
        for r in reference:
            if "failed" not in r:
                ref.setdefault(r["light"], []).append(r["shade_ms"])
        lights = [r["light"] for r in ok]
        if ok and all(l in ref for l in lights):
            rt = sum(statistics.mean(ref[l]) for l in lights)
            self.shade_ratio = self.shade / rt if rt > 0 else None
            self.frame_ratio = self.frame / rt if rt > 0 else None
        else:
            self.shade_ratio = self.frame_ratio = None


def mismatch(compare_rows, method):
    """Interior and surface mismatch in % over all lights of a scene, from compare's JSON."""
    rows = [r for r in compare_rows if r.get("method") == method and "failed" not in r
            and r.get("mismatch_interior_pct") is not None]
    interior = sum(r["interior_pixels"] for r in rows)
    surface = sum(r["surface_pixels"] for r in rows)
    if not rows or interior == 0 or surface == 0:
        return None, None
    bad_interior = sum(r["mismatch_interior_pct"] / 100 * r["interior_pixels"] for r in rows)
    bad_surface = sum(r["mismatch_raw_pct"] / 100 * r["surface_pixels"] for r in rows)
    return 100 * bad_interior / interior, 100 * bad_surface / surface


def fmt_ms(v):
    if v is None:
        return "–"
    return f"{v:.2f}" if v < 1 else f"{v:.1f}"


def fmt_ratio(v):
    if v is None:
        return "–"
    return f"{v:.1f}" if v >= 10 else f"{v:.2f}"


def fmt_pct(v):
    return "–" if v is None else f"{v:.4f}"


def fmt_mb(v):
    return "–" if v is None else f"{v / 1e6:.1f}"


def fmt_count(v):
    return f"{v:,}"


def code(scene):
    return f"`{scene}`"


# ---------------------------------------------------------------------------- report

def raytrace_medians(rows):
    """raytrace per light: the median of its runs among ROWS (several processes' rows)."""
    rows = [r for r in rows if r.get("method") == "raytrace"]
    out = []
    for light in sorted({r["light"] for r in rows}):
        mine = [r for r in rows if r["light"] == light]
        ok = [r for r in mine if "failed" not in r]
        if not ok:
            out.append(mine[0])
            continue
        out.append({"method": "raytrace", "light": light,
                    **{k: median([r[k] for r in ok]) for k in
                       ("prepare_ms", "build_ms", "shade_ms", "memory_bytes")},
                    "counters": ok[0].get("counters", {})})
    return out


def report(work, out, summary_path):
    meta = load(os.path.join(work, "meta.json"))
    scenes = meta["scenes"]
    passes = meta["passes"]
    bench = {}  # (pass, scene, method) -> rows of the process that timed the method
    for p in range(passes):
        for i, scene in enumerate(scenes):
            for m in METHODS[1:]:
                path = os.path.join(work, f"bench.{p}.{i}.{m}.json")
                bench[(p, scene, m)] = load(path) if os.path.getsize(path) else []
    compare = {s: load(os.path.join(work, f"compare.{i}.json")) for i, s in enumerate(scenes)}
    info = {s: load(os.path.join(work, f"info.{i}.json")) for i, s in enumerate(scenes)}

    def rows_of(p, scene, process, method):
        return [r for r in bench[(p, scene, process)] if r.get("method") == method]

    def all_rows(p, scene):
        return [r for m in METHODS[1:] for r in bench[(p, scene, m)]]

    def raytrace_rows(p, scene):
        """raytrace per light in a pass: the median of its runs in every process of the pass."""
        return raytrace_medians(all_rows(p, scene))

    # cells[method][scene] = [Cell per pass]
    cells = {m: {s: [Cell(rows_of(p, s, m, m), rows_of(p, s, m, "raytrace"))
                      for p in range(passes)] for s in scenes} for m in METHODS[1:]}
    cells["raytrace"] = {s: [Cell(raytrace_rows(p, s), raytrace_rows(p, s))
                             for p in range(passes)] for s in scenes}

    lines = []
    w = lines.append
    size = meta["size"]
    w("# Benchmarks")
    w("")
    w("Generated by `scripts/benchmarks.sh`; do not edit by hand. Regenerate with:")
    w("")
    w("```sh")
    w("bash scripts/build.sh            # Release build into build/")
    w(meta["command"])
    w("```")
    w("")
    w(f"- **Machine**: {meta['cpu']}, {meta['cores']} cores"
      f" ({meta['cpu_mhz']} MHz, {meta['memory_gb']} GB memory), {meta['os']}. "
      + (f"Every command runs with `--threads {meta['threads']}`." if meta.get("threads") else
         "Every command uses every core (`--threads` not given)."))
    w(f"- **Build**: {meta['build']}.")
    w(f"- **Scenes**: every built-in scene and every example file but four: "
      f"`examples/cubes-2000.json` is the built-in `cubes:2000` itself, "
      f"`examples/three-lights.json` the built-in `three-lights` at a smaller size, "
      f"`examples/house.json` is the sun study's, and `examples/knot-600k.json` (576,000 "
      f"triangles) is timed beside cube fields of up to 960,000 triangles in "
      f"[scaling.md](scaling.md).")
    w(f"- **Resolution**: {size} on every scene. The built-in scenes are {size} already; the "
      f"example files (1280x720) run from copies whose camera is {size}, the same view.")
    w(f"- **Timing**: {passes} pass{'es' if passes > 1 else ''} over the scenes; in each, per "
      f"scene and per method but `raytrace`, one process "
      f"`{meta['bench_command']}`, so that `raytrace` is timed just before and just after the "
      f"method, in the same process. Each stage (scan conversion, and per method and light "
      f"build and shade) runs {meta['warmup']} time{'s' if meta['warmup'] != 1 else ''} "
      f"untimed, then {meta['repeats']} time{'s' if meta['repeats'] != 1 else ''} timed; "
      f"`bench` reports the median of the timed runs. A method's ratio to `raytrace` divides "
      f"by the mean of the two `raytrace` shades of its process; the tables give the median "
      f"over the passes. *prepare* is timed once per process. Every method runs at its "
      f"default settings ([commands.md](commands.md#method-settings)).")
    w(f"- **Mismatch**: `{meta['compare_command']}`, once per scene (the masks do not depend "
      f"on timing); `bench` reports no mismatch.")
    w(f"- The whole script took {meta['elapsed_min']:.1f} min; load average (1 min) "
      f"{meta['load_start']} when it started and {meta['load_end']} when it ended.")
    w("")
    w("## Noise")
    w("")
    rt_swing = max((max(v) / min(v) for v in (
        [c.shade for c in cells["raytrace"][s] if c.shade] for s in MAIN_SCENES if s in scenes)
        if v), default=1)
    swing = f" (`raytrace`'s shade below by up to {rt_swing:.1f}x)" if passes > 1 else ""
    w(f"This machine's {meta['cores']} cores are shared with other work, so absolute times move "
      f"from pass to pass{swing} and the ms columns "
      "are only this run's. What to compare is the **ratio to `raytrace`'s shade in the same "
      "process**, which cancels much of the machine's load. Even the ratio moves: below, its "
      f"range over the {passes} pass{'es' if passes > 1 else ''} of this run for the frame "
      "(build + shade over raytrace's shade, same process), and `raytrace`'s own shade ms. A "
      "difference between two methods smaller than that range is not a measured one. The ratio "
      "cancels the load only when the load changes little within the process (timing "
      "`raytrace` before and after the method halves a steady drift) and the method's stages "
      "use every core as `raytrace`'s shade does. When another process takes one of the two "
      "cores, `raytrace`'s shade takes up to twice as long, but a stage that runs on one core "
      "does not slow down: `svbsp`'s prepare and build (only its shade is parallel) then "
      "measure up to 2x fewer times `raytrace` than on a quiet machine. `shadowmap`'s build "
      "(depth maps of 100 MB) keeps about the same time in both cases, so its frame ratio "
      "moves the same way. Shade ratios move least: typically by under 10% between two runs of "
      "this script. The load average above tells how busy this run was. Mismatch does not "
      "depend on timing: it is the same in every run.")
    w("")
    w("| scene | raytrace shade ms | " + " | ".join(f"{m} frame / raytrace" for m in METHODS[1:])
      + " |")
    w("|---|" + "---:|" * len(METHODS))
    for s in MAIN_SCENES:
        if s not in scenes:
            continue
        rt = [c.shade for c in cells["raytrace"][s] if c.shade is not None]
        row = [code(s), spread(rt, fmt_ms)]
        for m in METHODS[1:]:
            row.append(spread([c.frame_ratio for c in cells[m][s] if c.frame_ratio is not None],
                              fmt_ratio))
        w("| " + " | ".join(row) + " |")
    w("")

    w("## Scenes and scan conversion")
    w("")
    w("Per scene: polygons and triangles as loaded (`shadowkit info`), lights, *load ms* "
      "(parsing, welding, triangulation, the working frame; once per pass) and *scan ms*, the "
      "camera's scan conversion into the visible-surface buffer that every method shares "
      "(median of the timed runs), both medians over the passes.")
    w("")
    w("| scene | polygons | triangles | lights | load ms | scan ms |")
    w("|---|---:|---:|---:|---:|---:|")
    for s in scenes:
        rows = [r for p in range(passes) for m in METHODS[1:] for r in bench[(p, s, m)][:1]]
        load_ms = median([r.get("load_ms") for r in rows])
        scan_ms = median([r.get("scan_ms") for r in rows])
        w(f"| {code(s)} | {fmt_count(info[s]['polygons'])} | {fmt_count(info[s]['triangles'])} | "
          f"{len(info[s]['lights'])} | {fmt_ms(load_ms)} | {fmt_ms(scan_ms)} |")
    w("")

    summary = []
    for m in METHODS:
        has_prepare = any(c.prepare is not None and c.prepare >= 0.05
                          for s in scenes for c in cells[m][s])
        w(f"## {m}")
        w("")
        w(METHOD_NOTES[m])
        w("")
        if m == "raytrace":
            raytrace_table(w, scenes, cells, raytrace_rows, passes)
            summary += summary_lines(m, scenes, cells, compare)
            continue
        columns = "Per scene, summed over its lights: "
        if has_prepare:
            columns += "*prepare* ms (once per scene, not per light), "
        columns += ("*build* and *shade* ms, *frame* = build + shade (each column is a median "
                    "over the passes, so they need not add up exactly); *shade ×* and *frame ×*: "
                    "shade and frame over `raytrace`'s shade in the same process (below 1: "
                    "faster than `raytrace`); *memory*: the method's structures after a light's build "
                    "(largest over the lights); *interior* and *surface mismatch*: % of interior "
                    "pixels (3x3 neighbourhood uniform in the reference) and of all surface "
                    "pixels whose mask differs from `raytrace`'s.")
        w(columns)
        w("")
        head = ["scene"] + (["prepare ms"] if has_prepare else []) + [
            "build ms", "shade ms", "frame ms", "shade ×", "frame ×", "memory MB",
            "interior mismatch %", "surface mismatch %"]
        w("| " + " | ".join(head) + " |")
        w("|---|" + "---:|" * (len(head) - 1))
        for s in scenes:
            cs = cells[m][s]
            interior, surface = mismatch(compare[s], m)
            failed = sorted({f for c in cs for f in c.failed})
            if all(c.frame is None for c in cs):
                reason = "; ".join(failed) if failed else "no result"
                w(f"| {code(s)} | failed: {reason} |" + " |" * (len(head) - 2))
                continue
            row = [code(s) + (" (some lights failed: " + "; ".join(failed) + ")" if failed else "")]
            if has_prepare:
                row.append(fmt_ms(median([c.prepare for c in cs])))
            row += [fmt_ms(median([c.build for c in cs])), fmt_ms(median([c.shade for c in cs])),
                    fmt_ms(median([c.frame for c in cs])),
                    fmt_ratio(median([c.shade_ratio for c in cs])),
                    fmt_ratio(median([c.frame_ratio for c in cs])),
                    fmt_mb(median([c.memory for c in cs])), fmt_pct(interior), fmt_pct(surface)]
            w("| " + " | ".join(row) + " |")
        w("")
        summary += summary_lines(m, scenes, cells, compare)

    with open(out, "w") as f:
        f.write("\n".join(lines))
    body = [
        "# Benchmark summary",
        "",
        "Generated by `scripts/benchmarks.sh` with [benchmarks.md](benchmarks.md) (same run, "
        "same machine and settings; ratios are medians over its passes). One line per method "
        "for README.md to quote.",
        "",
    ] + [f"- {line}" for line in summary]
    with open(summary_path, "w") as f:
        f.write("\n".join(body) + "\n")
    print("\n".join(summary))


def raytrace_table(w, scenes, cells, raytrace_rows, passes):
    w("Per scene, summed over its lights: *prepare* ms (the BVH, once per scene), *build* "
      "and *shade* ms, *frame* = build + shade, *memory* (the BVH as Embree reports it, plus 8 "
      "bytes a face), *shadow rays* traced per frame, and *ns per ray*: shade time over rays "
      "(every core at work). Medians over the five processes of each pass (two runs each), "
      "then over the passes. The other tables divide by `raytrace`'s shade in their own "
      "process; against itself the ratio is 1 and the mismatch 0.")
    w("")
    head = ["scene", "prepare ms", "build ms", "shade ms", "frame ms", "memory MB",
            "shadow rays", "ns per ray"]
    w("| " + " | ".join(head) + " |")
    w("|---|" + "---:|" * (len(head) - 1))
    for s in scenes:
        cs = cells["raytrace"][s]
        if all(c.frame is None for c in cs):
            failed = sorted({f for c in cs for f in c.failed})
            w(f"| {code(s)} | failed: {'; '.join(failed)} |" + " |" * (len(head) - 2))
            continue
        rays = median([sum(r.get("counters", {}).get("shadow_rays", 0)
                           for r in raytrace_rows(p, s) if "failed" not in r)
                       for p in range(passes)])
        shade = median([c.shade for c in cs])
        per_ray = [c.shade * 1e6 / rays for c in cs if c.shade is not None] if rays else []
        w("| " + " | ".join([code(s), fmt_ms(median([c.prepare for c in cs])),
                             fmt_ms(median([c.build for c in cs])), fmt_ms(shade),
                             fmt_ms(median([c.frame for c in cs])),
                             fmt_mb(median([c.memory for c in cs])),
                             fmt_count(int(rays)) if rays else "–",
                             f"{median(per_ray):.0f}" if per_ray else "–"]) + " |")
    w("")


def spread(values, fmt):
    if not values:
        return "–"
    lo, hi = min(values), max(values)
    return fmt(lo) if fmt(lo) == fmt(hi) else f"{fmt(lo)}–{fmt(hi)}"


def summary_lines(m, scenes, cells, compare):
    def one(scene):
        cs = cells[m][scene]
        interior, _ = mismatch(compare[scene], m)
        if all(c.frame is None for c in cs):
            return f"`{scene}`: failed"
        return (f"`{scene}`: shade {fmt_ratio(median([c.shade_ratio for c in cs]))}x, frame "
                f"{fmt_ratio(median([c.frame_ratio for c in cs]))}x raytrace's shade, interior "
                f"mismatch {fmt_pct(interior)}%")

    parts = []
    for scene in [HEADLINE_SCENE] + ([CATMULL_CLARK_SCENE] if m == "voxel" else []):
        if scene in scenes:
            parts.append(one(scene))
    worst = None
    for s in scenes:
        interior, _ = mismatch(compare[s], m)
        if interior is not None and (worst is None or interior > worst[0]):
            worst = (interior, s)
    fastest = [median([c.frame_ratio for c in cells[m][s]]) for s in scenes]
    fastest = [r for r in fastest if r is not None]
    tail = ""
    if worst is not None and m != "raytrace":
        tail = (f"; interior mismatch at most {fmt_pct(worst[0])}% over the {len(scenes)} "
                f"scenes (`{worst[1]}`)")
    if fastest and m != "raytrace":
        tail += (f"; frame {fmt_ratio(min(fastest))}-{fmt_ratio(max(fastest))}x raytrace's "
                 f"shade over the scenes")
    if m == "raytrace":
        cs = cells[m][HEADLINE_SCENE] if HEADLINE_SCENE in scenes else []
        return [f"`raytrace`: the reference; `{HEADLINE_SCENE}`: BVH (prepare) "
                f"{fmt_ms(median([c.prepare for c in cs]))} ms, shade "
                f"{fmt_ms(median([c.shade for c in cs]))} ms"]
    return [f"`{m}`: " + "; ".join(parts) + tail]


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "widen":
        widen(*sys.argv[2:])
    elif len(sys.argv) == 5 and sys.argv[1] == "report":
        report(*sys.argv[2:])
    else:
        sys.exit(__doc__)
