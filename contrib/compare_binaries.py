#!/usr/bin/python3
"""Time two xcrack binaries on the same scenes, runs alternating.

A change on the solve's path must not make linear scenes slower: this runs
the baseline (an xcrack built from an earlier commit, e.g. in a git
worktree) and the current build on each scene, alternating so that both see
the same machine, and prints per scene the medians of the wall time and of
the assembly and solve phases (statistics.csv, summed over the run's rows),
their ratio new / baseline, and the largest relative difference of the K's
the two wrote (the same numbers, or the change moved them).

    git worktree add /tmp/baseline <commit> && (cd /tmp/baseline &&
        contrib/build.sh release)
    /usr/bin/python3 contrib/compare_binaries.py \\
        --baseline /tmp/baseline/build/release/xcrack [--runs 3] \\
        [--scenes demo penny]

Scenes: demo (prm/demo.prm, a 2D growth run of 24 steps), penny
(prm/benchmarks/sif_penny_3d.prm, a 3D static run of about 100 s).
"""
import argparse
import csv
import glob
import os
import statistics
import subprocess
import tempfile
import time

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
scenes = {
    "demo": os.path.join(top, "prm", "demo.prm"),
    "penny": os.path.join(top, "prm", "benchmarks", "sif_penny_3d.prm"),
}


def run(binary, scene, out):
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(f"include {scenes[scene]}\nset Output directory = {out}\n"
                "subsection Output\n  set Write vtu = false\nend\n")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    start = time.perf_counter()
    # From the repository's top: the benchmarks name files relative to it.
    subprocess.run([binary, prm], check=True, env=env, cwd=top,
                   stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    with open(os.path.join(out, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    phases = {p: sum(float(r[p]) for r in rows if r.get(p))
              for p in ("t_assemble", "t_solve")}
    phases["wall"] = wall
    return phases


def k_values(out):
    values = []
    for name in sorted(glob.glob(os.path.join(out, "front_*.csv"))):
        with open(name) as f:
            for row in csv.DictReader(f):
                values += [float(row[k]) for k in ("K_I", "K_II", "K_III")]
    return values


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--baseline", required=True,
                        help="the xcrack binary to compare with")
    parser.add_argument("--new", default=os.path.join(
        top, "build", "release", "xcrack"), help="default: build/release")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--scenes", nargs="+", default=["demo", "penny"],
                        choices=sorted(scenes))
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="xcrack-compare-")
    print("| scene | phase | baseline (s) | new (s) | new / baseline |")
    print("|---|---|---|---|---|")
    for scene in args.scenes:
        times = {"baseline": [], "new": []}
        for r in range(args.runs):
            for label, binary in (("baseline", args.baseline),
                                  ("new", args.new)):
                out = os.path.join(work, f"{scene}-{label}")
                times[label].append(run(binary, scene, out))
        for phase in ("wall", "t_assemble", "t_solve"):
            a = statistics.median(t[phase] for t in times["baseline"])
            b = statistics.median(t[phase] for t in times["new"])
            print(f"| {scene} | {phase} | {a:.2f} | {b:.2f} | {b / a:.3f} |")
        ka = k_values(os.path.join(work, f"{scene}-baseline"))
        kb = k_values(os.path.join(work, f"{scene}-new"))
        scale = max(abs(k) for k in ka + kb) if ka else 1
        difference = (max(abs(x - y) for x, y in zip(ka, kb)) / scale
                      if len(ka) == len(kb) and ka else float("nan"))
        print(f"| {scene} | largest K difference / max K | "
              f"{difference:.1e} | | |")


if __name__ == "__main__":
    main()
