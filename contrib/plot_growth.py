#!/usr/bin/env python3
"""Figures of a fatigue growth run: the crack size against the load cycles,
a(N), and the path of the crack (2D: the tips of every step; 3D: the
successive fronts seen along the crack plane's normal).

    /usr/bin/python3 contrib/plot_growth.py output/demo

Writes growth_cycles.png and growth_path.png next to the run's files and
prints the table of the steps. It reads statistics.csv (one row per solve;
the last row of each step is its state) and front_<step>.csv.
"""
import argparse
import csv
import os
import re

from xcrack_runs import run_files


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def steps(directory):
    """The last statistics row of each step, in order."""
    rows = read(os.path.join(directory, "statistics.csv"))
    last = {}
    for r in rows:
        last[int(r["step"])] = r
    return [last[s] for s in sorted(last)]


def fronts(directory):
    """{step: rows of front_<step>.csv} for the steps with one mesh, and the
    last mesh of a step solved on several."""
    result = {}
    for path in run_files(directory, r"front_.*\.csv"):
        match = re.match(r"front_(\d+)(\.\d+)?\.csv$", os.path.basename(path))
        if match:
            result[int(match.group(1))] = read(path)
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory", help="the run's output directory")
    parser.add_argument("--view", default="",
                        help="3D: the two axes of the fronts' figure, e.g. "
                        "xz (default: the two of largest extent)")
    parser.add_argument("--path-figure", default="",
                        help="where to write the figure of the path or "
                        "fronts (default: DIRECTORY/growth_path.png)")
    args = parser.parse_args()
    table = steps(args.directory)
    if not table or "crack_size" not in table[0]:
        raise SystemExit(f"{args.directory}/statistics.csv has no crack_size: "
                         "was it a run with a crack?")
    print("| step | cycles | crack size | K_max | advance |")
    print("|---|---|---|---|---|")
    for r in table:
        print(f"| {r['step']} | {float(r.get('cycles') or 0):.6g} | "
              f"{float(r['crack_size']):.6g} | {r.get('K_max', '')} | "
              f"{r.get('advance', '')} |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib missing: no figures; /usr/bin/python3 has it)")
        return

    cycles = [float(r.get("cycles") or 0) for r in table]
    size = [float(r["crack_size"]) for r in table]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.plot(cycles, size, "o-")
    ax.set_xlabel("load cycles N")
    ax.set_ylabel("crack size (2D: length, 3D: area)")
    ax.grid(True, lw=0.3)
    fig.tight_layout()
    path = os.path.join(args.directory, "growth_cycles.png")
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")

    by_step = fronts(args.directory)
    if not by_step:
        return
    fig, ax = plt.subplots(figsize=(5.5, 5))
    three_d = any(float(r["z"]) != 0 for rows in by_step.values() for r in rows)
    if not three_d:
        # The tips of every step, joined tip by tip.
        tips = {}
        for step in sorted(by_step):
            for r in by_step[step]:
                tips.setdefault(r["front"], []).append((float(r["x"]), float(r["y"])))
        for name, points in tips.items():
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-", ms=3,
                    label=f"tip {name}")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    else:
        # The fronts seen along the mean normal of the crack: the two axes
        # of largest extent of the front points.
        points = [(float(r["x"]), float(r["y"]), float(r["z"]))
                  for rows in by_step.values() for r in rows]
        spans = [max(p[d] for p in points) - min(p[d] for p in points)
                 for d in range(3)]
        a, b = sorted(range(3), key=lambda d: -spans[d])[:2]
        if args.view:
            if len(args.view) != 2 or any(c not in "xyz" for c in args.view):
                raise SystemExit(f"--view {args.view}: two of x, y, z")
            a, b = "xyz".index(args.view[0]), "xyz".index(args.view[1])
        for step in sorted(by_step):
            rows = by_step[step]
            for front in sorted({r["front"] for r in rows}):
                line = [r for r in rows if r["front"] == front]
                ax.plot([float(r["xyz"[a]]) for r in line],
                        [float(r["xyz"[b]]) for r in line], "-",
                        lw=0.8, color=plt.cm.viridis(step / max(by_step)))
        ax.set_xlabel("xyz"[a])
        ax.set_ylabel("xyz"[b])
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.3)
    ax.set_title("crack path" if not three_d else
                 f"fronts, step by step (0 to {max(by_step)}, dark to light)")
    if not three_d:
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = args.path_figure or os.path.join(args.directory, "growth_path.png")
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
