#!/usr/bin/python3
"""The level-set update methods as the advance shrinks from 5 to 0.1 front
cells: markdown tables for doc/verification/level-set-update.md.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_level_set_accuracy.py [--jobs 2]
        [--methods geometric,crack mesh,upwind,simplex] [--fractions 0.1,0.5,1,2,5]

Three scenes, each run per method and per advance a = f h (h the edge of
the cells at the front):

- kink (2D): the inclined centre crack of prm/benchmarks/sif_inclined_2d.prm
  on its fourth mesh (h = 1/16), one step by the maximum hoop stress (-43
  degrees). The kink the new tips show (the angle of the tip's move to the
  old direction, +-30 degrees) against the criterion's, and the advance
  they show against the one asked for.
- straight (3D): the straight front of prm/benchmarks/exact_mode_I_3d.prm
  (the Williams field on the boundary, K_I uniform) on its second mesh (h
  = 1/4), the body [-1, 5] x [-1, 1]^2 shifted by (0.0123, 0.0371) so that
  neither the crack plane nor the front lies on nodes, three steps: the
  front should stay straight and in its plane. Its spread along x and its
  largest |y|, in h.
- penny (3D): the coarse penny of tests/sif_penny_3d.prm.in (front cells
  of edge 1/4), three steps: the radius scatter of the last front (largest
  less smallest radius of its points), in h.

Per run also the level sets' quality after the last update, from the
solution file of the last step: in the cells whose centre lies within 4 h
of the front and farther than h (the gradients at the front are singular
by construction), the largest and mean | |grad lsn| - 1 | and |grad lsn .
grad lst| / |grad lst| (the Q1 gradients at the cells' centres).
"""
import argparse
import concurrent.futures
import glob
import math
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import read_csv, read_vtu, top, xcrack  # noqa: E402

SCENES = {
    "kink": {"prm": "prm/benchmarks/sif_inclined_2d.prm", "h": 0.0625,
             "steps": 1, "entries": ["Mesh refinement/Number of meshes=4"]},
    "straight": {"prm": "prm/benchmarks/exact_mode_I_3d.prm", "h": 0.25,
                 "steps": 3,
                 "entries": ["Mesh refinement/Number of meshes=2",
                             "Mesh/Lower corner=-1.0123, -1.0371, -1",
                             "Mesh/Upper corner=4.9877, 0.9629, 1",
                             "Mesh/Subdivisions=12, 4, 4"]},
    "penny": {"prm": "tests/sif_penny_3d.prm.in", "h": 0.25, "steps": 3,
              "entries": ["Mesh refinement/Maximum level=2",
                          "Mesh refinement/Front/Coarsening band=3"]},
}


def prm_file(scene, work):
    """The scene's parameter file (a test's template with its include
    resolved)."""
    path = os.path.join(top, SCENES[scene]["prm"])
    if not path.endswith(".in"):
        return path
    with open(path) as f:
        text = f.read().replace("@SOURCE_DIR@", os.path.join(top, "tests"))
    out = os.path.join(work, "scene.prm")
    with open(out, "w") as f:
        f.write(text)
    return out


def last_front(out, step):
    """The points (x, y, z, angle, advance) of the front file of @p step
    (of its last mesh), per front."""
    files = sorted(glob.glob(os.path.join(out, f"front_{step:03d}*.csv")))
    fronts = {}
    for row in read_csv(files[-1]):
        fronts.setdefault(row["front"], []).append(row)
    return list(fronts.values())


def field_quality(out, step, h, near):
    """Max and mean | |grad lsn| - 1 | and |grad lsn . grad lst| / |grad
    lst| over the cells of the solution file of @p step whose centre is
    within 4 h of the front and farther than h, the distance given by
    @p near (a function of the centre)."""
    files = sorted(glob.glob(os.path.join(out, f"solution-{step:03d}*.vtu")))
    defects, products = [], []
    for path in files:
        data = read_vtu(path, ("Points", "connectivity", "offsets", "lsn",
                               "lst"))
        points, lsn, lst = data["Points"], data["lsn"], data["lst"]
        start = 0
        for end in data["offsets"]:
            cell = [int(v) for v in data["connectivity"][start:end]]
            start = int(end)
            xs = [points[3 * v:3 * v + 3] for v in cell]
            dim = 2 if all(abs(x[2] - xs[0][2]) < 1e-12 for x in xs) else 3
            centre = [sum(x[d] for x in xs) / len(xs) for d in range(3)]
            distance = near(centre)
            if not h < distance < 4 * h:
                continue
            grad_n, grad_t = [], []
            for d in range(dim):
                lo = min(x[d] for x in xs)
                hi = max(x[d] for x in xs)
                top_ = [v for v, x in zip(cell, xs) if x[d] > (lo + hi) / 2]
                bottom = [v for v, x in zip(cell, xs) if x[d] <= (lo + hi) / 2]

                def mean(field, vertices):
                    return sum(field[v] for v in vertices) / len(vertices)
                grad_n.append((mean(lsn, top_) - mean(lsn, bottom)) / (hi - lo))
                grad_t.append((mean(lst, top_) - mean(lst, bottom)) / (hi - lo))
            norm_n = math.sqrt(sum(g * g for g in grad_n))
            norm_t = math.sqrt(sum(g * g for g in grad_t))
            defects.append(abs(norm_n - 1))
            if norm_t > 0:
                products.append(abs(sum(a * b for a, b in zip(grad_n, grad_t)))
                                / norm_t / max(norm_n, 1e-300))
    def stats(values):
        return (max(values), sum(values) / len(values)) if values else (
            float("nan"), float("nan"))
    return stats(defects), stats(products)


def run(scene, method, fraction):
    """One run: the scene's measures."""
    spec = SCENES[scene]
    h = spec["h"]
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        command = [xcrack, "-s", f"Output directory={out}",
                   "-s", "Output/Timing summary=false",
                   "-s", "Output/Write vtu=true",
                   "-s", f"Propagation/Number of steps={spec['steps']}",
                   "-s", f"Propagation/Maximum advance={fraction * h}",
                   "-s", f"Propagation/Level set update/Model name={method}"]
        for entry in spec["entries"] + ["Propagation/Growth law/Paris/C=1",
                                        "Propagation/Growth law/Paris/m=2"]:
            command += ["-s", entry]
        command.append(prm_file(scene, work))
        start = time.time()
        result = subprocess.run(command, capture_output=True, text=True,
                                env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
        wall = time.time() - start
        rows = read_csv(os.path.join(out, "statistics.csv"))
        steps = max(int(r["step"]) for r in rows)
        r = {"steps": steps, "wall": wall, "failed": result.returncode != 0,
             "levelset": sum(float(x["t_levelset"] or 0) for x in rows)}
        if steps < spec["steps"]:
            r["end"] = result.stdout.strip().splitlines()[-1][:80]
            return r
        front = last_front(out, steps)
        points = [(float(p["x"]), float(p["y"]), float(p["z"]))
                  for f in front for p in f]

        def near(x):
            return min(math.dist(x, p) for p in points)
        if scene == "kink":
            first = last_front(out, 0)
            kinks, advances = [], []
            for before, after in zip(first, front):
                p0, p1 = before[0], after[0]
                x0 = (float(p0["x"]), float(p0["y"]))
                x1 = (float(p1["x"]), float(p1["y"]))
                # The old direction: away from the crack's centre.
                e1 = (x0[0] / math.hypot(*x0), x0[1] / math.hypot(*x0))
                move = (x1[0] - x0[0], x1[1] - x0[1])
                # The kink from e1 towards e2 = e1 turned by +90 degrees.
                shown = math.atan2(e1[0] * move[1] - e1[1] * move[0],
                                   e1[0] * move[0] + e1[1] * move[1])
                kinks.append(abs(shown - float(p0["angle"])))
                advances.append(math.hypot(*move) / float(p0["advance"]) - 1)
            r["kink"] = math.degrees(max(kinks))
            r["advance"] = max(abs(a) for a in advances)
        elif scene == "straight":
            xs = [p[0] for p in points]
            r["spread"] = (max(xs) - min(xs)) / h
            r["plane"] = max(abs(p[1]) for p in points) / h
        else:
            radii = [math.hypot(p[0], p[1]) for p in points]
            r["scatter"] = (max(radii) - min(radii)) / h
            r["radius"] = sum(radii) / len(radii)
        r["defect"], r["product"] = field_quality(out, steps, h, near)
        return r


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--methods", default="geometric,crack mesh,upwind,simplex")
    parser.add_argument("--fractions", default="0.1,0.5,1,2,5")
    parser.add_argument("--scenes", default="kink,straight,penny")
    args = parser.parse_args()
    methods = args.methods.split(",")
    fractions = [float(f) for f in args.fractions.split(",")]
    scenes = args.scenes.split(",")
    jobs = [(s, m, f) for s in scenes for m in methods for f in fractions]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = dict(zip(jobs, pool.map(lambda j: run(*j), jobs)))

    measure = {"kink": "kink error (deg) | advance error",
               "straight": "front spread along x (h) | largest abs(y) (h)",
               "penny": "radius scatter (h) | mean radius"}
    for scene in scenes:
        print(f"\n{scene}:\n")
        print(f"| method | advance (h) | {measure[scene]} | max, mean "
              "abs(abs(grad lsn) - 1) | max, mean grad lsn . grad lst | "
              "wall | update |")
        print("|---|---|---|---|---|---|---|---|")
        for method in methods:
            for f in fractions:
                r = results[(scene, method, f)]
                if "end" in r:
                    print(f"| {method} | {f:g} | ended at step {r['steps']}: "
                          f"{r['end']} | | | | {r['wall']:.0f} s | |")
                    continue
                if scene == "kink":
                    a, b = f"{r['kink']:.2f}", f"{r['advance'] * 100:.1f} %"
                elif scene == "straight":
                    a, b = f"{r['spread']:.3f}", f"{r['plane']:.3f}"
                else:
                    a, b = f"{r['scatter']:.3f}", f"{r['radius']:.4f}"
                print(f"| {method} | {f:g} | {a} | {b} | "
                      f"{r['defect'][0]:.3f}, {r['defect'][1]:.4f} | "
                      f"{r['product'][0]:.3f}, {r['product'][1]:.4f} | "
                      f"{r['wall']:.0f} s | {r['levelset']:.2f} s |")


if __name__ == "__main__":
    main()
