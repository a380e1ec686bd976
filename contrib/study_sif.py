#!/usr/bin/python3
"""K_I, K_II by the interaction integral on the 2D benchmarks with exact
data (doc/benchmarks.md Cases 1 and 4): error against the exact K per mesh,
its convergence rate next to the energy rate, the independence of the
crowns, and the wall time of the extraction against the solve.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_sif.py [--meshes 6] [--runs 3]

Prints markdown tables (doc/verification.md) and writes
doc/figures/sif_convergence.png.
"""
import argparse
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import run_xcrack, top  # noqa: E402

benchmarks = {
    "Case 1, K_I = 1, K_II = 0.5": "sif_exact_2d.prm",
    "Case 4, beta = 30 deg": "sif_inclined_2d.prm",
}
crowns = [("1, 2", "cells"), ("2, 4", "cells"), ("3, 6", "cells"),
          ("0.2, 0.4", "absolute")]


def run(benchmark, meshes, crown, work):
    text = (f"include {os.path.join(top, 'prm', 'benchmarks', benchmark)}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n"
            f"subsection Fracture parameters\n  set Crown radii = {crown[0]}\n"
            f"  set Crown unit = {crown[1]}\nend\n")
    return run_xcrack(text, work)


def rate(rows, column, r):
    if r == 0:
        return "-"
    h = math.sqrt(float(rows[r - 1]["cells"]) / float(rows[r]["cells"]))
    return "%.2f" % (math.log(float(rows[r - 1][column]) /
                              float(rows[r][column])) / math.log(1 / h))


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", type=int, default=6)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for name, benchmark in benchmarks.items():
            for crown in crowns:
                times = []
                for _ in range(args.runs):
                    rows = run(benchmark, args.meshes, crown, work)
                    times.append([(float(r["t_fracture"]), float(r["t_solve"]))
                                  for r in rows])
                median = [(statistics.median(t[r][0] for t in times),
                           statistics.median(t[r][1] for t in times))
                          for r in range(len(rows))]
                results[(name, crown)] = (rows, median)

    for name in benchmarks:
        rows, median = results[(name, crowns[1])]
        print(f"\n{name}, crowns 2-4 cells\n")
        print("| cells | DoFs | energy error | rate | K_I error | rate | "
              "K_II error | rate | t_K / t_solve |")
        print("|---|---|---|---|---|---|---|---|---|")
        for r, row in enumerate(rows):
            print(f"| {row['cells']} | {row['dofs']} | "
                  f"{float(row['energy_error']):.2e} | "
                  f"{rate(rows, 'energy_error', r)} | "
                  f"{float(row['K_I_error']):.1e} | {rate(rows, 'K_I_error', r)} | "
                  f"{float(row['K_II_error']):.1e} | {rate(rows, 'K_II_error', r)} | "
                  f"{median[r][0] / median[r][1]:.2f} |")
        print(f"\n{name}: K_I on the finest mesh by crown\n")
        print("| crowns | K_I | K_II | K_I error | K_II error |")
        print("|---|---|---|---|---|")
        for crown in crowns:
            last = results[(name, crown)][0][-1]
            print(f"| {crown[0]} ({crown[1]}) | {float(last['K_I_1']):.6f} | "
                  f"{float(last['K_II_1']):.6f} | "
                  f"{float(last['K_I_error']):.1e} | "
                  f"{float(last['K_II_error']):.1e} |")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib missing: no figure)")
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, marker in zip(benchmarks, "os"):
        rows = results[(name, crowns[1])][0]
        dofs = [float(r["dofs"]) for r in rows]
        ax.loglog(dofs, [float(r["K_I_error"]) for r in rows], marker + "-",
                  label=f"{name}: K_I")
        ax.loglog(dofs, [float(r["K_II_error"]) for r in rows], marker + "--",
                  label=f"{name}: K_II")
        ax.loglog(dofs, [float(r["energy_error"]) for r in rows], marker + ":",
                  label=f"{name}: energy")
    ax.loglog([1e3, 1e5], [2e-3, 2e-5], "k-", lw=0.8, label="slope -1 (h^2)")
    ax.set_xlabel("DoFs")
    ax.set_ylabel("relative error")
    ax.set_title("Interaction integral, Q1, geometric enrichment, crowns 2-4 h")
    ax.legend(fontsize=7)
    fig.tight_layout()
    out = os.path.join(top, "doc", "figures", "sif_convergence.png")
    fig.savefig(out, dpi=120)
    print(f"\nwrote {out}")


if __name__ == "__main__":
    main()
