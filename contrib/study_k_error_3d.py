#!/usr/bin/python3
"""The K error estimate along a 3D front (issue 16, part 2; doc/verification.md
"K with a goal-oriented error estimate", the 3D part).

On the 3D K benchmarks with a known K (the penny under remote tension and
Case 1 in 3D, the Williams field imposed on a through crack), each mesh of
a front-refined sequence is solved with `Error estimate = true`. For every
mode the script compares, over the K nodes of the front, the true error
K_exact - K with the estimate written beside it in front_<step>.csv:

- the largest |error| and the largest |estimate| and their ratio;
- the means of both (signed), which tell whether the estimate sees the
  error common to the whole front;
- the share of nodes whose own effectivity (estimate / error) lies in
  [0.5, 2], counted only where the error exceeds 1e-3 of K (smaller errors
  are the round-off of K's mode mixing);
- the width of the estimate's crown in cells (the run calls the estimate
  unreliable under 4, marked *) and the time of the K extraction with the
  estimate against the solve.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_k_error_3d.py [--meshes 5] [--jobs 2]
        [--crown-weight linear|smooth]  (the reported K's weight)

With --k-tolerance-penny N, instead: the penny under `Strategy = k
tolerance` (topological enrichment, crown 0.25 to 0.75, tolerance 1 %,
Crown cells 4, at most N meshes; 45 s for N = 1, about 5 min for 3; the
tolerance and the reported crown's weight by --tolerance and --crown-weight), node
by node: the range of the K_I errors and of the K_I effectivities, and the
largest K_II estimate against the largest K_II error (doc/verification.md,
"The singular part's cut-off along a curved front").
"""
import argparse
import csv
import os
import statistics
import tempfile
from concurrent.futures import ThreadPoolExecutor

from xcrack_runs import benchmark_prm, front_file, run_xcrack

# benchmark, extra entries, reference (K_I, K_II, K_III)
BENCHMARKS = [
    ("sif_penny_3d", "", (1.12837917, 0.0, 0.0)),
    ("exact_mode_I_3d", "subsection Mesh refinement\n  set Strategy = front\n"
     "end\n", (1.0, 0.0, 0.0)),
]
MODES = ("K_I", "K_II", "K_III")


def run(benchmark, entries, meshes):
    """The statistics rows and, per mesh, the front table's rows."""
    with tempfile.TemporaryDirectory() as work:
        text = benchmark_prm(benchmark, work,
                             "subsection Fracture parameters\n"
                             "  set Error estimate = true\nend\n" + entries +
                             "subsection Mesh refinement\n"
                             f"  set Number of meshes = {meshes}\nend\n")
        rows = run_xcrack(text, work)
        fronts = []
        for row in rows:
            with open(os.path.join(work, "out",
                                   front_file(row, meshes))) as f:
                fronts.append(list(csv.DictReader(f)))
        return rows, fronts


def k_tolerance_penny_entries(tolerance, crown_weight):
    return ("subsection Fracture parameters\n  set Crown unit = absolute\n"
            "  set Crown radii = 0.25, 0.75\n"
            f"  set Crown weight = {crown_weight}\nend\n"
            "subsection Mesh refinement\n  set Strategy = k tolerance\n"
            f"  subsection K tolerance\n    set Tolerance = {tolerance}\n"
            "    set Crown cells = 4\n  end\nend\n"
            "subsection Enrichment\n  set Tip enrichment = topological\n"
            "  set Enrichment radius = 0\nend\n")


def k_tolerance_penny(meshes, tolerance, crown_weight):
    reference = BENCHMARKS[0][2]
    rows, fronts = run("sif_penny_3d",
                       k_tolerance_penny_entries(tolerance, crown_weight),
                       meshes)
    print("| mesh | DoFs | crown cells | K_I error (nodes) "
          "| K_I effectivity per node | largest K_II estimate "
          "| largest K_II error | goal met |")
    print("|---|---|---|---|---|---|---|---|")
    for row, front in zip(rows, fronts):
        errors = [reference[0] - float(p["K_I"]) for p in front]
        ratios = [float(p["K_I_error"]) / e for p, e in zip(front, errors)]
        print(f"| {row['mesh']} | {int(row['dofs']):,} "
              f"| {float(row['estimate_crown_cells']):.1f} "
              f"| {min(errors):.2e} to {max(errors):.2e} "
              f"| {min(ratios):.2f} to {max(ratios):.2f} "
              f"| {max(abs(float(p['K_II_error'])) for p in front):.1e} "
              f"| {max(abs(float(p['K_II'])) for p in front):.1e} "
              f"| {row['goal_met']} |")


def main(meshes, jobs, crown_weight):
    weight = ("subsection Fracture parameters\n"
              f"  set Crown weight = {crown_weight}\nend\n")
    with ThreadPoolExecutor(jobs) as pool:
        results = [pool.submit(run, b, e + weight, meshes)
                   for b, e, _ in BENCHMARKS]
        results = [r.result() for r in results]
    print("| benchmark | mesh | DoFs | crown cells | mode | max error "
          "| max estimate | ratio | mean error | mean estimate "
          "| nodes in [0.5, 2] | K extraction / solve (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for (benchmark, _, reference), (rows, fronts) in zip(BENCHMARKS,
                                                         results):
        for row, front in zip(rows, fronts):
            cells = float(row["estimate_crown_cells"])
            flag = "" if cells >= 4 else "*"
            for m, mode in enumerate(MODES):
                errors = [reference[m] - float(p[mode]) for p in front]
                estimates = [float(p[mode + "_error"]) for p in front]
                largest_error = max(abs(e) for e in errors)
                largest_estimate = max(abs(e) for e in estimates)
                counted = [(e, s) for e, s in zip(errors, estimates)
                           if abs(e) > 1e-3 * reference[0]]
                inside = sum(0.5 <= s / e <= 2 for e, s in counted)
                print(f"| {benchmark} | {row['mesh']} | {int(row['dofs']):,} "
                      f"| {cells:.1f}{flag} | {mode} | {largest_error:.2e} "
                      f"| {largest_estimate:.2e} "
                      f"| {largest_estimate / largest_error:.2f} "
                      f"| {statistics.mean(errors):+.2e} "
                      f"| {statistics.mean(estimates):+.2e} "
                      f"| {inside} of {len(counted)} "
                      f"| {float(row['t_fracture']):.1f} / "
                      f"{float(row['t_solve']):.1f} |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", type=int, default=5)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--k-tolerance-penny", type=int, metavar="N")
    parser.add_argument("--tolerance", type=float, default=0.01)
    parser.add_argument("--crown-weight", choices=["linear", "smooth"],
                        default="linear")
    arguments = parser.parse_args()
    if arguments.k_tolerance_penny:
        k_tolerance_penny(arguments.k_tolerance_penny, arguments.tolerance,
                          arguments.crown_weight)
    else:
        main(arguments.meshes, arguments.jobs, arguments.crown_weight)
