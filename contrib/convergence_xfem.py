#!/usr/bin/python3
"""Convergence of the X-FEM benchmarks of doc/benchmarks.md Case 1 (doc/verification.md).

Runs prm/benchmarks/exact_mode_I_2d.prm, exact_mixed_2d.prm and
exact_mode_I_3d.prm with the tip-enrichment variants below, prints one Markdown
table per run (cells, DoFs, enriched DoFs, relative L2 and energy errors,
orders against the mean cell size h = cells^(-1/dim), wall time of setup +
assembly + solve) and, where matplotlib is available, draws the energy error
against the DoFs in doc/figures/case1_convergence.png.

    contrib/build.sh release
    python3 contrib/convergence_xfem.py [--ranks 2] [--quick]
"""
import argparse
import math
import os
import tempfile

from xcrack_runs import run_xcrack, top

GEOMETRIC = "set Tip enrichment = geometric\n  set Enrichment radius = 0.25"
TOPOLOGICAL = "set Tip enrichment = topological\n  set Enrichment radius = 0"
NONE = "set Tip enrichment = none\n  set Enrichment radius = 0"
# Off the mesh lines: the tip inside a cell, the lips between two rows of nodes.
OFF_NODE = ("subsection Cracks\n  subsection Crack 1\n    set Start point = -2, 0.03\n"
            "    set End point = 0.07, 0.03\n  end\nend\n"
            "subsection Exact solution\n  set Tip = 0.07, 0.03\nend\n")

# (label, benchmark, degree, meshes, enrichment entries, extra prm text)
runs = [
    ("mode I, Q1, jump only", "exact_mode_I_2d", 1, 6, NONE, ""),
    ("mode I, Q1, topological", "exact_mode_I_2d", 1, 6, TOPOLOGICAL, ""),
    ("mode I, Q1, geometric r = 0.25", "exact_mode_I_2d", 1, 6, GEOMETRIC, ""),
    ("mode I, Q2, topological", "exact_mode_I_2d", 2, 5, TOPOLOGICAL, ""),
    ("mode I, Q2, geometric r = 0.25", "exact_mode_I_2d", 2, 5, GEOMETRIC, ""),
    ("mode I, Q1, geometric, tip off the nodes", "exact_mode_I_2d", 1, 5, GEOMETRIC, OFF_NODE),
    ("mode I, Q2, geometric, tip off the nodes", "exact_mode_I_2d", 2, 5, GEOMETRIC, OFF_NODE),
    ("mixed K_I = K_II = 1, Q1, geometric r = 0.25", "exact_mixed_2d", 1, 6, GEOMETRIC, ""),
    ("3D mode I, Q1, topological", "exact_mode_I_3d", 1, 4, TOPOLOGICAL, ""),
    ("3D mode I, Q1, geometric r = 0.25", "exact_mode_I_3d", 1, 4, GEOMETRIC, ""),
]


def run(work, benchmark, degree, meshes, enrichment, extra, ranks):
    return run_xcrack(
        f"include {top}/prm/benchmarks/{benchmark}.prm\n"
        f"set Output directory = {work}/out\n"
        f"subsection Discretization\n  set Degree = {degree}\n"
        "end\n"
        f"subsection Enrichment\n  {enrichment}\nend\n"
        f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n"
        "subsection Output\n  set Timing summary = false\nend\n" + extra,
        work, ranks)


def print_table(label, rows, dim):
    print(f"\n**{label}**\n")
    print("| cells | DoFs | enriched | L2 error | order | energy error | order | wall (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for i, r in enumerate(rows):
        orders = ["–", "–"]
        if i > 0:
            p = rows[i - 1]
            h_ratio = (float(r["cells"]) / float(p["cells"])) ** (1 / dim)
            orders = [f"{math.log(float(p[c]) / float(r[c])) / math.log(h_ratio):.2f}"
                      for c in ("L2_error", "energy_error")]
        wall = sum(float(r[t]) for t in ("t_setup", "t_assemble", "t_solve"))
        print(f"| {r['cells']} | {r['dofs']} | {r['enriched_dofs']} | "
              f"{float(r['L2_error']):.3e} | {orders[0]} | "
              f"{float(r['energy_error']):.3e} | {orders[1]} | {wall:.2f} |")


def plot(results):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("\n(matplotlib not available: no figure)")
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for label, dim, rows in results:
        ax = axes[0 if dim == 2 else 1]
        if "mixed" in label or "off" in label:
            continue
        ax.loglog([float(r["dofs"]) for r in rows],
                  [float(r["energy_error"]) for r in rows], "o-", label=label)
    for ax, dim in zip(axes, (2, 3)):
        n = [1e3, 1e5] if dim == 2 else [3e3, 1.5e5]
        for order, style in ((0.5, ":"), (1, "--"), (2, "-.")):
            if dim == 3 and order == 2:
                continue
            c = 0.5 if order < 2 else 2.0
            ax.loglog(n, [c * (x / n[0]) ** (-order / dim) for x in n], "k" + style,
                      label=f"h^{order}")
        ax.set_xlabel("DoFs")
        ax.set_ylabel("relative energy error")
        ax.set_title(f"Case 1, {dim}D")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    path = os.path.join(top, "doc", "figures", "case1_convergence.png")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=120)
    print(f"\nFigure: {path}")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2, help="ranks for the 3D runs")
    parser.add_argument("--quick", action="store_true", help="two meshes fewer")
    args = parser.parse_args()
    results = []
    with tempfile.TemporaryDirectory() as work:
        for label, benchmark, degree, meshes, enrichment, extra in runs:
            dim = 3 if benchmark.endswith("3d") else 2
            meshes = max(2, meshes - 2) if args.quick else meshes
            rows = run(work, benchmark, degree, meshes, enrichment, extra,
                       args.ranks if dim == 3 else 1)
            print_table(label, rows, dim)
            results.append((label, dim, rows))
    plot(results)


if __name__ == "__main__":
    main()
