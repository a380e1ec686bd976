#!/usr/bin/python3
"""K error against DoFs for every refinement strategy (issue 16; doc/
verification.md, "K error against DoFs, strategy by strategy").

Every run of a scene extracts K the same way (topological tip enrichment,
the crown as lengths, the linear crown weight; in 3D `k tolerance` also with
the smooth one), so the strategies differ only in their meshes: uniform (`global`), `front` (the tip's cells to the
maximum level), `kelly` (2D only: it reads the crack's opening as error),
`residual` (the cracks as boundaries, fixed number 0.2) and `k tolerance`
(one run with a tolerance it cannot meet within its meshes, so that every
mesh it takes is a point of the curve). The K error is the largest over
the tips (in 3D, the K nodes along the front) and the modes, relative to
the exact K_I. Prints a table per scene (every mesh: DoFs, K error and,
where the run estimates it, the largest estimated error) and draws
doc/figures/k_error_strategies.png.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_k_strategies.py --scenes 2d   # 20 s
    /usr/bin/python3 contrib/study_k_strategies.py               # 2D and 3D, 16 min

The 3D scenes stop at about 300k DoFs: two runs share the machine and the
direct solver's factorization of a 600k DoF X-FEM matrix takes about 12 GB.
"""
import argparse
import csv
import json
import os
import tempfile
from concurrent.futures import ThreadPoolExecutor

from xcrack_runs import benchmark_prm, front_file, run_xcrack, top

MODES = ("K_I", "K_II", "K_III")


def strategy(name, meshes, extra="", weight="linear"):
    """A run: its label, its number of meshes and its entries."""
    return (name + ("" if weight == "linear" else f", {weight} weight"),
            meshes,
            f"subsection Mesh refinement\n  set Strategy = {name}\n"
            f"  set Number of meshes = {meshes}\n{extra}end\n"
            "subsection Fracture parameters\n"
            f"  set Crown weight = {weight}\nend\n")


RESIDUAL = ("  subsection Residual\n    set Marking = fixed number\n"
            "    set Refine fraction = 0.2\n  end\n")
KELLY = "  subsection Kelly\n    set Refine fraction = 0.2\n  end\n"


def k_tolerance(tolerance, crown_cells):
    return (f"  subsection K tolerance\n    set Tolerance = {tolerance}\n"
            f"    set Crown cells = {crown_cells}\n  end\n")


# name: benchmark, exact (K_I, K_II, K_III), crown radii, maximum level,
# runs (label, meshes, entries).
SCENES = {
    "Case 1, 2D": ("exact_mode_I_2d", (1.0, 0.0, 0.0), (0.1, 0.3), 14,
                   [strategy("global", 6), strategy("front", 10),
                    strategy("kelly", 10, KELLY),
                    strategy("residual", 12, RESIDUAL),
                    strategy("k tolerance", 8, k_tolerance(1e-5, 8))]),
    "inclined crack, 2D": ("sif_inclined_2d", (1.32934039, 0.76749503, 0.0),
                           (0.1, 0.3), 14,
                           [strategy("global", 5), strategy("front", 10),
                            strategy("kelly", 10, KELLY),
                            strategy("residual", 12, RESIDUAL),
                            strategy("k tolerance", 8,
                                     k_tolerance(1e-5, 8))]),
    "Case 1, 3D": ("exact_mode_I_3d", (1.0, 0.0, 0.0), (0.2, 0.5), 10,
                   [strategy("global", 4), strategy("front", 6),
                    strategy("residual", 7, RESIDUAL),
                    strategy("k tolerance", 3, k_tolerance(2e-4, 4)),
                    strategy("k tolerance", 3, k_tolerance(2e-4, 4),
                             "smooth")]),
    "penny": ("sif_penny_3d", (1.12837917, 0.0, 0.0), (0.25, 0.75), 10,
              [strategy("global", 3), strategy("front", 5),
               strategy("residual", 5, RESIDUAL),
               strategy("k tolerance", 3, k_tolerance(2e-3, 4)),
               strategy("k tolerance", 3, k_tolerance(2e-3, 4), "smooth")]),
}


def run(scene, run_entries, meshes):
    """Per mesh: (DoFs, K error, largest estimated error or None, seconds
    of the whole solve)."""
    benchmark, exact, crown, max_level, _ = SCENES[scene]
    estimate = "k tolerance" in run_entries or "2D" in scene
    with tempfile.TemporaryDirectory() as work:
        text = benchmark_prm(
            benchmark, work,
            "subsection Enrichment\n  set Tip enrichment = topological\n"
            "  set Enrichment radius = 0\nend\n"
            "subsection Fracture parameters\n  set Crown unit = absolute\n"
            f"  set Crown radii = {crown[0]}, {crown[1]}\n"
            f"  set Error estimate = {str(estimate).lower()}\nend\n"
            f"subsection Mesh refinement\n  set Maximum level = {max_level}\n"
            "end\n" + run_entries)
        rows = run_xcrack(text, work)
        points = []
        for row in rows:
            time = sum(float(v) for k, v in row.items() if k.startswith("t_"))
            if "2D" in scene:
                tips = sorted({k.rsplit("_", 1)[1] for k in row
                               if k.startswith("K_I_") and
                               k.rsplit("_", 1)[1].isdigit()})
                values = [(float(row[f"{m}_{t}"]), e,
                           float(row[f"{m}_estimate_{t}"]))
                          for t in tips for m, e in zip(MODES[:2], exact)]
            else:
                with open(os.path.join(work, "out",
                                       front_file(row, meshes))) as f:
                    values = [(float(p[m]), e,
                               float(p[m + "_error"]) if estimate else 0)
                              for p in csv.DictReader(f)
                              for m, e in zip(MODES, exact)]
            error = max(abs(e - k) for k, e, _ in values) / exact[0]
            estimated = (max(abs(s) for _, _, s in values) / exact[0]
                         if estimate else None)
            points.append((int(row["dofs"]), error, estimated, time))
        return points


def main(scenes, jobs, results_file):
    runs = [(scene, name, meshes, entries) for scene in scenes
            for name, meshes, entries in SCENES[scene][4]]
    with ThreadPoolExecutor(jobs) as pool:
        futures = [pool.submit(run, scene, entries, meshes)
                   for scene, _, meshes, entries in runs]
        results = {f"{scene}|{name}": future.result()
                   for (scene, name, _, _), future in zip(runs, futures)}
    with open(results_file, "w") as f:
        json.dump(results, f)
    report(results)


def report(results):
    for scene in SCENES:
        keys = [k for k in results if k.startswith(scene + "|")]
        if not keys:
            continue
        print(f"\n{scene} ({SCENES[scene][0]}, topological, crown "
              f"{SCENES[scene][2][0]} to {SCENES[scene][2][1]})\n")
        print("| strategy | mesh | DoFs | K error | estimated | time (s) |")
        print("|---|---|---|---|---|---|")
        for key in keys:
            for m, (dofs, error, estimated, time) in enumerate(results[key]):
                print(f"| {key.split('|')[1]} | {m} | {dofs:,} | {error:.2e} "
                      f"| {'' if estimated is None else f'{estimated:.2e}'} "
                      f"| {time:.1f} |")
    draw(results)


def draw(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = [s for s in SCENES if any(k.startswith(s + "|") for k in results)]
    figure, axes = plt.subplots(1, len(scenes), figsize=(4.2 * len(scenes), 4))
    axes = axes if len(scenes) > 1 else [axes]
    styles = {"global": ("s-", "C0"), "front": ("^-", "C1"),
              "kelly": ("x-", "C2"), "residual": ("o-", "C3"),
              "k tolerance": ("D-", "C4"),
              "k tolerance, smooth weight": ("d--", "C5")}
    for axis, scene in zip(axes, scenes):
        for key, points in results.items():
            if not key.startswith(scene + "|"):
                continue
            name = key.split("|")[1]
            axis.loglog([p[0] for p in points], [p[1] for p in points],
                        styles[name][0], color=styles[name][1], label=name,
                        markersize=4)
        axis.set_title(f"{scene}: {SCENES[scene][0]}", fontsize=9)
        axis.set_xlabel("DoFs")
        axis.grid(True, which="both", linewidth=0.3)
    axes[0].set_ylabel("largest K error / K_I")
    axes[0].legend(fontsize=8)
    if len(scenes) > 2:
        axes[-1].legend(fontsize=8, loc="lower left")
    figure.tight_layout()
    path = os.path.join(top, "doc", "figures", "k_error_strategies.png")
    figure.savefig(path, dpi=120)
    print(f"\nwrote {path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenes", choices=["2d", "3d", "all"],
                        default="all")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--results",
                        default=os.path.join(tempfile.gettempdir(),
                                             "k_strategies.json"),
                        help="where the runs' numbers are kept (JSON)")
    parser.add_argument("--replot", action="store_true",
                        help="only print and draw the kept results")
    arguments = parser.parse_args()
    if arguments.replot:
        with open(arguments.results) as f:
            report(json.load(f))
    else:
        chosen = [s for s in SCENES if arguments.scenes == "all"
                  or s.endswith(arguments.scenes.upper())
                  or (arguments.scenes == "3d" and s == "penny")]
        main(chosen, arguments.jobs, arguments.results)
