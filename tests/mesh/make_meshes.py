#!/usr/bin/env python3
"""Write the small distorted meshes of the patch tests (Gmsh 2.2 format).

Interior nodes are moved off the regular grid, and boundary nodes are moved
along their (flat) boundary, so that no two cells are parallelograms of the
same shape. Boundary physical tags follow deal.II's colorize rule: 0/1 at the
lower/upper x, 2/3 for y, 4/5 for z.

    python3 tests/mesh/make_meshes.py   # rewrites distorted_2d.msh, distorted_3d.msh
"""
import itertools
import os
import random

here = os.path.dirname(os.path.abspath(__file__))


def coordinates(n, dim, seed):
    """Nodes of an n^dim grid on [0,1]^dim, randomly moved by up to 0.3 h."""
    rng = random.Random(seed)
    h = 1.0 / (n - 1)
    nodes = {}
    for index in itertools.product(range(n), repeat=dim):
        x = [i * h for i in index]
        for d in range(dim):
            if 0 < index[d] < n - 1:
                x[d] += rng.uniform(-0.3, 0.3) * h
        nodes[index] = x + [0.0] * (3 - dim)
    return nodes


def write(path, nodes, cells, faces):
    ids = {index: k + 1 for k, index in enumerate(sorted(nodes))}
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for index in sorted(nodes):
            f.write("%d %.15g %.15g %.15g\n" % ((ids[index],) + tuple(nodes[index])))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(cells) + len(faces)))
        k = 1
        for kind, tag, vertices in faces + cells:
            f.write("%d %d 2 %d %d %s\n" % (k, kind, tag, tag, " ".join(str(ids[v]) for v in vertices)))
            k += 1
        f.write("$EndElements\n")


def mesh_2d(n=4):
    nodes = coordinates(n, 2, seed=2)
    cells, faces = [], []
    for i, j in itertools.product(range(n - 1), repeat=2):
        cells.append((3, 10, [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]))
    for k in range(n - 1):
        faces.append((1, 0, [(0, k), (0, k + 1)]))
        faces.append((1, 1, [(n - 1, k), (n - 1, k + 1)]))
        faces.append((1, 2, [(k, 0), (k + 1, 0)]))
        faces.append((1, 3, [(k, n - 1), (k + 1, n - 1)]))
    write(os.path.join(here, "distorted_2d.msh"), nodes, cells, faces)


def mesh_3d(n=3):
    nodes = coordinates(n, 3, seed=3)
    cells, faces = [], []
    for i, j, k in itertools.product(range(n - 1), repeat=3):
        bottom = [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k)]
        top = [(a, b, c + 1) for a, b, c in bottom]
        cells.append((5, 10, bottom + top))
    for a, b in itertools.product(range(n - 1), repeat=2):
        square = [(a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1)]
        for d in range(3):
            for side, tag in ((0, 2 * d), (n - 1, 2 * d + 1)):
                quad = []
                for p, q in square:
                    index = [p, q]
                    index.insert(d, side)
                    quad.append(tuple(index))
                faces.append((3, tag, quad))
    write(os.path.join(here, "distorted_3d.msh"), nodes, cells, faces)


if __name__ == "__main__":
    mesh_2d()
    mesh_3d()
