#!/usr/bin/env python3
"""Adaptive refinement on a cracked body (doc/verification.md, "Adaptive
refinement that knows the crack"): the energy error against the DoFs for
each refinement strategy, printed as markdown tables.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_adaptivity.py case1 [--jobs 2]
    /usr/bin/python3 contrib/study_adaptivity.py case1_3d

`case1`: BENCHMARKS.md Case 1 (prm/benchmarks/exact_mode_I_2d.prm, the
exact Williams field of K_I = 1 on the boundary) with topological tip
enrichment (the tip cell's nodes only), where the energy error of uniform
refinement goes like N^(-1/4) and adaptivity must recover Q1's N^(-1/2).
Two meshes: the crack along a row of nodes ending on a node (the
benchmark's mesh), and a crack through the middle of a row of cells with
its tip at a cell's centre (5 x 5 cells). Strategies: global, front
(hand-made, around the tip), kelly (deal.II's indicator, which reads the
crack's opening as error) and residual (ResidualEstimator: the cracks as
boundaries), with fixed-number and fixed-fraction marking. The rate is the
least-squares slope of log(error) against log(DoFs) over the last four
meshes; "uniform at equal DoFs" is the error of global refinement
interpolated (log-log) at the strategy's last DoFs, divided by the
strategy's error.

`case1_3d`: the 3D version (prm/benchmarks/exact_mode_I_3d.prm, a
straight front through a cube), same strategies; optimal is N^(-1/3).
"""
import argparse
import math
import os
import tempfile
from concurrent.futures import ThreadPoolExecutor

from xcrack_runs import run_xcrack, top

TOPOLOGICAL = ("subsection Enrichment\n  set Tip enrichment = topological\n"
               "  set Enrichment radius = 0\nend\n")


def strategy_entries(strategy, fraction=None, marking=None):
    text = f"subsection Mesh refinement\n  set Strategy = {strategy}\n"
    if strategy == "kelly":
        text += f"  subsection Kelly\n    set Refine fraction = {fraction}\n  end\n"
    if strategy == "residual":
        text += (f"  subsection Residual\n    set Marking = {marking}\n"
                 f"    set Refine fraction = {fraction}\n  end\n")
    return text + "end\n"


def run(benchmark, label, entries, meshes, max_level):
    with tempfile.TemporaryDirectory() as work:
        text = (f"include {top}/prm/benchmarks/{benchmark}.prm\n"
                f"set Output directory = {work}/out\n"
                "subsection Output\n  set Timing summary = false\nend\n"
                f"subsection Mesh refinement\n  set Number of meshes = {meshes}\n"
                f"  set Maximum level = {max_level}\nend\n" + entries)
        rows = run_xcrack(text, work)
    return label, [(int(r["dofs"]), float(r["energy_error"]),
                    float(r["K_I_1"]) if "K_I_1" in r else float("nan"))
                   for r in rows]


def slope(points):
    x = [math.log(n) for n, _ in points]
    y = [math.log(e) for _, e in points]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return (sum((a - mx) * (b - my) for a, b in zip(x, y))
            / sum((a - mx) ** 2 for a in x))


def uniform_at(uniform, dofs):
    """log-log interpolation (or extrapolation by the last two) of the
    uniform error at `dofs`."""
    for (n0, e0), (n1, e1) in zip(uniform, uniform[1:]):
        if dofs <= n1 or (n1, e1) == uniform[-1]:
            t = math.log(dofs / n0) / math.log(n1 / n0)
            return math.exp(math.log(e0) + t * math.log(e1 / e0))


def table(results):
    uniform = [(n, e) for n, e, _ in results["global"]]
    print("| strategy | meshes | DoFs (last) | energy error (last) | rate in N "
          "(last 4) | uniform / this at equal DoFs | K_I (last) |")
    print("|---|---|---|---|---|---|---|")
    for label, rows in results.items():
        n, e, k = rows[-1]
        tail = [(a, b) for a, b, _ in rows[-4:]]
        rate = slope(tail) if len(set(a for a, _ in tail)) > 1 else float("nan")
        ratio = uniform_at(uniform, n) / e
        print(f"| {label} | {len(rows)} | {n:,} | {e:.3e} | {rate:.2f} | "
              f"{ratio:.2f} | {k:.5f} |")
    print()
    print("Error against DoFs, every mesh:")
    print()
    for label, rows in results.items():
        print(f"- {label}: " + ", ".join(f"{n:,}: {e:.3e}" for n, e, _ in rows))
    print()


def case1(jobs, three_d=False):
    if three_d:
        benchmarks = [("exact_mode_I_3d", "straight front", "")]
        adaptive_meshes, global_meshes, max_level = 9, 4, 8
    else:
        benchmarks = [
            ("exact_mode_I_2d", "crack along a row of nodes", ""),
            ("exact_mode_I_2d", "crack through a row of cells",
             "subsection Mesh\n  set Subdivisions = 5, 5\nend\n")]
        adaptive_meshes, global_meshes, max_level = 14, 7, 12
    for benchmark, title, mesh in benchmarks:
        cases = [("global", strategy_entries("global"), global_meshes),
                 ("front", strategy_entries("front"), adaptive_meshes),
                 ("kelly 0.2", strategy_entries("kelly", 0.2), adaptive_meshes),
                 ("residual, fixed number 0.2",
                  strategy_entries("residual", 0.2, "fixed number"),
                  adaptive_meshes),
                 ("residual, fixed fraction 0.5",
                  strategy_entries("residual", 0.5, "fixed fraction"),
                  adaptive_meshes)]
        with ThreadPoolExecutor(jobs) as pool:
            futures = [pool.submit(run, benchmark, label,
                                   TOPOLOGICAL + mesh + entries, meshes,
                                   max_level)
                       for label, entries, meshes in cases]
            results = dict(f.result() for f in futures)
        print(f"### {benchmark}, {title}, topological enrichment\n")
        table({label: [(n, e, k) for n, e, k in rows]
               for label, rows in results.items()})


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("study", choices=["case1", "case1_3d"])
    parser.add_argument("--jobs", type=int, default=2)
    arguments = parser.parse_args()
    case1(arguments.jobs, arguments.study == "case1_3d")
