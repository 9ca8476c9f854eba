#!/usr/bin/env python3
"""Measures the angular method the way Thakur, Cheng & Miura report it and writes CSV files
for docs/methods/angular.md and scripts/plot_svg.py (standard library only).

  python3 scripts/angular_measure.py [--shadowkit build/shadowkit] [--out docs/images]

results.csv      per scene and light: polygons, R, table construction, lookups, lookup time,
                 raytrace's shade time in the same run (the paper's results table)
scalability.csv  cube fields of 125 to 8000 cubes: table time and memory against polygons
                 (the paper's scalability simulation, Sec. 9 / Fig. 10)
resolution.csv   interior mismatch against raytrace and table time for R = 99, 299, 599,
                 1080, 2160 and automatic (Sec. 3, Figs. 6-7)
"""
import argparse
import csv
import json
import os
import subprocess

RESULT_SCENES = ["cubes", "tetra:3", "tetra:4", "room", "coil", "holed", "hole-like",
                 "examples/default.json", "examples/room.json", "examples/three-lights.json",
                 "examples/open-meshes.json"]
CUBE_COUNTS = [125, 500, 1000, 2000, 4000, 8000]
SWEEP_SCENES = ["cubes:2000", "examples/default.json", "table", "coil"]
RESOLUTIONS = [99, 299, 599, 1080, 2160, 0]


def run_json(shadowkit, args):
    out = subprocess.run([shadowkit] + args + ["--json"], check=True, capture_output=True,
                         text=True).stdout
    return json.loads(out)


def polygons(shadowkit, scene):
    return run_json(shadowkit, ["info", scene])["polygons"]


def bench(shadowkit, scene, repeats):
    """Per light: (raytrace record, angular record), timed in the same run."""
    records = run_json(shadowkit, ["bench", scene, "--methods", "raytrace,angular",
                                   "--repeats", str(repeats)])
    by = {}
    for r in records:
        by.setdefault(r["light"], {})[r["method"]] = r
    return [(by[l]["raytrace"], by[l]["angular"]) for l in sorted(by)]


def write(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    print("wrote", path)


def results(shadowkit, out, repeats):
    rows = []
    for scene in RESULT_SCENES:
        n = polygons(shadowkit, scene)
        for light, (rt, ang) in enumerate(bench(shadowkit, scene, repeats)):
            c = ang["counters"]
            rows.append([scene, light, n, int(c["theta_resolution"]), round(ang["build_ms"], 2),
                         int(c["lookup_calls"]), round(ang["shade_ms"], 2),
                         round(rt["shade_ms"], 2), round(ang["shade_ms"] / rt["shade_ms"], 2),
                         int(c["table_pairs"]), round(c["table_bytes"] / 1e6, 3)])
    write(os.path.join(out, "angular_results.csv"),
          ["scene", "light", "polygons", "R", "table_ms", "lookup_calls", "lookup_ms",
           "raytrace_shade_ms", "lookup_over_raytrace", "pairs", "memory_MB"], rows)


def scalability(shadowkit, out, repeats):
    rows = []
    for count in CUBE_COUNTS:
        scene = "cubes:%d" % count
        n = polygons(shadowkit, scene)
        rt, ang = bench(shadowkit, scene, repeats)[0]
        c = ang["counters"]
        rows.append([count, n, int(c["theta_resolution"]), round(ang["build_ms"], 2),
                     round(ang["shade_ms"], 2), round(rt["shade_ms"], 2),
                     int(c["lookup_calls"]), int(c["table_pairs"]), int(c["saturated_pairs"]),
                     round(c["table_bytes"] / 1e6, 3)])
    write(os.path.join(out, "angular_scalability.csv"),
          ["cubes", "polygons", "R", "table_ms", "lookup_ms", "raytrace_shade_ms",
           "lookup_calls", "pairs", "saturated_pairs", "memory_MB"], rows)


def resolution(shadowkit, out):
    rows = []
    for scene in SWEEP_SCENES:
        for r in RESOLUTIONS:
            records = run_json(shadowkit, ["compare", scene, "--methods", "angular",
                                           "--set", "angular.resolution=%d" % r])
            for rec in records:
                rows.append([scene, rec["light"], "auto" if r == 0 else r,
                             int(rec["counters"]["theta_resolution"]),
                             round(rec["mismatch_interior_pct"], 4), round(rec["build_ms"], 2)])
    write(os.path.join(out, "angular_resolution.csv"),
          ["scene", "light", "setting", "R", "mismatch_interior_pct", "table_ms"], rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shadowkit", default="build/shadowkit")
    parser.add_argument("--out", default="docs/images")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--only", choices=["results", "scalability", "resolution"])
    args = parser.parse_args()
    if args.only in (None, "results"):
        results(args.shadowkit, args.out, args.repeats)
    if args.only in (None, "scalability"):
        scalability(args.shadowkit, args.out, args.repeats)
    if args.only in (None, "resolution"):
        resolution(args.shadowkit, args.out)


if __name__ == "__main__":
    main()
