#!/usr/bin/python3
"""A 3D X-FEM solve on one rank and on two, the mesh shared among the ranks
by cells or by work (`Parallel/Partition`): the phases of the last mesh of
the penny of doc/benchmarks.md Case 5, their speed-up over one rank, the work
imbalance left (largest rank's work over the mean) and the K errors, which
must not depend on the split.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_partition.py [--runs 3] [--meshes 5] [--gathered]

--gathered solves the system with DOF gathering and CG + AMG (the set-up
of sif_ellipse_3d.prm, for meshes too large for MUMPS) instead of MUMPS on
the ungathered system, and adds a fourth configuration: split by work, CG +
AMG on the rows each rank assembled (`Linear solver/Partition = assembly`)
instead of rows moved to balance the matrix entries.

Runs alternate between the three configurations, so that a load that comes
and goes hits all of them; the two-rank runs use both cores of the machine.
Prints a markdown table of medians.
"""
import argparse
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xcrack_runs  # noqa: E402

PHASES = [("t_setup", "setup"), ("t_assemble", "assembly"),
          ("t_solve", "solve"), ("t_fracture", "K extraction")]
CONFIGURATIONS = [("one rank", 1, "cells"), ("two ranks, by cells", 2, "cells"),
                  ("two ranks, by work", 2, "work")]
ASSEMBLED_ROWS = ("by work, assembled rows", 2, "work")


def run(meshes, ranks, partition, gathered, work, solver_rows="balanced"):
    """The last statistics row of the penny on `meshes` meshes."""
    solver = ("subsection Linear solver\n  set Type = cg amg\n"
              "  set Maximum iterations = 10000\n"
              f"  set Partition = {solver_rows}\nend\n"
              "subsection Enrichment\n  set Gather tip DoFs = true\nend\n"
              if gathered else
              "subsection Linear solver\n  set Type = direct\nend\n")
    text = (f"include {os.path.join(xcrack_runs.top, 'prm', 'benchmarks', 'sif_penny_3d.prm')}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            + solver +
            f"subsection Parallel\n  set Partition = {partition}\nend\n"
            f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n")
    return xcrack_runs.run_xcrack(text, work, ranks)[-1]


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--meshes", type=int, default=5)
    parser.add_argument("--gathered", action="store_true")
    args = parser.parse_args()

    configurations = CONFIGURATIONS + ([ASSEMBLED_ROWS] if args.gathered
                                       else [])
    rows = {label: [] for label, _, _ in configurations}
    with tempfile.TemporaryDirectory() as work:
        for i in range(args.runs):
            for label, ranks, partition in configurations:
                rows[label].append(run(
                    args.meshes, ranks, partition, args.gathered, work,
                    "assembly" if label == ASSEMBLED_ROWS[0] else "balanced"))
                print(f"run {i + 1} {label}: "
                      + ", ".join(f"{name} {float(rows[label][-1][key]):.2f} s"
                                  for key, name in PHASES), file=sys.stderr)

    last = rows["one rank"][-1]
    print(f"\nPenny, mesh {last['mesh']}: {int(last['dofs']):,} DoFs "
          f"({int(last['enriched_dofs']):,} enriched), "
          + ("gathered, CG + AMG" if args.gathered else "MUMPS") + ", "
          f"median of {args.runs} runs (seconds; speed-up over one rank)\n")
    labels = [label for label, _, _ in configurations]
    print("| phase |" + "".join(f" {label} |" for label in labels))
    print("|---" * (len(labels) + 1) + "|")
    for key, name in PHASES + [(None, "the whole solve")]:
        medians = {}
        for label in labels:
            values = [sum(float(r[k]) for k, _ in PHASES) if key is None
                      else float(r[key]) for r in rows[label]]
            medians[label] = statistics.median(values)
        base = medians["one rank"]
        print(f"| {name} |" + "".join(
            f" {medians[label]:.2f}" + (f" ({base / medians[label]:.2f}x)"
                                        if label != "one rank" else "") + " |"
            for label in labels))
    # Each run's ratio to the one-rank run beside it: a load that comes and
    # goes hits both.
    whole = {label: [sum(float(r[k]) for k, _ in PHASES) for r in rows[label]]
             for label in labels}
    print("| speed-up, median of the runs' own |" + "".join(
        " - |" if label == "one rank" else
        f" {statistics.median(b / v for b, v in zip(whole['one rank'], whole[label])):.2f}x |"
        for label in labels))
    print("| work imbalance |" + "".join(
        f" {float(rows[label][-1].get('work_imbalance') or 1):.2f} |"
        for label in labels))
    print()
    for label in labels:
        print(f"{label}: {xcrack_runs.k_errors(rows[label][-1], 6)}")


if __name__ == "__main__":
    main()
