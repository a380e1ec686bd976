#!/usr/bin/python3
"""The cost of one 3D X-FEM solve by phase (setup, assembly, solve, K
extraction) on a mesh of the penny of doc/benchmarks.md Case 5, for the current
build and, to measure a change, a baseline build measured in the same
invocation (runs alternate between the builds, so that a load that comes and
goes hits both).

    contrib/build.sh release
    # before a change: keep the build aside
    mkdir -p /tmp/baseline && cp build/release/xcrack build/release/libxcrack_core.so* /tmp/baseline/
    # after it:
    /usr/bin/python3 contrib/study_step_cost.py --baseline /tmp/baseline [--runs 3] [--meshes 5] [--ranks 1]
        [--variant LABEL SECTION/ENTRY=VALUE ...]   # the current build with an entry changed

Prints a markdown table of the medians of each phase on the last mesh, with
the ratio baseline / current, and the K errors of both (the same problem
must give the same K, or the change says why not).
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


def run(binary, meshes, ranks, work, extra=""):
    """The last statistics row of the penny on `meshes` meshes with the
    xcrack at `binary` (None: the current build), `extra` parameter text
    added."""
    text = (f"include {os.path.join(xcrack_runs.top, 'prm', 'benchmarks', 'sif_penny_3d.prm')}\n"
            f"set Output directory = {os.path.join(work, 'out')}\n"
            "subsection Output\n  set Timing summary = false\nend\n"
            "subsection Linear solver\n  set Type = direct\nend\n"
            f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n"
            + extra)
    return xcrack_runs.run_xcrack(
        text, work, ranks,
        binary=os.path.join(binary, "xcrack") if binary else None)[-1]


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--baseline", help="directory with a baseline "
                        "build's xcrack and libxcrack_core.so")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--meshes", type=int, default=5)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--variant", nargs=2, action="append", default=[],
                        metavar=("LABEL", "SECTION/ENTRY=VALUE"),
                        help="also run the current build with one entry "
                        "changed, e.g. --variant 'tip rule near the front' "
                        "'Enrichment/Near-front quadrature tolerance=0'")
    args = parser.parse_args()

    builds = [("current", None, "")]
    if args.baseline:
        builds.insert(0, ("baseline", os.path.abspath(args.baseline), ""))
    for label, setting in args.variant:
        entry, value = setting.split("=", 1)
        section, name = entry.rsplit("/", 1)
        builds.insert(-1, (label, None, f"subsection {section}\n"
                           f"  set {name} = {value}\nend\n"))
    rows = {label: [] for label, _, _ in builds}
    with tempfile.TemporaryDirectory() as work:
        for i in range(args.runs):
            for label, binary, extra in builds:
                rows[label].append(run(binary, args.meshes, args.ranks, work,
                                       extra))
                print(f"run {i + 1} {label}: "
                      + ", ".join(f"{name} {float(rows[label][-1][key]):.2f} s"
                                  for key, name in PHASES), file=sys.stderr)

    last = rows["current"][-1]
    print(f"\nPenny, mesh {last['mesh']}: {int(last['dofs']):,} DoFs "
          f"({int(last['enriched_dofs']):,} enriched), {args.ranks} rank(s), "
          f"median of {args.runs} runs (seconds)\n")
    header = "| phase |" + "".join(f" {label} |" for label, _, _ in builds)
    if args.baseline:
        header += " baseline / current |"
    print(header)
    print("|---" * (header.count("|") - 1) + "|")
    for key, name in PHASES + [(None, "setup + assembly + K")]:
        medians = {}
        for label, _, _ in builds:
            values = [sum(float(r[k]) for k in ("t_setup", "t_assemble",
                                                 "t_fracture"))
                      if key is None else float(r[key]) for r in rows[label]]
            medians[label] = statistics.median(values)
        line = f"| {name} |" + "".join(f" {medians[label]:.2f} |"
                                       for label, _, _ in builds)
        if args.baseline:
            line += f" {medians['baseline'] / medians['current']:.2f} |"
        print(line)
    print()
    for label, _, _ in builds:
        print(f"{label}: {xcrack_runs.k_errors(rows[label][-1], 3)}")


if __name__ == "__main__":
    main()
