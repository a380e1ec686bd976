#!/usr/bin/python3
"""The same growths with each level-set update method, side by side, as a
markdown table for doc/verification/level-set-update.md.

    contrib/build.sh release
    /usr/bin/python3 contrib/compare_level_set_updates.py [--jobs 2]
        [--scenes paris_center_2d,dcb_2d,...] [--methods geometric,crack mesh]

A method may carry entries of its subsection after `@`, relative to
Propagation/Level set update: `upwind@Upwind/Grid spacing=1` runs the
upwind update on a grid of one front-cell edge.

Each shipped scene of prm/benchmarks/ (default: paris_center_2d, dcb_2d,
en_passant_2d, paris_ellipse_3d, mixed_mode_3pb_3d, surface_crack_3d; add
paris_penny_3d, 4 minutes a method) runs once per method (`-s
Propagation/Level set update/Model name=...`). Per run: the steps, the cycles, how it ended, the
wall time, the time of the level-set updates (absolute and as a share of
the wall time), and the distance of its last front to the first method's
front of the same step (the largest over its points of the distance to the
polyline of the other front), in front cells (the diameter the run
prints for its growth level) and absolute. A closed form of the cycles is
given where there is one (paris_center_2d: Griffith, 776,634 cycles;
paris_penny_3d: at the radius of the last crack, from a0 = 1).
"""
import argparse
import concurrent.futures
import csv
import glob
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import top, xcrack  # noqa: E402

def penny_cycles(row):
    """The penny's closed form (doc/verification/growth.md, "Paris law,
    penny crack") from a0 = 1 to the radius sqrt(area / pi) the run's last
    crack has."""
    a = math.sqrt(float(row["crack_size"]) / math.pi)
    return 2 * (1 - a ** -0.5) / (1e-3 * (2 / math.sqrt(math.pi)) ** 3)


# The closed form of the cycles, from the last statistics row.
CLOSED_FORMS = {"paris_center_2d": lambda row: 776634.444,
                "paris_penny_3d": penny_cycles}


def run(scene, method, work):
    """Run the scene with the method into work/out; return what the table
    needs."""
    out = os.path.join(work, "out")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    name, *entries = method.split("@")
    settings = []
    for entry in entries:
        settings += ["-s", f"Propagation/Level set update/{entry}"]
    start = time.time()
    result = subprocess.run(
        [xcrack, "-s", f"Output directory={out}",
         "-s", "Output/Timing summary=false", "-s", "Output/Write vtu=false",
         "-s", f"Propagation/Level set update/Model name={name}"] + settings +
        [os.path.join(top, "prm", "benchmarks", scene + ".prm")],
        env=env, capture_output=True, text=True)
    wall = time.time() - start
    with open(os.path.join(out, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "run.json")) as f:
        reason = json.load(f)["reason"]
    match = re.search(r"diameter ([0-9.eE+-]+)\)", result.stdout)
    fronts = {}
    for path in glob.glob(os.path.join(out, "front_*.csv")):
        m = re.match(r"front_(\d+)(\.\d+)?\.csv$", os.path.basename(path))
        if m:
            with open(path) as f:
                # Per front (its column), its points in order.
                points = {}
                for r in csv.DictReader(f):
                    points.setdefault(r["front"], []).append(
                        tuple(float(r[c]) for c in ("x", "y", "z")))
                points = list(points.values())
            # Of a step on several meshes, the last one.
            key = int(m.group(1))
            if key not in fronts or path > fronts[key][0]:
                fronts[key] = (path, points)
    return {
        "steps": max(int(r["step"]) for r in rows),
        "cycles": float(rows[-1]["cycles"]),
        "last": rows[-1],
        "reason": reason,
        "wall": wall,
        "levelset": sum(float(r["t_levelset"] or 0) for r in rows),
        "h": float(match.group(1)) if match else float("nan"),
        "fronts": {k: v[1] for k, v in fronts.items()},
        "failed": result.returncode != 0,
    }


def short(reason):
    for key, text in (("would leave the body", "tip at the surface"),
                      ("cuts through", "tip at the surface"),
                      ("piece of crack", "piece of crack"),
                      ("reached the surface", "front at the surface"),
                      ("Maximum crack size", "crack size"),
                      ("last step", "last step"),
                      ("singular", "singular system"),
                      ("enriched zones meet", "cracks about to meet"),
                      ("no cell at the front", "front outside the mesh")):
        if key in reason:
            return text
    return reason[:60]


def distance(a, b):
    """The largest distance of a point of the fronts a to the nearest front
    of b, a polyline through its points in their order (a 2D tip: the
    point)."""
    def to_segment(p, u, v):
        e = [y - x for x, y in zip(u, v)]
        length = sum(c * c for c in e)
        w = 0 if length == 0 else max(0, min(1, sum(
            (x - y) * c for x, y, c in zip(p, u, e)) / length))
        return math.dist(p, [x + w * c for x, c in zip(u, e)])

    def to_front(p, front):
        return min([math.dist(p, front[0])] +
                   [to_segment(p, u, v) for u, v in zip(front, front[1:])])
    return max(min(to_front(p, front) for front in b)
               for front in a for p in front)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--scenes", default="paris_center_2d,dcb_2d,"
                        "en_passant_2d,paris_ellipse_3d,mixed_mode_3pb_3d,"
                        "surface_crack_3d")
    parser.add_argument("--methods", default="geometric,crack mesh")
    args = parser.parse_args()
    scenes = args.scenes.split(",")
    methods = args.methods.split(",")

    def one(job):
        scene, method = job
        with tempfile.TemporaryDirectory() as work:
            return job, run(scene, method, work)

    jobs = [(s, m) for s in scenes for m in methods]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = dict(pool.map(one, jobs))

    print("| scene | method | steps | cycles | closed form | end | "
          "last front to the first method's | wall | level-set update |")
    print("|---|---|---|---|---|---|---|---|---|")
    for scene in scenes:
        first = results[(scene, methods[0])]
        for method in methods:
            r = results[(scene, method)]
            closed = CLOSED_FORMS.get(scene)
            closed = (f"{(r['cycles'] / closed(r['last']) - 1) * 100:+.2f} %"
                      if closed else "-")
            gap = "-"
            if method != methods[0]:
                common = min(r["steps"], first["steps"])
                if common in r["fronts"] and common in first["fronts"]:
                    d = distance(r["fronts"][common], first["fronts"][common])
                    gap = (f"{d / r['h']:.2f} cells ({d:.3g}) at step "
                           f"{common}")
            print(f"| {scene} | {method} | {r['steps']} | {r['cycles']:.5g} "
                  f"| {closed} | {short(r['reason'])} | {gap} | "
                  f"{r['wall']:.0f} s | {r['levelset']:.2f} s "
                  f"({r['levelset'] / r['wall'] * 100:.1f} %) |")


if __name__ == "__main__":
    main()
