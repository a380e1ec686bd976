#!/usr/bin/python3
"""Can K carry its own error estimate? (issue 16, part 2; doc/verification.md
"K and its error: what the cheap estimates are worth").

On the 2D K benchmarks with a known K this measures, on each mesh of the
benchmark's own refinement, the true error of K from the shipped crowns
(2 to 4 cells) against two estimates that need no extra solve and the
goal-oriented one:

- crowns: the interaction integral is linear in q, and the shipped q (1 to
  0 from 2 to 4 cells) is the mean of the q of the crowns 2-3 and 3-4, so
  K(2,4) = (K(2,3) + K(3,4)) / 2; the estimate is |K(2,3) - K(3,4)| / 2,
  the spread of two independent extractions about their mean;
- jumps: |K_jump - K|, K_jump from the displacement jumps over the crown
  (doc/benchmarks.md's cross-check);
- dual: xcrack's own estimate (`Fracture parameters/Error estimate`,
  KErrorEstimator): signed, so its effectivity is (K_exact - K)_estimated /
  (K_exact - K), negative when it points the wrong way. Rows whose dual
  crown is under 4 cells wide are flagged unreliable by the run itself
  (marked *) and left out of the summary.

Effectivity = estimate / true error; a reliable estimate stays within 0.5
to 2 on every benchmark and mesh.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_k_error.py [--jobs 2]   # and sif_sent_2d
                                                          # against its own
                                                          # extrapolated K
    /usr/bin/python3 contrib/study_k_error.py --cost   # what the estimate costs
"""
import argparse
import statistics
import tempfile
from concurrent.futures import ThreadPoolExecutor

from xcrack_runs import benchmark_prm, run_xcrack

# benchmark, extra entries, reference (K_I, K_II)
BENCHMARKS = [
    # (exact_mode_I_2d and exact_mixed_2d repeat sif_exact_2d's errors:
    # on its mesh, symmetric about the crack, the modes do not mix.)
    ("sif_exact_2d", "", (1.0, 0.5)),
    ("exact_mode_I_2d", "subsection Enrichment\n  set Tip enrichment = "
     "topological\n  set Enrichment radius = 0\nend\n", (1.0, 0.0)),
    ("sif_inclined_2d", "", (1.32934039, 0.76749503)),
    ("sif_sent_2d", "", (1.606801, 0.0)),
]


def run(benchmark, entries, crowns):
    with tempfile.TemporaryDirectory() as work:
        text = benchmark_prm(benchmark, work,
                             "subsection Fracture parameters\n"
                             f"  set Crown radii = {crowns[0]}, {crowns[1]}\n"
                             "  set Crown unit = cells\n"
                             "  set Error estimate = true\nend\n" + entries)
        return run_xcrack(text, work)


def main(jobs):
    print("| benchmark | mesh | DoFs | mode | K error | crowns estimate "
          "| effectivity | jumps estimate | effectivity | dual estimate "
          "| effectivity |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    summary = {"crowns": [], "jumps": [], "dual": []}
    for benchmark, entries, reference in BENCHMARKS:
        with ThreadPoolExecutor(jobs) as pool:
            full, inner, outer = [f.result() for f in [
                pool.submit(run, benchmark, entries, c)
                for c in [(2, 4), (2, 3), (3, 4)]]]
        label = benchmark + (" (topological)" if entries else "")
        for m, (f, i, o) in enumerate(zip(full, inner, outer)):
            for mode, column, ref in [("I", "K_I", reference[0]),
                                      ("II", "K_II", reference[1])]:
                if ref == 0:
                    continue
                k = float(f[f"{column}_1"])
                error = abs(k - ref)
                crowns = abs(float(i[f"{column}_1"]) - float(o[f"{column}_1"])) / 2
                jumps = abs(float(f[f"{column}_jump_1"]) - k)
                dual = float(f[f"{column}_estimate_1"])
                e_c, e_j = crowns / error, jumps / error
                e_d = dual / (ref - k)
                reliable = float(f["estimate_crown_cells"]) >= 4
                summary["crowns"].append(e_c)
                summary["jumps"].append(e_j)
                if reliable:
                    summary["dual"].append(e_d)
                print(f"| {label} | {m} | {int(f['dofs']):,} | {mode} | "
                      f"{error / ref:.2e} | {crowns / ref:.2e} | {e_c:.2f} | "
                      f"{jumps / ref:.2e} | {e_j:.1f} | {abs(dual) / ref:.2e} "
                      f"| {e_d:.2f}{'' if reliable else '*'} |")
    print()
    for name, values in summary.items():
        inside = sum(0.5 <= v <= 2 for v in values)
        print(f"- {name}: effectivity from {min(values):.2f} to "
              f"{max(values):.1f}, within [0.5, 2] in {inside} of "
              f"{len(values)} cases")


def sent_extrapolated(meshes=6):
    """sif_sent_2d against a reference of its own: its handbook K is itself
    about 0.3 % off, more than K's error on the finer meshes. K on `meshes`
    meshes, Richardson-extrapolated from the last three (rate from their
    differences), and the dual estimate's effectivity against that."""
    with tempfile.TemporaryDirectory() as work:
        rows = run_xcrack(benchmark_prm(
            "sif_sent_2d", work,
            "subsection Fracture parameters\n  set Error estimate = true\n"
            f"end\nsubsection Mesh refinement\n  set Number of meshes = "
            f"{meshes}\nend\n"), work)
    k = [float(r["K_I_1"]) for r in rows]
    ratio = (k[-2] - k[-3]) / (k[-1] - k[-2])
    reference = k[-1] + (k[-1] - k[-2]) / (ratio - 1)
    print(f"\nsif_sent_2d: K_I extrapolated from meshes {meshes - 3} to "
          f"{meshes - 1}: {reference:.6f} (ratio of differences {ratio:.2f})\n")
    print("| mesh | DoFs | K_I | K_I + estimate | effectivity |")
    print("|---|---|---|---|---|")
    for m, (row, value) in enumerate(zip(rows, k)):
        estimate = float(row["K_I_estimate_1"])
        reliable = float(row["estimate_crown_cells"]) >= 4
        print(f"| {m} | {int(row['dofs']):,} | {value:.6f} | "
              f"{value + estimate:.6f} | "
              f"{estimate / (reference - value):.2f}"
              f"{'' if reliable else '*'} |")


def cost(runs=3):
    """Wall time of the K extraction (with the estimate: the wide crown,
    the dual solves and the recovery) and of the solve on the last mesh of
    exact_mode_I_2d with topological enrichment, estimate off and on; one
    job at a time, medians of `runs` runs, alternating."""
    entries = BENCHMARKS[1][1]
    times = {False: [], True: []}
    for _ in range(runs):
        for on in (False, True):
            with tempfile.TemporaryDirectory() as work:
                text = benchmark_prm(
                    "exact_mode_I_2d", work,
                    "subsection Fracture parameters\n"
                    f"  set Error estimate = {str(on).lower()}\nend\n"
                    + entries)
                last = run_xcrack(text, work)[-1]
            times[on].append((float(last["t_fracture"]),
                              float(last["t_solve"]), int(last["dofs"])))
    print("| estimate | DoFs | K extraction (s) | solve (s) |")
    print("|---|---|---|---|")
    for on in (False, True):
        f = statistics.median(t[0] for t in times[on])
        s = statistics.median(t[1] for t in times[on])
        print(f"| {'on' if on else 'off'} | {times[on][0][2]:,} | {f:.2f} "
              f"| {s:.2f} |")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--cost", action="store_true")
    arguments = parser.parse_args()
    if arguments.cost:
        cost()
    else:
        main(arguments.jobs)
        sent_extrapolated()
