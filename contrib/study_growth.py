#!/usr/bin/python3
"""Fatigue growth studies (doc/benchmarks.md Case 9), printed as markdown tables
for doc/verification.md and doc/performance.md.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_growth.py paris [--jobs 2]
    /usr/bin/python3 contrib/study_growth.py advance
    /usr/bin/python3 contrib/study_growth.py cost [--runs 3]
    /usr/bin/python3 contrib/study_growth.py dcb [--jobs 2] [--update NAME]
    /usr/bin/python3 contrib/study_growth.py kink [--jobs 2]

`paris`: prm/benchmarks/paris_center_2d.prm (Griffith centre crack,
a0 = 1 mm -> af = 10 mm, closed form 776,634 cycles) for several values of
Propagation/Maximum advance: the cycles, their error, the number of steps,
the cells (first and largest over the run) and the wall time; then the same
crack in a plate 50 mm wide (a/b from 0.04 to 0.4), whose reference is the
quadrature of the Paris law with Tada's finite-width factor (744,562.39
cycles): there K^2 is not linear in a and the cycles converge with the
advance.

`advance`: the same crack from a = 1 to 2 mm with Maximum advance from 0.1
to 5 front cells: the cycles against the closed form (332,671 cycles).

`dcb`: prm/benchmarks/dcb_2d.prm (doc/benchmarks.md Case 11) for the three
initial kinks, with explicit and predictor-corrector directions and Maximum
advance 0.1, 0.05 and 0.025 on front cells of 0.012, and at 0.05 on cells
half as large (both directions): the height of the path at x = 4.6, 5.0 and 5.4 (the ordering
of the kinks, the convergence in advance and mesh), where each run ended
and why, and the figure doc/figures/dcb_paths.png. `--update` selects the
level-set update method (Propagation/Level set update/Model name; default
geometric); other methods draw doc/figures/dcb_paths_<method>.png.

`kink`: K_II / K_I at the tip of a kink of 10 degrees and length s at the
end of the DCB's crack, on meshes refined around it (crowns of 2 to 4
cells): a kink shorter than the crowns is read wrong under the beam's
T-stress.

`cost`: the wall time of each phase of a step (solve, assembly, K, level-set
update, refinement, checkpoint, output) on the 2D benchmark and on a coarse
3D penny, median over --runs runs of the whole scene.
"""
import argparse
import concurrent.futures
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import run_xcrack, top  # noqa: E402

CENTER = os.path.join(top, "prm", "benchmarks", "paris_center_2d.prm")
INFINITE = 776634.444
TADA_W50 = 744562.39

# The plate 50 mm wide: the same crack, mesh and law.
FINITE = """
subsection Mesh
  set Lower corner = -0.025, -0.05
  set Upper corner = 0.025, 0.05
  set Subdivisions = 4, 8
end
subsection Boundary conditions
  set Neumann       = 2: 0; -100 | 3: 0; 100
  set Pinned points = 0, -0.05: xy | 0, 0.05: x
end
subsection Fracture parameters
  set Reference K = 100*sqrt(pi*abs(x))*(1 - 0.025*(abs(x)/0.025)^2 + 0.06*(abs(x)/0.025)^4)*sqrt(1/cos(pi*abs(x)/0.05)); 0
end
subsection Mesh refinement
  set Number of meshes = 7
  set Maximum level    = 6
end
"""


def run(extra, advance, work):
    text = (f"include {CENTER}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            f"subsection Propagation\n  set Maximum advance = {advance}\n"
            "  set Number of steps = 400\nend\n" + extra)
    start = time.time()
    rows = run_xcrack(text, work)
    return rows, time.time() - start


def paris(args):
    advances = [2e-3, 1e-3, 5e-4, 2.5e-4]
    for title, extra, reference in [
            ("infinite plate (1 m wide), closed form 776,634.444 cycles", "",
             INFINITE),
            ("plate 50 mm wide, Tada's factor by quadrature: 744,562.39 "
             "cycles", FINITE, TADA_W50)]:

        def one(advance):
            with tempfile.TemporaryDirectory() as work:
                return advance, run(extra, advance, work)

        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = dict(pool.map(one, advances))
        print(f"\n{title}\n")
        print("| Maximum advance (mm) | steps | cycles | error | cells "
              "(first, largest) | wall (s) |")
        print("|---|---|---|---|---|---|")
        for advance in advances:
            rows, wall = results[advance]
            steps = [r for r in rows if r["mesh"] == "0" and int(r["step"]) > 0]
            last = rows[-1]
            n = float(last["cycles"])
            cells = [int(r["cells"]) for r in rows
                     if int(r["step"]) > 0 or r is rows[-1]]
            first = [int(r["cells"]) for r in rows if int(r["step"]) == 0][-1]
            print(f"| {advance * 1e3:g} | {len(steps)} | {n:,.0f} | "
                  f"{(n - reference) / reference:+.2%} | {first}, "
                  f"{max(cells + [first])} | {wall:.0f} |")


def advance(args):
    """The Griffith crack from a = 1 to 2 mm with Maximum advance from 0.1
    to 5 front cells (h = 0.122 mm): the cycles against the closed form."""
    h = 0.125 / 2 ** 10
    a0, af = 1e-3, 2e-3
    coefficient = 1e-11 * (100 * 3.141592653589793 ** 0.5) ** 3
    exact = 2 * (a0 ** -0.5 - af ** -0.5) / coefficient
    print(f"\nGriffith crack a = 1 -> 2 mm, closed form {exact:,.1f} cycles, "
          f"front cells h = {h * 1e3:.3f} mm\n")
    print("| Maximum advance | steps | cycles | error | wall (s) |")
    print("|---|---|---|---|---|")
    for ratio in [0.1, 0.5, 1, 2, 5]:
        with tempfile.TemporaryDirectory() as work:
            rows, wall = run(
                "subsection Termination criteria\n  subsection Crack size\n"
                f"    set Maximum crack size = {2 * af}\n  end\nend\n",
                ratio * h, work)
        steps = [r for r in rows if int(r["step"]) > 0]
        n = float(rows[-1]["cycles"])
        print(f"| {ratio} h | {len(steps)} | {n:,.0f} | "
              f"{(n - exact) / exact:+.2%} | {wall:.0f} |", flush=True)


def tip_path(work):
    """The tip positions of a 2D run in work/out, step by step (of several
    tips, the one nearest to the previous step's)."""
    import csv
    import glob
    import re
    tips = {}
    for path in glob.glob(os.path.join(work, "out", "front_*.csv")):
        match = re.match(r"front_(\d+)\.csv$", os.path.basename(path))
        if match:
            with open(path) as f:
                rows = list(csv.DictReader(f))
            if rows:
                tips[int(match.group(1))] = [(float(r["x"]), float(r["y"]))
                                             for r in rows]
    path = []
    for k in sorted(tips):
        candidates = tips[k]
        if path:
            candidates = sorted(candidates,
                                key=lambda p: math.dist(p, path[-1]))
        path.append(candidates[0])
    return path


def height_at(path, x):
    """y of the path at abscissa x (linear between the tips), or None."""
    for (x0, y0), (x1, y1) in zip(path, path[1:]):
        if x0 <= x <= x1 and x1 > x0:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return None


def dcb(args):
    dcb_prm = os.path.join(top, "prm", "benchmarks", "dcb_2d.prm")
    variants = []
    for kink in ["1.43", "2.86", "5.71"]:
        for integration in ["explicit", "predictor-corrector"]:
            for advance in [0.1, 0.05, 0.025]:
                variants.append((kink, integration, advance, 5))
        for integration in ["explicit", "predictor-corrector"]:
            variants.append((kink, integration, 0.05, 6))

    def one(variant):
        kink, integration, advance, levels = variant
        with tempfile.TemporaryDirectory() as work:
            text = (f"include {dcb_prm}\n"
                    f"set Output directory = {os.path.join(work, 'out')}\n"
                    "subsection Output\n  set Timing summary = false\nend\n"
                    "subsection Cracks\n  subsection Crack 1\n"
                    f"    set File name = {top}/prm/cracks/dcb_kink_{kink}.msh\n"
                    "  end\nend\n"
                    f"subsection Propagation\n  set Maximum advance = {advance}\n"
                    f"  set Direction integration = {integration}\n"
                    "  set Number of steps = 400\n"
                    "  subsection Level set update\n"
                    f"    set Model name = {args.update}\n  end\nend\n"
                    f"subsection Mesh refinement\n  set Number of meshes = {levels + 1}\n"
                    f"  set Maximum level = {levels}\nend\n")
            start = time.time()
            try:
                run_xcrack(text, work)
            except subprocess.CalledProcessError:
                pass  # run.json says why
            with open(os.path.join(work, "out", "run.json")) as f:
                reason = json.load(f)["reason"]
            return variant, (tip_path(work), time.time() - start, reason)

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = dict(pool.map(one, variants))
    print(f"Level-set update: {args.update}\n")
    print("| theta0 (deg) | direction | advance | front cells h | y(4.6) | "
          "y(5.0) | y(5.4) | last tip | end | wall time |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for variant in variants:
        kink, integration, advance, levels = variant
        path, seconds, reason = results[variant]
        end = ("face" if "would leave the body" in reason or
                         "cuts through" in reason else
               "piece of crack" if "piece of crack" in reason else
               "singular" if "singular" in reason else
               "front outside the mesh" if "no cell at the front" in reason else
               reason)
        heights = [height_at(path, x) for x in (4.6, 5.0, 5.4)]
        print(f"| {kink} | {integration} | {advance} | "
              f"{11.8 / 30 / 2 ** levels:.4f} | " +
              " | ".join("-" if y is None else f"{y:.3f}" for y in heights) +
              f" | ({path[-1][0]:.2f}, {path[-1][1]:.2f}) | {end} "
              f"| {seconds:.0f} s |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6.5, 3.5))
    colours = {"1.43": "C0", "2.86": "C1", "5.71": "C2"}
    styles = {("explicit", 0.025): "--", ("predictor-corrector", 0.1): ":",
              ("predictor-corrector", 0.025): "-"}
    for variant, (path, _, _) in results.items():
        kink, integration, advance, levels = variant
        if (integration, advance) not in styles or levels != 5:
            continue
        ax.plot([p[0] for p in path], [p[1] for p in path],
                styles[(integration, advance)], color=colours[kink],
                label=f"{kink} deg, {integration}, advance {advance}")
    ax.set_xlim(3.9, 6.5)
    ax.set_ylim(-0.1, 1.97)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title(f"DCB: tip paths, front cells h = {11.8 / 30 / 32:.4f} "
                 f"(beam top at y = 1.97), {args.update}")
    ax.legend(fontsize=6)
    ax.grid(True, lw=0.3)
    fig.tight_layout()
    name = ("dcb_paths.png" if args.update == "geometric" else
            f"dcb_paths_{args.update.replace(' ', '_')}.png")
    path = os.path.join(top, "doc", "figures", name)
    fig.savefig(path, dpi=120)


def cost(args):
    scenes = {
        "paris_center_2d (2D, Maximum advance 1 mm)": (
            f"include {CENTER}\n", "2D"),
        "penny, 3D (tests/growth_penny_3d, 3 steps)": (
            f"include {os.path.join(top, 'tests', 'sif_penny_3d.prm.in')}\n"
            "subsection Mesh refinement\n  set Maximum level = 2\n"
            "  subsection Front\n    set Coarsening band = 3\n  end\nend\n"
            "subsection Propagation\n  set Number of steps = 3\n"
            "  set Maximum advance = 0.25\n  subsection Growth law\n"
            "    subsection Paris\n      set C = 1e-3\n    end\n  end\nend\n",
            "3D")}
    phases = ["solve", "assemble", "fracture", "levelset", "refine",
              "checkpoint", "output", "setup"]
    for name, (text, _) in scenes.items():
        per_run = []
        for _ in range(args.runs):
            with tempfile.TemporaryDirectory() as work:
                rows = run_xcrack(
                    text + f"set Output directory = {os.path.join(work, 'out')}\n"
                    "subsection Output\n  set Timing summary = false\n"
                    "  set Write vtu = true\nend\n", work)
            growth = [r for r in rows if int(r["step"]) > 0]
            per_run.append({p: sum(float(r.get(f"t_{p}") or 0) for r in growth)
                            / len(growth) for p in phases})
        median = {p: statistics.median(run[p] for run in per_run)
                  for p in phases}
        total = sum(median.values())
        print(f"\n{name}: median of {args.runs} runs, seconds per step\n")
        print("| phase | s per step | share |")
        print("|---|---|---|")
        for p in phases:
            print(f"| {p} | {median[p]:.3f} | {median[p] / total:.1%} |")
        print(f"| total | {total:.3f} | |")


def kink(args):
    dcb_prm = os.path.join(top, "prm", "benchmarks", "dcb_2d.prm")
    lengths = [0.025, 0.05, 0.1, 0.2, 0.4]
    levels = 6
    angle = math.radians(10)

    def one(length):
        with tempfile.TemporaryDirectory() as work:
            # The DCB's crack (from x = -0.5 to 3.94 along y = 0) and a kink.
            points = ([(-0.5, 0.0)] + [(0.5 * i, 0.0) for i in range(8)] +
                      [(3.94, 0.0), (3.94 + length * math.cos(angle),
                                     length * math.sin(angle))])
            mesh = os.path.join(work, "kink.msh")
            with open(mesh, "w") as f:
                f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
                        f"{len(points)}\n")
                for i, (x, y) in enumerate(points):
                    f.write(f"{i + 1} {x!r} {y!r} 0\n")
                f.write(f"$EndNodes\n$Elements\n{len(points) - 1}\n")
                for i in range(len(points) - 1):
                    f.write(f"{i + 1} 1 2 0 1 {i + 1} {i + 2}\n")
                f.write("$EndElements\n")
            text = (f"include {dcb_prm}\n"
                    f"set Output directory = {os.path.join(work, 'out')}\n"
                    "subsection Output\n  set Timing summary = false\nend\n"
                    "subsection Cracks\n  subsection Crack 1\n"
                    f"    set File name = {mesh}\n  end\nend\n"
                    "subsection Propagation\n  set Number of steps = 0\nend\n"
                    f"subsection Mesh refinement\n  set Number of meshes = {levels + 1}\n"
                    f"  set Maximum level = {levels}\nend\n")
            rows = run_xcrack(text, work)
            return length, [float(r["K_II_1"]) / float(r["K_I_1"]) for r in rows]

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        ratios = dict(pool.map(one, lengths))
    shown = range(2, levels + 1)
    print("| kink length s | " + " | ".join(
        f"h = {11.8 / 30 / 2 ** level:.4f}" for level in shown) + " |")
    print("|---|" + "---|" * len(shown))
    for length in lengths:
        print(f"| {length} | " + " | ".join(
            f"{ratios[length][level]:.4f}" for level in shown) + " |")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study",
                        choices=["paris", "advance", "cost", "dcb", "kink"])
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--update", default="geometric",
                        help="the level-set update method of `dcb`")
    args = parser.parse_args()
    {"paris": paris, "advance": advance, "cost": cost, "dcb": dcb,
     "kink": kink}[args.study](args)


if __name__ == "__main__":
    main()
