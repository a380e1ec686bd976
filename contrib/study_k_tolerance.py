#!/usr/bin/python3
"""Refinement to a K tolerance against uniform refinement (issue 16, part 3).

For 2D benchmarks with a known K (topological tip enrichment, the crowns as
lengths, 0.1 to 0.3 from the tip), prints:
- uniform refinement: per mesh, cells, DoFs and the K error (largest over
  the tips and modes, relative to the largest |K|);
- `Mesh refinement/Strategy = k tolerance` for several tolerances and
  `Crown cells`: the meshes it took, the cells and DoFs of the last one, the
  true and the estimated K error there, whether the goal was met, and the
  wall time of the whole run (the sum of its phases).

    /usr/bin/python3 contrib/study_k_tolerance.py            # 20 s
    /usr/bin/python3 contrib/study_k_tolerance.py --crown-weight smooth
    /usr/bin/python3 contrib/study_k_tolerance.py --picture  # 10 s

`--picture` draws doc/figures/k_tolerance_meshes.png: the meshes on which
Case 1 (tolerance 3e-4) and the inclined crack (1e-3) met their goal.
"""
import argparse
import math
import os
import tempfile
from concurrent.futures import ThreadPoolExecutor

from study_adaptivity import read_cells
from xcrack_runs import benchmark_prm, run_xcrack, top

TOPOLOGICAL = ("subsection Enrichment\n  set Tip enrichment = topological\n"
               "  set Enrichment radius = 0\nend\n")
# benchmark, reference (K_I, K_II), number of tips, uniform meshes
BENCHMARKS = [
    ("exact_mode_I_2d", (1.0, 0.0), 1, 6),
    ("sif_inclined_2d", (1.32934039, 0.76749503), 2, 5),
]
PHASES = ["t_setup", "t_assemble", "t_solve", "t_errors", "t_fracture",
          "t_output", "t_refine"]


def run(benchmark, reference, refinement, picture=False,
        crown_weight="linear"):
    """The rows of statistics.csv; with `picture`, and the corners of the
    last mesh's cells."""
    with tempfile.TemporaryDirectory() as work:
        text = benchmark_prm(
            benchmark, work,
            f"subsection Output\n  set Write vtu = {str(picture).lower()}\n"
            "end\n" + TOPOLOGICAL +
            "subsection Fracture parameters\n"
            "  set Crown unit = absolute\n  set Crown radii = 0.1, 0.3\n"
            f"  set Crown weight = {crown_weight}\n"
            f"  set Reference K = {reference[0]}; {reference[1]}\n"
            "  set Error estimate = true\nend\n"
            "subsection Mesh refinement\n" + refinement + "end\n")
        rows = run_xcrack(text, work)
        if not picture:
            return rows
        last = int(rows[-1]["mesh"])
        return rows, read_cells(
            f"{work}/out/solution-000.{last:02d}.0000.vtu")


def k_errors(row, reference, n_tips):
    """True and estimated K errors (largest over tips and modes) relative to
    the largest |K| of the reference."""
    scale = math.hypot(*reference)
    true = estimated = 0
    for t in range(1, n_tips + 1):
        for mode, ref in zip(["K_I", "K_II"], reference):
            k = float(row[f"{mode}_{t}"])
            # Symmetric tips: the second tip's K_II has the same sign here.
            true = max(true, abs(ref - k) / scale)
            estimated = max(estimated,
                            abs(float(row[f"{mode}_estimate_{t}"])) / scale)
    return true, estimated


def main(jobs, crown_weight):
    for benchmark, reference, n_tips, n_uniform in BENCHMARKS:
        print(f"\n{benchmark} (topological, crown 0.1 to 0.3, "
              f"{crown_weight} weight)\n")
        print("| refinement | meshes | cells | DoFs | K error | estimated "
              "| goal met | time (s) |")
        print("|---|---|---|---|---|---|---|---|")
        cases = [("uniform", f"  set Number of meshes = {n_uniform}\n")]
        for crown_cells in [8, 16]:
            for tolerance in [1e-2, 3e-3, 1e-3, 3e-4, 1e-4]:
                cases.append((
                    f"k tolerance {tolerance:g}, crown cells {crown_cells}",
                    k_tolerance(tolerance).replace(
                        "  end\n",
                        f"    set Crown cells = {crown_cells}\n  end\n")))
        with ThreadPoolExecutor(jobs) as pool:
            results = [pool.submit(run, benchmark, reference, c[1], False,
                                   crown_weight) for c in cases]
            results = [r.result() for r in results]
        for (label, _), rows in zip(cases, results):
            # Uniform: a row per mesh; k tolerance: its last mesh, the
            # number of meshes it solved and the time of the whole run.
            uniform = (label == "uniform")
            shown = rows if uniform else rows[-1:]
            time = sum(float(r[p]) for r in rows for p in PHASES)
            for row in shown:
                true, estimated = k_errors(row, reference, n_tips)
                met = row.get("goal_met", "")
                meshes = int(row["mesh"]) + 1 if uniform else len(rows)
                print(f"| {label} | {meshes} "
                      f"| {int(row['cells']):,} | {int(row['dofs']):,} "
                      f"| {true:.2e} | {estimated:.2e} | "
                      f"{'yes' if met == '1' else 'no' if met else ''} "
                      f"| {'' if uniform else f'{time:.1f}'} |")


def k_tolerance(tolerance):
    return ("  set Number of meshes = 20\n  set Strategy = k tolerance\n"
            f"  subsection K tolerance\n    set Tolerance = {tolerance}\n"
            "  end\n")


def picture(jobs):
    cases = [("exact_mode_I_2d", (1.0, 0.0), 3e-4, [(-1, 0), (0, 0)]),
             ("sif_inclined_2d", (1.32934039, 0.76749503), 1e-3,
              [(-0.866, -0.5), (0.866, 0.5)])]
    with ThreadPoolExecutor(jobs) as pool:
        results = [pool.submit(run, b, r, k_tolerance(t), True)
                   for b, r, t, _ in cases]
        results = [r.result() for r in results]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    figure, axes = plt.subplots(1, 2, figsize=(10, 5))
    for axis, (benchmark, _, tolerance, crack), (rows, cells) in zip(
            axes, cases, results):
        axis.add_collection(PolyCollection(cells, facecolors="none",
                                           edgecolors="k", linewidths=0.15))
        axis.plot(*zip(*crack), "r-", linewidth=1)
        corners = [p for cell in cells for p in cell]
        axis.set_xlim(min(p[0] for p in corners), max(p[0] for p in corners))
        axis.set_ylim(min(p[1] for p in corners), max(p[1] for p in corners))
        axis.set_aspect("equal")
        axis.set_title(f"{benchmark}, tolerance {tolerance:g}: "
                       f"{len(cells):,} cells", fontsize=10)
    figure.tight_layout()
    path = os.path.join(top, "doc", "figures", "k_tolerance_meshes.png")
    figure.savefig(path, dpi=150)
    print(f"wrote {path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--picture", action="store_true")
    parser.add_argument("--crown-weight", choices=["linear", "smooth"],
                        default="linear",
                        help="Fracture parameters/Crown weight of every run")
    arguments = parser.parse_args()
    if arguments.picture:
        picture(arguments.jobs)
    else:
        main(arguments.jobs, arguments.crown_weight)
