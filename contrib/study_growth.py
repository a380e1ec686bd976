#!/usr/bin/env python3
"""Fatigue growth studies (BENCHMARKS.md Case 9), printed as markdown tables
for doc/verification.md and doc/performance.md.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_growth.py paris [--jobs 2]
    /usr/bin/python3 contrib/study_growth.py cost [--runs 3]

`paris`: prm/benchmarks/paris_center_2d.prm (Griffith centre crack,
a0 = 1 mm -> af = 10 mm, closed form 776,634 cycles) for several values of
Propagation/Maximum advance: the cycles, their error, the number of steps,
the cells (first and largest over the run) and the wall time; then the same
crack in a plate 50 mm wide (a/b from 0.04 to 0.4), whose reference is the
quadrature of the Paris law with Tada's finite-width factor (744,562.39
cycles): there K^2 is not linear in a and the cycles converge with the
advance.

`cost`: the wall time of each phase of a step (solve, assembly, K, level-set
update, refinement, checkpoint, output) on the 2D benchmark and on a coarse
3D penny, median over --runs runs of the whole scene.
"""
import argparse
import concurrent.futures
import os
import statistics
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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("study", choices=["paris", "cost"])
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    {"paris": paris, "cost": cost}[args.study](args)


if __name__ == "__main__":
    main()
