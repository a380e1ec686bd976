#!/usr/bin/python3
"""Contact on the crack lips: accuracy and cost of the penalty formulation.

Runs the closed crack benchmark (prm/benchmarks/closed_crack_2d.prm: an
inclined centre crack under uniaxial compression, frictionless lips, the
exact closed-crack field on the boundary) and prints Markdown tables:

1. per mesh, for each pressure space (`lip points`, the naive one, and
   `cells`): K_I over the load's K scale p sqrt(pi a), the K_II error, the
   Newton steps, the closed fraction of the lips and the range of the
   contact pressure (exact: 0.75 everywhere);
2. against the penalty coefficient (pressure space `cells`, one mesh): the
   same, and the relative L2 error of the displacement.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_contact.py [--meshes 6] [--sweep-mesh 4]
"""
import argparse
import csv
import math
import os
import subprocess
import tempfile

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")
k_scale = math.sqrt(math.pi)  # p sqrt(pi a), p = a = 1


def run(work, meshes, space, coefficient):
    out = os.path.join(work, "out")
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(f"""include {top}/prm/benchmarks/closed_crack_2d.prm
set Output directory = {out}
subsection Contact
  subsection Penalty
    set Pressure space = {space}
    set Penalty coefficient = {coefficient}
  end
end
subsection Mesh refinement
  set Number of meshes = {meshes}
end
subsection Output
  set Timing summary = false
end
""")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    subprocess.run([xcrack, prm], check=True, env=env,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "statistics.csv")) as f:
        return list(csv.DictReader(f))


def row(r):
    return (f"{int(r['dofs']):,} | {abs(float(r['K_I_1'])) / k_scale:.2e} | "
            f"{float(r['K_II_error']):.2e} | {r['newton_iterations']} | "
            f"{float(r['contact_closed']):.3f} | "
            f"{float(r['contact_pressure_min']):.3f} to "
            f"{float(r['contact_pressure_max']):.3f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--meshes", type=int, default=6)
    parser.add_argument("--sweep-mesh", type=int, default=4,
                        help="the mesh (0-based) of the coefficient sweep")
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="xcrack-contact-")
    print("| space | DoFs | abs(K_I) / p sqrt(pi a) | K_II error | Newton "
          "steps | closed | contact pressure |")
    print("|---|---|---|---|---|---|---|")
    for space in ("lip points", "cells"):
        for r in run(work, args.meshes, space, 1000):
            print(f"| {space} | {row(r)} |")
    print()
    print("| coefficient | DoFs | abs(K_I) / p sqrt(pi a) | K_II error | "
          "Newton steps | closed | contact pressure | L2 error |")
    print("|---|---|---|---|---|---|---|---|")
    for c in (1e1, 1e2, 1e3, 1e4, 1e5, 1e6):
        r = run(work, args.sweep_mesh + 1, "cells", c)[-1]
        print(f"| {c:.0e} | {row(r)} | {float(r['L2_error']):.3e} |")


if __name__ == "__main__":
    main()
