#!/usr/bin/env python3
"""The cost of a 2D growth step by phase (issue 44 §4): what a step spends
outside the solve and the K extraction, on the demo (prm/demo.prm) and on
paris_center_2d with its VTU files written, for the current build and, to
measure a change, a baseline build measured in the same invocation (runs
alternate between the builds).

    contrib/build.sh release
    # before a change: keep the build aside
    mkdir -p /tmp/baseline && cp build/release/xcrack build/release/libxcrack_core.so* /tmp/baseline/
    # after it:
    /usr/bin/python3 contrib/study_2d_step.py --baseline /tmp/baseline [--runs 5]

Prints per scene a markdown table of the median seconds per growth step of
each phase (statistics.csv's t_* columns over the steps after step 0), the
overhead (every phase but solve and K extraction) as a share of the step,
the ratio baseline / current, the cycles at the end (the same problem must
give the same life) and the bytes of VTU files written.
"""
import argparse
import glob
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import xcrack_runs  # noqa: E402

PHASES = ["solve", "fracture", "assemble", "setup", "refine", "levelset",
          "checkpoint", "output", "errors"]
WORK = {"solve", "fracture"}
SCENES = {
    "demo (prm/demo.prm)": "demo",
    "paris_center_2d, VTU on": "benchmarks/paris_center_2d",
}


def run(scene, binary, work):
    """Per-step seconds of each phase, the cycles at the end and the VTU
    bytes of one run of `scene` (a prm under prm/) by `binary`."""
    text = (f"include {xcrack_runs.top}/prm/{scene}.prm\n"
            f"set Output directory = {work}/out\n"
            "subsection Output\n  set Timing summary = false\n"
            "  set Write vtu = true\nend\n")
    rows = xcrack_runs.run_xcrack(text, work, binary=binary)
    growth = [r for r in rows if int(r["step"]) > 0]
    per_step = {p: sum(xcrack_runs.number(r.get(f"t_{p}"), 0.)
                       for r in growth) / len(growth) for p in PHASES}
    vtu = sum(os.path.getsize(f)
              for f in glob.glob(os.path.join(work, "out", "*.vtu")))
    return per_step, float(rows[-1]["cycles"]), vtu


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--baseline", help="directory with a baseline "
                        "build's xcrack and libxcrack_core.so")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    builds = [("current", None)]
    if args.baseline:
        builds.insert(0, ("baseline",
                          os.path.join(os.path.abspath(args.baseline),
                                       "xcrack")))
    for name, scene in SCENES.items():
        results = {label: [] for label, _ in builds}
        for _ in range(args.runs):
            for label, binary in builds:
                with tempfile.TemporaryDirectory() as work:
                    results[label].append(run(scene, binary, work))
        print(f"\n{name}: seconds per growth step, median of {args.runs} "
              "runs\n")
        labels = [label for label, _ in builds]
        print("| phase | " + " | ".join(labels) +
              (" | baseline / current |" if args.baseline else " |"))
        print("|---" * (len(labels) + 1 + bool(args.baseline)) + "|")
        medians = {label: {p: statistics.median(r[0][p]
                                                for r in results[label])
                           for p in PHASES} for label in labels}
        for p in PHASES + ["step", "overhead"]:
            values = {}
            for label in labels:
                m = medians[label]
                step = sum(m.values())
                values[label] = (step if p == "step" else
                                 step - sum(m[w] for w in WORK)
                                 if p == "overhead" else m[p])
            cells = []
            for label in labels:
                v = values[label]
                step = sum(medians[label].values())
                share = f" ({v / step:.0%})" if p != "step" else ""
                cells.append(f"{v:.4f}{share}")
            ratio = ""
            if args.baseline and values["current"] > 0:
                ratio = f" | {values['baseline'] / values['current']:.2f}"
            print(f"| {p} | " + " | ".join(cells) + ratio + " |")
        for label in labels:
            cycles = {f"{r[1]:.6g}" for r in results[label]}
            vtu = statistics.median(r[2] for r in results[label])
            print(f"\n{label}: cycles at the end {', '.join(sorted(cycles))}; "
                  f"VTU files {vtu / 1e6:.2f} MB")


if __name__ == "__main__":
    main()
