#!/usr/bin/python3
"""Convergence tables of the manufactured-solution benchmarks (doc/verification.md).

Runs prm/benchmarks/manufactured_{2d,3d}.prm with Q1 and Q2 elements and prints
one Markdown table per run: cells, DoFs, relative L2 and energy errors, and
the measured orders against the mean cell size h = cells^(-1/dim).

    contrib/build.sh release
    python3 contrib/convergence_manufactured.py [--ranks 2]
"""
import argparse
import math
import tempfile

from xcrack_runs import run_xcrack, top

# (benchmark, degree, number of meshes): the finest meshes stay below ~1 min.
runs = [("manufactured_2d", 1, 7), ("manufactured_2d", 2, 6),
        ("manufactured_3d", 1, 5), ("manufactured_3d", 2, 4)]


def main():
    parser = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        for name, degree, meshes in runs:
            rows = run_xcrack(
                f"include {top}/prm/benchmarks/{name}.prm\n"
                f"set Output directory = {work}/out\n"
                f"subsection Discretization\n  set Degree = {degree}\nend\n"
                f"subsection Mesh refinement\n  set Number of meshes = {meshes}\nend\n"
                "subsection Output\n  set Timing summary = false\nend\n",
                work, args.ranks)
            dim = 2 if name.endswith("2d") else 3
            print(f"\n**{name}, Q{degree}** (optimal orders: L2 {degree + 1}, "
                  f"energy {degree}; {args.ranks} ranks, direct solver)\n")
            print("| mesh | cells | DoFs | L2 error | order | energy error | order | t_solve (s) |")
            print("|---|---|---|---|---|---|---|---|")
            for i, r in enumerate(rows):
                orders = ["–", "–"]
                if i > 0:
                    p = rows[i - 1]
                    h_ratio = (float(r["cells"]) / float(p["cells"])) ** (1 / dim)
                    orders = [f"{math.log(float(p[c]) / float(r[c])) / math.log(h_ratio):.2f}"
                              for c in ("L2_error", "energy_error")]
                print(f"| {r['mesh']} | {r['cells']} | {r['dofs']} | "
                      f"{float(r['L2_error']):.3e} | {orders[0]} | "
                      f"{float(r['energy_error']):.3e} | {orders[1]} | "
                      f"{float(r['t_solve']):.2f} |")


if __name__ == "__main__":
    main()
