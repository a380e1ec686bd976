#!/usr/bin/python3
"""K along 3D fronts (doc/benchmarks.md Cases 5 and 6): the error of each K
against the reference per mesh of the benchmarks, the convergence of
each front basis, and the cost and gain of each choice of the extraction
(crowns, basis, front segments, tip rule) on the penny.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_sif_3d.py convergence [--meshes 6] [--direct]
    /usr/bin/python3 contrib/study_sif_3d.py bases [--meshes 6] [--jobs 2]
    /usr/bin/python3 contrib/study_sif_3d.py trade [--meshes 6] [--jobs 2]
    /usr/bin/python3 contrib/study_sif_3d.py rules [--meshes 6] [--jobs 2]

Prints markdown tables (doc/verification.md, doc/performance.md);
`convergence` also writes doc/figures/sif_convergence_3d.png, `bases`
doc/figures/sif_bases_3d.png. A six-mesh run of one benchmark takes
about five minutes on one core.

`bases`: the K_I error of the penny per mesh for each front basis (the
rate against the front cell size h). `trade`: on the penny's last mesh,
one knob at a time against the shipped choice (crowns 2-4 cells, Legendre
degree 5, 6 tip quadrature points): the crowns (their independence: the
front-averaged K_I against the baseline's), the basis and its size, the
tip rule, the near-front rule; with the wall time of the extraction.
`rules`: on both pennies' last mesh, the near-front cells' rule (tip rule,
Gauss 6^3, graded by tolerance) against the K's change from a reference
quadrature, with the wall times of the assembly and the extraction.
`--jobs 2` runs two choices at once (one core each); the times are then
those of a loaded machine, compared with the baseline run under the same
load.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xcrack_runs import front_file, run_xcrack, top  # noqa: E402

benchmarks = {
    "penny, tension": "sif_penny_3d.prm",
    "penny, shear": "sif_penny_shear_3d.prm",
    "ellipse b/a = 0.5": "sif_ellipse_3d.prm",
}


def run(benchmark, meshes, work, smoothing=None, fracture="", enrichment="",
        extra=""):
    """Run a benchmark with `meshes` meshes in work/out; smoothing is
    (basis, Legendre degree, front segments); fracture and enrichment are
    extra lines for those subsections, extra more parameter text."""
    text = (f"include {os.path.join(top, 'prm', 'benchmarks', benchmark)}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n")
    if smoothing:
        fracture += (f"  set Smoothing = {smoothing[0]}\n"
                     f"  set Legendre degree = {smoothing[1]}\n"
                     f"  set Front segments = {smoothing[2]}\n")
    if fracture:
        text += f"subsection Fracture parameters\n{fracture}end\n"
    if enrichment:
        text += f"subsection Enrichment\n{enrichment}end\n"
    return run_xcrack(text + extra, work)


def front_k(work, rows):
    """K_I at the points of the front file of the last row of a run in
    work/out (front_000.<mesh>.csv of step 0 solved on several meshes)."""
    with open(os.path.join(work, "out", front_file(rows[-1], len(rows)))) as f:
        return [float(r["K_I"]) for r in csv.DictReader(f)]


def run_choices(choices, meshes, jobs, benchmark="sif_penny_3d.prm"):
    """Run each (label, kwargs of run()) in its own directory, `jobs` at
    once; return {label: (statistics rows, K_I along the last front)}."""
    def one(choice):
        label, kwargs = choice
        with tempfile.TemporaryDirectory() as work:
            rows = run(benchmark, meshes, work, **kwargs)
            return label, (rows, front_k(work, rows))
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        return dict(pool.map(one, choices))


# The shear and ellipse prms gather the tip DoFs and solve with CG + AMG to
# reach h = 1/32; `convergence --direct` runs every benchmark as the tables
# up to h = 1/16 were measured (no gathering, MUMPS).
DIRECT = ("subsection Enrichment\n  set Gather tip DoFs = false\nend\n"
          "subsection Linear solver\n  set Type = direct\nend\n")


def convergence(args):
    table = {}
    with tempfile.TemporaryDirectory() as work:
        for name, benchmark in benchmarks.items():
            rows = run(benchmark, args.meshes, work, extra=(DIRECT if args.direct
                                                            else ""))
            table[name] = rows
            print(f"\n{name} ({benchmark})\n")
            print("| mesh | DoFs | K_I error | K_II error | K_III error | "
                  "t_solve (s) | t_fracture (s) |")
            print("|---|---|---|---|---|---|---|")
            for r in rows:
                print(f"| {r['mesh']} | {r['dofs']} | "
                      f"{float(r['K_I_error']):.2e} | "
                      f"{float(r['K_II_error']):.2e} | "
                      f"{float(r['K_III_error']):.2e} | "
                      f"{float(r['t_solve']):.1f} | "
                      f"{float(r['t_fracture']):.1f} |")

    def draw(ax):
        for name, rows in table.items():
            dofs = [float(r["dofs"]) for r in rows]
            mode = "K_II_error" if "shear" in name else "K_I_error"
            ax.loglog(dofs, [float(r[mode]) for r in rows], "o-",
                      label=f"{name}: {mode.replace('_error', '')}")
        ax.set_xlabel("DoFs")
        ax.set_ylabel("max relative error along the front")
    save_figure(draw, "sif_convergence_3d.png")


def save_figure(draw, name):
    """doc/figures/<name>: a log-log figure that draw(ax) fills, with the
    1 % target as a dotted line (nothing without matplotlib)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    draw(ax)
    ax.axhline(0.01, color="gray", lw=0.8, ls=":")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    path = os.path.join(top, "doc", "figures", name)
    fig.savefig(path, dpi=120)
    print(f"\nwrote {path}")


def bases(args):
    choices = [("Legendre degree 5", {"smoothing": ("legendre", 5, 0)}),
               ("Lagrange", {"smoothing": ("lagrange", 0, 0)}),
               ("Lagrange regularised",
                {"smoothing": ("lagrange regularized", 0, 0)})]
    results = run_choices(choices, args.meshes, args.jobs)
    print("\npenny (sif_penny_3d.prm), K_I error per mesh (h: front cell "
          "size; rate: log2 of the error ratio to the previous mesh)\n")
    labels = [c[0] for c in choices]
    print("| mesh | h | DoFs | " + " | ".join(
        f"{l} | rate" for l in labels) + " |")
    print("|---|---|---|" + "---|---|" * len(labels))
    first = results[labels[0]][0]
    for i, r in enumerate(first):
        h = 2.0 ** (1 - int(r["mesh"]))
        cells = []
        for l in labels:
            rows = results[l][0]
            e = float(rows[i]["K_I_error"])
            rate = (f"{math.log2(float(rows[i - 1]['K_I_error']) / e):.2f}"
                    if i > 0 else "-")
            cells.append(f"{e:.2e} | {rate}")
        print(f"| {r['mesh']} | {h:g} | {r['dofs']} | " + " | ".join(cells)
              + " |")
    plot_bases(labels, {l: results[l][0] for l in labels})


def plot_bases(labels, rows_of):
    """doc/figures/sif_bases_3d.png: K_I error against h for each basis
    (rows_of: label -> statistics rows with step and K_I_error)."""
    first = rows_of[labels[0]]

    def draw(ax):
        for l in labels:
            rows = rows_of[l]
            ax.loglog([2.0 ** (1 - int(r["mesh"])) for r in rows],
                      [float(r["K_I_error"]) for r in rows], "o-", label=l)
        hs = [2.0 ** (1 - int(r["mesh"])) for r in first[-3:]]
        ax.loglog(hs, [0.5 * h * h / hs[-1] ** 2 *
                       float(first[-1]["K_I_error"]) for h in hs],
                  "k--", lw=0.8, label="h^2")
        ax.invert_xaxis()
        ax.set_xlabel("front cell size h")
        ax.set_ylabel("max relative K_I error along the penny front")
    save_figure(draw, "sif_bases_3d.png")


def trade(args):
    base = "  set Crown radii = 2, 4\n"
    choices = [
        ("baseline: crowns 2-4, Legendre 5, tip rule 6", {"fracture": base}),
        ("crowns 1-2", {"fracture": "  set Crown radii = 1, 2\n"}),
        ("crowns 1.5-3", {"fracture": "  set Crown radii = 1.5, 3\n"}),
        ("crowns 3-6", {"fracture": "  set Crown radii = 3, 6\n"}),
        ("Legendre degree 0", {"fracture": base,
                               "smoothing": ("legendre", 0, 0)}),
        ("Legendre degree 2", {"fracture": base,
                               "smoothing": ("legendre", 2, 0)}),
        ("Legendre degree 7", {"fracture": base,
                               "smoothing": ("legendre", 7, 0)}),
        ("Lagrange, segments about r_sup", {"fracture": base,
                                             "smoothing": ("lagrange", 0, 0)}),
        ("Lagrange, 16 segments", {"fracture": base,
                                   "smoothing": ("lagrange", 0, 16)}),
        ("Lagrange, 50 segments", {"fracture": base,
                                   "smoothing": ("lagrange", 0, 50)}),
        ("Lagrange regularised", {"fracture": base, "smoothing":
                                  ("lagrange regularized", 0, 0)}),
        ("tip rule 3 points", {"fracture": base, "enrichment":
                               "  set Tip quadrature points = 3\n"}),
        ("tip rule 10 points", {"fracture": base, "enrichment":
                                "  set Tip quadrature points = 10\n"}),
    ] + [(f"near-front cells: Gauss {n}^3", {
        "fracture": base,
        "enrichment": f"  set Near-front quadrature points = {n}\n"})
         for n in (4, 6, 8)]
    results = run_choices(choices, args.meshes, args.jobs)
    rows0, k0 = results[choices[0][0]]
    mean0 = statistics.fmean(k0)
    t0 = float(rows0[-1]["t_fracture"])
    last0 = rows0[-1]
    print(f"\npenny (sif_penny_3d.prm), mesh {last0['mesh']}: "
          f"{last0['dofs']} DoFs, t_solve {float(last0['t_solve']):.0f} s "
          f"(baseline); {args.jobs} run(s) at once\n")
    print("| choice | front points | K_I error | K_I min | K_I max | "
          "mean K_I / baseline - 1 | t_K (s) | t_K / baseline |")
    print("|---|---|---|---|---|---|---|---|")
    for label, _ in choices:
        rows, k = results[label]
        last = rows[-1]
        t = float(last["t_fracture"])
        print(f"| {label} | {len(k)} | {float(last['K_I_error']):.2e} | "
              f"{min(k):.4f} | {max(k):.4f} | "
              f"{statistics.fmean(k) / mean0 - 1:+.1e} | {t:.0f} | "
              f"{t / t0:.2f} |")


def front_ks(work, rows):
    """(K_I, K_II, K_III) at the points of the last front file of a run."""
    with open(os.path.join(work, "out", front_file(rows[-1], len(rows)))) as f:
        return [tuple(float(r[k]) for k in ("K_I", "K_II", "K_III"))
                for r in csv.DictReader(f)]


def rules(args):
    """The near-front cells' rule against the K it gives and its cost: on
    the last mesh of each penny, the tip rule (the shipped rule up to commit
    dc87695), the tip rule with 10 points everywhere (the quadrature
    reference), Gauss 6^3, and graded Gauss rules by tolerance. 'quadrature error': the largest change of any K along the
    front against the reference rule, over the largest |K| there."""
    tip = "  set Near-front quadrature tolerance = 0\n"
    choices = [("tip rule, 6 points", tip),
               ("tip rule, 10 points (reference)",
                tip + "  set Tip quadrature points = 10\n"),
               ("Gauss 6^3", "  set Near-front quadrature points = 6\n")] + [
        (f"graded, tolerance {t:g}" + (" (shipped)" if t == 1e-6 else ""),
         f"  set Near-front quadrature tolerance = {t:g}\n")
        for t in (1e-2, 1e-3, 1e-4, 1e-6)]
    for benchmark in ("sif_penny_3d.prm", "sif_penny_shear_3d.prm"):
        def one(choice):
            label, enrichment = choice
            with tempfile.TemporaryDirectory() as work:
                rows = run(benchmark, args.meshes, work, enrichment=enrichment,
                           extra=DIRECT)
                return label, (rows, front_ks(work, rows))
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            results = dict(pool.map(one, choices))
        reference = results[choices[1][0]][1]
        k_scale = max(abs(v) for k in reference for v in k)
        last = results[choices[0][0]][0][-1]
        print(f"\n{benchmark}, mesh {last['mesh']}: {last['dofs']} DoFs; "
              f"{args.jobs} run(s) at once\n")
        print("| near-front rule | K_I error | K_II error | K_III error | "
              "quadrature error | t_assemble (s) | t_K (s) |")
        print("|---|---|---|---|---|---|---|")
        for label, _ in choices:
            rows, ks = results[label]
            last = rows[-1]
            change = max(abs(a - b) for k, r in zip(ks, reference)
                         for a, b in zip(k, r)) / k_scale
            print(f"| {label} | {float(last['K_I_error']):.2e} | "
                  f"{float(last['K_II_error']):.2e} | "
                  f"{float(last['K_III_error']):.2e} | {change:.1e} | "
                  f"{float(last['t_assemble']):.1f} | "
                  f"{float(last['t_fracture']):.1f} |")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=["convergence", "bases", "trade",
                                          "rules"])
    parser.add_argument("--meshes", type=int, default=6)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--direct", action="store_true",
                        help="convergence: no gathering, direct solver")
    args = parser.parse_args()
    {"convergence": convergence, "bases": bases, "trade": trade,
     "rules": rules}[args.study](args)


if __name__ == "__main__":
    main()
