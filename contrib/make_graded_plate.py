#!/usr/bin/python3
"""Write prm/benchmarks/meshes/graded_plate_2d.msh (Gmsh 2.2 format).

A square plate [-60, 60]^2 whose core [-4, 4]^2 is a uniform grid (30 x 29
cells, so that neither the line y = 0 nor the points x = +-1, +-3 fall on
nodes) and whose cells grow geometrically from the core to the edges. Wide
enough (half-width 20 times the crack span) for cracks in the core to see an
infinite plate (finite-width effect on K below 0.2 %), and fine enough at
the start for the enriched zones of cracks a few cells apart not to meet.
Boundary physical tags follow deal.II's colorize rule: 0/1 at the lower/upper
x, 2/3 at the lower/upper y.

    python3 contrib/make_graded_plate.py
"""
import argparse
import os

here = os.path.dirname(os.path.abspath(__file__))
target = os.path.join(here, "..", "prm", "benchmarks", "meshes", "graded_plate_2d.msh")


def graded(core, n_core, outer, n_outer):
    """Node coordinates: n_core uniform cells on [-core, core], then n_outer
    cells on each side growing geometrically (continuing the core spacing)
    out to +-outer."""
    h = 2 * core / n_core
    # Growth ratio r with h r + h r^2 + ... + h r^n = outer - core (bisection).
    lo, hi = 1.0, 3.0
    for _ in range(200):
        r = 0.5 * (lo + hi)
        total = h * r * (r ** n_outer - 1) / (r - 1)
        lo, hi = (r, hi) if total < outer - core else (lo, r)
    steps = [h * r ** (k + 1) for k in range(n_outer)]
    steps[-1] += (outer - core) - sum(steps)
    right = [core]
    for s in steps:
        right.append(right[-1] + s)
    middle = [-core + k * h for k in range(n_core + 1)]
    return [-x for x in reversed(right[1:])] + middle + right[1:]


def main():
    argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    xs = graded(4.0, 30, 60.0, 16)
    ys = graded(4.0, 29, 60.0, 16)
    nx, ny = len(xs), len(ys)
    node = lambda i, j: j * nx + i + 1
    cells, faces = [], []
    for j in range(ny - 1):
        for i in range(nx - 1):
            cells.append((3, 10, [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
    for j in range(ny - 1):
        faces.append((1, 0, [node(0, j), node(0, j + 1)]))
        faces.append((1, 1, [node(nx - 1, j), node(nx - 1, j + 1)]))
    for i in range(nx - 1):
        faces.append((1, 2, [node(i, 0), node(i + 1, 0)]))
        faces.append((1, 3, [node(i, ny - 1), node(i + 1, ny - 1)]))
    with open(target, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % (nx * ny))
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                f.write("%d %.15g %.15g 0\n" % (node(i, j), x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(cells) + len(faces)))
        for k, (kind, tag, vertices) in enumerate(faces + cells):
            f.write("%d %d 2 %d %d %s\n" % (k + 1, kind, tag, tag, " ".join(map(str, vertices))))
        f.write("$EndElements\n")
    print("%s: %d x %d cells, core spacing %.4g, largest %.4g" % (
        os.path.relpath(target), nx - 1, ny - 1, 8.0 / 30, xs[1] - xs[0]))


if __name__ == "__main__":
    main()
