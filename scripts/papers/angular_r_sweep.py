#!/usr/bin/env python3
"""Regenerates the measured part of docs/papers/thakur-cheng-miura.md: the interior mismatch of
`angular` against raytrace as the theta resolution R grows (Thakur03 Sec. 3, Figs. 6-7), with
the exact assists (angular.exact=1, the default) and without them (exact=0, the discretized
method as published); R from eq. 4 as written (resolution=eq4) against the automatic R; and,
with the light inside the room, one table over the turn against Sec. 11.2's two hemispheres
(angular.light_inside); the RE-loops paper's own pairing against the far-sheet walk
(angular.pairing, and its rules alone: angular.fallback=0), with the R sweep redone for each;
and each of these settings on every built-in, example and sweep scene.

    python3 scripts/papers/angular_r_sweep.py [--repeats N] [--out FILE]

Needs build/shadowkit (or SHADOWKIT=path). Mismatches come from `shadowkit compare --json`
(the worst light of each scene), counters and times from `shadowkit bench --json` (medians
over --repeats runs, default 9, after one warm-up). The page's text between the lines
<!-- angular_r_sweep.py: begin --> and <!-- angular_r_sweep.py: end --> is replaced.
"""
import argparse
import os
import pathlib
import json
import subprocess
import sys

from svbsp_table1 import exactness_scenes

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
SHADOWKIT = os.environ.get("SHADOWKIT", str(ROOT / "build" / "shadowkit"))
PAGE = ROOT / "docs" / "papers" / "thakur-cheng-miura.md"
BEGIN, END = "<!-- angular_r_sweep.py: begin -->", "<!-- angular_r_sweep.py: end -->"

SWEEP_SCENES = ["table", "coil", "holed", "cubes:500", "examples/default.json"]
# 99, 299 and 599 are the paper's quality steps; then one and two entries per scan line of a
# 1080-row image, and beyond.
RESOLUTIONS = ["99", "299", "599", "1080", "2160", "4320"]
ROOM_SCENES = ["room", "examples/room.json"]
# Each pairing's settings: the walk, the paper's rules checked against the far sheet (walked
# where they fail), and its rules alone.
PAIRINGS = {"walk": {"pairing": "walk"}, "paper": {"pairing": "paper"},
            "paper, `fallback=0`": {"pairing": "paper", "fallback": 0}}
PAIRING_SCENES = ["coil", "holed", "hole-like", "table", "cubes:500", "examples/house.json",
                  "examples/subdivision.json"]


def run(args):
    done = subprocess.run([SHADOWKIT] + args + ["--json"], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"angular_r_sweep.py: shadowkit {' '.join(args)} failed: {done.stderr.strip()}")
    return json.loads(done.stdout)


def scene_arg(scene):
    return str(ROOT / scene) if "/" in scene else scene


def set_args(settings):
    out = []
    for key, value in settings.items():
        out += ["--set", f"angular.{key}={value}"]
    return out


def compare(scene, settings):
    """The worst light's interior mismatch (%), and every light's R as text."""
    rows = [r for r in run(["compare", scene_arg(scene), "--methods", "angular"] +
                           set_args(settings)) if r["method"] == "angular"]
    worst = max(r["mismatch_interior_pct"] for r in rows)
    return worst, "/".join(f"{r['counters']['theta_resolution']:.0f}" for r in rows)


def bench(scene, settings, repeats):
    """angular's counters and times summed over the scene's lights, and raytrace's shade time
    in the same run (the README's unit of time: the machine's load cancels out)."""
    rows = run(["bench", scene_arg(scene), "--methods", "raytrace,angular", "--repeats",
                str(repeats)] + set_args(settings))
    total = {"build_ms": 0.0, "shade_ms": 0.0, "raytrace_ms": 0.0}
    for r in rows:
        if r["method"] == "raytrace":
            total["raytrace_ms"] += r["shade_ms"]
            continue
        total["build_ms"] += r["build_ms"]
        total["shade_ms"] += r["shade_ms"]
        for key, value in r["counters"].items():
            total[key] = total.get(key, 0) + value
    return total


def r_sweep(pairing_settings):
    head = "| R |" + "".join(f" `{s}` exact=1 | exact=0 |" for s in SWEEP_SCENES)
    lines = [head, "|---|" + "---:|---:|" * len(SWEEP_SCENES)]
    for r in RESOLUTIONS + ["0", "eq4"]:
        cells, label = [], {"0": "automatic (0)", "eq4": "`eq4`"}.get(r, r)
        for scene in SWEEP_SCENES:
            for exact in ("1", "0"):
                pct, resolution = compare(scene, {"resolution": r, "exact": exact,
                                                  **pairing_settings})
                shown = f"{pct:.4f}" if r in RESOLUTIONS else f"{pct:.4f} (R {resolution})"
                cells.append(f" {shown} |")
        lines.append(f"| {label} |" + "".join(cells))
    return lines


def light_inside(repeats):
    """Each mode at the automatic R (turn: over the theta in view; hemispheres: over the whole
    turn, which Sec. 11.2 splits) and at one fixed R for both."""
    lines = ["| scene | light_inside | resolution | exact | R | lookups | build ms | shade ms | "
             "time (x raytrace) | mismatch % |", "|---|---|---|---|---:|---:|---:|---:|---:|---:|"]
    for scene in ROOM_SCENES:
        for resolution in ("0", "4320"):
            for mode in ("turn", "hemispheres"):
                for exact in ("1", "0"):
                    settings = {"light_inside": mode, "resolution": resolution, "exact": exact}
                    b = bench(scene, settings, repeats)
                    pct, _ = compare(scene, settings)
                    lines.append(f"| `{scene}` | {mode} | {resolution} | {exact} | "
                                 f"{b['theta_resolution']:.0f} | {b['lookup_calls']:.0f} | "
                                 f"{b['build_ms']:.2f} | {b['shade_ms']:.2f} | "
                                 f"{(b['build_ms'] + b['shade_ms']) / b['raytrace_ms']:.2f} | "
                                 f"{pct:.4f} |")
    return lines


def pairings(repeats):
    """Each pairing at the automatic R: the table's pairs, the paper's own count of ridge-edge
    pairs, of the ones it walked and of the VREPIPs it split loops at, build and shade times,
    and the mismatch."""
    lines = ["| scene | pairing | R | table pairs | RE pairs | walked | VREPIPs | objects paper/walk | "
             "build ms | shade ms | mismatch % |",
             "|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|"]
    for scene in PAIRING_SCENES:
        for pairing, settings in PAIRINGS.items():
            b = bench(scene, settings, repeats)
            pct, resolution = compare(scene, settings)
            paper = settings["pairing"] == "paper"
            counts = (f"{b['re_pairs']:.0f} | {b['pairing_fallbacks']:.0f} | {b['vrepips']:.0f} | "
                      f"{b['paper_objects']:.0f}/{b['walked_objects']:.0f}") if paper else "– | – | – | –"
            lines.append(f"| `{scene}` | {pairing} | {resolution} | {b['table_pairs']:.0f} | "
                         f"{counts} | {b['build_ms']:.2f} | {b['shade_ms']:.2f} | {pct:.4f} |")
    return lines


# Every built-in, example and sweep scene: the list the svbsp page measures too.
MODES = {"default": {}, "`exact=0`": {"exact": 0}, "`resolution=eq4`": {"resolution": "eq4"},
         "`light_inside=hemispheres`": {"light_inside": "hemispheres"},
         "all three": {"exact": 0, "resolution": "eq4", "light_inside": "hemispheres"},
         "`pairing=paper`": {"pairing": "paper"},
         "`pairing=paper`, `fallback=0`": {"pairing": "paper", "fallback": 0}}


def modes_everywhere():
    """Each setting's worst light on every scene, and each setting's worst scene."""
    scenes = exactness_scenes()
    columns = {mode: [compare(scene, settings)[0] for scene in scenes]
               for mode, settings in MODES.items()}
    summary = "Worst interior mismatch (%): " + "; ".join(
        f"{mode} {max(pcts):.4f} (`{scenes[pcts.index(max(pcts))]}`)"
        for mode, pcts in columns.items()) + "."
    table = ["| scene |" + "".join(f" {mode} |" for mode in MODES),
             "|---|" + "---:|" * len(MODES)]
    table += [f"| `{scene}` |" + "".join(f" {columns[mode][i]:.4f} |" for mode in MODES)
              for i, scene in enumerate(scenes)]
    return [summary, ""] + table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--out", default=str(PAGE))
    args = parser.parse_args()
    body = ["Interior mismatch (%) against raytrace, worst light, each scene at its own image "
            "size; for the automatic R and eq4, each light's R:", ""] + r_sweep(PAIRINGS["walk"])
    body += ["", "The same with the RE-loops paper's pairing (`pairing=paper`):", ""]
    body += r_sweep(PAIRINGS["paper"])
    body += ["", "The same with the paper's rules alone (`pairing=paper`, `fallback=0`):", ""]
    body += r_sweep(PAIRINGS["paper, `fallback=0`"])
    body += ["", "Paper pairing against the walk at the automatic R, summed over the lights "
             f"(times: medians of {args.repeats} runs; RE pairs, walked and objects are paper "
             "pairing's counters; with `fallback=0`, walked counts the pairs left as the rules "
             "made them):", ""] + pairings(args.repeats)
    body += ["", "The light inside the room, summed over its lights (times: medians of "
             f"{args.repeats} runs):", ""] + light_inside(args.repeats)
    body += ["", "Each setting on every built-in, example and sweep scene, worst light, at the "
             "automatic R unless eq4:", ""] + modes_everywhere()
    page = pathlib.Path(args.out)
    text = page.read_text()
    start, end = text.index(BEGIN) + len(BEGIN), text.index(END)
    page.write_text(text[:start] + "\n" + "\n".join(body) + "\n" + text[end:])


if __name__ == "__main__":
    main()
