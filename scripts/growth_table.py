#!/usr/bin/env python3
"""Regenerates docs/scaling.md: every method's cost against the triangle count, from 125 to
80,000 cubes (960k triangles), the 576k-triangle knot, the 500k-triangle terrain and the IFC
house, with the fitted growth exponents, the ratios to raytrace's shade, peak memory and the
goals met or not.

    python3 scripts/growth_table.py [--quick] [--sizes N,N,...] [--methods M,M,...] [--voxel]
        [--repeats N] [--warmup N] [--passes P] [--threads N] [--no-extras] [--no-peak]
        [--out FILE] [--keep DIR] [--from DIR]

Needs build/shadowkit (or SHADOWKIT=path) and /usr/bin/time for peak memory. Per pass, scene
and method but raytrace, one process `shadowkit bench SCENE --methods raytrace,METHOD,raytrace
--json` (as scripts/benchmarks.sh), so each method's timings and memory are its own and its
ratio divides by raytrace's shade in the same process; medians over the passes. Peak memory:
`/usr/bin/time -v shadowkit render` per method on the largest cube field.

  defaults    --sizes 125,500,2000,8000,30000,80000 --repeats 5 --warmup 1 --passes 3, the
              knot, the terrain and the IFC house beside the cube fields; writes docs/scaling.md, and
              docs/images/growth_time.svg, growth_memory.svg, growth_data.csv
  --quick     cubes:125,500,2000, one pass of one timed run, no warm-up, the IFC house only as
              extra scene; writes /tmp/shadowkit-growth-quick/scaling.md (seconds)
  --sizes     cube counts, comma-separated
  --methods   default raytrace,shadowmap,volume,svbsp,angular; --voxel adds voxel (slow)
  --no-extras only the cube fields (not the room, examples/knot-600k.json, terrain:500 and the
              IFC house)
  --no-peak   no /usr/bin/time runs
  --out       the page (default docs/scaling.md); plots and CSV go to images/ beside it
  --keep      keep the raw JSON (bench, info, peak memory, meta) in DIR
  --from      measure nothing: write the page again from the raw JSON a --keep run left in DIR
"""
import argparse
import csv
import json
import math
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import benchmarks_report as br  # noqa: E402  Cell, medians, number formats
import plot_svg  # noqa: E402

SHADOWKIT = os.environ.get("SHADOWKIT", str(ROOT / "build" / "shadowkit"))
IFC_HOUSE = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc"
KNOT = "examples/knot-600k.json"
TERRAIN = "terrain:500"
SIZES = [125, 500, 2000, 8000, 30000, 80000]
# A method with a setting is written METHOD.KEY=VALUE and run with --set METHOD.KEY=VALUE.
METHODS = ["raytrace", "shadowmap", "shadowmap.tiles=all", "volume", "svbsp", "angular"]
QUICK_DIR = pathlib.Path("/tmp/shadowkit-growth-quick")

# The goals, each with the scenes it holds on: "cubes<=N" the cube fields up to N
# triangles, "cubes>=N" those from N, "cubes=N" the one of N, "ifc" the IFC house, "all" every
# scene. Each is judged at its worst scene.
GOALS = [
    ("`volume` frame / `raytrace` shade", "volume.frame_ratio", 1.0, "x",
     ["cubes<=96002", "ifc"]),
    ("`volume` frame / `raytrace` shade", "volume.frame_ratio", 2.0, "x", ["cubes>=960002"]),
    ("`volume` memory per triangle", "volume.bytes_per_triangle", 300, "B", ["cubes>=960002"]),
    ("`angular` frame / `raytrace` shade", "angular.frame_ratio", 0.5, "x", ["all"]),
    ("`svbsp` build per light", "svbsp.build", 100, "ms", ["cubes=96002"]),
    ("`svbsp` build per light", "svbsp.build", 2000, "ms", ["cubes>=960002"]),
    ("`svbsp` scene BSP tree (prepare)", "svbsp.prepare", 1000, "ms", ["cubes>=960002"]),
    ("`shadowmap` frame / `raytrace` shade", "shadowmap.frame_ratio", 1.0, "x", ["all"]),
    ("`shadowmap` lookups (`tiles=all`) / `raytrace` shade", "shadowmap.tiles=all.shade_ratio",
     0.3, "x", ["all"]),
    ("scan conversion / `raytrace` shade", "scan_ratio", 0.3, "x", ["all"]),
]
STAGES = [("prepare", "prepare ms"), ("build", "build ms"), ("shade", "shade ms"),
          ("frame", "frame ms"), ("memory", "memory MB")]
PREPARE_NOTES = {"raytrace": "the BVH", "svbsp": "the scene BSP tree",
                 "volume": "light-independent set-up", "voxel": "the voxelization"}


# ---------------------------------------------------------------------------- measuring

def method_of(m):
    """The method of a METHODS entry, without its setting."""
    return m.split(".", 1)[0]


def settings_of(m):
    """The command-line setting of a METHODS entry, if it has one."""
    return ["--set", m] if "." in m else []


def run(command, out=None):
    """Runs shadowkit; status 3 (a method failed on a light: a `failed` row) is a result."""
    with open(out, "w") if out else open(os.devnull, "w") as sink:
        status = subprocess.run(command, stdout=sink).returncode
    if status not in (0, 3):
        sys.exit(f"growth_table.py: {' '.join(map(str, command))} ended with status {status}")


def peak_rss(command, out):
    """Maximum resident set size of COMMAND in bytes, from /usr/bin/time -v (kept in OUT)."""
    result = subprocess.run(["/usr/bin/time", "-v", *command], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    pathlib.Path(out).write_text(result.stderr)
    return parse_rss(result.stderr)


def parse_rss(text):
    for line in text.splitlines():
        if "Maximum resident set size" in line:
            return int(line.rsplit(":", 1)[1]) * 1024
    return None


def machine(threads):
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                if l.startswith("model name")), "unknown CPU")
    mem = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
    cache = pathlib.Path(SHADOWKIT).resolve().parent / "CMakeCache.txt"
    march = next((l.split("=", 1)[1].strip() for l in cache.read_text().splitlines()
                  if l.startswith("SHADOWKIT_MARCH:")), "") if cache.exists() else ""
    return {"cpu": cpu, "cores": os.cpu_count(), "memory_gb": f"{mem / 2**20:.0f}",
            "threads": threads or "", "march": march}


def measure(args, scenes, methods, work):
    threads = ["--threads", args.threads] if args.threads else []
    start = time.monotonic()
    load_start = os.getloadavg()[0]
    for i, scene in enumerate(scenes):
        run([SHADOWKIT, "info", scene, "--json", *threads], work / f"info.{i}.json")
    walls = {}
    for p in range(args.passes):
        for i, scene in enumerate(scenes):
            for m in methods[1:]:
                print(f"growth_table.py: pass {p + 1}/{args.passes}: {scene} {m}", file=sys.stderr)
                began = time.monotonic()
                run([SHADOWKIT, "bench", scene, "--methods", f"raytrace,{method_of(m)},raytrace",
                     *settings_of(m), "--repeats", str(args.repeats), "--warmup",
                     str(args.warmup), "--json", *threads], work / f"bench.{p}.{i}.{m}.json")
                walls[f"{p}.{i}.{m}"] = time.monotonic() - began
    peak = None
    if not args.no_peak and os.access("/usr/bin/time", os.X_OK):
        peak = f"cubes:{max(args.sizes)}"
        print(f"growth_table.py: peak memory on {peak}", file=sys.stderr)
        scratch = tempfile.mkdtemp(prefix="shadowkit-growth-render-")
        peak_rss([SHADOWKIT, "info", peak, *threads], work / "peak.info.txt")
        for m in methods:
            peak_rss([SHADOWKIT, "render", peak, "--method", method_of(m), *settings_of(m),
                      "--mask", f"{scratch}/mask", *threads], work / f"peak.{m}.txt")
        shutil.rmtree(scratch, ignore_errors=True)
    meta = {"scenes": scenes, "methods": methods, "sizes": args.sizes, "passes": args.passes,
            "repeats": args.repeats, "warmup": args.warmup, "peak_scene": peak,
            "command": args.shown, "walls": walls,
            "elapsed_min": (time.monotonic() - start) / 60,
            "load_start": f"{load_start:.2f}", "load_end": f"{os.getloadavg()[0]:.2f}",
            **machine(args.threads)}
    (work / "meta.json").write_text(json.dumps(meta, indent=1))


# ---------------------------------------------------------------------------- figures

def load_json(path):
    text = pathlib.Path(path).read_text()
    return json.loads(text) if text.strip() else []


class Figures:
    """Medians over the passes of one method on one scene, from benchmarks_report's Cell."""

    def __init__(self, cells, scan_ratios):
        med = lambda key: br.median([getattr(c, key) for c in cells])
        self.prepare, self.build, self.shade = med("prepare"), med("build"), med("shade")
        self.frame, self.memory = med("frame"), med("memory")
        self.shade_ratio, self.frame_ratio = med("shade_ratio"), med("frame_ratio")
        self.scan_ratio = br.median(scan_ratios)
        self.failed = sorted({f for c in cells for f in c.failed})

    def get(self, stage):
        return getattr(self, stage)


def raytrace_rows(processes):
    """raytrace per light: the median of its runs in every process of a pass."""
    return br.raytrace_medians([r for rs in processes for r in rs])


def scan_ratio(rows):
    """scan_ms over raytrace's shade (summed over lights, mean of its runs) in one process."""
    rt = [r for r in rows if r.get("method") == "raytrace" and "failed" not in r]
    if not rt or "scan_ms" not in rows[0]:
        return None
    per_light = {}
    for r in rt:
        per_light.setdefault(r["light"], []).append(r["shade_ms"])
    shade = sum(statistics.mean(v) for v in per_light.values())
    return rows[0]["scan_ms"] / shade if shade > 0 else None


def figures(work):
    meta = load_json(work / "meta.json")
    scenes, methods, passes = meta["scenes"], meta["methods"], meta["passes"]
    bench = {(p, i, m): load_json(work / f"bench.{p}.{i}.{m}.json")
             for p in range(passes) for i in range(len(scenes)) for m in methods[1:]}
    info = [load_json(work / f"info.{i}.json") for i in range(len(scenes))]
    fig, scene_rows = {}, []
    for i, scene in enumerate(scenes):
        for m in methods[1:]:
            cells, ratios = [], []
            for p in range(passes):
                rows = bench[(p, i, m)]
                cells.append(br.Cell([r for r in rows if r.get("method") == method_of(m)],
                                     [r for r in rows if r.get("method") == "raytrace"]))
                ratios.append(scan_ratio(rows))
            fig[(scene, m)] = Figures(cells, ratios)
        cells, ratios = [], []
        for p in range(passes):
            processes = [bench[(p, i, m)] for m in methods[1:]]
            rows = raytrace_rows(processes)
            cells.append(br.Cell(rows, rows))
            ratios += [scan_ratio(rs) for rs in processes]
        fig[(scene, "raytrace")] = Figures(cells, ratios)
        first = [bench[(p, i, m)][0] for p in range(passes) for m in methods[1:]
                 if bench[(p, i, m)]]
        scene_rows.append({
            "scene": scene, "polygons": info[i]["polygons"], "triangles": info[i]["triangles"],
            "lights": len(info[i]["lights"]),
            "resolution": f"{info[i]['camera']['width']}x{info[i]['camera']['height']}",
            "load": br.median([r.get("load_ms") for r in first]),
            "scan": br.median([r.get("scan_ms") for r in first]),
            "scan_ratio": fig[(scene, "raytrace")].scan_ratio})
    peak = {}
    if meta.get("peak_scene"):
        for m in ["info"] + methods:
            path = work / f"peak.{m}.txt"
            if path.exists():
                peak[m] = parse_rss(path.read_text())
    return meta, fig, scene_rows, peak


def exponent(points):
    """Least-squares k of value ~ triangles^k (slope of log value against log triangles)."""
    points = [(math.log(t), math.log(v)) for t, v in points if v and v > 0]
    if len(points) < 2:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    den = sum((x - mx) ** 2 for x, _ in points)
    return sum((x - mx) * (y - my) for x, y in points) / den if den else None


# ---------------------------------------------------------------------------- the page

def name(scene):
    if scene.startswith("/"):
        return pathlib.Path(scene).name
    return scene


def fmt_k(k):
    return "–" if k is None else f"{k:.2f}"


def fmt_stage(stage, v):
    return br.fmt_mb(v) if stage == "memory" else br.fmt_ms(v)


def goal_value(key, fig, scene, scene_row):
    if key == "scan_ratio":
        return scene_row["scan_ratio"]
    method, attr = key.rsplit(".", 1)
    f = fig.get((scene, method))
    if not f:
        return None
    if attr == "bytes_per_triangle":
        return f.memory and f.memory / scene_row["triangles"]
    return f.get(attr)


def goal_scenes(scope, scenes, tri):
    """The scenes a goal's scope names (see GOALS)."""
    chosen = []
    for part in scope:
        for s in scenes:
            cube = s.startswith("cubes:")
            if (part == "all" or (part == "ifc" and s.endswith(".ifc"))
                    or (cube and part.startswith("cubes<=") and tri[s] <= int(part[7:]))
                    or (cube and part.startswith("cubes>=") and tri[s] >= int(part[7:]))
                    or (cube and part.startswith("cubes=") and tri[s] == int(part[6:]))):
                chosen.append(s)
    return list(dict.fromkeys(chosen))


def fmt_goal(v, unit):
    if v is None:
        return "–"
    return {"x": f"{br.fmt_ratio(v)}x", "ms": f"{v:,.0f} ms", "B": f"{v:,.0f} B"}[unit]


def write_csv(path, meta, fig, scene_rows):
    by_scene = {r["scene"]: r for r in scene_rows}
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["scene", "kind", "polygons", "triangles", "method", "load_ms", "scan_ms",
                      "prepare_ms", "build_ms", "shade_ms", "frame_ms", "memory_mb",
                      "shade_ratio", "frame_ratio", "scan_ratio"])
        num = lambda v, d=4: "" if v is None else f"{v:.{d}f}"
        for scene in meta["scenes"]:
            s = by_scene[scene]
            for m in meta["methods"]:
                g = fig[(scene, m)]
                out.writerow([name(scene), "cubes" if scene.startswith("cubes:") else "extra",
                              s["polygons"], s["triangles"], m, num(s["load"]), num(s["scan"]),
                              num(g.prepare), num(g.build), num(g.shade), num(g.frame),
                              num(g.memory and g.memory / 1e6), num(g.shade_ratio),
                              num(g.frame_ratio), num(g.scan_ratio)])


def plots(csv_path, images, scene_rows):
    """growth_time.svg and growth_memory.svg over the cube fields, by plot_svg.py."""
    rows = plot_svg.load(csv_path, ["kind!=extra"])
    if len({r["triangles"] for r in rows}) < 2:
        return []
    options = dict(x="triangles", logx=True, logy=True, xlabel="triangles (cube fields)")
    lines = plot_svg.series(rows, "triangles", ["frame_ms"], ["method"])
    lines = {f"{k} frame": v for k, v in lines.items()}
    for r in [r for r in rows if r["method"] in ("raytrace", "svbsp") and r["prepare_ms"]]:
        lines.setdefault(f"{r['method']} prepare", []).append(
            (float(r["triangles"]), float(r["prepare_ms"])))
    lines["scan conversion"] = [(float(s["triangles"]), s["scan"]) for s in scene_rows
                                if s["scene"].startswith("cubes:") and s["scan"]]
    lines = {k: sorted(v) for k, v in lines.items() if any(y > 0 for _, y in v)}
    written = []
    time_svg = images / "growth_time.svg"
    time_svg.write_text(plot_svg.plot(lines, argparse.Namespace(
        **options, title="Time against triangles (build + shade per light; prepare once)",
        ylabel="ms")))
    memory = plot_svg.series(rows, "triangles", ["memory_mb"], ["method"])
    memory_svg = images / "growth_memory.svg"
    memory_svg.write_text(plot_svg.plot(
        {k: v for k, v in memory.items() if any(y > 0 for _, y in v)}, argparse.Namespace(
            **options, title="Each method's structures after a light's build", ylabel="MB")))
    written += [time_svg, memory_svg]
    return written


def report(work, out):
    meta, fig, scene_rows, peak = figures(work)
    scenes, methods = meta["scenes"], meta["methods"]
    cubes = [s for s in scenes if s.startswith("cubes:")]
    extras = [s for s in scenes if not s.startswith("cubes:")]
    tri = {r["scene"]: r["triangles"] for r in scene_rows}
    by_scene = {r["scene"]: r for r in scene_rows}
    images = out.parent / "images"
    images.mkdir(parents=True, exist_ok=True)
    csv_path = images / "growth_data.csv"
    write_csv(csv_path, meta, fig, scene_rows)
    svgs = plots(csv_path, images, scene_rows)

    lines = []
    w = lines.append
    w("# Scaling: cost against the triangle count")
    w("")
    w("Generated by `scripts/growth_table.py`; do not edit by hand. Regenerate with:")
    w("")
    w("```sh")
    w("bash scripts/build.sh            # Release build into build/")
    w(" ".join(["python3 scripts/growth_table.py"] + meta["command"]))
    w("```")
    w("")
    w(f"- **Machine**: {meta['cpu']}, {meta['cores']} cores (`nproc`), {meta['memory_gb']} GB "
      "memory" + (f"; a Release build for `-march={meta['march']}`" if meta.get("march") else "")
      + ". " + (f"Every command runs with `--threads {meta['threads']}`."
                if meta.get("threads") else "Every command uses every core."))
    resolutions = sorted({r["resolution"] for r in scene_rows})
    w(f"- **Resolution**: {', '.join(resolutions)} on every scene: the shaded pixels stay the "
      "same while the triangles grow, so what grows with the scene is each method's work per "
      "triangle, not per pixel.")
    w(f"- **Timing**: {meta['passes']} pass{'es' if meta['passes'] != 1 else ''} over the "
      "scenes; in each, per scene and per method but `raytrace`, one process `build/shadowkit "
      f"bench SCENE --methods raytrace,METHOD,raytrace --repeats {meta['repeats']} --warmup "
      f"{meta['warmup']} --json`, as [benchmarks.md](benchmarks.md) times: each method's "
      "timings and memory are its own, and its ratio divides by the mean of the two "
      "`raytrace` shades of its own process. `bench` reports the median of the timed runs; "
      "the tables give the median over the passes (`raytrace`'s own figures: over all its "
      "runs of a pass, then over the passes). *prepare* runs once per process, *build* and "
      "*shade* per light; *frame* = build + shade; *memory*: the method's structures after a "
      "light's build, as `bench` reports them. Every method at its default settings; "
      "`shadowmap.tiles=all` is `shadowmap` with `--set shadowmap.tiles=all`, Williams's "
      "order: the whole maps drawn in *build*, the lookups alone in *shade* (by default the "
      "camera pass draws the tiles it looks up, so its *shade* holds the drawing).")
    w(f"- The whole run took {meta['elapsed_min']:.1f} min; load average (1 min) "
      f"{meta['load_start']} when it started and {meta['load_end']} when it ended. The "
      "machine is shared: absolute ms move from run to run, ratios in the same process much "
      "less ([benchmarks.md](benchmarks.md#noise)).")
    w("")

    w("## Scenes")
    w("")
    w("The cube fields are the built-in `cubes:N` (the angular paper's scalability field: N "
      "cubes of 6 quads in a fixed volume over one ground quad, 12 triangles a cube). *load* is "
      "parsing, tessellation, welding and the working frame; *scan* the camera's scan "
      "conversion into the visible-surface buffer that every method shares, and *scan / "
      "raytrace*: scan over `raytrace`'s shade in the same process.")
    w("")
    w("| scene | polygons | triangles | lights | load ms | scan ms | scan / raytrace |")
    w("|---|---:|---:|---:|---:|---:|---:|")
    for r in scene_rows:
        w(f"| `{name(r['scene'])}` | {r['polygons']:,} | {r['triangles']:,} | {r['lights']} | "
          f"{br.fmt_ms(r['load'])} | {br.fmt_ms(r['scan'])} | {br.fmt_ratio(r['scan_ratio'])} |")
    w("")
    if KNOT in scenes:
        w(f"`{KNOT}`: the (2,3) torus knot of `examples/models/torus-knot.obj` (2,000 quads) "
          "as a Catmull-Clark surface at `tessellation` 12 (2,000 x 12 x 12 x 2 = 576,000 "
          "triangles) over the bumpy Catmull-Clark ground of `examples/subdivision.json` "
          "at `tessellation` 8 (8,192 triangles), one directional light: the knot shadows the ground and its own "
          "strands.")
    if TERRAIN in scenes:
        w(f"`{TERRAIN}`: the built-in height field of 500 x 500 cells, two triangles each "
          "([scene-format.md](scene-format.md#built-in-scenes)), under a sun 17 degrees high: "
          "one open mesh of 500,000 triangles, one sub-object, whose hills shadow each other "
          "over the whole view.")
    if any(s.endswith(".ifc") for s in scenes):
        w("`AC14-FZK-Haus.ifc`: the IFC house of Debian's `assimp-testmodels`, as a whole scene "
          "([formats.md](formats.md)): its own camera and sun; loaded from the import cache "
          "when an earlier command left it there.")
    w("")

    w("## Goals")
    w("")
    w("The speed and memory each method is held to, on the scenes named, judged at its worst "
      "scene. *scenes*: `all` every scene above, `cubes<=N` the cube fields of at most N "
      "triangles, `cubes>=N` those of at least N, `cubes=N` the one of N, `ifc` the IFC house. "
      "Ratios divide by "
      "`raytrace`'s shade in the same process. A goal whose scenes were not measured shows –.")
    w("")
    w("| goal | limit | scenes | worst | at | met |")
    w("|---|---:|---|---:|---|---|")
    for label, key, limit, unit, scope in GOALS:
        if key.rsplit(".", 1)[0] not in methods and key != "scan_ratio":
            continue
        values = [(goal_value(key, fig, s, by_scene[s]), s)
                  for s in goal_scenes(scope, scenes, tri)]
        values = [(v, s) for v, s in values if v is not None]
        worst, at = max(values) if values else (None, "")
        w(f"| {label} | ≤ {fmt_goal(limit, unit)} | {', '.join(scope)} | "
          f"{fmt_goal(worst, unit)} | {f'`{name(at)}`' if at else ''} | "
          f"{'–' if worst is None else ('met' if worst <= limit else '**not met**')} |")
    w("")

    w("## Growth")
    w("")
    w("Per method and stage, ms (memory MB) on each scene, and *k*: the least-squares "
      "exponent of value ~ triangles^k over the cube fields (1: linear in the triangles, 0: "
      "independent of them). Stages that stay below 0.05 ms everywhere are left out.")
    w("")
    head = (["method", "stage"] + [f"`{name(s)}`" for s in cubes] + ["k"]
            + [f"`{name(s)}`" for s in extras])
    row = lambda cells: w("| " + " | ".join(cells) + " |")
    row(head)
    w("|---|---|" + "---:|" * (len(head) - 2))
    row(["triangles", ""] + [f"{tri[s]:,}" for s in cubes] + [""] + [f"{tri[s]:,}" for s in extras])
    row(["scan conversion", "ms"] + [br.fmt_ms(by_scene[s]["scan"]) for s in cubes]
        + [fmt_k(exponent([(tri[s], by_scene[s]["scan"]) for s in cubes]))]
        + [br.fmt_ms(by_scene[s]["scan"]) for s in extras])
    for m in methods:
        for stage, label in STAGES:
            values = [fig[(s, m)].get(stage) for s in scenes]
            if stage != "memory" and all(v is None or v < 0.05 for v in values):
                continue
            if stage == "frame" and m == "raytrace":
                continue  # its build is next to nothing: frame = shade
            if stage == "prepare" and m in PREPARE_NOTES:
                label = f"prepare ms ({PREPARE_NOTES[m]})"
            k = exponent([(tri[s], fig[(s, m)].get(stage)) for s in cubes])
            row([f"`{m}`", label] + [fmt_stage(stage, fig[(s, m)].get(stage)) for s in cubes]
                + [fmt_k(k)] + [fmt_stage(stage, fig[(s, m)].get(stage)) for s in extras])
    failed = [(s, m, f) for (s, m), g in fig.items() for f in g.failed]
    if failed:
        w("")
        w("Failed: " + "; ".join(f"`{m}` on `{name(s)}` ({f})" for s, m, f in failed) + ".")
    w("")
    for svg in svgs:
        w(f"![{svg.stem.replace('_', ' ')}](images/{svg.name})")
        w("")
    w(f"The numbers behind the tables and plots: [images/{csv_path.name}](images/{csv_path.name}).")
    w("")

    w("## Ratios to `raytrace`'s shade")
    w("")
    w("Per scene, each method's frame (and `shadowmap`'s lookups, the shade of "
      "`shadowmap.tiles=all`) over `raytrace`'s "
      "shade in the same process: the figures the goals are stated in; `svbsp` in ms, its "
      "build per light and its scene BSP tree.")
    w("")
    cols = [("raytrace shade ms", lambda s: br.fmt_ms(fig[(s, "raytrace")].shade), "raytrace"),
            ("scan / raytrace", lambda s: br.fmt_ratio(by_scene[s]["scan_ratio"]), "raytrace")]
    for m in methods[1:]:
        cols.append((f"{m} frame ×", lambda s, m=m: br.fmt_ratio(fig[(s, m)].frame_ratio), m))
        if m == "shadowmap.tiles=all":
            cols.append(("shadowmap lookups ×",
                         lambda s, m=m: br.fmt_ratio(fig[(s, m)].shade_ratio), m))
        if m == "svbsp":
            cols.append(("svbsp build ms", lambda s: br.fmt_ms(fig[(s, "svbsp")].build), m))
            cols.append(("svbsp scene BSP ms", lambda s: br.fmt_ms(fig[(s, "svbsp")].prepare), m))
    w("| scene | triangles | " + " | ".join(c[0] for c in cols) + " |")
    w("|---|---:|" + "---:|" * len(cols))
    for s in scenes:
        w(f"| `{name(s)}` | {tri[s]:,} | " + " | ".join(c[1](s) for c in cols) + " |")
    w("")

    if peak:
        w("## Peak memory")
        w("")
        w(f"Maximum resident set size of `/usr/bin/time -v build/shadowkit render "
          f"{meta['peak_scene']} --method METHOD --mask PREFIX` "
          f"({tri.get(meta['peak_scene'], 0):,} triangles): the whole process (scene, "
          "visible-surface buffer, the method, the mask), once per method. `info` loads the "
          "scene and stops: the part every method shares. *structures*: the method's own, as "
          "`bench` reports them.")
        w("")
        w("| command | peak RSS MB | structures MB |")
        w("|---|---:|---:|")
        for m in ["info"] + methods:
            if m not in peak:
                continue
            f = fig.get((meta["peak_scene"], m))
            command = f"render --method {method_of(m)}" + (
                f" --set {m}" if settings_of(m) else "")
            w(f"| {'`info`' if m == 'info' else f'`{command}`'} | "
              f"{br.fmt_mb(peak[m])} | {br.fmt_mb(f.memory) if f else '–'} |")
        w("")
    out.write_text("\n".join(lines))
    return lines


# ---------------------------------------------------------------------------- main

def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--sizes")
    parser.add_argument("--methods")
    parser.add_argument("--voxel", action="store_true")
    parser.add_argument("--repeats", type=int)
    parser.add_argument("--warmup", type=int)
    parser.add_argument("--passes", type=int)
    parser.add_argument("--threads")
    parser.add_argument("--no-extras", action="store_true")
    parser.add_argument("--no-peak", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--keep")
    parser.add_argument("--from", dest="source")
    args = parser.parse_args()

    out = pathlib.Path(args.out) if args.out else (
        QUICK_DIR / "scaling.md" if args.quick else ROOT / "docs" / "scaling.md")
    out.parent.mkdir(parents=True, exist_ok=True)
    if args.source:
        report(pathlib.Path(args.source), out)
        print(out)
        return

    # The options that change what is measured, for the page's command line.
    args.shown = [a for a in sys.argv[1:]]
    for flag in ("--out", "--keep"):
        if flag in args.shown:
            i = args.shown.index(flag)
            del args.shown[i:i + 2]
    args.sizes = [int(n) for n in args.sizes.split(",")] if args.sizes else (
        [125, 500, 2000] if args.quick else SIZES)
    methods = args.methods.split(",") if args.methods else list(METHODS)
    if args.voxel and "voxel" not in methods:
        methods.append("voxel")
    methods = ["raytrace"] + [m for m in methods if m != "raytrace"]
    if len(methods) < 2:
        sys.exit("growth_table.py: --methods needs a method besides raytrace")
    args.repeats = args.repeats if args.repeats is not None else (1 if args.quick else 5)
    args.warmup = args.warmup if args.warmup is not None else (0 if args.quick else 1)
    args.passes = args.passes if args.passes is not None else (1 if args.quick else 3)
    if not os.access(SHADOWKIT, os.X_OK):
        sys.exit(f"growth_table.py: no {SHADOWKIT}; run scripts/build.sh or set SHADOWKIT")

    scenes = [f"cubes:{n}" for n in args.sizes]
    if not args.no_extras:
        scenes.append("room")  # the light inside the scene, which angular's goal names
        if not args.quick:
            scenes.append(str(ROOT / KNOT))
            scenes.append(TERRAIN)
        if os.path.exists(IFC_HOUSE):
            scenes.append(IFC_HOUSE)
        else:
            print(f"growth_table.py: no {IFC_HOUSE} (Debian's assimp-testmodels); skipped",
                  file=sys.stderr)
    if args.keep:
        work = pathlib.Path(args.keep)
        work.mkdir(parents=True, exist_ok=True)
    else:
        work = pathlib.Path(tempfile.mkdtemp(prefix="shadowkit-growth-"))
    try:
        measure(args, scenes, methods, work)
        # Scene paths inside the repository are shown relative to it.
        meta = json.loads((work / "meta.json").read_text())
        meta["scenes"] = [os.path.relpath(s, ROOT) if s.startswith(str(ROOT)) else s
                          for s in meta["scenes"]]
        (work / "meta.json").write_text(json.dumps(meta, indent=1))
        lines = report(work, out)
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    print("\n".join(l for l in lines if l.startswith("|")))
    print(out)


if __name__ == "__main__":
    main()
