#!/usr/bin/python3
"""Contact by Lagrange multipliers: which pressure space is stable.

Runs two closed cracks under uniaxial compression p = 1 with frictionless
lips, the exact closed-crack field on the boundary
(prm/benchmarks/closed_crack_2d.prm and a variant):

- `30 deg`: the benchmark itself, a centre crack of half-length 1 at 30
  degrees (exact contact pressure 0.75 everywhere on the lips);
- `45 deg, near nodes`: the same crack at 45 degrees, moved up by 0.003 so
  that it passes just above a node of every diagonal (0.02 h to 0.1 h from
  them on the meshes below; exact pressure 0.5).

Each is solved with `Contact/Formulation = lagrange` on the three
multiplier spaces (`vital nodes`, the stable one; `edges`, the naive one;
`cells`) and with the penalty on its default space (`cells`), and a
Markdown table gives per mesh the multipliers, the Newton steps, the range
of the contact pressure, K_I over the load's K scale p sqrt(pi a), the K_II
error over it and the relative L2 error. The figure
doc/figures/lip_pressure.png draws the pressure along the lips (the mean of
each cell's piece against the distance from the crack's centre) for the
three multiplier spaces on one mesh of each crack.

    contrib/build.sh release
    /usr/bin/python3 contrib/study_multipliers.py [--meshes 5] [--plot-mesh 3]
"""
import argparse
import csv
import math
import os
import re
import tempfile

from xcrack_runs import benchmark_prm, run_xcrack, top
k_scale = math.sqrt(math.pi)  # p sqrt(pi a), p = a = 1

cases = {
    "30 deg": (30, 0.0),
    "45 deg, near nodes": (45, 0.003),
}
formulations = [
    ("lagrange", "vital nodes"),
    ("lagrange", "edges"),
    ("lagrange", "cells"),
    ("penalty", "cells"),
]


def scene(case):
    """The crack, exact solution and reference K of @p case."""
    angle, shift = cases[case]
    b = math.radians(angle)
    c, s = math.cos(b), math.sin(b)
    k_ii = -k_scale * s * c
    return f"""subsection Cracks
  subsection Crack 1
    set Start point = {-c:.14f}, {-s + shift:.14f}
    set End point   = {c:.14f}, {s + shift:.14f}
  end
end
subsection Exact solution
  set Tip           = 0, {shift}
  set Tip direction = {c:.14f}, {s:.14f}
end
subsection Fracture parameters
  set Reference K = 0; {k_ii:.10f}
end
""", k_ii, c * c


def run(work, case, formulation, space, meshes):
    """Solve @p case; its output directory and rows, fronts, exact K_II and
    pressure."""
    work = os.path.join(work, re.sub(r"\W+", "_",
                                     f"{case}_{formulation}_{space}"))
    os.makedirs(work, exist_ok=True)
    crack, k_ii, pressure = scene(case)
    section = "Lagrange" if formulation == "lagrange" else "Penalty"
    entry = "Multiplier space" if formulation == "lagrange" else "Pressure space"
    rows = run_xcrack(benchmark_prm("closed_crack_2d", work, f"""{crack}
subsection Contact
  set Formulation = {formulation}
  subsection {section}
    set {entry} = {space}
  end
end
subsection Linear solver
  set Type = direct
end
subsection Mesh refinement
  set Number of meshes = {meshes}
end
subsection Output
  set Write vtu = true
end
"""), work)
    out = os.path.join(work, "out")
    fronts = []
    for mesh in range(len(rows)):
        with open(os.path.join(out, f"front_000.{mesh:02d}.csv")) as f:
            fronts.append(list(csv.DictReader(f)))
    return out, rows, fronts, k_ii, pressure


def lip_pressure(directory, mesh, angle):
    """(s, mean pressure) of each cell's piece of lip in crack-<mesh>.vtu."""
    with open(os.path.join(directory, f"crack-000.{mesh:02d}.vtu")) as f:
        text = f.read()
    def array(name):
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>\n(.*?)</DataArray>'
                      % name, text, re.S)
        return [[float(v) for v in line.split()]
                for line in m.group(1).strip().split("\n")]
    m = re.search(r'<Points>\n<DataArray[^>]*>\n(.*?)</DataArray>', text, re.S)
    points = [[float(v) for v in line.split()]
              for line in m.group(1).strip().split("\n")]
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    found = []
    for corners, p, kind in zip(array("connectivity"),
                                array("contact_pressure"), array("kind")):
        if kind[0] != 0:
            continue
        a, b = points[int(corners[0])], points[int(corners[1])]
        found.append((0.5 * ((a[0] + b[0]) * c + (a[1] + b[1]) * s), p[0]))
    return sorted(found)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", type=int, default=5)
    parser.add_argument("--plot-mesh", type=int, default=3,
                        help="the mesh whose pressures the figure draws")
    parser.add_argument("--figure",
                        default=os.path.join(top, "doc", "figures",
                                             "lip_pressure.png"))
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="xcrack-multipliers-")
    curves = {}
    print("| crack | formulation | space | DoFs | multipliers | Newton steps |"
          " contact pressure / exact | abs(K_I) / p sqrt(pi a) |"
          " K_II error / p sqrt(pi a) | L2 error |")
    print("|---" * 10 + "|")
    for case in cases:
        for formulation, space in formulations:
            out, rows, fronts, k_ii, pressure = run(work, case, formulation,
                                                    space, args.meshes)
            for r, front in zip(rows, fronts):
                k_i = max(abs(float(t["K_I"])) for t in front)
                e_ii = max(abs(float(t["K_II"]) - k_ii) for t in front)
                multipliers = r.get("contact_multipliers", "")
                multipliers = (str(int(float(multipliers)))
                               if multipliers else "-")
                low = float(r["contact_pressure_min"]) / pressure
                high = float(r["contact_pressure_max"]) / pressure
                print(f"| {case} | {formulation} | {space} | "
                      f"{int(r['dofs']):,} | {multipliers} | "
                      f"{r['newton_iterations']} | {low:.3f} to {high:.3f} | "
                      f"{k_i / k_scale:.1e} | {e_ii / k_scale:.1e} | "
                      f"{float(r['L2_error']):.3e} |", flush=True)
            if formulation == "lagrange":
                curves[(case, space)] = (
                    lip_pressure(out, args.plot_mesh, cases[case][0]),
                    pressure, int(rows[args.plot_mesh]["dofs"]))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, len(cases), figsize=(11, 4))
    for axis, case in zip(axes, cases):
        dofs = 0
        for (c, space), (points, pressure, n) in curves.items():
            if c != case:
                continue
            dofs = n
            axis.plot([s for s, _ in points], [p / pressure for _, p in points],
                      ".-", linewidth=0.8, markersize=3,
                      label=f"{space}{' (naive)' if space == 'edges' else ''}")
        axis.axhline(1, color="k", linewidth=0.5)
        axis.set_title(f"{case}, mesh {args.plot_mesh} ({dofs:,} DoFs)")
        axis.set_xlabel("distance from the crack's centre along the lips")
        axis.set_ylabel("contact pressure / exact (mean of each cell's lips)")
        axis.legend()
    figure.tight_layout()
    figure.savefig(args.figure, dpi=120)
    print(f"\nfigure: {args.figure}")


if __name__ == "__main__":
    main()
