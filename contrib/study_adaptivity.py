#!/usr/bin/python3
"""Adaptive refinement on a cracked body (doc/verification.md, "Adaptive
refinement that knows the crack"): the energy error against the DoFs for
each refinement strategy, printed as markdown tables.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_adaptivity.py case1 [--jobs 2]
    /usr/bin/python3 contrib/study_adaptivity.py case1_3d

`case1`: doc/benchmarks.md Case 1 (prm/benchmarks/exact_mode_I_2d.prm, the
exact Williams field of K_I = 1 on the boundary) with topological tip
enrichment (the tip cell's nodes only), where the energy error of uniform
refinement goes like N^(-1/4) and adaptivity must recover Q1's N^(-1/2).
Two meshes: the crack along a row of nodes ending on a node (the
benchmark's mesh), and a crack through the middle of a row of cells with
its tip at a cell's centre (5 x 5 cells). Strategies: global, front
(hand-made, around the tip), kelly (deal.II's indicator, which reads the
crack's opening as error) and residual (ResidualEstimator: the cracks as
boundaries), with fixed-number and fixed-fraction marking. The rate is the
least-squares slope of log(error) against log(DoFs) over the last four
meshes; "uniform at equal DoFs" is the error of global refinement
interpolated (log-log) at the strategy's last DoFs, divided by the
strategy's error.

`case1_3d`: the 3D version (prm/benchmarks/exact_mode_I_3d.prm, a
straight front through a cube), same strategies; optimal is N^(-1/3)
(30 min; the K_I column is empty: a 3D front has no single K).

`hole`: prm/benchmarks/adaptive_hole_2d.prm, an edge crack heading for a
hole (the square [-1,1]^2 with a hole of radius 0.2 at its centre, crack
from the left face to x = -0.5 at y = 0.05, bottom held, tension 1 on the
top): K_I and the cells of global and residual refinement, and
doc/figures/adapted_mesh_hole.png, the tenth residual mesh (refined at the
tip, around the hole where the stress concentrates, and at the corners
where the held bottom meets the free sides).

`collinear`: several cracks, prm/benchmarks/sif_collinear_2d.prm (two
collinear cracks in a large plate, closed-form K_I at the four tips) with
topological enrichment: the largest K_I error over the tips against the
DoFs for front and residual refinement.

`case1` also draws doc/figures/adaptivity_case1.png (error against DoFs),
and `meshes` draws doc/figures/adapted_meshes_case1.png: the tenth mesh of
kelly and of residual on Case 1, crack along a row of nodes.
"""
import argparse
import base64
import math
import os
import re
import struct
import tempfile
import zlib
from concurrent.futures import ThreadPoolExecutor

from xcrack_runs import run_xcrack, top

TOPOLOGICAL = ("subsection Enrichment\n  set Tip enrichment = topological\n"
               "  set Enrichment radius = 0\nend\n")


def strategy_entries(strategy, fraction=None, marking=None):
    text = f"subsection Mesh refinement\n  set Strategy = {strategy}\n"
    if strategy == "kelly":
        text += f"  subsection Kelly\n    set Refine fraction = {fraction}\n  end\n"
    if strategy == "residual":
        text += (f"  subsection Residual\n    set Marking = {marking}\n"
                 f"    set Refine fraction = {fraction}\n  end\n")
    return text + "end\n"


def run_scene(benchmark, entries, meshes, picture_mesh=None):
    """Run prm/benchmarks/<benchmark>.prm with `entries` on `meshes` meshes:
    the rows of statistics.csv and, with `picture_mesh`, the corners of
    that mesh's cells (2D)."""
    with tempfile.TemporaryDirectory() as work:
        vtu = "false" if picture_mesh is None else "true"
        text = (f"include {top}/prm/benchmarks/{benchmark}.prm\n"
                f"set Output directory = {work}/out\n"
                "subsection Output\n  set Timing summary = false\n"
                f"  set Write vtu = {vtu}\nend\n"
                f"subsection Mesh refinement\n  set Number of meshes = {meshes}\n"
                "end\n" + entries)
        rows = run_xcrack(text, work)
        cells = (None if picture_mesh is None else read_cells(
            f"{work}/out/solution-000.{picture_mesh:02d}.0000.vtu"))
    return rows, cells


def run(benchmark, label, entries, meshes, max_level, cells=False):
    """The (DoFs, energy error, K_I) of every mesh; with `cells`, the
    corners of the last mesh's cells instead (2D)."""
    rows, picture = run_scene(
        benchmark, entries + "subsection Mesh refinement\n"
        f"  set Maximum level = {max_level}\nend\n", meshes,
        meshes - 1 if cells else None)
    if cells:
        return label, picture
    return label, [(int(r["dofs"]), float(r["energy_error"]),
                    float(r["K_I_1"]) if "K_I_1" in r else float("nan"))
                   for r in rows]


def read_cells(vtu):
    """The corners of the cells of a 2D deal.II vtu file (zlib-compressed,
    one patch of four points per cell, in deal.II's lexicographic order)."""
    with open(vtu) as f:
        text = f.read()
    data = re.search(r'<Points>\s*<DataArray[^>]*>\s*([^<\s]+)', text).group(1)
    n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
    header_chars = 4 * math.ceil(4 * (3 + n_blocks) / 3)
    header = struct.unpack(f"<{3 + n_blocks}I",
                           base64.b64decode(data[:header_chars]))
    raw, compressed = b"", base64.b64decode(data[header_chars:])
    for size in header[3:]:
        raw += zlib.decompress(compressed[:size])
        compressed = compressed[size:]
    xyz = struct.unpack(f"<{len(raw) // 4}f", raw)
    points = [(xyz[i], xyz[i + 1]) for i in range(0, len(xyz), 3)]
    return [[points[i], points[i + 1], points[i + 3], points[i + 2]]
            for i in range(0, len(points), 4)]


def draw_meshes(jobs):
    cases = [("kelly, 0.2", strategy_entries("kelly", 0.2)),
             ("residual, 0.2", strategy_entries("residual", 0.2, "fixed number"))]
    with ThreadPoolExecutor(jobs) as pool:
        futures = [pool.submit(run, "exact_mode_I_2d", label,
                               TOPOLOGICAL + entries, 10, 12, True)
                   for label, entries in cases]
        meshes = dict(f.result() for f in futures)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    figure, axes = plt.subplots(1, 2, figsize=(10, 5))
    for axis, (label, cells) in zip(axes, meshes.items()):
        axis.add_collection(PolyCollection(cells, facecolors="none",
                                           edgecolors="k", linewidths=0.2))
        axis.plot([-1, 0], [0, 0], "r-", linewidth=1)
        axis.set_xlim(-1, 1)
        axis.set_ylim(-1, 1)
        axis.set_aspect("equal")
        axis.set_title(f"{label}: {len(cells)} cells (crack in red)")
    figure.tight_layout()
    path = os.path.join(top, "doc", "figures", "adapted_meshes_case1.png")
    figure.savefig(path, dpi=150)
    print(f"wrote {path}")




def hole(jobs):
    def run_hole(label, entries, meshes, cells=False):
        # The picture: the tenth mesh (the last ones are black).
        rows, picture = run_scene("adaptive_hole_2d", entries, meshes,
                                  9 if cells else None)
        return label, [(int(r["cells"]), int(r["dofs"]), float(r["K_I_1"]))
                       for r in rows], picture

    cases = [("global", strategy_entries("global"), 5, False),
             ("residual, fixed number 0.2",
              strategy_entries("residual", 0.2, "fixed number"), 16, True)]
    with ThreadPoolExecutor(jobs) as pool:
        results = [f.result() for f in
                   [pool.submit(run_hole, *case) for case in cases]]
    reference = results[1][1][-1][2]
    print(f"K_I against the last residual mesh ({reference:.6f}):\n")
    print("| strategy | mesh | cells | DoFs | K_I | K_I / reference - 1 |")
    print("|---|---|---|---|---|---|")
    for label, rows, _ in results:
        for m, (cells, dofs, k) in enumerate(rows):
            print(f"| {label} | {m} | {cells:,} | {dofs:,} | {k:.6f} | "
                  f"{k / reference - 1:+.2e} |")
    print()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    picture = results[1][2]
    figure, axis = plt.subplots(figsize=(6, 6))
    axis.add_collection(PolyCollection(picture, facecolors="none",
                                       edgecolors="k", linewidths=0.2))
    axis.plot([-1, -0.5], [0.05, 0.05], "r-", linewidth=1)
    axis.set_xlim(-1, 1)
    axis.set_ylim(-1, 1)
    axis.set_aspect("equal")
    axis.set_title(f"residual, tenth mesh: {len(picture)} cells (crack in red)")
    figure.tight_layout()
    path = os.path.join(top, "doc", "figures", "adapted_mesh_hole.png")
    figure.savefig(path, dpi=150)
    print(f"wrote {path}")


def collinear(jobs):
    reference = {"inner": 1.857461, "outer": 1.822000}

    def run_collinear(label, entries, meshes):
        rows, _ = run_scene("sif_collinear_2d", TOPOLOGICAL + entries, meshes)
        result = []
        for r in rows:
            # Tips 1, 4 outer (|x| = 3), 2, 3 inner, numbered crack by crack.
            errors = [abs(float(r[f"K_I_{t}"]) / reference[kind] - 1)
                      for t, kind in [(1, "outer"), (2, "inner"),
                                      (3, "inner"), (4, "outer")]
                      if f"K_I_{t}" in r]
            result.append((int(r["dofs"]), max(errors)))
        return label, result

    cases = [("front (band 4)", strategy_entries("front"), 5),
             ("residual, fixed number 0.2",
              strategy_entries("residual", 0.2, "fixed number"), 12)]
    with ThreadPoolExecutor(jobs) as pool:
        results = [f.result() for f in
                   [pool.submit(run_collinear, *case) for case in cases]]
    print("| strategy | mesh | DoFs | largest K_I error over the 4 tips |")
    print("|---|---|---|---|")
    for label, rows in results:
        for m, (dofs, error) in enumerate(rows):
            print(f"| {label} | {m} | {dofs:,} | {100 * error:.3f} % |")
    print()


def plot(all_results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, len(all_results),
                                figsize=(5.5 * len(all_results), 4.5))
    if len(all_results) == 1:
        axes = [axes]
    for axis, (title, results) in zip(axes, all_results.items()):
        for label, rows in results.items():
            axis.loglog([n for n, _, _ in rows], [e for _, e, _ in rows],
                        "o-", markersize=3, label=label)
        axis.set_xlabel("DoFs")
        axis.set_ylabel("relative energy error")
        axis.set_title(title)
        axis.grid(True, which="both", linewidth=0.3)
        axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=150)
    print(f"wrote {path}")


def slope(points):
    x = [math.log(n) for n, _ in points]
    y = [math.log(e) for _, e in points]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return (sum((a - mx) * (b - my) for a, b in zip(x, y))
            / sum((a - mx) ** 2 for a in x))


def uniform_at(uniform, dofs):
    """log-log interpolation (or extrapolation by the last two) of the
    uniform error at `dofs`."""
    for (n0, e0), (n1, e1) in zip(uniform, uniform[1:]):
        if dofs <= n1 or (n1, e1) == uniform[-1]:
            t = math.log(dofs / n0) / math.log(n1 / n0)
            return math.exp(math.log(e0) + t * math.log(e1 / e0))


def table(results):
    uniform = [(n, e) for n, e, _ in results["global"]]
    print("| strategy | meshes | DoFs (last) | energy error (last) | rate in N "
          "(last 4) | uniform / this at equal DoFs | K_I (last) |")
    print("|---|---|---|---|---|---|---|")
    for label, rows in results.items():
        n, e, k = rows[-1]
        tail = [(a, b) for a, b, _ in rows[-4:]]
        rate = slope(tail) if len(set(a for a, _ in tail)) > 1 else float("nan")
        ratio = uniform_at(uniform, n) / e
        k_text = "-" if math.isnan(k) else f"{k:.5f}"
        print(f"| {label} | {len(rows)} | {n:,} | {e:.3e} | {rate:.2f} | "
              f"{ratio:.2f} | {k_text} |")
    print()
    print("Error against DoFs, every mesh:")
    print()
    for label, rows in results.items():
        print(f"- {label}: " + ", ".join(f"{n:,}: {e:.3e}" for n, e, _ in rows))
    print()


def case1(jobs, three_d=False):
    # In 3D, front refinement of a whole straight front runs out of memory
    # (24 GiB) on its ninth mesh: it stops at the seventh.
    front_meshes = 14
    if three_d:
        benchmarks = [("exact_mode_I_3d", "straight front", "")]
        adaptive_meshes, global_meshes, max_level = 8, 4, 8
        front_meshes = 7
    else:
        benchmarks = [
            ("exact_mode_I_2d", "crack along a row of nodes", ""),
            ("exact_mode_I_2d", "crack through a row of cells",
             "subsection Mesh\n  set Subdivisions = 5, 5\nend\n")]
        adaptive_meshes, global_meshes, max_level = 14, 7, 12
    all_results = {}
    for benchmark, title, mesh in benchmarks:
        cases = [("global", strategy_entries("global"), global_meshes),
                 ("front", strategy_entries("front"), front_meshes),
                 ("kelly 0.2", strategy_entries("kelly", 0.2), adaptive_meshes),
                 ("residual, fixed number 0.2",
                  strategy_entries("residual", 0.2, "fixed number"),
                  adaptive_meshes),
                 ("residual, fixed fraction 0.5",
                  strategy_entries("residual", 0.5, "fixed fraction"),
                  adaptive_meshes)]
        with ThreadPoolExecutor(jobs) as pool:
            futures = [pool.submit(run, benchmark, label,
                                   TOPOLOGICAL + mesh + entries, meshes,
                                   max_level)
                       for label, entries, meshes in cases]
            results = dict(f.result() for f in futures)
        print(f"### {benchmark}, {title}, topological enrichment\n")
        table(results)
        all_results[title] = results
    name = "adaptivity_case1_3d.png" if three_d else "adaptivity_case1.png"
    plot(all_results, os.path.join(top, "doc", "figures", name))


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=["case1", "case1_3d", "meshes", "hole",
                                          "collinear"])
    parser.add_argument("--jobs", type=int, default=2)
    arguments = parser.parse_args()
    if arguments.study == "meshes":
        draw_meshes(arguments.jobs)
    elif arguments.study == "hole":
        hole(arguments.jobs)
    elif arguments.study == "collinear":
        collinear(arguments.jobs)
    else:
        case1(arguments.jobs, arguments.study == "case1_3d")
