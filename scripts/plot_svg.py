#!/usr/bin/env python3
"""Line plots of CSV columns as SVG, with the standard library only.

  python3 scripts/plot_svg.py DATA.csv --x COL --y COL[,COL...] [--group COL[,COL...]]
      [--where COL!=VALUE] [--logx] [--logy] [--title T] [--xlabel X] [--ylabel Y] -o OUT.svg

One line per y column and per distinct value of the --group columns; rows whose --where test
fails are left out.
"""
import argparse
import csv
import math

WIDTH, HEIGHT = 760, 400
LEFT, RIGHT, TOP, BOTTOM = 70, 250, 40, 50
COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
          "#7f7f7f", "#bcbd22", "#17becf"]


def load(path, where):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for test in where:
        col, value = test.split("!=")
        rows = [r for r in rows if r[col] != value]
    return rows


def series(rows, x, ys, group):
    lines = {}
    for r in rows:
        key = " ".join(r[g] if i == 0 else "%s %s" % (g, r[g]) for i, g in enumerate(group))
        for y in ys:
            name = (key + " " + y if len(ys) > 1 else key or y).strip()
            lines.setdefault(name, []).append((float(r[x]), float(r[y])))
    return {name: sorted(points) for name, points in lines.items()}


def axis(lo, hi, log):
    """Maps data to [0, 1] and gives tick values."""
    if log:
        lo, hi = math.log10(lo), math.log10(hi)
        steps = (1,) if hi - lo > 2 else (1, 2, 5)  # 1-2-5 ticks over few decades
        ticks = [m * 10 ** e for e in range(math.floor(lo), math.ceil(hi) + 1) for m in steps]
        return (lambda v: (math.log10(v) - lo) / (hi - lo or 1)), ticks
    span = hi - lo or 1
    step = 10 ** math.floor(math.log10(span / 5))
    step *= 2 if span / step > 10 else 1
    first = math.floor(lo / step) * step
    ticks = [first + i * step for i in range(int((hi - first) / step) + 2) if first + i * step <= hi + 1e-12]
    return (lambda v: (v - lo) / span), ticks


def label(v):
    return ("%g" % v) if abs(v) < 1e5 else ("%.0e" % v)


def plot(lines, args):
    xs = [p[0] for pts in lines.values() for p in pts]
    ys = [p[1] for pts in lines.values() for p in pts]
    positive = [v for v in ys if v > 0]
    ylo = min(positive) if args.logy else min(0, min(ys))
    fx, xticks = axis(min(xs), max(xs), args.logx)
    fy, yticks = axis(ylo, max(ys), args.logy)
    w, h = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM
    px = lambda v: LEFT + w * fx(v)
    py = lambda v: TOP + h * (1 - fy(v))
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'font-family="sans-serif" font-size="12">' % (WIDTH, HEIGHT),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="22" font-size="14">%s</text>' % (LEFT, args.title)]
    for t in xticks:
        if min(xs) <= t <= max(xs):
            out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (px(t), TOP, px(t), TOP + h))
            out.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' % (px(t), TOP + h + 16, label(t)))
    for t in yticks:
        if ylo <= t <= max(ys):
            out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (LEFT, py(t), LEFT + w, py(t)))
            out.append('<text x="%d" y="%.1f" text-anchor="end">%s</text>' % (LEFT - 6, py(t) + 4, label(t)))
    out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>' % (LEFT, TOP, w, h))
    out.append('<text x="%d" y="%d" text-anchor="middle">%s</text>' % (LEFT + w / 2, HEIGHT - 10, args.xlabel or args.x))
    out.append('<text transform="translate(16 %d) rotate(-90)" text-anchor="middle">%s</text>' % (TOP + h / 2, args.ylabel))
    for i, (name, pts) in enumerate(sorted(lines.items())):
        color = COLORS[i % len(COLORS)]
        pts = [(x, y) for x, y in pts if y > 0 or not args.logy]
        path = " ".join("%.1f,%.1f" % (px(x), py(y)) for x, y in pts)
        out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (path, color))
        for x, y in pts:
            out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (px(x), py(y), color))
        ly = TOP + 10 + 18 * i
        out.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>' % (LEFT + w + 12, ly, LEFT + w + 32, ly, color))
        out.append('<text x="%d" y="%d">%s</text>' % (LEFT + w + 38, ly + 4, name))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv")
    parser.add_argument("--x", required=True)
    parser.add_argument("--y", required=True)
    parser.add_argument("--group", default="")
    parser.add_argument("--where", action="append", default=[])
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    parser.add_argument("--title", default="")
    parser.add_argument("--xlabel", default="")
    parser.add_argument("--ylabel", default="")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    rows = load(args.csv, args.where)
    group = [g for g in args.group.split(",") if g]
    lines = series(rows, args.x, args.y.split(","), group)
    with open(args.output, "w") as f:
        f.write(plot(lines, args))
    print("wrote", args.output)


if __name__ == "__main__":
    main()
