#!/usr/bin/env python3
"""K along semi-elliptical surface cracks against Newman and Raju's
equations (issue 44, doc/verification/sif-3d.md "Where the front meets a
free surface"): the series a/c x a/t x load at step 0, in a plate 8c wide
and 8c long (c = 1; --half-width, --half-length change it), front cells
about a/8 to a/13.

  /usr/bin/python3 contrib/study_surface_k.py --jobs 1
  /usr/bin/python3 contrib/study_surface_k.py --shapes 0.6 --depths 0.3 \\
      --loads tension --refine 1      # one case, one level finer

Prints a markdown table: per case the front cells, DoFs, K_I against
Newman-Raju at phi = 0 (the points on the face), the largest error for
10 <= phi <= 90 deg and at the deepest point, and the wall time. Errors
are relative to Newman-Raju's K at the point under tension, to their
largest K along the front under bending (theirs vanishes at the deepest
point of a deep crack). The runs stay in --work.
"""
import argparse
import concurrent.futures
import csv
import glob
import math
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import newman_raju  # noqa: E402

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def scene(a_c, a_t, load, refine, b=4.0, length=4.0, smoothing="legendre 3"):
    """The prm text of one case and its geometry: a plate 2 b wide and
    2 length long."""
    c = 1.0
    a = a_c * c
    t = a / a_t
    # Base cells about the thickness (at most 1), front cells a/8 or finer.
    ny = max(1, round(t))
    h0 = t / ny
    nx = round(2 * b / h0)
    nz = round(2 * length / h0)
    level = math.ceil(math.log2(8 * h0 / a)) + refine
    h = h0 / 2 ** level
    expression = newman_raju.expression(
        a, c, t, b, tension=1.0 if load == "tension" else 0.0,
        bending=1.0 if load == "bending" else 0.0)
    stress = "1" if load == "tension" else f"(1 - 2 * y / {t!r})"
    centre = (0.1 * h, 0, 0.11 * h)
    text = f"""set Dimension = 3
set Output directory = output

subsection Mesh
  set Lower corner = {-b}, 0, {-length}
  set Upper corner = {b}, {t!r}, {length}
  set Subdivisions = {nx}, {ny}, {nz}
end

subsection Material
  set Young's modulus = 1
  set Poisson's ratio = 0.3
end

subsection Cracks
  set Number of cracks = 1
  subsection Crack 1
    set Shape              = ellipse
    set Center             = {centre[0]!r}, 0, {centre[2]!r}
    set Normal             = 0, 0, 1
    set In-plane direction = 1, 0, 0
    set Semi-axes          = {c!r}, {a!r}
  end
end

subsection Boundary conditions
  set Neumann       = 4: 0; 0; -{stress} | 5: 0; 0; {stress}
  set Pinned points = {-b}, {t!r}, {-length}: xyz | {b}, {t!r}, {-length}: yz | {-b}, {t!r}, {length}: y
end

subsection Enrichment
  set Tip enrichment    = geometric
  set Enrichment radius = {2 * h!r}
end

subsection Fracture parameters
  set Crown radii     = 2, 4
  set Smoothing       = {smoothing.split()[0]}
  set Legendre degree = {smoothing.split()[1] if " " in smoothing else 3}
  set Reference K     = {expression}
end

subsection Mesh refinement
  set Number of meshes = {level + 1}
  set Strategy         = front
  set Maximum level    = {level}
  subsection Front
    set Front band      = 2
    set Coarsening band = 6
  end
end

subsection Propagation
  set Number of steps = 0
end

subsection Output
  set Write vtu = false
end
"""
    return text, dict(a=a, c=c, t=t, b=b, h=h, centre=centre)


def run(case, executable, work, refine, b, length, smoothing):
    a_c, a_t, load = case
    name = (f"ac{a_c}_at{a_t}_{load}_b{b}_l{length}_r{refine}_"
            f"{smoothing.replace(' ', '')}")
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    text, geometry = scene(a_c, a_t, load, refine, b, length, smoothing)
    with open(os.path.join(directory, "case.prm"), "w") as f:
        f.write(text)
    start = time.time()
    result = subprocess.run([executable, "case.prm"], cwd=directory,
                            capture_output=True, text=True)
    wall = time.time() - start
    with open(os.path.join(directory, "screen.log"), "w") as f:
        f.write(result.stdout + result.stderr)
    if result.returncode != 0:
        return case, None, f"exit {result.returncode}"
    fronts = sorted(glob.glob(os.path.join(directory, "output",
                                           "front_*.csv")))
    rows = list(csv.DictReader(open(fronts[-1])))
    dofs = 0
    for line in result.stdout.splitlines():
        if " dofs," in line:
            dofs = int(line.split(" cells, ")[1].split(" dofs")[0])
    g = geometry
    # Errors relative to Newman-Raju's K at the point under tension; under
    # bending relative to their largest K along the front, since theirs
    # falls to zero at the deepest point of a deep crack.
    equation = (newman_raju.k_tension if load == "tension" else
                newman_raju.k_bending)
    points = []
    for r in rows:
        x = float(r["x"]) - g["centre"][0]
        y = float(r["y"])
        phi = math.atan2(y / g["a"], abs(x) / g["c"])
        points.append((math.degrees(phi), float(r["K_I"]),
                       equation(g["a"], g["c"], g["t"], g["b"], phi)))
    scale = max(abs(k) for _, _, k in points)
    points = [(phi, (k - k_nr) / (abs(k_nr) if load == "tension" else scale))
              for phi, k, k_nr in points]
    surface = [e for p, e in points if p < 1e-6]
    interior = [e for p, e in points if p >= 10]
    deepest = max(points, key=lambda pe: pe[0])[1]
    return case, dict(h=g["h"], dofs=dofs, surface=surface,
                      interior=max(interior, key=abs), deepest=deepest,
                      wall=wall), None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--executable",
                        default=os.path.join(TOP, "build/release/xcrack"))
    parser.add_argument("--work", default="/tmp/study_surface_k")
    parser.add_argument("--shapes", default="0.2,0.6,1.0", help="a/c")
    parser.add_argument("--depths", default="0.2,0.5,0.8", help="a/t")
    parser.add_argument("--loads", default="tension,bending")
    parser.add_argument("--refine", type=int, default=0,
                        help="levels beyond front cells of about a/8")
    parser.add_argument("--half-width", type=float, default=4.0,
                        help="b, the plate's half-width (c = 1)")
    parser.add_argument("--half-length", type=float, default=4.0,
                        help="the plate's half-length across the crack "
                        "plane, where the load is applied")
    parser.add_argument("--smoothing", default="legendre 3",
                        help="K along the front: 'legendre N' or 'lagrange'")
    parser.add_argument("--jobs", type=int, default=1)
    args = parser.parse_args()
    cases = [(float(s), float(d), load)
             for s in args.shapes.split(",") for d in args.depths.split(",")
             for load in args.loads.split(",")]
    print("| a/c | a/t | load | front cells | DoFs | phi = 0 | "
          "largest, 10-90 deg | deepest | wall |")
    print("|---|---|---|---|---|---|---|---|---|")
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for case, r, error in pool.map(
                lambda c: run(c, args.executable, args.work, args.refine,
                              args.half_width, args.half_length,
                              args.smoothing),
                cases):
            a_c, a_t, load = case
            if error:
                print(f"| {a_c} | {a_t} | {load} | | | {error} | | | |")
                continue
            surface = ", ".join(f"{100 * e:+.1f} %" for e in r["surface"])
            print(f"| {a_c} | {a_t} | {load} | {r['h']:.4g} | {r['dofs']:,} "
                  f"| {surface} | {100 * r['interior']:+.1f} % | "
                  f"{100 * r['deepest']:+.1f} % | {r['wall']:.0f} s |",
                  flush=True)


if __name__ == "__main__":
    main()
