#!/usr/bin/env python3
"""Regenerates the measured part of docs/papers/chin-feiner-1989.md: Chin & Feiner's Table 1
for Tetra256 and Tetra1024 with svbsp.paper=1, each §6 refinement switched on alone over the
paper's algorithm and off alone under the default, contour planes against the default, and the
interior mismatch of the default, contour_planes=1 and paper=1 against raytrace on every
built-in, example and sweep scene.

    python3 scripts/papers/svbsp_table1.py [--repeats N] [--out FILE]

Needs build/shadowkit (or SHADOWKIT=path). Counts come from `shadowkit bench --json`, times
are its medians over --repeats runs (default 9) after one warm-up, mismatches from
`shadowkit compare --json` at each scene's own image size. The page's text between the lines
<!-- svbsp_table1.py: begin --> and <!-- svbsp_table1.py: end --> is replaced; the rest of
the page is left as it is. Under a minute on two cores.
"""
import argparse
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
SHADOWKIT = os.environ.get("SHADOWKIT", str(ROOT / "build" / "shadowkit"))
PAGE = ROOT / "docs" / "papers" / "chin-feiner-1989.md"
BEGIN, END = "<!-- svbsp_table1.py: begin -->", "<!-- svbsp_table1.py: end -->"

# Haines's SPD tetra light (1.876066, -18.123936, -5.000422), moved with the tetrahedron onto
# the built-in tetra:L (apex up, base corners in the generator's order): the rotation taking
# SPD's apex (-1, -1, 1) and base (-1, 1, -1), (1, -1, -1), (1, 1, 1) to the generator's,
# scaled by its edge 4 over SPD's 2 sqrt 2 (docs/papers/chin-feiner-1989.md).
SPD_LIGHT = [-23.124358, 10.6, 9.743159]

# Table 1's rows for the two scenes of recursive tetrahedra.
TABLE1 = {
    "Tetra256": {"level": 3, "secs": 4.15, "input": 258, "facing": 130, "edges": 390,
                 "nodes": 577, "fragments": 723},
    "Tetra1024": {"level": 4, "secs": 25.44, "input": 1026, "facing": 514, "edges": 1542,
                  "nodes": 2894, "fragments": 3345},
}

REFINEMENTS = ["skip_edges_in_tree", "merge_siblings", "whole_pieces", "far_side", "balance",
               "footprints"]

CONTOUR_SCENES = ["cubes:2000", "tetra:4", "three-lights", "table", "room",
                  "examples/default.json", "examples/room.json"]


def run(args):
    done = subprocess.run([SHADOWKIT] + args, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"svbsp_table1.py: shadowkit {' '.join(args)} failed: {done.stderr.strip()}")
    return json.loads(done.stdout)


def set_args(settings):
    out = []
    for key, value in settings.items():
        out += ["--set", f"svbsp.{key}={value}"]
    return out


def bench(scene, settings, repeats):
    """Counters summed over the scene's lights, times summed over them (medians per light)."""
    rows = run(["bench", scene, "--methods", "svbsp", "--json", "--repeats", str(repeats),
                "--warmup", "1" if repeats > 1 else "0"] + set_args(settings))
    total = {"prepare_ms": rows[0]["prepare_ms"], "build_ms": 0.0}
    for r in rows:
        total["build_ms"] += r["build_ms"]
        for key, value in r["counters"].items():
            if key.startswith("bsp_") or key in ("convex_units", "input_polygons"):
                total[key] = value  # per scene, not per light
            else:
                total[key] = total.get(key, 0) + value
    return total


def worst_mismatch(scene, settings):
    rows = run(["compare", scene, "--methods", "svbsp", "--json"] + set_args(settings))
    return max(r["mismatch_interior_pct"] for r in rows if r["method"] == "svbsp")


def spd_scene(tmp, level, light=SPD_LIGHT):
    """tetra:LEVEL lit by \p light (by default Haines's), as a scene file in \p tmp."""
    path = pathlib.Path(tmp) / f"tetra{level}-light.json"
    path.write_text(json.dumps({"generator": f"tetra:{level}",
                                "lights": [{"type": "point", "position": light}]}))
    return str(path)


def ratio(ours, paper):
    return f"{100 * (ours - paper) / paper:+.0f}%"


def ms(value):
    return f"{value:.2f}" if value < 10 else f"{value:.1f}"


def table1(tmp, repeats):
    lines = ["| scene | | input polygons | front-facing polygons | front-facing edges | "
             "SVBSP nodes | fragments | time |",
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    for name, paper in TABLE1.items():
        ours = bench(spd_scene(tmp, paper["level"]), {"paper": 1}, repeats)
        lines.append(f"| {name} | Table 1 | {paper['input']} | {paper['facing']} | "
                     f"{paper['edges']} | {paper['nodes']} | {paper['fragments']} | "
                     f"{paper['secs']} s |")
        lines.append(f"| | `svbsp.paper=1` | {ours['input_polygons']:.0f} | "
                     f"{ours['front_facing_polygons']:.0f} | {ours['front_facing_edges']:.0f} | "
                     f"{ours['svbsp_nodes']:.0f} ({ratio(ours['svbsp_nodes'], paper['nodes'])}) | "
                     f"{ours['fragments']:.0f} ({ratio(ours['fragments'], paper['fragments'])}) | "
                     f"{ms(ours['build_ms'])} ms |")
    return lines


def light_sweep(tmp):
    """paper=1 counts with the SPD light turned about the vertical axis, every 30 degrees."""
    radius = math.hypot(SPD_LIGHT[0], SPD_LIGHT[2])
    lines = ["| light azimuth |" + "".join(f" {n} front-facing | {n} nodes | {n} fragments |"
                                         for n in TABLE1),
             "|---:|" + "---:|---:|---:|" * len(TABLE1)]
    for degrees in range(0, 360, 30):
        turn = math.radians(degrees)
        light = [radius * math.cos(turn), SPD_LIGHT[1], radius * math.sin(turn)]
        cells = []
        for paper in TABLE1.values():
            r = bench(spd_scene(tmp, paper["level"], light), {"paper": 1}, 1)
            cells.append(f" {r['front_facing_polygons']:.0f} | {r['svbsp_nodes']:.0f} | "
                         f"{r['fragments']:.0f} |")
        lines.append(f"| {degrees}° |" + "".join(cells))
    return lines


def refinement_rows():
    rows = [("the paper's algorithm (`paper=1`)", {"paper": 1})]
    rows += [(f"+ `{r}`", {"paper": 1, r: 1}) for r in REFINEMENTS + ["contour_planes"]]
    rows.append(("+ all of them, one-sided", dict({"paper": 1, "contour_planes": 1},
                                                   **{r: 1 for r in REFINEMENTS})))
    rows.append(("the default (two-sided, every refinement but contour planes)", {}))
    rows += [(f"− `{r}`", {r: 0}) for r in REFINEMENTS]
    rows.append(("+ `contour_planes`", {"contour_planes": 1}))
    return rows


def refinements(tmp, repeats):
    scenes = [(name, spd_scene(tmp, paper["level"])) for name, paper in TABLE1.items()]
    head = "| settings |" + "".join(f" {n} nodes | {n} fragments (lit) | {n} ms |"
                                     for n, _ in scenes)
    lines = [head, "|---|" + "---:|---:|---:|" * len(scenes)]
    for label, settings in refinement_rows():
        cells = []
        for _, scene in scenes:
            r = bench(scene, settings, repeats)
            cells.append(f" {r['svbsp_nodes']:.0f} | {r['fragments']:.0f} "
                         f"({r['lit_fragments']:.0f}) | {ms(r['build_ms'])} |")
        lines.append(f"| {label} |" + "".join(cells))
    return lines


def contour(repeats):
    lines = ["| scene | convex solids kept whole | nodes, default | nodes, contour | "
             "fragments, default | fragments, contour | prepare ms, default | "
             "prepare ms, contour | build ms, default | build ms, contour |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for scene in CONTOUR_SCENES:
        d = bench(scene, {}, repeats)
        c = bench(scene, {"contour_planes": 1}, repeats)
        lines.append(f"| `{scene}` | {c['convex_units']:.0f} | {d['svbsp_nodes']:.0f} | "
                     f"{c['svbsp_nodes']:.0f} | {d['fragments']:.0f} | {c['fragments']:.0f} | "
                     f"{ms(d['prepare_ms'])} | {ms(c['prepare_ms'])} | {ms(d['build_ms'])} | "
                     f"{ms(c['build_ms'])} |")
    return lines


def exactness_scenes():
    builtin = ["cubes:2000", "tetra:3", "tetra:4", "room", "table", "three-lights", "square",
               "coil", "holed", "hole-like"]
    examples = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "examples").glob("*.json"))
    sweep = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "examples" / "sweep").glob("*.json"))
    return builtin + examples + sweep


def exactness():
    modes = [("default", {}), ("`contour_planes=1`", {"contour_planes": 1}),
             ("`paper=1`", {"paper": 1})]
    lines = ["| scene |" + "".join(f" {m} |" for m, _ in modes), "|---|" + "---:|" * len(modes)]
    worst = {m: (0.0, "") for m, _ in modes}
    for scene in exactness_scenes():
        cells = []
        for mode, settings in modes:
            pct = worst_mismatch(str(ROOT / scene) if "/" in scene else scene, settings)
            worst[mode] = max(worst[mode], (pct, scene))
            cells.append(f" {pct:.4f} |")
        lines.append(f"| `{scene}` |" + "".join(cells))
    summary = [f"Worst interior mismatch: " + "; ".join(
        f"{m} {p:.4f}% (`{s}`)" for m, (p, s) in worst.items()) + "."]
    return summary + [""] + lines


def generated(repeats):
    with tempfile.TemporaryDirectory() as tmp:
        parts = [
            "#### Table 1, Tetra256 and Tetra1024",
            "", *table1(tmp, repeats), "",
            "#### The light turned about the vertical, `svbsp.paper=1`",
            "", *light_sweep(tmp), "",
            "#### Each refinement of §6, alone",
            "", *refinements(tmp, repeats), "",
        ]
    parts += ["#### Contour planes against the default", "", *contour(repeats), "",
              "#### Interior mismatch against `raytrace`, %, worst light", "", *exactness()]
    return "\n".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--out", default=str(PAGE))
    args = parser.parse_args()
    if not os.access(SHADOWKIT, os.X_OK):
        sys.exit(f"svbsp_table1.py: no {SHADOWKIT}; run scripts/build.sh")
    page = pathlib.Path(args.out)
    text = page.read_text()
    if BEGIN not in text or END not in text:
        sys.exit(f"svbsp_table1.py: {page} has no {BEGIN} ... {END} lines")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    page.write_text(head + BEGIN + "\n" + generated(args.repeats) + "\n" + END + tail)
    print(f"wrote {page}")


if __name__ == "__main__":
    main()
