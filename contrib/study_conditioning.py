#!/usr/bin/env python3
"""Condition number of the Heaviside-enriched matrix against the distance of
the crack to a row of nodes, with and without the volume criterion.

A crack crossing the unit square (8 x 8 Q1 cells, h = 0.125) at height
0.5 + delta splits it; the lower part is clamped and the upper one moved
rigidly, so the exact solution is known. For each delta the script prints
the condition number of the stiffness matrix (free DoFs, dense eigenvalues)
and the relative L2 error, with `Heaviside volume tolerance` = 0 (every cut
support enriched) and = 1e-9 (the default).

    contrib/build.sh release
    python3 contrib/study_conditioning.py
"""
import csv
import os
import subprocess
import tempfile

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")


def run(delta, tolerance, work):
    y = repr(0.5 + delta)
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(f"""set Dimension = 2
set Output directory = {work}/out
subsection Output
  set Write vtu = false
  set Timing summary = false
  set Condition number up to dofs = 5000
end
subsection Mesh
  set Subdivisions = 8, 8
end
subsection Enrichment
  set Heaviside volume tolerance = {tolerance}
end
subsection Boundary conditions
  set Dirichlet = 2: 0; 0 | 3: 0.01; 0.1
end
subsection Exact solution
  set Displacement = y >= {y} ? 0.01 : 0; y >= {y} ? 0.1 : 0
end
subsection Cracks
  set Number of cracks = 1
  subsection Crack 1
    set Start point = -0.1, {y}
    set End point = 1.1, {y}
    set Tips = none
  end
end
""")
    subprocess.run([xcrack, prm], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    with open(os.path.join(work, "out", "statistics.csv")) as f:
        row = list(csv.DictReader(f))[0]
    return row


def main():
    print("| delta / h | enriched DoFs (tol 0) | condition number (tol 0) | "
          "L2 error (tol 0) | enriched DoFs (tol 1e-9) | condition number "
          "(tol 1e-9) | L2 error (tol 1e-9) |")
    print("|---|---|---|---|---|---|---|")
    h = 0.125
    with tempfile.TemporaryDirectory() as work:
        for exponent in [1, 2, 4, 6, 8, 10, 12]:
            delta = 10.0 ** (-exponent) * h
            a = run(delta, 0, work)
            b = run(delta, 1e-9, work)
            print(f"| 1e-{exponent} | {a['enriched_dofs']} | "
                  f"{float(a['condition_number']):.2e} | {float(a['L2_error']):.1e} | "
                  f"{b['enriched_dofs']} | {float(b['condition_number']):.2e} | "
                  f"{float(b['L2_error']):.1e} |")
        a = run(0.0, 0, work)
        print(f"| 0 (through the nodes) | {a['enriched_dofs']} | "
              f"{float(a['condition_number']):.2e} | {float(a['L2_error']):.1e} | "
              "same | same | same |")


if __name__ == "__main__":
    main()
