#!/usr/bin/python3
"""Condition number of the Heaviside-enriched matrix against the distance of
the crack to a row of nodes, with and without the volume criterion and fit
to vertex.

A crack crossing the unit square (8 x 8 Q1 cells, h = 0.125) at height
0.5 + delta splits it; the lower part is clamped and the upper one moved
rigidly, so the exact solution is known. For each delta the script prints
the condition number of the stiffness matrix (free DoFs, dense eigenvalues)
and the relative L2 error, with `Heaviside volume tolerance` = 0 (every cut
support enriched) and = 1e-9 (the default), and with `Fit to vertex
tolerance` = 1e-2 (the error against the crack where it was given: what
moving it costs).

A second table tilts the crack (slope 0.3) so that it passes delta from
one node (and 0.1 h or more from the others): the condition number for
several fit-to-vertex tolerances.

A third table takes doc/benchmarks.md Case 1 (prm/benchmarks/exact_mode_I_2d.prm)
on its first three meshes: the condition number against h for a geometric
tip zone, with and without DOF gathering.

    contrib/build.sh release
    python3 contrib/study_conditioning.py
"""
import argparse
import csv
import os
import subprocess
import tempfile

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
xcrack = os.path.join(top, "build", "release", "xcrack")


def run(delta, tolerance, work, fit=0.0, slope=0.0):
    """The crack y = 0.5 + delta + slope (x - 0.5) across the square."""
    y = f"0.5 + {delta!r} + {slope!r} * (x - 0.5)"
    y_start = 0.5 + delta + slope * (-0.1 - 0.5)
    y_end = 0.5 + delta + slope * (1.1 - 0.5)
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
  set Fit to vertex tolerance = {fit}
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
    set Start point = -0.1, {y_start!r}
    set End point = 1.1, {y_end!r}
    set Tips = none
  end
end
""")
    subprocess.run([xcrack, prm], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    with open(os.path.join(work, "out", "statistics.csv")) as f:
        row = list(csv.DictReader(f))[0]
    return row


def case1(work, meshes, zone, radius, gather):
    """Last row of statistics.csv of Case 1 in 2D with the given zone."""
    prm = os.path.join(work, "run.prm")
    with open(prm, "w") as f:
        f.write(f"""include {top}/prm/benchmarks/exact_mode_I_2d.prm
set Output directory = {work}/out
subsection Output
  set Timing summary = false
  set Condition number up to dofs = 5000
end
subsection Fracture parameters
  set Compute = false
end
subsection Mesh refinement
  set Number of meshes = {meshes}
end
subsection Enrichment
  set Tip enrichment = {zone}
  set Enrichment radius = {radius}
  set Gather tip DoFs = {str(gather).lower()}
end
""")
    subprocess.run([xcrack, prm], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    with open(os.path.join(work, "out", "statistics.csv")) as f:
        return list(csv.DictReader(f))


def main():
    argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    print("| delta / h | enriched DoFs (tol 0) | condition number (tol 0) | "
          "L2 error (tol 0) | enriched DoFs (tol 1e-9) | condition number "
          "(tol 1e-9) | L2 error (tol 1e-9) | enriched DoFs (fit 1e-2) | "
          "condition number (fit 1e-2) | crack moved by (fit 1e-2) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    h = 0.125
    with tempfile.TemporaryDirectory() as work:
        for exponent in [1, 2, 3, 4, 6, 8, 10, 12]:
            delta = 10.0 ** (-exponent) * h
            cells = []
            for tolerance, fit in [(0, 0), (1e-9, 0), (1e-9, 1e-2)]:
                r = run(delta, tolerance, work, fit)
                # A fitted crack lies at the row: its error against the
                # given crack is the band of wrong jump between the two,
                # which the cells' Gauss points do not see; report the move.
                error = (f"{float(r['L2_error']):.1e}" if fit == 0 else
                         f"{delta if delta <= fit * h else 0:.1e}")
                cells.append(f"{r['enriched_dofs']} | "
                             f"{float(r['condition_number']):.2e} | {error}")
            print(f"| 1e-{exponent} | " + " | ".join(cells) + " |")
        a = run(0.0, 0, work)
        print(f"| 0 (through the nodes) | {a['enriched_dofs']} | "
              f"{float(a['condition_number']):.2e} | {float(a['L2_error']):.1e} | "
              "same | same | same | same | same | same |")

        print("\nTilted crack (slope 0.3), delta above the node (0.5, 0.5) "
              "(condition numbers):\n")
        fits = [0, 1e-3, 1e-2, 1e-1]
        print("| delta / h | " + " | ".join(f"fit {f:g}" for f in fits) + " |")
        print("|---|" + "---|" * len(fits))
        for exponent in [2, 3, 4, 5]:
            delta = 10.0 ** (-exponent) * h
            row = [run(delta, 1e-9, work, fit, slope=0.3) for fit in fits]
            print(f"| 1e-{exponent} | " + " | ".join(
                f"{float(r['condition_number']):.2e}" for r in row) + " |")

        print("\nCase 1 (2D), condition number on the first meshes "
              "(h = 1/4, 1/8, 1/16), free enriched DoFs in brackets:\n")
        zones = [("topological", 0, False), ("geometric", 0.25, False),
                 ("geometric", 0.25, True), ("geometric", 0.5, False),
                 ("geometric", 0.5, True)]
        print("| zone | h = 1/4 | h = 1/8 | h = 1/16 |")
        print("|---|---|---|---|")
        for zone, radius, gather in zones:
            rows = case1(work, 3, zone, radius, gather)
            label = zone + (f" r = {radius}" if radius else "") + \
                (", gathered" if gather else "")
            print(f"| {label} | " + " | ".join(
                f"{float(r['condition_number']):.2e} ({r['enriched_dofs']})"
                for r in rows) + " |")


if __name__ == "__main__":
    main()
