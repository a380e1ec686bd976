#!/usr/bin/python3
"""Baseline timing of an uncracked 3D Q1 elasticity solve (about 200k DoFs).

Every later X-FEM solve is compared with this. For each solver (direct MUMPS,
CG + AMG) and each rank count (1, 2) the run is repeated and the median of
each phase's wall time is printed as a Markdown table, with the ratio to the
direct solver on one rank measured in the same invocation.

    contrib/build.sh release
    python3 contrib/benchmark_baseline.py [--runs 3] [--subdivisions 40]

The scene is the 3D manufactured solution (prm/benchmarks/manufactured_3d.prm)
on one uniform mesh of subdivisions^3 cells, so the errors double as a check
that every configuration solved the same problem.
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")


def run(solver, ranks, subdivisions, workdir):
    prm = os.path.join(workdir, "baseline.prm")
    with open(prm, "w") as f:
        f.write(f"""include {top}/prm/benchmarks/manufactured_3d.prm
set Output directory = {workdir}/out
subsection Mesh
  set Subdivisions = {subdivisions}, {subdivisions}, {subdivisions}
  set Initial global refinement = 0
end
subsection Mesh refinement
  set Number of meshes = 1
end
subsection Linear solver
  set Type = {solver}
  set Relative tolerance = 1e-8
end
subsection Output
  set Write vtu = false
  set Timing summary = false
end
""")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OPENBLAS_NUM_THREADS="1")
    command = [xcrack, prm]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks)] + command
    start = time.perf_counter()
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    with open(os.path.join(workdir, "out", "statistics.csv")) as f:
        row = list(csv.DictReader(f))[-1]
    row["t_total"] = wall
    return row


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--subdivisions", type=int, default=40)
    args = parser.parse_args()
    if not os.path.exists(xcrack):
        sys.exit("build first: contrib/build.sh release")

    phases = ["t_setup", "t_assemble", "t_solve", "t_errors", "t_total"]
    results = []
    with tempfile.TemporaryDirectory() as workdir:
        for solver in ["direct", "cg amg"]:
            for ranks in [1, 2]:
                rows = [run(solver, ranks, args.subdivisions, workdir)
                        for _ in range(args.runs)]
                medians = {p: statistics.median(float(r[p]) for r in rows)
                           for p in phases}
                results.append((solver, ranks, rows[0], medians))

    reference = results[0][3]["t_solve"]
    print(f"Median of {args.runs} runs; ratio = t_solve / t_solve(direct, 1 rank).\n")
    print("| solver | ranks | dofs | iterations | energy error | t_setup (s) | "
          "t_assemble (s) | t_solve (s) | t_errors (s) | total (s) | solve ratio |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for solver, ranks, row, m in results:
        print(f"| {solver} | {ranks} | {row['dofs']} | {row['solver_iterations']} | "
              f"{float(row['energy_error']):.4e} | {m['t_setup']:.2f} | "
              f"{m['t_assemble']:.2f} | {m['t_solve']:.2f} | {m['t_errors']:.2f} | "
              f"{m['t_total']:.2f} | "
              f"{m['t_solve'] / reference:.3f} |")


if __name__ == "__main__":
    main()
