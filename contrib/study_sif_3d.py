#!/usr/bin/env python3
"""K along 3D fronts (BENCHMARKS.md Cases 5 and 6): the error of each K
against the reference per cycle of the benchmarks, and the choice of the
smoothing along the front (Legendre degree, Lagrange, regularised
Lagrange, number of front segments) on the penny at a given cycle, with
the wall time of the extraction next to the solve.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_sif_3d.py convergence [--cycles 6]
    /usr/bin/python3 contrib/study_sif_3d.py smoothing [--cycles 5] [--runs 1]

Prints markdown tables (doc/verification.md); `convergence` also writes
doc/figures/sif_convergence_3d.png. A six-cycle run of one benchmark takes
about five minutes on one core.
"""
import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import run_xcrack, top  # noqa: E402

benchmarks = {
    "penny, tension": "sif_penny_3d.prm",
    "penny, shear": "sif_penny_shear_3d.prm",
    "ellipse b/a = 0.5": "sif_ellipse_3d.prm",
}
smoothings = [
    ("legendre", 0, 0), ("legendre", 2, 0), ("legendre", 5, 0),
    ("legendre", 7, 0), ("lagrange", 0, 0), ("lagrange", 0, 50),
    ("lagrange regularized", 0, 0), ("lagrange regularized", 0, 50),
]


def run(benchmark, cycles, work, smoothing=None):
    text = (f"include {os.path.join(top, 'prm', 'benchmarks', benchmark)}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            f"subsection Mesh refinement\n  set Number of cycles = {cycles}\nend\n")
    if smoothing:
        text += ("subsection Fracture parameters\n"
                 f"  set Smoothing = {smoothing[0]}\n"
                 f"  set Legendre degree = {smoothing[1]}\n"
                 f"  set Front segments = {smoothing[2]}\nend\n")
    return run_xcrack(text, work)


def convergence(args):
    table = {}
    with tempfile.TemporaryDirectory() as work:
        for name, benchmark in benchmarks.items():
            rows = run(benchmark, args.cycles, work)
            table[name] = rows
            print(f"\n{name} ({benchmark})\n")
            print("| cycle | DoFs | K_I error | K_II error | K_III error | "
                  "t_solve (s) | t_fracture (s) |")
            print("|---|---|---|---|---|---|---|")
            for r in rows:
                print(f"| {r['step']} | {r['dofs']} | "
                      f"{float(r['K_I_error']):.2e} | "
                      f"{float(r['K_II_error']):.2e} | "
                      f"{float(r['K_III_error']):.2e} | "
                      f"{float(r['t_solve']):.1f} | "
                      f"{float(r['t_fracture']):.1f} |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, rows in table.items():
        dofs = [float(r["dofs"]) for r in rows]
        mode = "K_II_error" if "shear" in name else "K_I_error"
        ax.loglog(dofs, [float(r[mode]) for r in rows], "o-",
                  label=f"{name}: {mode.replace('_error', '')}")
    ax.axhline(0.01, color="gray", lw=0.8, ls=":")
    ax.set_xlabel("DoFs")
    ax.set_ylabel("max relative error along the front")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    path = os.path.join(top, "doc", "figures", "sif_convergence_3d.png")
    fig.savefig(path, dpi=120)
    print(f"\nwrote {path}")


def smoothing(args):
    print(f"\npenny (sif_penny_3d.prm), {args.cycles} cycles, last cycle\n")
    print("| smoothing | degree | front segments | nodes | K_I error | "
          "K_I min | K_I max | t_fracture (s, median) | t_solve (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for choice in smoothings:
            times, rows = [], None
            for _ in range(args.runs):
                rows = run("sif_penny_3d.prm", args.cycles, work, choice)
                times.append(float(rows[-1]["t_fracture"]))
            last = rows[-1]
            with open(os.path.join(work, "out",
                                   f"front_{int(last['step']):03d}.csv")) as f:
                nodes = len(f.readlines()) - 1
            print(f"| {choice[0]} | {choice[1] if choice[0] == 'legendre' else '-'}"
                  f" | {choice[2] or 'auto'} | {nodes} | "
                  f"{float(last['K_I_error']):.2e} | "
                  f"{float(last['K_I_min_1']):.4f} | "
                  f"{float(last['K_I_max_1']):.4f} | "
                  f"{statistics.median(times):.1f} | "
                  f"{float(last['t_solve']):.1f} |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("study", choices=["convergence", "smoothing"])
    parser.add_argument("--cycles", type=int, default=None)
    parser.add_argument("--runs", type=int, default=1)
    args = parser.parse_args()
    if args.study == "convergence":
        args.cycles = args.cycles or 6
        convergence(args)
    else:
        args.cycles = args.cycles or 5
        smoothing(args)


if __name__ == "__main__":
    main()
