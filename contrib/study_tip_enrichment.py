#!/usr/bin/python3
"""Speed/accuracy trade of the crack-tip enrichment (doc/performance.md).

On doc/benchmarks.md Case 1 (prm/benchmarks/exact_mode_I_2d.prm, and the 3D
version on two ranks) this sweeps the enrichment radius (topological, then
geometric radii in multiples of the cell size h and fixed), the points per
direction of the tip rule, DOF gathering, and the degree, and prints for each choice the
relative energy error, the enriched DoFs and the wall time of setup +
assembly + solve (median of --runs runs). The X-FEM overhead is the solve
time divided by that of the uncracked body on the same mesh (same boundary
data, no crack), measured in the same run.

    contrib/build.sh release
    python3 contrib/study_tip_enrichment.py [--runs 3] [--meshes 5]
"""
import argparse
import statistics
import tempfile

from xcrack_runs import run_xcrack, top


def run(work, benchmark, meshes, entries, ranks, repeats):
    """Last row of statistics.csv, with median times over the repeats."""
    text = (f"include {top}/prm/benchmarks/{benchmark}.prm\n"
            f"set Output directory = {work}/out\n"
            f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n"
            "subsection Output\n  set Timing summary = false\nend\n" + entries)
    rows = [run_xcrack(text, work, ranks)[-1] for _ in range(repeats)]
    result = dict(rows[0])
    for t in ("t_setup", "t_assemble", "t_solve"):
        result[t] = statistics.median(float(r[t]) for r in rows)
    result["wall"] = result["t_setup"] + result["t_assemble"] + result["t_solve"]
    return result


def enrichment(zone, radius=0.0, points=6, degree=1, gather=False):
    return ("subsection Enrichment\n"
            f"  set Tip enrichment = {zone}\n  set Enrichment radius = {radius}\n"
            f"  set Tip quadrature points = {points}\n"
            f"  set Gather tip DoFs = {str(gather).lower()}\nend\n"
            f"subsection Discretization\n  set Degree = {degree}\nend\n")


UNCRACKED = ("subsection Cracks\n  set Number of cracks = 0\nend\n"
             "subsection Enrichment\n  set Tip enrichment = topological\n"
             "  set Enrichment radius = 0\nend\n")


def study(work, benchmark, meshes, ranks, repeats, h):
    dim = 3 if benchmark.endswith("3d") else 2
    base = run(work, benchmark, meshes, UNCRACKED, ranks, repeats)
    print(f"\n**{benchmark}, {meshes} meshes (h = {h:g}), {ranks} rank(s), "
          f"median of {repeats}.** Uncracked body on the same mesh: "
          f"{base['dofs']} DoFs, t_solve {base['t_solve']:.3f} s, "
          f"setup + assembly + solve {base['wall']:.3f} s.\n")
    print("| choice | DoFs | enriched | energy error | wall (s) | t_solve ÷ uncracked |")
    print("|---|---|---|---|---|---|")
    choices = [("jump only", enrichment("none"))]
    choices.append(("topological", enrichment("topological")))
    for k in (1, 2, 4):
        choices.append((f"geometric r = {k}h", enrichment("geometric", k * h)))
    for r in (0.1, 0.25, 0.5):
        choices.append((f"geometric r = {r}", enrichment("geometric", r)))
    for p in (3, 10):
        choices.append((f"geometric r = 0.25, tip rule {p} points",
                        enrichment("geometric", 0.25, p)))
    for r in (0.25, 0.5) + ((0.9,) if dim == 2 else ()):
        choices.append((f"gathered, r = {r}",
                        enrichment("geometric", r, gather=True)))
    if dim == 2:
        choices.append(("Q2, topological", enrichment("topological", degree=2)))
        choices.append(("Q2, geometric r = 0.25",
                        enrichment("geometric", 0.25, degree=2)))
    for label, entries in choices:
        r = run(work, benchmark, meshes, entries, ranks, repeats)
        print(f"| {label} | {r['dofs']} | {r['enriched_dofs']} | "
              f"{float(r['energy_error']):.3e} | {r['wall']:.3f} | "
              f"{r['t_solve'] / base['t_solve']:.2f} |")


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--meshes", type=int, default=5, help="2D meshes")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        # 2D: 8 x 8 cells on [-1,1]^2 refined meshes - 1 times.
        study(work, "exact_mode_I_2d", args.meshes, 1, args.runs,
              0.25 / 2 ** (args.meshes - 1))
        # 3D: 4 x 4 x 4 cells refined twice (4096 cells).
        study(work, "exact_mode_I_3d", 3, 2, args.runs, 0.5 / 4)


if __name__ == "__main__":
    main()
